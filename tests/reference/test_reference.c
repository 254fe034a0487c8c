/* test_reference.c - the reference model (tests/reference/) against docs/model.md 8
 * check values, analytic cases and the 50 frictional contact problems of
 * tests/data/fc2d_cases.json. Links no core object. Run from the repository
 * root (reads configs/fig6.ini and tests/data/fc2d_cases.json).
 *
 * Tolerances are stated where they are used, with where they come from. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ref_dynamics.h"
#include "ref_kinematics.h"
#include "ref_lcp.h"
#include "ref_modes.h"
#include "ref_scene.h"
#include "ref_step.h"
#include "scene_ini.h"

#define SCENE_PATH_FIG6 "configs/fig6.ini"
#define FC2D_PATH "tests/data/fc2d_cases.json"

/* Fails unless |actual - expected| <= abs_tol + rel_tol |expected|. */
#define assert_close(what, actual, expected, abs_tol, rel_tol) \
    check_close(what, (double)(actual), (double)(expected), (double)(abs_tol), (double)(rel_tol), __FILE__, __LINE__)

static void check_close(const char *what, double actual, double expected, double abs_tol, double rel_tol,
                        const char *file, int line)
{
    const double tolerance = abs_tol + rel_tol * fabs(expected);
    if (!(fabs(actual - expected) <= tolerance)) {
        print_error("%s: got %.15g, expected %.15g (difference %.3g, tolerance %.3g)\n", what, actual, expected,
                    actual - expected, tolerance);
        _fail(file, line);
    }
}

static scene_params load_fig6(void)
{
    static scene_file file;
    char err[1024];
    if (scene_load(SCENE_PATH_FIG6, &file, err, sizeof err) != 0) {
        print_error("%s\n", err);
        fail();
    }
    return file.params;
}

static void build(ref_scene *scene, const scene_params *p)
{
    char err[256];
    if (ref_scene_init(scene, p, 1, err, sizeof err) != 0) {
        print_error("%s\n", err);
        fail();
    }
}

/* ---- modes ---------------------------------------------------------------- */

static void test_modes_match_model_check_values(void **state)
{
    /* docs/model.md 8, rounded to 5 significant digits there: relative 1e-4 */
    static const double f_want[5] = { 260.28, 719.01, 1412.3, 2339.0, 3500.1 };
    static const double gamma_want[5] = { 0.10333, 0.0, 0.044932, 0.0, 0.028315 };
    static ref_scene scene;
    scene_params p = load_fig6();
    int k;
    (void)state;

    build(&scene, &p);
    assert_int_equal(scene.n_modes, 5);
    for (k = 0; k < 5; ++k) {
        char what[32];
        snprintf(what, sizeof what, "f_%d [Hz]", k + 1);
        assert_close(what, scene.modes.omega[k] / (2.0 * (double)REF_PI), f_want[k], 0.0, 1e-4);
        snprintf(what, sizeof what, "gamma_%d", k + 1);
        /* antisymmetric modes: zero up to quadrature rounding */
        assert_close(what, scene.modes.gamma[k], gamma_want[k], 1e-14, 1e-4);
    }
    /* ideal clamps: f_1 = 274.19 Hz */
    p.beam.k_rot = 1e12;
    p.modes = 1;
    build(&scene, &p);
    assert_close("f_1, ideal clamps [Hz]", scene.modes.omega[0] / (2.0 * (double)REF_PI), 274.19, 0.0, 1e-4);
}

/* Simpson's rule on [0, 1] with 20000 intervals of f(mode k, xi) in long double */
typedef long double (*mode_integrand)(const ref_modes *m, int i, int j, long double xi);

static long double simpson(const ref_modes *m, int i, int j, mode_integrand f)
{
    const int n = 20000;
    const long double h = 1.0L / n;
    long double sum = f(m, i, j, 0.0L) + f(m, i, j, 1.0L);
    int s;
    for (s = 1; s < n; ++s)
        sum += (s % 2 ? 4.0L : 2.0L) * f(m, i, j, h * s);
    return sum * h / 3.0L;
}

static long double product_phi(const ref_modes *m, int i, int j, long double xi)
{
    long double a[3], b[3];
    ref_modes_shape(m, i, xi, a);
    ref_modes_shape(m, j, xi, b);
    return a[0] * b[0];
}

static long double product_curvature(const ref_modes *m, int i, int j, long double xi)
{
    long double a[3], b[3];
    ref_modes_shape(m, i, xi, a);
    ref_modes_shape(m, j, xi, b);
    return a[2] * b[2];
}

static void test_modes_satisfy_boundary_conditions_orthonormality_and_rayleigh(void **state)
{
    static ref_scene scene;
    scene_params p = load_fig6();
    const double L = p.beam.length, m = p.beam.mass, k_r = p.beam.k_rot;
    int i, j;
    (void)state;

    build(&scene, &p);
    for (i = 0; i < scene.n_modes; ++i) {
        const ref_modes *modes = &scene.modes;
        const long double kappa = modes->kappa;
        long double at0[3], at1[3], mid[3];
        double omega2;
        ref_modes_shape(modes, i, 0.0L, at0);
        ref_modes_shape(modes, i, 1.0L, at1);
        ref_modes_shape(modes, i, 0.5L, mid);
        /* |phi| is O(10 / sqrt(kg)); the basis is bounded, so the ends vanish to rounding */
        assert_close("phi(0)", at0[0], 0.0, 1e-13, 0.0);
        assert_close("phi(1)", at1[0], 0.0, 1e-13, 0.0);
        /* docs/model.md 3: EI w'' = +k_r w' at x = 0, EI w'' = -k_r w' at x = L */
        assert_close("phi''(0) - kappa phi'(0)", at0[2] - kappa * at0[1], 0.0, 1e-10 * fabsl(kappa * at0[1]), 0.0);
        assert_close("phi''(1) + kappa phi'(1)", at1[2] + kappa * at1[1], 0.0, 1e-10 * fabsl(kappa * at1[1]), 0.0);
        /* rho A L int phi_i phi_j = delta_ij by an independent rule */
        for (j = 0; j < scene.n_modes; ++j)
            assert_close("rho A L int phi_i phi_j", m * (double)simpson(modes, i, j, product_phi), i == j ? 1.0 : 0.0,
                         1e-11, 0.0);
        /* Rayleigh: omega^2 = EI/L^3 int phi''^2 + k_r/L^2 (phi'(0)^2 + phi'(1)^2)
         * (bending plus both clamp springs over kinetic energy with rho A L int phi^2 = 1):
         * checks lambda, the spring sign and the scaling together */
        omega2 = (double)(modes->ei / (L * L * L) * simpson(modes, i, i, product_curvature)
                          + k_r / (L * L) * (at0[1] * at0[1] + at1[1] * at1[1]));
        assert_close("Rayleigh quotient omega^2", omega2, scene.modes.omega[i] * scene.modes.omega[i], 0.0, 1e-9);
        /* symmetric modes (1, 3, 5) are even about the centre, antisymmetric odd */
        if (i % 2 == 1)
            assert_close("antisymmetric phi(1/2)", mid[0], 0.0, 1e-13, 0.0);
        for (j = 0; j < scene.n_modes; ++j) {
            assert_close("I_ij = I_ji", scene.modes.slope_gram[i][j], scene.modes.slope_gram[j][i], 1e-12, 0.0);
            if ((i + j) % 2)
                assert_close("I_ij, mixed symmetry", scene.modes.slope_gram[i][j], 0.0, 1e-10, 0.0);
        }
    }
}

/* ---- stretching ----------------------------------------------------------- */

static const double *stretch_q;

static long double slope_squared(const ref_modes *m, int i, int j, long double xi)
{
    long double w_xi = 0.0L, v[3];
    int k;
    (void)i;
    (void)j;
    for (k = 0; k < m->n; ++k) {
        ref_modes_shape(m, k, xi, v);
        w_xi += v[1] * stretch_q[k];
    }
    return w_xi * w_xi;
}

/* V = k_ax/2 dL^2, dL = 1/(2L) int_0^1 w_xi^2 dxi, integrated directly */
static double stretch_energy(const ref_scene *scene, const double *q)
{
    long double dl;
    stretch_q = q;
    dl = simpson(&scene->modes, 0, 0, slope_squared) / (2.0L * scene->length);
    return (double)(0.5L * scene->modes.k_ax * dl * dl);
}

static void test_stretching_is_the_gradient_of_the_stretching_energy(void **state)
{
    static ref_scene scene;
    static const double q[5] = { 3e-4, -1e-4, 5e-5, 2e-5, -1e-5 }; /* w ~ 4 mm: the cubic term matters */
    scene_params p = load_fig6();
    double force[REF_MAX_MODES];
    int n;
    (void)state;

    build(&scene, &p);
    ref_dynamics_stretching(&scene, q, force);
    for (n = 0; n < 5; ++n) {
        double qp[5], qm[5];
        const double delta = 1e-8;
        memcpy(qp, q, sizeof qp);
        memcpy(qm, q, sizeof qm);
        qp[n] += delta;
        qm[n] -= delta;
        /* central difference of a quartic: error ~ delta^2 V''''; relative 1e-6 */
        assert_close("N_n = dV/dq_n", force[n], (stretch_energy(&scene, qp) - stretch_energy(&scene, qm)) / (2.0 * delta),
                     1e-9 * fabs(force[0]), 1e-6);
    }
    p.stretching = 0;
    build(&scene, &p);
    ref_dynamics_stretching(&scene, q, force);
    assert_close("stretching off", force[0], 0.0, 0.0, 0.0);
}

/* ---- force directions ----------------------------------------------------- */

/* The gap of corner i with the beam point held at abscissa x_b (material
 * point), and the beam surface offset along the unit normal (unit = 1) or
 * along (-w', 1) (unit = 0). Written from docs/model.md 4 independently of
 * ref_kinematics.c. */
static void material_gap(const ref_scene *s, const ref_excitation *ex, const double *q, int i, double x_b, int unit,
                         double g[2])
{
    const double cb = cos(q[s->i_beta]), sb = sin(q[s->i_beta]);
    const double rx = s->corner[i][0], rz = s->corner[i][1], zeta = s->zeta[i];
    const double px = q[s->i_x] + cb * rx + sb * rz, pz = q[s->i_z] - sb * rx + cb * rz;
    double phi[REF_MAX_MODES], phi_xi[REF_MAX_MODES], w = 0.0, w_x = 0.0, alpha, bx, bz;
    int k;

    ref_modes_eval(&s->modes, x_b / s->length, phi, phi_xi);
    for (k = 0; k < s->n_modes; ++k) {
        w += phi[k] * q[k];
        w_x += phi_xi[k] / s->length * q[k];
    }
    alpha = atan(w_x);
    if (unit) {
        bx = x_b + zeta * s->half_thickness * -sin(alpha);
        bz = ex->w0 + w + zeta * s->half_thickness * cos(alpha);
    } else {
        bx = x_b + zeta * s->half_thickness * -w_x;
        bz = ex->w0 + w + zeta * s->half_thickness;
    }
    g[0] = zeta * (-sin(alpha) * (px - bx) + cos(alpha) * (pz - bz));
    g[1] = zeta * (-cos(alpha) * (px - bx) - sin(alpha) * (pz - bz));
}

/* max over coordinates of |W - dg/dq| / max |W| for corner i at q */
static double direction_error(const ref_scene *scene, const ref_excitation *ex, const double *q, int i, int unit,
                              double *slope)
{
    ref_contact c;
    double worst = 0.0, size = 0.0;
    int k, row;

    ref_kinematics_corner(scene, ex, q, i, &c);
    {
        double phi[REF_MAX_MODES], phi_x[REF_MAX_MODES], w;
        const double x_p = q[scene->i_x] + cos(q[scene->i_beta]) * scene->corner[i][0]
                           + sin(q[scene->i_beta]) * scene->corner[i][1];
        ref_scene_beam(scene, q, x_p, &w, slope, phi, phi_x);
    }
    for (row = 0; row < 2; ++row)
        for (k = 0; k < scene->n_q; ++k)
            if (fabs(c.dir[row][k]) > size)
                size = fabs(c.dir[row][k]);
    for (k = 0; k < scene->n_q; ++k) {
        const double x_b = q[scene->i_x] + cos(q[scene->i_beta]) * scene->corner[i][0]
                           + sin(q[scene->i_beta]) * scene->corner[i][1];
        const double delta = 1e-9; /* sqrt(kg) m, m or rad */
        double qp[REF_MAX_Q], qm[REF_MAX_Q], gp[2], gm[2];
        memcpy(qp, q, sizeof qp);
        memcpy(qm, q, sizeof qm);
        qp[k] += delta;
        qm[k] -= delta;
        material_gap(scene, ex, qp, i, x_b, unit, gp);
        material_gap(scene, ex, qm, i, x_b, unit, gm);
        for (row = 0; row < 2; ++row) {
            const double fd = (gp[row] - gm[row]) / (2.0 * delta);
            const double err = fabs(fd - c.dir[row][k]) / size;
            if (err > worst)
                worst = err;
        }
    }
    return worst;
}

static void test_force_directions_are_the_material_gap_derivatives(void **state)
{
    static ref_scene scene;
    scene_params p = load_fig6();
    ref_excitation ex;
    double q[REF_MAX_Q] = { 0 };
    double slope, err;
    int i;
    (void)state;

    build(&scene, &p);
    ref_scene_excitation(&scene, 0.001L, &ex);
    q[scene.i_x] = 0.3 * scene.length;
    q[scene.i_z] = -scene.com_offset + 1e-5;
    q[scene.i_beta] = 0.003;
    /* straight beam: the published directions are the exact derivatives
     * (central differences with step 1e-9: error ~1e-7 of the largest entry) */
    for (i = 0; i < REF_CORNERS; ++i) {
        err = direction_error(&scene, &ex, q, i, 0, &slope);
        assert_close("W vs dg/dq, straight beam", err, 0.0, 1e-6, 0.0);
    }
    /* bent beam (w ~ 0.3 mm, w' ~ 1e-2 at the corners): the published model
     * matches the gap with the unit-normal offset to O(w'^2) */
    q[0] = 3e-5;
    q[1] = -1e-5;
    q[2] = 5e-6;
    q[4] = 1e-6;
    for (i = 0; i < REF_CORNERS; ++i) {
        err = direction_error(&scene, &ex, q, i, 1, &slope);
        print_message("corner %d: w' = %.3e, max |W - dg/dq| / max|W| = %.3e (unit normal)\n", i + 1, slope, err);
        assert_close("W vs dg/dq, bent beam", err, 0.0, 1e-6 + 2.0 * slope * slope, 0.0);
    }
    /* w~ = dg/dt at fixed q: only the base motion w0(t) moves the beam */
    for (i = 0; i < REF_CORNERS; ++i) {
        const long double t = 0.001L, dt = 1e-7L;
        ref_excitation ep, em;
        ref_contact c;
        double gp[2], gm[2], x_b;
        int row;
        ref_kinematics_corner(&scene, &ex, q, i, &c);
        x_b = q[scene.i_x] + cos(q[scene.i_beta]) * scene.corner[i][0] + sin(q[scene.i_beta]) * scene.corner[i][1];
        ref_scene_excitation(&scene, t + dt, &ep);
        ref_scene_excitation(&scene, t - dt, &em);
        material_gap(&scene, &ep, q, i, x_b, 0, gp);
        material_gap(&scene, &em, q, i, x_b, 0, gm);
        for (row = 0; row < 2; ++row)
            assert_close("w~ = dg/dt", c.w_tilde[row], (gp[row] - gm[row]) / (2.0 * (double)dt),
                         1e-7 * fabs(ex.w0_dot), 0.0);
    }
}

static void test_pcs_kinematics_use_the_prescribed_position(void **state)
{
    static ref_scene scene;
    scene_params p = load_fig6();
    ref_excitation ex;
    ref_contact a, b;
    double q[REF_MAX_Q] = { 2e-5, -1e-5, 5e-6, 0.0, 1e-6 };
    int i;
    (void)state;

    p.model = 1;
    p.s0 = 0.25;
    build(&scene, &p);
    ref_scene_excitation(&scene, 0.0L, &ex);
    q[scene.i_x] = 0.4 * scene.length; /* the state's x_C: not used by the kinematics */
    q[scene.i_z] = -scene.com_offset;
    for (i = 0; i < REF_CORNERS; ++i) {
        ref_kinematics_corner(&scene, &ex, q, i, &a);
        q[scene.i_x] = 0.1 * scene.length;
        ref_kinematics_corner(&scene, &ex, q, i, &b);
        q[scene.i_x] = 0.4 * scene.length;
        assert_close("PCS gap independent of the state's x_C", a.gap[0], b.gap[0], 0.0, 0.0);
        assert_close("PCS W_N,x_C", a.dir[0][scene.i_x], b.dir[0][scene.i_x], 0.0, 0.0);
    }
    assert_int_equal(scene.end_stops, 0);
}

static void test_excitation_phase_is_exact_after_a_million_periods(void **state)
{
    static ref_scene scene;
    scene_params p = load_fig6();
    ref_excitation ex;
    const double omega = 2.0 * (double)REF_PI * p.frequency;
    (void)state;

    build(&scene, &p);
    /* t = (1e6 + 1/4) / f_ex: Omega t = pi/2 mod 2 pi */
    ref_scene_excitation(&scene, (1000000.0L + 0.25L) / (long double)p.frequency, &ex);
    assert_close("w0 at a quarter period", ex.w0, 0.0, 1e-9 * p.acceleration / (omega * omega), 0.0);
    assert_close("dw0 at a quarter period", ex.w0_dot, -p.acceleration / omega, 0.0, 1e-12);
    /* time from the step count: step 10^9 of dt = 2e-5 is t = 20000 s */
    assert_true(fabsl(ref_scene_time(&scene, 2000000000ULL) - 1e9L * (long double)p.dt) <= 1e-12L);
}

/* ---- free beam mode -------------------------------------------------------- */

/* One step of docs/model.md 5 for q'' + 2 D omega q' + omega^2 q = 0 */
static void scalar_midpoint(double omega, double damping, double dt, double *q, double *u)
{
    const double q_m = *q + 0.5 * dt * *u;
    const double u_e = *u + dt * (-omega * omega * q_m - 2.0 * damping * omega * *u);
    *q = q_m + 0.5 * dt * u_e;
    *u = u_e;
}

static void test_free_mode_oscillates_at_omega_with_decay_d(void **state)
{
    static ref_scene scene;
    static ref_state st;
    static const int modes[3] = { 0, 2, 4 };
    scene_params p = load_fig6();
    ref_step_options options;
    int m;
    (void)state;

    /* no gravity, no base motion, no stretching: the slider floats centred in
     * its 25 um play while the beam vibrates at 1 um */
    p.gravity = 0.0;
    p.acceleration = 0.0;
    p.stretching = 0;
    build(&scene, &p);
    ref_step_default_options(&options);
    for (m = 0; m < 3; ++m) {
        const int k = modes[m];
        const double omega = scene.modes.omega[k], damping = scene.damping, dt = scene.dt_sub;
        const double q0 = 1e-7;
        const int steps = 20000;
        double tq, tu, t11, t12, t21, t22, trace, det, radius, theta, omega_d, sigma;
        double omega_c, sigma_c, q_map = q0, u_map = 0.0, prev = q0;
        double first_up = -1.0, last_up = -1.0;
        int ups = 0, n, other;

        /* the scheme's transfer matrix T (columns: T e_q, T e_u) and its eigenvalues r e^(+-i theta) */
        tq = 1.0;
        tu = 0.0;
        scalar_midpoint(omega, damping, dt, &tq, &tu);
        t11 = tq;
        t21 = tu;
        tq = 0.0;
        tu = 1.0;
        scalar_midpoint(omega, damping, dt, &tq, &tu);
        t12 = tq;
        t22 = tu;
        trace = t11 + t22;
        det = t11 * t22 - t12 * t21;
        radius = sqrt(det);
        theta = acos(trace / (2.0 * radius));
        omega_d = theta / dt;
        sigma = -log(radius) / dt;
        omega_c = omega * sqrt(1.0 - damping * damping);
        sigma_c = damping * omega;
        print_message("mode %d: omega dt = %.4f; discrete/continuous - 1: frequency %.3e (theory (omega dt)^2/24 = "
                      "%.3e), decay %.3e\n",
                      k + 1, omega * dt, omega_d / omega_c - 1.0, omega * omega * dt * dt / 24.0, sigma / sigma_c - 1.0);
        /* leapfrog frequency error (omega dt)^2/24 + O((omega dt)^4) plus D omega dt / 2 from
         * the explicit damping: bound (omega dt)^2/12 + D omega dt;
         * explicit damping decay error ~ D omega dt + (omega dt)^2 / 8: bound 2 D omega dt + (omega dt)^2 / 4 */
        assert_close("discrete vs continuous frequency", omega_d, omega_c, 0.0,
                     omega * omega * dt * dt / 12.0 + damping * omega * dt);
        assert_close("discrete vs continuous decay", sigma, sigma_c, 0.0,
                     2.0 * damping * omega * dt + omega * omega * dt * dt / 4.0);

        ref_state_init(&scene, &st);
        st.q[k] = q0;
        for (n = 1; n <= steps; ++n) {
            ref_step_report report;
            double x;
            assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
            assert_int_equal(report.active, 0);
            scalar_midpoint(omega, damping, dt, &q_map, &u_map);
            x = st.q[k];
            if (prev < 0.0 && x >= 0.0) {
                const double t_cross = dt * ((double)(n - 1) + prev / (prev - x));
                if (first_up < 0.0)
                    first_up = t_cross;
                last_up = t_cross;
                ++ups;
            }
            prev = x;
        }
        /* the full model reduces to the scalar scheme (rounding only) */
        assert_close("q_k vs scalar scheme", st.q[k], q_map, 1e-9 * q0, 0.0);
        assert_close("u_k vs scalar scheme", st.u[k], u_map, 1e-9 * q0 * omega, 0.0);
        for (other = 0; other < scene.n_modes; ++other)
            if (other != k)
                assert_close("uncoupled mode", st.q[other], 0.0, 0.0, 0.0);
        /* zero crossings of r^n sin(n theta) are spaced 2 pi / omega_d exactly;
         * linear interpolation at a crossing errs by O((omega dt)^3) of a step */
        assert_close("measured frequency", 2.0 * (double)REF_PI * (ups - 1) / (last_up - first_up), omega_d, 0.0,
                     1e-6);
        /* decay over the run: r^steps */
        assert_close("amplitude decay", sqrt(st.q[k] * st.q[k] + (st.u[k] * st.u[k]) / (omega_d * omega_d)),
                     q0 * exp(-sigma * dt * steps), 0.0, 2e-2);
    }
}

/* ---- rigid beam: drop, rest on a tilted beam, end stop --------------------- */

static scene_params rigid_beam_params(void)
{
    scene_params p = load_fig6();
    p.modes = 0;
    p.acceleration = 0.0;
    p.tilt = 0.0;
    return p;
}

static void test_dropped_slider_rebounds_with_restitution(void **state)
{
    static ref_scene scene;
    static ref_state st;
    scene_params p = rigid_beam_params();
    ref_step_options options;
    const double e_n = 0.5;
    double fall, v_expected, z_contact, u_before = 0.0, u_after = 0.0, t_impact = 0.0, apex;
    int n, impact = 0;
    (void)state;

    p.play_ratio = 21.0; /* R = 21 mm: the slot's top falls 10 mm onto the beam */
    p.rotation = 1;
    p.e_n = e_n;
    build(&scene, &p);
    ref_step_default_options(&options);
    ref_state_init(&scene, &st);
    fall = 0.5 * (scene.slot_height - 2.0 * scene.half_thickness);
    z_contact = -scene.com_offset - fall;
    v_expected = sqrt(2.0 * p.gravity * fall);
    for (n = 1; n < 20000 && !impact; ++n) {
        ref_step_report report;
        const double u = st.u[scene.i_z];
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        if (report.active && st.u[scene.i_z] > 0.0) {
            impact = 1;
            u_before = u;
            u_after = st.u[scene.i_z];
            t_impact = scene.dt_sub * n;
            assert_int_equal(report.active, 2); /* both top corners */
        }
    }
    assert_true(impact);
    print_message("drop: impact at t = %.5f s with %.6f m/s (continuous %.6f), rebound %.6f m/s\n", t_impact,
                  -u_before, v_expected, u_after);
    /* Newton's law is exact in the step that closes the contact */
    assert_close("rebound velocity = -e_N impact velocity", u_after, -e_n * u_before, 0.0, 1e-12);
    /* continuous free fall: the step's start velocity is within g dt of sqrt(2 g H) */
    assert_close("impact velocity", -u_before, v_expected, 2.0 * p.gravity * scene.dt_sub, 0.0);
    assert_close("impact time", t_impact, sqrt(2.0 * fall / p.gravity), 2.0 * scene.dt_sub, 0.0);
    assert_close("no sideways motion", st.u[scene.i_x], 0.0, 1e-15, 0.0);
    assert_close("no rotation", st.q[scene.i_beta], 0.0, 1e-15, 0.0);
    assert_close("no spin", st.u[scene.i_beta], 0.0, 1e-12, 0.0);
    /* rebound apex: e_N^2 H above the contact, within the step's position error 2 v dt */
    apex = st.q[scene.i_z];
    for (n = 0; n < 20000 && st.u[scene.i_z] > 0.0; ++n) {
        ref_step_report report;
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        if (st.q[scene.i_z] > apex)
            apex = st.q[scene.i_z];
    }
    assert_close("rebound apex", apex - z_contact, e_n * e_n * fall, 2.0 * v_expected * scene.dt_sub, 0.0);
}

/* slider resting on its top corners, 1 nm into the beam, at s = 0.5 */
static void rest_on_top_corners(const ref_scene *scene, ref_state *st)
{
    ref_state_init(scene, st);
    st->q[scene->i_z] = -scene->com_offset - 0.5 * (scene->slot_height - 2.0 * scene->half_thickness) - 1e-9;
}

static void run_tilted(double tilt_deg, double mu_over_tan, int rotation, double *dx, double *du, double *beta,
                       double *accel)
{
    static ref_scene scene;
    static ref_state st;
    scene_params p = rigid_beam_params();
    ref_step_options options;
    const int steps = 5000;
    const double theta = tilt_deg * (double)REF_PI / 180.0;
    double x0;
    int n;

    p.tilt = tilt_deg;
    p.mu = mu_over_tan * tan(theta);
    p.rotation = rotation;
    p.s0 = 0.5;
    build(&scene, &p);
    ref_step_default_options(&options);
    rest_on_top_corners(&scene, &st);
    x0 = st.q[scene.i_x];
    for (n = 0; n < steps; ++n) {
        ref_step_report report;
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        assert_int_equal(report.active, 2);
    }
    *dx = st.q[scene.i_x] - x0;
    *du = st.u[scene.i_x];
    *beta = st.q[scene.i_beta];
    *accel = p.gravity * (sin(theta) - p.mu * cos(theta));
}

static void test_slider_on_tilted_beam_sticks_above_tan_theta_and_slides_below(void **state)
{
    const double t = 5000 * 2e-5;
    int rotation;
    (void)state;

    for (rotation = 0; rotation <= 1; ++rotation) {
        double dx, du, beta, accel;
        /* mu = 1.2 tan(theta): sticks; rounding only */
        run_tilted(10.0, 1.2, rotation, &dx, &du, &beta, &accel);
        assert_close("stick: x_C unchanged [m]", dx, 0.0, 1e-14, 0.0);
        assert_close("stick: u_x", du, 0.0, 1e-13, 0.0);
        assert_close("stick: beta", beta, 0.0, 1e-12, 0.0);
        /* mu = 0.5 tan(theta): x = -a t^2/2 exactly for the midpoint scheme */
        run_tilted(10.0, 0.5, rotation, &dx, &du, &beta, &accel);
        print_message("slide (rotation %s): a = %.9f m/s^2, measured %.9f\n", rotation ? "free" : "locked", accel,
                      -du / t);
        assert_close("slide: u_x = -g (sin - mu cos) t", du, -accel * t, 0.0, 1e-9);
        assert_close("slide: dx = -g (sin - mu cos) t^2 / 2", dx, -0.5 * accel * t * t, 0.0, 1e-9);
        assert_close("slide: beta", beta, 0.0, 1e-12, 0.0);
    }
}

static void test_slider_rides_a_rigid_beam_shaken_below_g(void **state)
{
    static ref_scene scene;
    static ref_state st;
    scene_params p = rigid_beam_params();
    ref_step_options options;
    double rel0, worst = 0.0;
    int n;
    (void)state;

    /* base acceleration a = 5 m/s^2 < g: the slider hanging on its top
     * corners never lifts off, it moves with the base (w~ carries dw0/dt) */
    p.acceleration = 5.0;
    p.rotation = 1;
    build(&scene, &p);
    ref_step_default_options(&options);
    rest_on_top_corners(&scene, &st);
    rel0 = st.q[scene.i_z] + scene.com_offset; /* z_C - w0 + d: resting, 1 nm into the beam */
    {
        ref_excitation ex0;
        ref_scene_excitation(&scene, 0.0L, &ex0);
        st.q[scene.i_z] += ex0.w0;
    }
    for (n = 1; n <= 10000; ++n) {
        ref_step_report report;
        ref_excitation ex;
        double drift;
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        ref_scene_excitation(&scene, ref_scene_time(&scene, 2 * st.step), &ex);
        drift = fabs(st.q[scene.i_z] - ex.w0 + scene.com_offset - rel0);
        if (drift > worst)
            worst = drift;
    }
    print_message("riding: max |z_C - w0 - const| = %.3e m over 0.2 s (base amplitude %.3e m)\n", worst,
                  p.acceleration / pow(2.0 * (double)REF_PI * p.frequency, 2.0));
    /* the velocity constraint holds at the midpoint, so z_C follows w0 with
     * a lag of up to dt/2 each way: bound (a / Omega) dt */
    assert_close("slider moves with the base", worst, 0.0, p.acceleration / (2.0 * (double)REF_PI * p.frequency) * scene.dt_sub,
                 0.0);
}

static void test_end_stop_returns_the_slider_with_restitution(void **state)
{
    static ref_scene scene;
    static ref_state st;
    scene_params p = rigid_beam_params();
    ref_step_options options;
    double u_before = 0.0, u_after = 0.0, x_low;
    int n, impact = 0;
    (void)state;

    p.tilt = 10.0;
    p.mu = 0.0;
    p.rotation = 0;
    p.e_n = 0.5;
    p.s0 = (0.5 * p.slot_width + 1e-3) / p.beam.length;
    build(&scene, &p);
    ref_step_default_options(&options);
    rest_on_top_corners(&scene, &st);
    x_low = st.q[scene.i_x];
    for (n = 0; n < 20000 && !impact; ++n) {
        ref_step_report report;
        const double u = st.u[scene.i_x];
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        if (st.q[scene.i_x] < x_low)
            x_low = st.q[scene.i_x];
        if (report.active == 3) {
            impact = 1;
            u_before = u;
            u_after = st.u[scene.i_x];
        }
    }
    assert_true(impact);
    assert_close("stop: rebound = -e_N impact velocity", u_after, -0.5 * u_before, 0.0, 1e-12);
    /* at most the midpoint overshoot v dt / 2 beyond the stop */
    assert_true(x_low >= 0.5 * p.slot_width + 0.5 * u_before * scene.dt_sub - 1e-15);
}

/* ---- contact solve: fc2d cases --------------------------------------------- */

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text;
    long size;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    text = malloc((size_t)size + 1);
    if (text && fread(text, 1, (size_t)size, f) != (size_t)size) {
        free(text);
        text = NULL;
    }
    if (text)
        text[size] = '\0';
    fclose(f);
    return text;
}

static void test_contact_solvers_reproduce_fc2d_cases(void **state)
{
    char *text = read_text(FC2D_PATH);
    cJSON *root, *cases, *item;
    long enum_systems = 0, pgs_sweeps = 0, pgs_max = 0;
    double enum_err = 0.0, pgs_err = 0.0;
    int count = 0;
    (void)state;

    assert_non_null(text);
    root = cJSON_Parse(text);
    assert_non_null(root);
    cases = cJSON_GetObjectItemCaseSensitive(root, "cases");
    assert_true(cJSON_IsArray(cases));
    cJSON_ArrayForEach(item, cases) {
        static ref_lcp lcp;
        const int n = cJSON_GetObjectItemCaseSensitive(item, "n")->valueint;
        const double mu = cJSON_GetObjectItemCaseSensitive(item, "mu")->valuedouble;
        const cJSON *w = cJSON_GetObjectItemCaseSensitive(item, "W");
        const cJSON *q = cJSON_GetObjectItemCaseSensitive(item, "q");
        const cJSON *r = cJSON_GetObjectItemCaseSensitive(item, "r_enum");
        int dim[REF_MAX_CONTACTS];
        double mus[REF_MAX_CONTACTS], want[REF_MAX_ROWS], p_enum[REF_MAX_ROWS], p_guess[REF_MAX_ROWS],
            p_pgs[REF_MAX_ROWS], scale = 1.0;
        ref_mode mode[REF_MAX_CONTACTS];
        ref_lcp_info info;
        int i, j;

        assert_true(n >= 1 && n <= REF_CORNERS);
        for (i = 0; i < n; ++i) {
            dim[i] = 2;
            mus[i] = mu;
        }
        ref_lcp_layout(&lcp, n, dim, mus);
        for (i = 0; i < 2 * n; ++i) {
            const cJSON *row = cJSON_GetArrayItem(w, i);
            for (j = 0; j < 2 * n; ++j)
                lcp.g[i][j] = cJSON_GetArrayItem(row, j)->valuedouble;
            lcp.c[i] = cJSON_GetArrayItem(q, i)->valuedouble;
            want[i] = cJSON_GetArrayItem(r, i)->valuedouble;
            if (fabs(want[i]) > scale)
                scale = fabs(want[i]);
        }
        /* enumeration of all modes */
        for (i = 0; i < n; ++i)
            mode[i] = REF_TAKEOFF;
        assert_int_equal(ref_lcp_enumerate(&lcp, p_enum, mode, 1, &info), 0);
        assert_int_equal(info.ambiguous, 0); /* every case has exactly one solution */
        enum_systems += info.iterations;
        /* from a guess (the warm path of the step) */
        for (i = 0; i < n; ++i)
            mode[i] = REF_STICK;
        assert_int_equal(ref_lcp_enumerate(&lcp, p_guess, mode, 0, &info), 0);
        /* PGS to 1e-13, no cap */
        for (i = 0; i < 2 * n; ++i)
            p_pgs[i] = 0.0;
        assert_int_equal(ref_lcp_pgs(&lcp, p_pgs, 1e-13, 100000000L, &info), 0);
        pgs_sweeps += info.iterations;
        if (info.iterations > pgs_max)
            pgs_max = info.iterations;
        for (i = 0; i < 2 * n; ++i) {
            assert_close("enumeration vs r_enum", p_enum[i], want[i], 1e-10 * scale, 0.0);
            assert_close("guessed enumeration vs r_enum", p_guess[i], want[i], 1e-10 * scale, 0.0);
            assert_close("PGS vs r_enum", p_pgs[i], want[i], 1e-10 * scale, 0.0);
            if (fabs(p_enum[i] - want[i]) / scale > enum_err)
                enum_err = fabs(p_enum[i] - want[i]) / scale;
            if (fabs(p_pgs[i] - want[i]) / scale > pgs_err)
                pgs_err = fabs(p_pgs[i] - want[i]) / scale;
        }
        ++count;
    }
    assert_int_equal(count, 50);
    print_message("fc2d: 50 cases; enumeration %ld systems, max error %.2e; PGS %ld sweeps (max %ld), max error %.2e\n",
                  enum_systems, enum_err, pgs_sweeps, pgs_max, pgs_err);
    cJSON_Delete(root);
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_modes_match_model_check_values),
        cmocka_unit_test(test_modes_satisfy_boundary_conditions_orthonormality_and_rayleigh),
        cmocka_unit_test(test_stretching_is_the_gradient_of_the_stretching_energy),
        cmocka_unit_test(test_force_directions_are_the_material_gap_derivatives),
        cmocka_unit_test(test_pcs_kinematics_use_the_prescribed_position),
        cmocka_unit_test(test_excitation_phase_is_exact_after_a_million_periods),
        cmocka_unit_test(test_free_mode_oscillates_at_omega_with_decay_d),
        cmocka_unit_test(test_dropped_slider_rebounds_with_restitution),
        cmocka_unit_test(test_slider_on_tilted_beam_sticks_above_tan_theta_and_slides_below),
        cmocka_unit_test(test_slider_rides_a_rigid_beam_shaken_below_g),
        cmocka_unit_test(test_end_stop_returns_the_slider_with_restitution),
        cmocka_unit_test(test_contact_solvers_reproduce_fc2d_cases),
    };
    return cmocka_run_group_tests_name("reference", tests, NULL, NULL);
}
