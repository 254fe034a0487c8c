/* bs_contact.c - contact kinematics of the four slot corners and the clamp stops.
 *
 * Slot corner i (P1..P4, counter-clockwise from top left), zeta_i = +1 for the
 * top corners P1, P4 (they touch the beam's top surface), -1 for P2, P3:
 *
 *   r_P   = (x_C, z_C) + A(beta) rho_i,   rho_i = r_CP,i (scene->corner)
 *   A rho = ( cos b rho_x + sin b rho_z, -sin b rho_x + cos b rho_z )
 *   w, w' = sum phi_k q_k, sum phi_k' q_k at x_P;   alpha = atan w'
 *   r_B   = (x_P, w0 + w) + zeta h/2 (-w', 1)
 *   n     = zeta (-sin alpha, cos alpha),   t = zeta (-cos alpha, -sin alpha)
 *   d     = r_P - r_B = ( zeta h/2 w',  z_P - w0 - w - zeta h/2 )
 *   g_N   = n.d,   g_T = t.d           (active when g_N < 0)
 *
 * Force directions W = (dg/dq)^T, the published model's (MODEL.md 4):
 *   slider: dg/d(x_C, z_C, beta) = C [I | A' rho],  C = [n^T; t^T],
 *           A' rho = dA/dbeta rho = ((A rho)_z, -(A rho)_x)
 *   beam:   dg/dq_k = -C e_k + C' d phi_k',   C' = dC/dalpha = [t^T; -n^T],
 *           e_k = dr_B/dq_k = (0, phi_k) + zeta h/2 [(-phi_k', 0) - (-w'^2, w') phi_k']
 *   so with a1 = zeta h/2 (w'^2 - 1), a2 = -zeta h/2 w':
 *           W_N,k = -n_z phi_k + (-n_x a1 - n_z a2 + g_T) phi_k'
 *           W_T,k = -t_z phi_k + (-t_x a1 - t_z a2 - g_N) phi_k'
 *   base:   w~ = -C (0, dw0/dt)
 *
 * Clamp end stops (MODEL.md 9.6): frictionless unilateral contacts on x_C,
 * g = x_C - stop_min (left) and g = stop_max - x_C (right), W = (0, +-1, 0, 0).
 *
 * Generalised mass M = diag(1 (modal), m, m, J_C).
 */
#include "bs_contact.h"
#include "bs_port.h"
#include "bs_shape.h"

static void add_corner(const bs_scene *scene, const bs_contact_frame *frame, int corner,
                       bs_real cos_beta, bs_real sin_beta, bs_contact_set *set,
                       bs_real base_term[BS_MAX_CONTACTS][2])
{
    const int n = scene->n_modes;
    const bs_real zeta = (corner == 0 || corner == 3) ? BS_R(1.0) : BS_R(-1.0);
    const bs_real hh = scene->half_thickness;
    const bs_real *rho = scene->corner[corner];
    const bs_real arm_x = cos_beta * rho[0] + sin_beta * rho[1];
    const bs_real arm_z = -sin_beta * rho[0] + cos_beta * rho[1];
    const bs_real x_p = frame->x_kinematic + arm_x;
    const bs_real z_p = frame->z + arm_z;
    bs_real phi[BS_MAX_MODES];
    bs_real slope[BS_MAX_MODES];
    bs_real w = BS_R(0.0);
    bs_real w_slope = BS_R(0.0);
    bs_real cos_alpha, sin_alpha, n_x, n_z, t_x, t_z, d_x, d_z, gap_n, gap_t;
    bs_real a1, a2, coef_nn, coef_ns, coef_tn, coef_ts;
    int a;
    int k;

    bs_shape_eval(scene, x_p, phi, slope);
    for (k = 0; k < n; ++k) {
        w += phi[k] * frame->q_beam[k];
        w_slope += slope[k] * frame->q_beam[k];
    }
    d_x = zeta * hh * w_slope;
    d_z = z_p - frame->base.displacement - w - zeta * hh;
    /* g_N = cos(alpha) (zeta d_z - h/2 w'^2): the sign needs no square root */
    gap_n = zeta * d_z - hh * w_slope * w_slope;
    if (!(gap_n < BS_R(0.0)))
        return;
    cos_alpha = BS_R(1.0) / bs_sqrt(BS_R(1.0) + w_slope * w_slope);
    sin_alpha = w_slope * cos_alpha;
    n_x = -zeta * sin_alpha;
    n_z = zeta * cos_alpha;
    t_x = -zeta * cos_alpha;
    t_z = -zeta * sin_alpha;
    gap_n = n_x * d_x + n_z * d_z;
    gap_t = t_x * d_x + t_z * d_z;

    a = set->count++;
    set->id[a] = corner;
    set->mu[a] = scene->mu;
    a1 = zeta * hh * (w_slope * w_slope - BS_R(1.0));
    a2 = -zeta * hh * w_slope;
    coef_nn = -n_z;                               /* factor of phi_k in W_N */
    coef_ns = -n_x * a1 - n_z * a2 + gap_t;       /* factor of phi_k' in W_N */
    coef_tn = -t_z;
    coef_ts = -t_x * a1 - t_z * a2 - gap_n;
    for (k = 0; k < n; ++k) {
        set->dir_beam[a][0][k] = coef_nn * phi[k] + coef_ns * slope[k];
        set->dir_beam[a][1][k] = coef_tn * phi[k] + coef_ts * slope[k];
    }
    set->dir_slider[a][0][0] = n_x;
    set->dir_slider[a][0][1] = n_z;
    set->dir_slider[a][0][2] = n_x * arm_z - n_z * arm_x;
    set->dir_slider[a][1][0] = t_x;
    set->dir_slider[a][1][1] = t_z;
    set->dir_slider[a][1][2] = t_x * arm_z - t_z * arm_x;
    base_term[a][0] = -n_z * frame->base.velocity;
    base_term[a][1] = -t_z * frame->base.velocity;
}

static void add_stop(const bs_scene *scene, int id, bs_real sign, bs_contact_set *set,
                     bs_real base_term[BS_MAX_CONTACTS][2])
{
    const int a = set->count++;
    int k;

    set->id[a] = id;
    set->mu[a] = BS_R(0.0);
    for (k = 0; k < scene->n_modes; ++k) {
        set->dir_beam[a][0][k] = BS_R(0.0);
        set->dir_beam[a][1][k] = BS_R(0.0);
    }
    for (k = 0; k < 3; ++k) {
        set->dir_slider[a][0][k] = BS_R(0.0);
        set->dir_slider[a][1][k] = BS_R(0.0);
    }
    set->dir_slider[a][0][0] = sign;
    base_term[a][0] = BS_R(0.0);
    base_term[a][1] = BS_R(0.0);
}

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

void bs_contact_detect(const bs_scene *scene, const bs_contact_frame *frame,
                       bs_contact_set *set, bs_real base_term[BS_MAX_CONTACTS][2])
{
    bs_real cos_beta, sin_beta;
    int corner;

    rotation(frame->beta, &cos_beta, &sin_beta);
    set->count = 0;
    for (corner = 0; corner < BS_CORNERS; ++corner)
        add_corner(scene, frame, corner, cos_beta, sin_beta, set, base_term);
    if (frame->stops) {
        if (frame->x_stops < scene->stop_min)
            add_stop(scene, BS_STOP_LEFT, BS_R(1.0), set, base_term);
        if (frame->x_stops > scene->stop_max)
            add_stop(scene, BS_STOP_RIGHT, BS_R(-1.0), set, base_term);
    }
}

void bs_contact_velocity(const bs_scene *scene, const bs_contact_set *set,
                         const bs_real *u_beam, const bs_real *u_slider,
                         const bs_real base_term[BS_MAX_CONTACTS][2],
                         bs_real gamma[2 * BS_MAX_CONTACTS])
{
    int a;
    int r;
    int k;

    for (a = 0; a < set->count; ++a) {
        for (r = 0; r < 2; ++r) {
            const bs_real *beam = set->dir_beam[a][r];
            const bs_real *slider = set->dir_slider[a][r];
            bs_real v = base_term[a][r] + slider[0] * u_slider[0] + slider[1] * u_slider[1]
                        + slider[2] * u_slider[2];
            for (k = 0; k < scene->n_modes; ++k)
                v += beam[k] * u_beam[k];
            gamma[2 * a + r] = v;
        }
    }
}

void bs_contact_delassus(const bs_scene *scene, bs_contact_set *set)
{
    const int rows = 2 * set->count;
    int i;
    int j;
    int k;

    for (i = 0; i < rows; ++i) {
        const bs_real *beam_i = set->dir_beam[i / 2][i % 2];
        const bs_real *slider_i = set->dir_slider[i / 2][i % 2];
        for (j = i; j < rows; ++j) {
            const bs_real *beam_j = set->dir_beam[j / 2][j % 2];
            const bs_real *slider_j = set->dir_slider[j / 2][j % 2];
            bs_real g = scene->mass_inv * (slider_i[0] * slider_j[0] + slider_i[1] * slider_j[1])
                        + scene->inertia_inv * slider_i[2] * slider_j[2];
            for (k = 0; k < scene->n_modes; ++k)
                g += beam_i[k] * beam_j[k];
            set->delassus[i][j] = g;
            set->delassus[j][i] = g;
        }
    }
}

void bs_contact_apply(const bs_scene *scene, const bs_contact_set *set,
                      bs_real *u_beam, bs_real *u_slider)
{
    int a;
    int k;

    for (a = 0; a < set->count; ++a) {
        const bs_real p_n = set->percussion[2 * a];
        const bs_real p_t = set->percussion[2 * a + 1];
        const bs_real (*slider)[3] = set->dir_slider[a];
        for (k = 0; k < scene->n_modes; ++k)
            u_beam[k] += set->dir_beam[a][0][k] * p_n + set->dir_beam[a][1][k] * p_t;
        u_slider[0] += scene->mass_inv * (slider[0][0] * p_n + slider[1][0] * p_t);
        u_slider[1] += scene->mass_inv * (slider[0][1] * p_n + slider[1][1] * p_t);
        u_slider[2] += scene->inertia_inv * (slider[0][2] * p_n + slider[1][2] * p_t);
    }
}
