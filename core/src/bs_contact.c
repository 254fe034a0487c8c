/* bs_contact.c - contact kinematics of the four slot corners and the clamp
 * stops, and the contact problem they pose.
 *
 * Slot corner i (P1..P4, counter-clockwise from top left), zeta_i = +1 for the
 * top corners P1, P4 (they touch the beam's top surface), -1 for P2, P3:
 *
 *   r_P   = (x_C, z_r) + A(beta) rho_i,   rho_i = r_CP,i (the scene's corner)
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
 * Each row's beam part is a combination of two vectors, phi and phi' at the
 * corner: the set keeps those and the two coefficients per row, never the
 * rows, and forms every product with them in passes over the modes (a lone
 * corner's in one, two corners' in three: each corner's own, then the cross
 * products; corner_pass, cross_products):
 *   W_r^T u         = c_r0 (phi . u) + c_r1 (phi' . u)
 *   W_r^T M^-1 W_s  = c_r0 c_s0 (phi_a . phi_b) + c_r0 c_s1 (phi_a . phi'_b)
 *                   + c_r1 c_s0 (phi'_a . phi_b) + c_r1 c_s1 (phi'_a . phi'_b) + slider part
 *   M^-1 W P        = sum_a (c_N0 P_N + c_T0 P_T) phi_a + (c_N1 P_N + c_T1 P_T) phi'_a
 * (with the implicit step's modal masses 1 / mode_gain_k in the dot products
 * of M^-1). cos alpha = 1 / sqrt(1 + w'^2) is a binomial series for the
 * slopes that occur, exact to rounding there, and the formula beyond.
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
#include "bs_inline.h"
#include "bs_port.h"
#include "bs_shape.h"

/* The beam part of M^-1: the implicit step's mode gains (prepared as 1 for
 * an explicit scene); a build without the implicit step multiplies by
 * nothing. */
#if BS_WITH_IMPLICIT
#define MODE_GAIN(k, i) ((k)->mode_gain[i])
#else
#define MODE_GAIN(k, i) ((void)(k), BS_R(1.0))
#endif

/* The start of a sum over the modes: its mode-0 term (rather than 0 + it:
 * an addition and a 0 from flash saved), or 0 for a rigid beam (no modes).
 * With n a constant (bs_inline.h) the test is folded away. */
#define MODE_0_TERM(n, term) ((n) > 0 ? (term) : BS_R(0.0))

/* The coefficients of the series below, and their bound on the square of
 * the angle (0.05^2), in k->series: a controller reads a literal from flash,
 * with wait states, and these from the sim's RAM (bs_contact_prepare). */
enum { SMALL_SQ, SIN_6, SIN_20, SIN_42, COS_12, COS_30, COS_56 };

void bs_contact_prepare(bs_step_constants *k)
{
    bs_real *c = k->series;
    c[SMALL_SQ] = BS_R(0.0025);
    c[SIN_6] = BS_R(0.16666666666666667);
    c[SIN_20] = BS_R(0.05);
    c[SIN_42] = BS_R(0.023809523809523808);
    c[COS_12] = BS_R(0.083333333333333333);
    c[COS_30] = BS_R(0.033333333333333333);
    c[COS_56] = BS_R(0.017857142857142857);
}

/* cos alpha = (1 + w'^2)^(-1/2). For x = w'^2 < 1/400 (slopes below 0.05, all
 * but the wildest steps) the binomial series 1 - x/2 + 3x^2/8 - 5x^3/16 + ...,
 * alternating with falling terms, stops below half an ulp: in float after
 * x^2 (next term 5/16 x^3 < 5e-9), in double after x^5 (231/1024 x^6 < 6e-17).
 * A square root and a division saved per corner in contact. */
BS_INLINE bs_real cos_of_slope(const bs_real *c, bs_real w_slope)
{
    const bs_real x = w_slope * w_slope;
    if (x < c[SMALL_SQ]) {
#if BS_REAL_FLOAT
        return BS_R(1.0) - x * (BS_R(0.5) - x * BS_R(0.375));
#else
        return BS_R(1.0) - x * (BS_R(0.5) - x * (BS_R(0.375) - x * (BS_R(0.3125)
               - x * (BS_R(0.2734375) - x * BS_R(0.24609375)))));
#endif
    }
    return BS_R(1.0) / bs_sqrt(BS_R(1.0) + x);
}

/* A slot corner at the midpoint and the beam under it. */
typedef struct corner_point {
    bs_real arm_x, arm_z;          /* A rho */
    bs_real z;                     /* z_P */
    bs_real t;                     /* local offset from its side's expansion */
    bs_real w, w_slope;            /* w and w' at x_P (0 inside a clamp) */
    int on_beam;                   /* x_P within [0, L] */
} corner_point;

/* Appends corner (its point p, zeta its side of the beam) to the active
 * set: its phi and phi', the coefficients of its rows' beam parts and their
 * slider parts. d_z = z_P - w - zeta h/2, already found in contact; hh = h/2
 * as the side has it (read again here, it cost a load a corner). */
BS_INLINE void add_corner(int n, const bs_step_constants *k, const bs_shape_cache *cache, int corner,
                          bs_real hh, bs_real zeta, bs_real d_z, const corner_point *p, const bs_real (*warm)[BS_ROWS],
                          bs_contact_set *set)
{
    const bs_real w_slope = p->w_slope;
    const bs_real d_x = zeta * hh * w_slope;
    const bs_real cos_alpha = cos_of_slope(k->series, w_slope);
    const bs_real sin_alpha = w_slope * cos_alpha;
    const bs_real n_x = -zeta * sin_alpha, n_z = zeta * cos_alpha;
    const bs_real gap_n = n_x * d_x + n_z * d_z;
    const bs_real a1 = zeta * hh * (w_slope * w_slope - BS_R(1.0));
    const bs_real a2 = -zeta * hh * w_slope;
    const bs_real t_x = -zeta * cos_alpha, t_z = -zeta * sin_alpha;
    const bs_real gap_t = t_x * d_x + t_z * d_z;
    /* the factor of phi_k' in W_N: g_T is part of the normal row with or
     * without friction (the tangent turns with the beam's slope) */
    const bs_real coef_ns = -n_x * a1 - n_z * a2 + gap_t;
    bs_real *normal;
    const int a = set->count++;

    set->id[a] = corner;
    BS_FORGET(cache); /* the 20 coefficients of the side's mode sums: kept, they spilled */
    bs_shape_expanded(n, cache, p->t, p->on_beam, k->slope_scale, set->phi[a], set->slope[a]);
    set->percussion[BS_ROWS * a] = warm[corner][0]; /* the warm start: its last percussion */
#if BS_WITH_FRICTION
    set->percussion[BS_ROWS * a + 1] = warm[corner][1];
#endif
    normal = set->dir_slider[BS_ROWS * a];
    normal[0] = n_x;
    normal[1] = n_z;
#if BS_WITH_ROTATION
    normal[2] = n_x * p->arm_z - n_z * p->arm_x;
#endif
#if BS_WITH_FRICTION
    {
        bs_real *tangent = set->dir_slider[BS_ROWS * a + 1];
        set->mu[a] = k->mu;
        set->beam_coef[a][1][0] = -t_z;
        set->beam_coef[a][1][1] = -t_x * a1 - t_z * a2 - gap_n;
        tangent[0] = t_x;
        tangent[1] = t_z;
#if BS_WITH_ROTATION
        tangent[2] = t_x * p->arm_z - t_z * p->arm_x;
#endif
    }
#else
    (void)gap_n; /* the tangential row is what needs it */
#endif
    set->beam_coef[a][0][0] = -n_z;
    set->beam_coef[a][0][1] = coef_ns;
}

/* The slot corner rho at the slider pose: its arm A rho, height and offset
 * in the side's expansion (t); whether it is over the beam is found later
 * (on_beam_or_clamped). */
BS_INLINE void locate_corner(const bs_step_constants *k, const bs_contact_frame *frame, const bs_real *rho,
                             bs_real cos_beta, bs_real sin_beta, bs_real centre, corner_point *p)
{
    p->arm_x = cos_beta * rho[0] + sin_beta * rho[1];
    p->arm_z = -sin_beta * rho[0] + cos_beta * rho[1];
    p->z = frame->z + p->arm_z;
    p->t = k->slope_scale * (frame->x_kinematic + p->arm_x - centre);
}

/* Corner p within the reach of an expansion that is not wholly on the beam
 * (near a clamp, rare): over the beam if its x is in [0, L], else inside
 * the clamp, which moves with the base: w = w' = 0 there. */
static void on_beam_or_clamped(bs_real length, const bs_contact_frame *frame, corner_point *p)
{
    const bs_real x = frame->x_kinematic + p->arm_x;
    p->on_beam = x >= BS_R(0.0) && x <= length;
    if (!p->on_beam)
        p->w = p->w_slope = BS_R(0.0);
}

/* One side of the slot: its top corner (P1 or P4, zeta = +1) and bottom
 * corner (P2 or P3, zeta = -1) over the beam, from the side's expansion of
 * the mode shapes (expanded anew at their midpoint when either is beyond
 * its reach), each added to the set if g_N < 0. Returns 1 if a corner is on
 * the wrong side of the beam's axis (zeta d_z < -h/2: more than h/2 into
 * the beam, which no step of a held contact reaches; the slider has left
 * the beam), else 0. */
BS_INLINE int side_of_slot(int n, const bs_scene *scene, const bs_step_constants *k, const bs_contact_frame *frame,
                        bs_shape_cache *cache, int top_id, int bottom_id, bs_real cos_beta, bs_real sin_beta,
                        bs_contact_set *set)
{
    const bs_real hh = k->half_thickness;
    const int first = top_id < bottom_id ? top_id : bottom_id;
    bs_real rho[4], sum[BS_SHAPE_TERMS];
    const bs_real *row; /* of cache->coef: mode i's coefficients, then i + 1's */
    corner_point top, bottom;
    bs_real dw, d_top, d_bottom;
    int i, m;

    /* the side's corners, neighbours in k->corner (P1, P2 and P3, P4): one load */
    bs_load_4(&k->corner[0][0] + 2 * first, rho);
    locate_corner(k, frame, &rho[2 * (top_id - first)], cos_beta, sin_beta, cache->centre, &top);
    locate_corner(k, frame, &rho[2 * (bottom_id - first)], cos_beta, sin_beta, cache->centre, &bottom);
    /* a new expansion: once in many steps (bs_shape.c), off the straight path */
    if (BS_UNLIKELY(!(bs_fabs(top.t) <= frame->reach && bs_fabs(bottom.t) <= frame->reach))) {
        const bs_real x_top = frame->x_kinematic + top.arm_x, x_bottom = frame->x_kinematic + bottom.arm_x;
        bs_shape_expand(scene, BS_R(0.5) * (x_top + x_bottom), cache);
        top.t = k->slope_scale * (x_top - cache->centre);
        bottom.t = k->slope_scale * (x_bottom - cache->centre);
    }
    /* w = sum_m s_m t^m with s_m = sum_k q_k b[k][m]: the modes summed once
     * for both corners (0 inside a clamp, which moves with the base), mode
     * by mode from its coefficients loaded at once (bs_shape_terms), each
     * sum begun with its mode-0 term (0 for a rigid beam: no modes) */
    for (m = 0; m < BS_SHAPE_TERMS; ++m)
        sum[m] = BS_R(0.0);
    row = cache->coef[0];
    for (i = 0; i < n; ++i) {
        const bs_real q = frame->q_beam[i];
        bs_real b[BS_SHAPE_TERMS];
        bs_shape_terms(&row, b);
        for (m = 0; m < BS_SHAPE_TERMS; ++m)
            sum[m] = i > 0 ? sum[m] + q * b[m] : q * b[m];
        BS_SHAPE_TERMS_HERE(sum);
    }
    bs_shape_taylor(sum, top.t, &top.w, &dw);
    top.w_slope = k->slope_scale * dw;
    bs_shape_taylor(sum, bottom.t, &bottom.w, &dw);
    bottom.w_slope = k->slope_scale * dw;
    /* both on the beam when the whole reach is (bs_shape_expand), else
     * each tested (0 inside a clamp, which moves with the base): the four
     * corners' two tests each were 16 cycles a step (mid-fig6-float
     * 2364.8 -> 2348.8, the same hash) */
    top.on_beam = bottom.on_beam = 1;
    if (BS_UNLIKELY(!cache->on_beam)) {
        on_beam_or_clamped(k->length, frame, &top);
        on_beam_or_clamped(k->length, frame, &bottom);
    }
    /* g_N < 0 as zeta d_z - h/2 w'^2 < 0 (cos alpha > 0 needs no root) */
    d_top = top.z - top.w - hh;
    d_bottom = bottom.z - bottom.w + hh;
    if (d_top - hh * top.w_slope * top.w_slope < BS_R(0.0)) {
        if (d_top + hh < BS_R(0.0))
            return 1;
        add_corner(n, k, cache, top_id, hh, BS_R(1.0), d_top, &top, frame->warm, set);
    }
    if (-d_bottom - hh * bottom.w_slope * bottom.w_slope < BS_R(0.0)) {
        if (-d_bottom + hh < BS_R(0.0))
            return 1;
        add_corner(n, k, cache, bottom_id, hh, BS_R(-1.0), d_bottom, &bottom, frame->warm, set);
    }
    return 0;
}

static void add_stop(int id, bs_real sign, const bs_real (*warm)[BS_ROWS], bs_contact_set *set)
{
    const int a = set->count++;
    int r, c;

    set->id[a] = id;
    for (r = 0; r < BS_ROWS; ++r)
        set->percussion[BS_ROWS * a + r] = warm[id][r];
#if BS_WITH_FRICTION
    set->mu[a] = BS_R(0.0);
#endif
    for (r = 0; r < BS_ROWS; ++r) {
        set->beam_coef[a][r][0] = set->beam_coef[a][r][1] = BS_R(0.0);
        for (c = 0; c < BS_SLIDER_DOF; ++c)
            set->dir_slider[BS_ROWS * a + r][c] = BS_R(0.0);
    }
    set->dir_slider[BS_ROWS * a][0] = sign;
}

#if BS_WITH_ROTATION
/* cos and sin of the slider rotation. The play keeps beta within a few
 * (R - h) / B ~ 0.005 rad; for |beta| < 0.05 the Taylor polynomials below
 * are exact to rounding in double (first omitted terms beta^9/9! = 5e-18 and
 * beta^10/10! = 3e-20) and save two library calls per step. */
BS_INLINE void rotation(const bs_real *c, bs_real beta, bs_real *cos_beta, bs_real *sin_beta)
{
    const bs_real b2 = beta * beta;
    bs_real lead[4]; /* c[SMALL_SQ] .. c[SIN_42], one load (bs_load_4) */
    bs_load_4(c, lead);
    if (b2 < lead[SMALL_SQ]) { /* multiplications by 1/6, 1/20, ...: no division */
        *sin_beta = beta * (BS_R(1.0) - b2 * lead[SIN_6]
                            * (BS_R(1.0) - b2 * lead[SIN_20] * (BS_R(1.0) - b2 * lead[SIN_42])));
        *cos_beta = BS_R(1.0) - b2 * BS_R(0.5)
                    * (BS_R(1.0) - b2 * c[COS_12] * (BS_R(1.0) - b2 * c[COS_30] * (BS_R(1.0) - b2 * c[COS_56])));
        return;
    }
    *cos_beta = bs_cos(beta);
    *sin_beta = bs_sin(beta);
}
#endif

BS_INLINE bs_status detect(int n, const bs_scene *scene, const bs_step_constants *k, const bs_contact_frame *frame,
                           bs_contact_set *set)
{
    bs_real cos_beta = BS_R(1.0), sin_beta = BS_R(0.0);

#if BS_WITH_ROTATION
    rotation(k->series, frame->beta, &cos_beta, &sin_beta);
#endif
    set->count = 0; /* in the order found: P1, P2, P4, P3, the stops */
    if (side_of_slot(n, scene, k, frame, &frame->cache[0], 0, 1, cos_beta, sin_beta, set)
        || side_of_slot(n, scene, k, frame, &frame->cache[1], 3, 2, cos_beta, sin_beta, set))
        return BS_E_ESCAPED;
    if (frame->stops) {
        if (frame->x_stops < k->stop_min)
            add_stop(BS_STOP_LEFT, BS_R(1.0), frame->warm, set);
        if (frame->x_stops > k->stop_max)
            add_stop(BS_STOP_RIGHT, BS_R(-1.0), frame->warm, set);
    }
    return BS_OK;
}

/* Inlined into its caller, the step, where the whole program is optimised
 * at once (-flto, as every Cortex-M image is built): as a call it saved and
 * restored 21 registers and read its frame back from memory (mid-fig6-float
 * 2767.6 -> 2742.3 cycles a step, 280 bytes more stack; GCC then leaves the
 * pair solve a call).
 * Elsewhere an ordinary function. */
BS_STEP_STAGE_ALWAYS
bs_status bs_contact_detect(const bs_scene *scene, const bs_step_constants *k, const bs_contact_frame *frame,
                            bs_contact_set *set)
{
    BS_MODES_SWITCH(BS_NMODES(scene), return detect(MODES, scene, k, frame, set));
    return BS_OK; /* not reached */
}

/* The products of two corners' shape vectors a and b over the modes:
 * dot[0] = phi_a . M^-1 phi_b, [1] phi_a . M^-1 phi'_b, [2] phi'_a . M^-1
 * phi_b, [3] phi'_a . M^-1 phi'_b (M^-1: the mode gains, 1 when explicit). */
BS_INLINE void cross_products(int n, const bs_step_constants *k, const bs_contact_set *set, int a, int b,
                              bs_real *dot)
{
    const bs_real *phi_a = set->phi[a], *slope_a = set->slope[a], *phi_b = set->phi[b], *slope_b = set->slope[b];
    bs_real pp = MODE_0_TERM(n, MODE_GAIN(k, 0) * phi_a[0] * phi_b[0]);
    bs_real ps = MODE_0_TERM(n, MODE_GAIN(k, 0) * phi_a[0] * slope_b[0]);
    bs_real sp = MODE_0_TERM(n, MODE_GAIN(k, 0) * slope_a[0] * phi_b[0]);
    bs_real ss = MODE_0_TERM(n, MODE_GAIN(k, 0) * slope_a[0] * slope_b[0]);
    int i;
    for (i = 1; i < n; ++i) {
        const bs_real gp = MODE_GAIN(k, i) * phi_a[i], gs = MODE_GAIN(k, i) * slope_a[i];
        pp += gp * phi_b[i];
        ps += gp * slope_b[i];
        sp += gs * phi_b[i];
        ss += gs * slope_b[i];
    }
    dot[0] = pp;
    dot[1] = ps;
    dot[2] = sp;
    dot[3] = ss;
}

/* W_r^T M^-1 W_s of a row with beam coefficients x and slider part sx and a
 * row with y and sy: the beam part from the shape products dot
 * (cross_products; NULL when either is a stop) and the slider part. */
BS_INLINE bs_real delassus_entry(const bs_step_constants *k, const bs_real *x, const bs_real *sx, const bs_real *y,
                              const bs_real *sy, const bs_real *dot)
{
    bs_real g = k->mass_inv * (sx[0] * sy[0] + sx[1] * sy[1]);
#if BS_WITH_ROTATION
    g += k->inertia_inv * sx[2] * sy[2];
#endif
    if (dot)
        g += x[0] * (y[0] * dot[0] + y[1] * dot[1]) + x[1] * (y[0] * dot[2] + y[1] * dot[3]);
    return g;
}

/* The rows of G of contact a against contact b (b <= a; dot: their shape
 * products or NULL), with the compliance on the diagonal. */
BS_INLINE void delassus_block(const bs_step_constants *k, bs_contact_set *set, int a, int b, const bs_real *dot)
{
    bs_real (*g)[BS_ROWS * BS_MAX_CONTACTS] = set->delassus;
    const int ra = BS_ROWS * a, rb = BS_ROWS * b;
    const bs_real *na = set->beam_coef[a][0], *nb = set->beam_coef[b][0];
    const bs_real *sna = set->dir_slider[ra], *snb = set->dir_slider[rb];
    bs_real nn = delassus_entry(k, na, sna, nb, snb, dot);
#if BS_WITH_FRICTION
    const bs_real *ta = set->beam_coef[a][1], *tb = set->beam_coef[b][1];
    const bs_real *sta = set->dir_slider[ra + 1], *stb = set->dir_slider[rb + 1];
    bs_real nt = delassus_entry(k, na, sna, tb, stb, dot), tt = delassus_entry(k, ta, sta, tb, stb, dot);
    if (a == b) {
        tt *= k->compliance[1];
    } else {
        const bs_real tn = delassus_entry(k, ta, sta, nb, snb, dot);
        g[ra + 1][rb] = g[rb][ra + 1] = tn;
    }
    g[ra][rb + 1] = g[rb + 1][ra] = nt;
    g[ra + 1][rb + 1] = g[rb + 1][ra + 1] = tt;
#endif
    if (a == b)
        nn *= k->compliance[0];
    g[ra][rb] = g[rb][ra] = nn;
}

/* W_r^T u of row r of contact a: the beam part from phi . u and phi' . u. */
BS_INLINE bs_real row_velocity(const bs_contact_set *set, int a, int r, bs_real phi_u, bs_real slope_u,
                            const bs_real *u_slider)
{
    const bs_real *c = set->beam_coef[a][r];
    const bs_real *slider = set->dir_slider[BS_ROWS * a + r];
    bs_real v = c[0] * phi_u + c[1] * slope_u + slider[0] * u_slider[0] + slider[1] * u_slider[1];
#if BS_WITH_ROTATION
    v += slider[2] * u_slider[2];
#endif
    return v;
}

/* Products of one corner's shape vectors with the velocities: [0] phi . u,
 * [1] phi' . u at the free velocities, [2] and [3] at those before the step. */
typedef struct shape_velocities {
    bs_real at[4];
} shape_velocities;

/* c of contact a from its shape products with the velocities. */
BS_INLINE void free_velocity(const bs_step_constants *k, bs_contact_set *set, int a, const shape_velocities *v,
                          const bs_real *u_slider, const bs_real *u_slider_before)
{
    bs_real c_n = row_velocity(set, a, 0, v->at[0], v->at[1], u_slider);
#if BS_WITH_RESTITUTION
    c_n += k->e_n * row_velocity(set, a, 0, v->at[2], v->at[3], u_slider_before);
#else
    (void)k;
    (void)u_slider_before;
#endif
    set->free_velocity[BS_ROWS * a] = c_n;
#if BS_WITH_FRICTION
    set->free_velocity[BS_ROWS * a + 1] = row_velocity(set, a, 1, v->at[0], v->at[1], u_slider);
#endif
}

/* One corner's pass over the modes: its velocities and self products, then
 * its rows of c and of the Delassus matrix. The whole problem of a lone
 * corner (most contact steps), and the first and last pass of two. */
BS_INLINE void corner_pass(int n, const bs_step_constants *k, bs_contact_set *set, int a, const bs_real *u_beam,
                           const bs_real *u_slider, const bs_real *u_beam_before, const bs_real *u_slider_before)
{
    const bs_real *phi = set->phi[a], *slope = set->slope[a];
    shape_velocities v = { { MODE_0_TERM(n, phi[0] * u_beam[0]), MODE_0_TERM(n, slope[0] * u_beam[0]), BS_R(0.0),
                             BS_R(0.0) } };
    bs_real dot[4];
    int i;
#if BS_WITH_RESTITUTION
    v.at[2] = MODE_0_TERM(n, phi[0] * u_beam_before[0]);
    v.at[3] = MODE_0_TERM(n, slope[0] * u_beam_before[0]);
#endif
    dot[0] = MODE_0_TERM(n, MODE_GAIN(k, 0) * phi[0] * phi[0]);
    dot[1] = MODE_0_TERM(n, MODE_GAIN(k, 0) * phi[0] * slope[0]);
    dot[3] = MODE_0_TERM(n, MODE_GAIN(k, 0) * slope[0] * slope[0]);
    for (i = 1; i < n; ++i) {
        const bs_real gp = MODE_GAIN(k, i) * phi[i], gs = MODE_GAIN(k, i) * slope[i];
        v.at[0] += phi[i] * u_beam[i];
        v.at[1] += slope[i] * u_beam[i];
#if BS_WITH_RESTITUTION
        v.at[2] += phi[i] * u_beam_before[i];
        v.at[3] += slope[i] * u_beam_before[i];
#endif
        dot[0] += gp * phi[i];
        dot[1] += gp * slope[i];
        dot[3] += gs * slope[i];
    }
    (void)u_beam_before;
    dot[2] = dot[1];
    free_velocity(k, set, a, &v, u_slider, u_slider_before);
    delassus_block(k, set, a, a, dot);
}

/* Two corners in contact (the rest but a few): a pass for each corner
 * (corner_pass) and one between them for the cross products, each with its
 * rows written when it ends: at most 4 + 20 sums and shape values live at
 * once (in two passes, the second's 11 sums beside both corners' 20 values
 * spilled, and the velocities reloaded). */
BS_INLINE void problem_of_two(int n, const bs_step_constants *k, bs_contact_set *set,
                           const bs_real *u_beam, const bs_real *u_slider, const bs_real *u_beam_before,
                           const bs_real *u_slider_before)
{
    bs_real dot[4];
    /* read back what the detection (inlined before it) wrote: kept, it
     * spilled (here rather than in problem, whose lone corner is better off
     * with what GCC keeps) */
    BS_FORGET(set);
    /* and the step's velocities, its own arrays: GCC read each of u_beam's
     * again at every product, four times in all (mid-fig6-float 2455.6 ->
     * 2441.9 cycles a step with u_slider's; the same for u_beam_before,
     * u_slider_before or k cost 3 to 5 more) */
    BS_FORGET(u_beam);
    BS_FORGET(u_slider);
    corner_pass(n, k, set, 0, u_beam, u_slider, u_beam_before, u_slider_before);
    cross_products(n, k, set, 1, 0, dot);
    delassus_block(k, set, 1, 0, dot);
    corner_pass(n, k, set, 1, u_beam, u_slider, u_beam_before, u_slider_before);
}

BS_INLINE void problem(int n, const bs_step_constants *k, bs_contact_set *set, const bs_real *u_beam,
                       const bs_real *u_slider, const bs_real *u_beam_before, const bs_real *u_slider_before)
{
    int corners, a, b, i;

    corners = (set->count > 0 && set->id[0] < BS_CORNERS) + (set->count > 1 && set->id[1] < BS_CORNERS);

    if (set->count == 1 && corners == 1) {
        corner_pass(n, k, set, 0, u_beam, u_slider, u_beam_before, u_slider_before);
        return;
    }
    if (set->count == 2 && corners == 2) {
        problem_of_two(n, k, set, u_beam, u_slider, u_beam_before, u_slider_before);
        return;
    }
    /* stops, three or more contacts: pair by pair */
    for (a = 0; a < set->count; ++a) {
        const int corner = set->id[a] < BS_CORNERS;
        shape_velocities v = { { BS_R(0.0), BS_R(0.0), BS_R(0.0), BS_R(0.0) } };
        bs_real dot[4];
        if (corner)
            for (i = 0; i < n; ++i) {
                v.at[0] += set->phi[a][i] * u_beam[i];
                v.at[1] += set->slope[a][i] * u_beam[i];
#if BS_WITH_RESTITUTION
                v.at[2] += set->phi[a][i] * u_beam_before[i];
                v.at[3] += set->slope[a][i] * u_beam_before[i];
#endif
            }
        free_velocity(k, set, a, &v, u_slider, u_slider_before);
        for (b = 0; b <= a; ++b) {
            const int both = corner && set->id[b] < BS_CORNERS;
            if (both)
                cross_products(n, k, set, a, b, dot);
            delassus_block(k, set, a, b, both ? dot : (const bs_real *)0);
        }
    }
}

/* Inlined into a compiled scene's step (BS_STEP_STAGE). */
BS_STEP_STAGE
void bs_contact_problem(const bs_scene *scene, const bs_step_constants *k, bs_contact_set *set,
                        const bs_real *u_beam, const bs_real *u_slider, const bs_real *u_beam_before,
                        const bs_real *u_slider_before)
{
    BS_MODES_SWITCH(BS_NMODES(scene), problem(MODES, k, set, u_beam, u_slider, u_beam_before, u_slider_before));
}

/* Contact a's push on the slider and the coefficients of phi and phi' in
 * its push on the beam: W P = along_phi phi + along_slope phi' (beam),
 * push (slider). */
BS_INLINE void percussion_of(const bs_contact_set *set, int a, bs_real *along_phi, bs_real *along_slope,
                             bs_real *push)
{
    const bs_real *p = &set->percussion[BS_ROWS * a];
    const bs_real *normal = set->dir_slider[BS_ROWS * a];
    int c;
    *along_phi = set->beam_coef[a][0][0] * p[0];
    *along_slope = set->beam_coef[a][0][1] * p[0];
    for (c = 0; c < BS_SLIDER_DOF; ++c)
        push[c] += normal[c] * p[0];
#if BS_WITH_FRICTION
    {
        const bs_real *tangent = set->dir_slider[BS_ROWS * a + 1];
        *along_phi += set->beam_coef[a][1][0] * p[1];
        *along_slope += set->beam_coef[a][1][1] * p[1];
        for (c = 0; c < BS_SLIDER_DOF; ++c)
            push[c] += tangent[c] * p[1];
    }
#endif
}

BS_INLINE void apply(int n, const bs_step_constants *k, const bs_contact_set *set, bs_real *u_beam,
                     bs_real *u_slider)
{
    bs_real push[BS_SLIDER_DOF], along_phi[2], along_slope[2];
    int a, i;

    for (i = 0; i < BS_SLIDER_DOF; ++i) /* +0 from a core register, not a literal from flash */
        push[i] = BS_ZERO;
    if (set->count == 1 && set->id[0] < BS_CORNERS) { /* one corner (most contact steps): no loop over the set */
        const bs_real (*slope)[BS_MAX_MODES] = set->slope;
        BS_FORGET(slope); /* beyond a VLDR's reach of the sim: one base, not an address computed for each */
        percussion_of(set, 0, &along_phi[0], &along_slope[0], push);
        for (i = 0; i < n; ++i)
            u_beam[i] += MODE_GAIN(k, i) * (along_phi[0] * set->phi[0][i] + along_slope[0] * slope[0][i]);
    } else if (set->count == 2 && set->id[1] < BS_CORNERS) { /* two corners: one pass over the modes */
        const bs_real (*slope)[BS_MAX_MODES] = set->slope;
        BS_FORGET(slope);
        percussion_of(set, 0, &along_phi[0], &along_slope[0], push);
        percussion_of(set, 1, &along_phi[1], &along_slope[1], push);
        for (i = 0; i < n; ++i)
            u_beam[i] += MODE_GAIN(k, i) * ((along_phi[0] * set->phi[0][i] + along_slope[0] * slope[0][i])
                                            + (along_phi[1] * set->phi[1][i] + along_slope[1] * slope[1][i]));
    } else {
        for (a = 0; a < set->count; ++a) {
            percussion_of(set, a, &along_phi[0], &along_slope[0], push);
            if (set->id[a] < BS_CORNERS)
                for (i = 0; i < n; ++i)
                    u_beam[i] += MODE_GAIN(k, i) * (along_phi[0] * set->phi[a][i] + along_slope[0] * set->slope[a][i]);
        }
    }
    u_slider[0] += k->mass_inv * push[0];
    u_slider[1] += k->mass_inv * push[1];
#if BS_WITH_ROTATION
    u_slider[2] += k->inertia_inv * push[2];
#endif
}

/* Inlined into a compiled scene's step (BS_STEP_STAGE). */
BS_STEP_STAGE
void bs_contact_apply(const bs_scene *scene, const bs_step_constants *k, const bs_contact_set *set,
                      bs_real *u_beam, bs_real *u_slider)
{
    BS_MODES_SWITCH(BS_NMODES(scene), apply(MODES, k, set, u_beam, u_slider));
}
