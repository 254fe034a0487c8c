/* bs_contact.c - contact kinematics of the four slot corners and the clamp stops.
 *
 * Slot corner i (P1..P4, counter-clockwise from top left), zeta_i = +1 for the
 * top corners P1, P4 (they touch the beam's top surface), -1 for P2, P3:
 *
 *   r_P   = (x_C, z_r) + A(beta) rho_i,   rho_i = r_CP,i (scene->corner)
 *   A rho = ( cos b rho_x + sin b rho_z, -sin b rho_x + cos b rho_z )
 *   w, w' = sum phi_k q_k, sum phi_k' q_k at x_P;   alpha = atan w'
 *   r_B   = (x_P, w) + zeta h/2 (-w', 1)
 *   n     = zeta (-sin alpha, cos alpha),   t = zeta (-cos alpha, -sin alpha)
 *   d     = r_P - r_B = ( zeta h/2 w',  z_P - w - zeta h/2 )
 *   g_N   = n.d = cos(alpha) (zeta d_z - h/2 w'^2),   g_T = t.d
 *   (active when g_N < 0; the sign needs no square root)
 *
 * Force directions W = (dg/dq)^T, the published model's (docs/model.md 4):
 *   slider: dg/d(x_C, z_C, beta) = C [I | A' rho],  C = [n^T; t^T],
 *           A' rho = dA/dbeta rho = ((A rho)_z, -(A rho)_x)
 *   beam:   dg/dq_k = -C e_k + C' d phi_k',   C' = dC/dalpha = [t^T; -n^T],
 *           e_k = dr_B/dq_k = (0, phi_k) + zeta h/2 [(-phi_k', 0) - (-w'^2, w') phi_k']
 *   so with a1 = zeta h/2 (w'^2 - 1), a2 = -zeta h/2 w':
 *           W_N,k = -n_z phi_k + (-n_x a1 - n_z a2 + g_T) phi_k'
 *           W_T,k = -t_z phi_k + (-t_x a1 - t_z a2 - g_N) phi_k'
 * Heights are relative to the base (z_r = z_C - w0, docs/model.md 10): the
 * base's motion enters the slider's equation as an inertial force instead,
 * and the contact velocity has no base term (w~ = 0).
 * Without friction only the normal row exists; with the rotation locked the
 * beta column does not.
 *
 * The beam under the corners: the two corners of a side share a Taylor
 * expansion of the mode shapes (bs_shape.c), and with the expansion's
 * coefficients b[k][m] the deflection there is
 *   w = sum_m s_m t^m,   s_m = sum_k q_k b[k][m],   w' = 2 shape_scale dw/dt,
 * BS_SHAPE_TERMS sums over the modes for both corners of a side; the per-mode
 * phi_k and phi_k' that the force directions need only for a corner in contact.
 *
 * Clamp end stops (docs/model.md 9.6): frictionless unilateral contacts on x_C,
 * g = x_C - stop_min (left) and g = stop_max - x_C (right), W = (0, +-1, 0, 0).
 *
 * Generalised mass M = diag(1 (modal), m, m, J_C); with the implicit step the
 * modal entries are the effective masses 1 / mode_gain_k (docs/design.md 4).
 *
 * Redundant contacts (two corners of one face sticking, or all four with one
 * mode) make G singular: the percussions are not unique, and warm starts let
 * an internal squeeze drift from step to step into numbers whose rounding
 * wrecks the step. A relative compliance on the diagonal, G_ii (1 + eps),
 * makes the problem positive definite with a unique, bounded solution. It also
 * lets a closed contact give way at about eps of its free velocity, which
 * dissipates energy in every contact step; so eps is as small as the
 * precision allows: 1e-8 in double; in float 3e-7 (normal rows) and 3e-6
 * (tangential rows, whose near-parallel pairs float cannot resolve below
 * that; without it the solve stalls above its tolerance).
 */
#include "bs_contact.h"
#include "bs_port.h"
#include "bs_shape.h"

/* A slot corner at the midpoint and the beam under it. */
typedef struct corner_point {
    bs_real arm_x, arm_z;          /* A rho */
    bs_real x, z;                  /* r_P */
    bs_real t;                     /* local offset from its side's expansion */
    bs_real w, w_slope;            /* w and w' at x (0 inside a clamp) */
    int on_beam;                   /* x within [0, L] */
} corner_point;

static bs_real corner_zeta(int corner)
{
    return (corner == 0 || corner == 3) ? BS_R(1.0) : BS_R(-1.0);
}

static void locate_corner(const bs_scene *scene, const bs_contact_frame *frame, int corner,
                          bs_real cos_beta, bs_real sin_beta, corner_point *p)
{
    const bs_real *rho = scene->corner[corner];
    p->arm_x = cos_beta * rho[0] + sin_beta * rho[1];
    p->arm_z = -sin_beta * rho[0] + cos_beta * rho[1];
    p->x = frame->x_kinematic + p->arm_x;
    p->z = frame->z + p->arm_z;
    p->on_beam = p->x >= BS_R(0.0) && p->x <= scene->length;
}

/* w and w' at corner p from its side's sums s_m (0 inside a clamp, which
 * moves with the base). */
static void deflection_at(const bs_real *sum, bs_real slope_scale, corner_point *p)
{
    bs_real w, dw;
    bs_shape_taylor(sum, p->t, &w, &dw);
    p->w = p->on_beam ? w : BS_R(0.0);
    p->w_slope = p->on_beam ? slope_scale * dw : BS_R(0.0);
}

/* The beam under the two corners of one side from the side's expansion,
 * expanded anew at their midpoint when either is out of its reach. */
static void beam_under_side(const bs_scene *scene, const bs_real *q, bs_real reach, bs_shape_cache *cache,
                            corner_point *top, corner_point *bottom)
{
    bs_real sum[BS_SHAPE_TERMS];
    int k, m;

    top->t = bs_shape_offset(scene, cache, top->x);
    bottom->t = bs_shape_offset(scene, cache, bottom->x);
    if (!(bs_fabs(top->t) <= reach && bs_fabs(bottom->t) <= reach)) {
        bs_shape_expand(scene, BS_R(0.5) * (top->x + bottom->x), cache);
        top->t = bs_shape_offset(scene, cache, top->x);
        bottom->t = bs_shape_offset(scene, cache, bottom->x);
    }
    for (m = 0; m < BS_SHAPE_TERMS; ++m)
        sum[m] = BS_R(0.0);
    for (k = 0; k < BS_NMODES(scene); ++k)
        for (m = 0; m < BS_SHAPE_TERMS; ++m)
            sum[m] += q[k] * cache->coef[k][m];
    deflection_at(sum, BS_R(2.0) * scene->shape_scale, top);
    deflection_at(sum, BS_R(2.0) * scene->shape_scale, bottom);
}

/* Appends the evaluated corner to the active set if g_N < 0. Returns 1 if
 * the corner is on the wrong side of the beam's axis (zeta d_z < -h/2: more
 * than h/2 into the beam, which no step of a held contact reaches; the slider
 * has left the beam), else 0. */
static int add_corner(const bs_scene *scene, const bs_contact_frame *frame, int corner,
                      const corner_point *p, bs_contact_set *set)
{
    const int n = BS_NMODES(scene);
    const bs_real zeta = corner_zeta(corner);
    const bs_real hh = scene->half_thickness;
    const bs_real w_slope = p->w_slope;
    bs_real phi[BS_MAX_MODES], slope[BS_MAX_MODES];
    bs_real cos_alpha, sin_alpha, n_x, n_z, d_x, d_z, gap_n, a1, a2, coef_nn, coef_ns;
    int a;
    int k;

    d_x = zeta * hh * w_slope;
    d_z = p->z - p->w - zeta * hh;
    if (!(zeta * d_z - hh * w_slope * w_slope < BS_R(0.0)))
        return 0;
    if (zeta * d_z + hh < BS_R(0.0))
        return 1;
    bs_shape_expanded(scene, &frame->cache[corner == 0 || corner == 1 ? 0 : 1], p->t, p->on_beam, phi, slope);
    cos_alpha = BS_R(1.0) / bs_sqrt(BS_R(1.0) + w_slope * w_slope);
    sin_alpha = w_slope * cos_alpha;
    n_x = -zeta * sin_alpha;
    n_z = zeta * cos_alpha;
    gap_n = n_x * d_x + n_z * d_z;

    a = set->count++;
    set->id[a] = corner;
    a1 = zeta * hh * (w_slope * w_slope - BS_R(1.0));
    a2 = -zeta * hh * w_slope;
    coef_nn = -n_z;                               /* factor of phi_k in W_N */
    coef_ns = -n_x * a1 - n_z * a2;               /* factor of phi_k' in W_N, + g_T below */
    set->dir_slider[BS_ROWS * a][0] = n_x;
    set->dir_slider[BS_ROWS * a][1] = n_z;
#if BS_WITH_ROTATION
    set->dir_slider[BS_ROWS * a][2] = n_x * p->arm_z - n_z * p->arm_x;
#endif
#if BS_WITH_FRICTION
    {
        const bs_real t_x = -zeta * cos_alpha;
        const bs_real t_z = -zeta * sin_alpha;
        const bs_real gap_t = t_x * d_x + t_z * d_z;
        const bs_real coef_tn = -t_z;
        const bs_real coef_ts = -t_x * a1 - t_z * a2 - gap_n;
        coef_ns += gap_t;
        set->mu[a] = scene->mu;
        for (k = 0; k < n; ++k)
            set->dir_beam[BS_ROWS * a + 1][k] = coef_tn * phi[k] + coef_ts * slope[k];
        set->dir_slider[BS_ROWS * a + 1][0] = t_x;
        set->dir_slider[BS_ROWS * a + 1][1] = t_z;
#if BS_WITH_ROTATION
        set->dir_slider[BS_ROWS * a + 1][2] = t_x * p->arm_z - t_z * p->arm_x;
#endif
    }
#else
    (void)gap_n; /* the tangential row is what needs it */
#endif
    for (k = 0; k < n; ++k)
        set->dir_beam[BS_ROWS * a][k] = coef_nn * phi[k] + coef_ns * slope[k];
    return 0;
}

static void add_stop(const bs_scene *scene, int id, bs_real sign, bs_contact_set *set)
{
    const int a = set->count++;
    int r, k;

    set->id[a] = id;
#if BS_WITH_FRICTION
    set->mu[a] = BS_R(0.0);
#endif
    for (r = 0; r < BS_ROWS; ++r) {
        for (k = 0; k < BS_NMODES(scene); ++k)
            set->dir_beam[BS_ROWS * a + r][k] = BS_R(0.0);
        for (k = 0; k < BS_SLIDER_DOF; ++k)
            set->dir_slider[BS_ROWS * a + r][k] = BS_R(0.0);
    }
    set->dir_slider[BS_ROWS * a][0] = sign;
}

#if BS_WITH_ROTATION
/* cos and sin of the slider rotation. The play keeps beta within a few
 * (R - h) / B ~ 0.005 rad; for |beta| < 0.05 the Taylor polynomials below
 * are exact to rounding in double (first omitted terms beta^9/9! = 5e-18 and
 * beta^10/10! = 3e-20) and save two library calls per step. */
static void rotation(bs_real beta, bs_real *cos_beta, bs_real *sin_beta)
{
    const bs_real b2 = beta * beta;
    if (b2 < BS_R(0.0025)) { /* multiplications by 1/6, 1/20, ...: no division */
        *sin_beta = beta * (BS_R(1.0) - b2 * BS_R(0.16666666666666667)
                            * (BS_R(1.0) - b2 * BS_R(0.05) * (BS_R(1.0) - b2 * BS_R(0.023809523809523808))));
        *cos_beta = BS_R(1.0) - b2 * BS_R(0.5)
                    * (BS_R(1.0) - b2 * BS_R(0.083333333333333333)
                       * (BS_R(1.0) - b2 * BS_R(0.033333333333333333) * (BS_R(1.0) - b2 * BS_R(0.017857142857142857))));
        return;
    }
    *cos_beta = bs_cos(beta);
    *sin_beta = bs_sin(beta);
}
#endif

bs_status bs_contact_detect(const bs_scene *scene, const bs_contact_frame *frame, bs_contact_set *set)
{
    bs_real cos_beta = BS_R(1.0), sin_beta = BS_R(0.0);
    corner_point at[BS_CORNERS];
    int corner;

#if BS_WITH_ROTATION
    rotation(frame->beta, &cos_beta, &sin_beta);
#endif
    set->count = 0;
    for (corner = 0; corner < BS_CORNERS; ++corner)
        locate_corner(scene, frame, corner, cos_beta, sin_beta, &at[corner]);
    beam_under_side(scene, frame->q_beam, frame->reach, &frame->cache[0], &at[0], &at[1]); /* P1, P2 */
    beam_under_side(scene, frame->q_beam, frame->reach, &frame->cache[1], &at[3], &at[2]); /* P4, P3 */
    for (corner = 0; corner < BS_CORNERS; ++corner)
        if (add_corner(scene, frame, corner, &at[corner], set))
            return BS_E_ESCAPED;
    if (frame->stops) {
        if (frame->x_stops < scene->stop_min)
            add_stop(scene, BS_STOP_LEFT, BS_R(1.0), set);
        if (frame->x_stops > scene->stop_max)
            add_stop(scene, BS_STOP_RIGHT, BS_R(-1.0), set);
    }
    return BS_OK;
}

/* W_r^T u of active contact a, row r. */
static bs_real row_velocity(const bs_scene *scene, const bs_contact_set *set, int a, int r,
                            const bs_real *u_beam, const bs_real *u_slider)
{
    const bs_real *beam = set->dir_beam[BS_ROWS * a + r];
    const bs_real *slider = set->dir_slider[BS_ROWS * a + r];
    bs_real v = slider[0] * u_slider[0];
    int k;
    v += slider[1] * u_slider[1];
#if BS_WITH_ROTATION
    v += slider[2] * u_slider[2];
#endif
    for (k = 0; k < BS_NMODES(scene); ++k)
        v += beam[k] * u_beam[k];
    return v;
}

void bs_contact_free_velocity(const bs_scene *scene, bs_contact_set *set,
                              const bs_real *u_beam, const bs_real *u_slider,
                              const bs_real *u_beam_before, const bs_real *u_slider_before)
{
    int a, r;

#if !BS_WITH_RESTITUTION
    (void)u_beam_before;
    (void)u_slider_before;
#endif
    for (a = 0; a < set->count; ++a)
        for (r = 0; r < BS_ROWS; ++r) {
            bs_real v = row_velocity(scene, set, a, r, u_beam, u_slider);
#if BS_WITH_RESTITUTION
            if (r == 0)
                v += scene->e_n * row_velocity(scene, set, a, 0, u_beam_before, u_slider_before);
#endif
            set->free_velocity[BS_ROWS * a + r] = v;
        }
}

void bs_contact_delassus(const bs_scene *scene, bs_contact_set *set)
{
    const int rows = BS_ROWS * set->count;
    int i, j, k;

    for (i = 0; i < rows; ++i) {
        const bs_real *slider_i = set->dir_slider[i];
        /* beam part of M^-1 W_i, formed once per row; a local copy even without
         * the implicit gains: the stores to set->delassus may alias dir_beam, so
         * through a pointer the compiler reloads row i for every entry (the
         * explicit Cortex-M builds ran 2-4 % more instructions in their worst steps) */
        bs_real beam_i[BS_MAX_MODES];
#if BS_WITH_ROTATION
        const bs_real rotation_i = scene->inertia_inv * slider_i[2];
#endif
        for (k = 0; k < BS_NMODES(scene); ++k)
#if BS_WITH_IMPLICIT
            beam_i[k] = set->dir_beam[i][k] * scene->mode_gain[k];
#else
            beam_i[k] = set->dir_beam[i][k];
#endif
        for (j = i; j < rows; ++j) {
            const bs_real *beam_j = set->dir_beam[j];
            const bs_real *slider_j = set->dir_slider[j];
            bs_real g = scene->mass_inv * (slider_i[0] * slider_j[0] + slider_i[1] * slider_j[1]);
#if BS_WITH_ROTATION
            g += rotation_i * slider_j[2];
#endif
            for (k = 0; k < BS_NMODES(scene); ++k)
                g += beam_i[k] * beam_j[k];
            set->delassus[i][j] = g;
            set->delassus[j][i] = g;
        }
        set->delassus[i][i] *= BS_R(1.0) + (i % BS_ROWS ? BS_CONTACT_COMPLIANCE_T : BS_CONTACT_COMPLIANCE);
    }
}

void bs_contact_apply(const bs_scene *scene, const bs_contact_set *set,
                      bs_real *u_beam, bs_real *u_slider)
{
    int i, k;

    for (i = 0; i < BS_ROWS * set->count; ++i) {
        const bs_real p = set->percussion[i];
        const bs_real *slider = set->dir_slider[i];
        for (k = 0; k < BS_NMODES(scene); ++k)
#if BS_WITH_IMPLICIT
            u_beam[k] += scene->mode_gain[k] * set->dir_beam[i][k] * p;
#else
            u_beam[k] += set->dir_beam[i][k] * p;
#endif
        u_slider[0] += scene->mass_inv * slider[0] * p;
        u_slider[1] += scene->mass_inv * slider[1] * p;
#if BS_WITH_ROTATION
        u_slider[2] += scene->inertia_inv * slider[2] * p;
#endif
    }
}
