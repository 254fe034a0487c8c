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
#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ref_dynamics.h"
#include "ref_kinematics.h"
#include "ref_lcp.h"
#include "ref_modes.h"
#include "ref_replay.h"
#include "ref_run.h"
#include "ref_scene.h"
#include "ref_step.h"
#include "scene_ini.h"

#define SCENE_PATH_FIG6 "configs/fig6.ini"
/* the imaginary unit in double (complex.h's I is a float complex) */
#define UNIT_I ((double complex)I)
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
    /* the energy the balance test uses: k_ax/2 dL^2 with dL from I_ij, vs the
     * direct integral (Simpson, 20000 intervals: ~1e-12 relative) */
    assert_close("stretching energy", ref_dynamics_stretching_energy(&scene, q), stretch_energy(&scene, q), 0.0, 1e-9);
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
 * along (-w', 1) (unit = 0). Written from docs/model.md 4 in the base frame
 * of docs/model.md 10 (no w0) independently of ref_kinematics.c. */
static void material_gap(const ref_scene *s, const double *q, int i, double x_b, int unit, double g[2])
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
        bz = w + zeta * s->half_thickness * cos(alpha);
    } else {
        bx = x_b + zeta * s->half_thickness * -w_x;
        bz = w + zeta * s->half_thickness;
    }
    g[0] = zeta * (-sin(alpha) * (px - bx) + cos(alpha) * (pz - bz));
    g[1] = zeta * (-cos(alpha) * (px - bx) - sin(alpha) * (pz - bz));
}

/* max over coordinates of |W - dg/dq| / max |W| for corner i at q */
static double direction_error(const ref_scene *scene, const double *q, int i, int unit, double *slope)
{
    ref_contact c;
    double worst = 0.0, size = 0.0;
    int k, row;

    ref_kinematics_corner(scene, q, i, &c);
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
        material_gap(scene, qp, i, x_b, unit, gp);
        material_gap(scene, qm, i, x_b, unit, gm);
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
    double q[REF_MAX_Q] = { 0 };
    double slope, err;
    int i;
    (void)state;

    build(&scene, &p);
    q[scene.i_x] = 0.3 * scene.length;
    q[scene.i_z] = -scene.com_offset + 1e-5;
    q[scene.i_beta] = 0.003;
    /* straight beam: the published directions are the exact derivatives
     * (central differences with step 1e-9: error ~1e-7 of the largest entry) */
    for (i = 0; i < REF_CORNERS; ++i) {
        err = direction_error(&scene, q, i, 0, &slope);
        assert_close("W vs dg/dq, straight beam", err, 0.0, 1e-6, 0.0);
    }
    /* bent beam (w ~ 0.3 mm, w' ~ 1e-2 at the corners): the published model
     * matches the gap with the unit-normal offset to O(w'^2) */
    q[0] = 3e-5;
    q[1] = -1e-5;
    q[2] = 5e-6;
    q[4] = 1e-6;
    for (i = 0; i < REF_CORNERS; ++i) {
        err = direction_error(&scene, q, i, 1, &slope);
        print_message("corner %d: w' = %.3e, max |W - dg/dq| / max|W| = %.3e (unit normal)\n", i + 1, slope, err);
        assert_close("W vs dg/dq, bent beam", err, 0.0, 1e-6 + 2.0 * slope * slope, 0.0);
    }
    /* the base frame (docs/model.md 10): the gap is that of docs/model.md 4
     * with r_B = (x_P, w) + zeta h/2 (-w', 1), no w0 (the slider's height is
     * z_r = z_C - w0), and there is no time argument at all (w~ = 0) */
    for (i = 0; i < REF_CORNERS; ++i) {
        ref_contact c;
        double g[2], x_b;
        ref_kinematics_corner(&scene, q, i, &c);
        x_b = q[scene.i_x] + cos(q[scene.i_beta]) * scene.corner[i][0] + sin(q[scene.i_beta]) * scene.corner[i][1];
        material_gap(&scene, q, i, x_b, 0, g);
        assert_close("base-frame gap g_N", c.gap[0], g[0], 1e-15, 0.0);
    }
}

static void test_pcs_kinematics_use_the_prescribed_position(void **state)
{
    static ref_scene scene;
    scene_params p = load_fig6();
    ref_contact a, b;
    double q[REF_MAX_Q] = { 2e-5, -1e-5, 5e-6, 0.0, 1e-6 };
    int i;
    (void)state;

    p.model = 1;
    p.s0 = 0.25;
    build(&scene, &p);
    q[scene.i_x] = 0.4 * scene.length; /* the state's x_C: not used by the kinematics */
    q[scene.i_z] = -scene.com_offset;
    for (i = 0; i < REF_CORNERS; ++i) {
        ref_kinematics_corner(&scene, q, i, &a);
        q[scene.i_x] = 0.1 * scene.length;
        ref_kinematics_corner(&scene, q, i, &b);
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
    double z_rest, worst = 0.0;
    int n;
    (void)state;

    /* base acceleration a = 5 m/s^2 < g: the slider hanging on its top
     * corners never lifts off, it moves with the base. In the base frame
     * (docs/model.md 10) the inertial force -m ddw0 only changes how hard it
     * presses (m (g - 5) .. m (g + 5)), so z_r = z_C - w0 stays where it is:
     * the closed contact gives xi_N = u_E + e_N u_B = 0 with u_B = 0 every step */
    p.acceleration = 5.0;
    p.rotation = 1;
    build(&scene, &p);
    ref_step_default_options(&options);
    rest_on_top_corners(&scene, &st);
    z_rest = st.q[scene.i_z];
    for (n = 1; n <= 10000; ++n) {
        ref_step_report report;
        double drift;
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        assert_int_equal(report.active, 2);
        drift = fabs(st.q[scene.i_z] - z_rest);
        if (drift > worst)
            worst = drift;
    }
    print_message("riding: max |z_r - z_r(0)| = %.3e m over 0.2 s (base amplitude %.3e m)\n", worst,
                  p.acceleration / pow(2.0 * (double)REF_PI * p.frequency, 2.0));
    /* rounding of z_r ~ 4e-3 m: a few ulps */
    assert_close("slider moves with the base: z_r constant", worst, 0.0, 1e-17, 0.0);
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

/* ---- excitation: step means and schedules (docs/model.md 10) -------------- */

static void test_step_mean_of_the_harmonic_is_the_closed_form_and_the_schedule_quadrature(void **state)
{
    static ref_scene harmonic, constant;
    scene_params p = load_fig6();
    static const uint64_t steps[] = { 0, 1, 17, 1000, 123457, 3000000, 987654321 };
    double worst_closed = 0.0, worst_gl = 0.0;
    size_t i;
    (void)state;

    build(&harmonic, &p);
    /* the same excitation as a schedule of one point: held before and after it,
     * so its step mean goes through the Gauss-Legendre path */
    snprintf(p.schedule, sizeof p.schedule, "0:%.17g:%.17g", p.frequency, p.acceleration);
    build(&constant, &p);
    assert_int_equal(constant.schedule_points, 1);
    for (i = 0; i < sizeof steps / sizeof steps[0]; ++i) {
        const uint64_t n = steps[i];
        ref_excitation b, e;
        double closed, mean, gl;
        ref_scene_excitation(&harmonic, ref_scene_time(&harmonic, 2 * n), &b);
        ref_scene_excitation(&harmonic, ref_scene_time(&harmonic, 2 * n + 2), &e);
        /* (dw0(t_E) - dw0(t_B)) / dt: two values of size a/Omega ~ 0.018 m/s
         * differ by ~ a dt ~ 3e-4 m/s: their rounding (~2e-18 m/s) over dt is ~1e-13 m/s^2 */
        closed = (e.w0_dot - b.w0_dot) / harmonic.dt_sub;
        mean = ref_scene_step_accel(&harmonic, n);
        gl = ref_scene_step_accel(&constant, n);
        if (fabs(mean - closed) > worst_closed)
            worst_closed = fabs(mean - closed);
        if (fabs(gl - mean) > worst_gl)
            worst_gl = fabs(gl - mean);
        assert_close("harmonic step mean vs (dw0(t_E) - dw0(t_B)) / dt", mean, closed, 1e-10 * p.acceleration, 0.0);
        /* 8-point Gauss-Legendre of a cosine over Omega dt = 0.016 rad: exact to
         * rounding, which is that of the phase: the long double time's ulp at t
         * times 2 pi f (t = 2e4 s at the last n: 5e-13 relative) */
        assert_close("schedule (Gauss-Legendre) vs harmonic step mean", gl, mean,
                     p.acceleration * (1e-14 + 8.0 * (double)REF_PI * p.frequency
                                                   * (double)(ref_scene_time(&harmonic, 2 * n) * LDBL_EPSILON)),
                     0.0);
    }
    print_message("step mean: max |sinc form - closed form| = %.2e m/s^2, max |Gauss-Legendre - sinc form| = %.2e m/s^2\n",
                  worst_closed, worst_gl);
}

static void test_schedule_cycles_are_continuous_and_integrate_a_linear_ramp(void **state)
{
    static ref_scene scene;
    scene_params p = load_fig6();
    static const long double t_k[3] = { 0.1L, 0.3L, 0.5L };
    int k;
    (void)state;

    /* 100 Hz held to 0.1 s, a ramp to 140 Hz at 0.3 s, held; amplitude 5 -> 10 -> 10 */
    snprintf(p.schedule, sizeof p.schedule, "0.1:100:5, 0.3:140:10, 0.5:140:10");
    build(&scene, &p);
    assert_int_equal(scene.schedule_points, 3);
    /* continuity at every point: both sides 2e-15 s apart, f < 140 Hz: < 3e-13 cycles */
    for (k = 0; k < 3; ++k) {
        const long double eps = 1e-15L;
        const long double below = ref_scene_cycles(&scene, t_k[k] - eps), above = ref_scene_cycles(&scene, t_k[k] + eps);
        assert_close("cycles continuous at a schedule point", (double)(above - below), 0.0, 1e-12, 0.0);
    }
    /* int_0^t f dt: 100 t before the ramp; on it 10 + 100 s + (40 / 0.2) s^2 / 2, s = t - 0.1;
     * after it 10 + 24 + 140 (t - 0.3) */
    for (k = 0; k <= 60; ++k) {
        const long double t = 0.01L * k, s = t - 0.1L;
        const long double want = t <= 0.1L ? 100.0L * t
                                 : t <= 0.3L ? 10.0L + 100.0L * s + 100.0L * s * s
                                             : 34.0L + 140.0L * (t - 0.3L);
        assert_close("cycles = int f dt", (double)ref_scene_cycles(&scene, t), (double)want, 1e-12, 0.0);
    }
    /* step means across a schedule point (the kink of f and a there): the
     * Gauss-Legendre per piece vs Simpson with 20000 intervals of
     * -a(t) cos(2 pi cycles(t)) over the whole step (Simpson's error at the
     * kink: O(h^2) ~ 1e-8 of a * (Omega dt) * (df/f) ~ 1e-13 m/s^2) */
    for (k = 0; k < 2; ++k) {
        const long double t_b = t_k[k] - 0.3L * scene.dt_sub, t_e = t_b + scene.dt_sub;
        const int m = 20000;
        long double sum = 0.0L;
        int j;
        for (j = 0; j <= m; ++j) {
            const long double t = t_b + (t_e - t_b) * j / m;
            ref_excitation ex;
            ref_scene_excitation(&scene, t, &ex);
            sum += (j == 0 || j == m ? 1.0L : j % 2 ? 4.0L : 2.0L) * ex.w0_ddot;
        }
        sum /= 3.0L * m;
        assert_close("scheduled step mean across a point", (double)ref_scene_mean_accel(&scene, t_b, t_e), (double)sum,
                     1e-11, 0.0);
    }
}

/* ---- one mode, floating slider: the linear FRFs (docs/model.md 10, 11) ------ */

/* One mode, no stretching, no gravity, a slot 20 mm tall (r_h = 20) centred on
 * the beam: the slider floats and no contact closes (asserted in every step). */
static scene_params floating_one_mode(double damping, double frequency)
{
    scene_params p = load_fig6();
    p.modes = 1;
    p.stretching = 0;
    p.gravity = 0.0;
    p.tilt = 0.0;
    p.play_ratio = 20.0;
    p.damping_ratio = damping;
    p.frequency = frequency;
    p.s0 = 0.5;
    p.load = SCENE_LOAD_NONE;
    p.patch_start = 0.0;
    p.patch_end = 0.02;
    p.coupling = 9.7e-5;
    p.capacitance = 18e-9;
    return p;
}

/* docs/model.md 11 for one mode, harmonic ddw0 = Re(A e^(i W t)):
 *   (w_k^2 - W^2 + 2 i D w_k W) Q + theta V = -gamma A,  (i W C_p + 1/R) V = i W theta Q
 * => V/A = -gamma i W theta / den,  Q/A = -gamma (i W C_p + 1/R) / den,
 *    den = (i W C_p + 1/R)(w_k^2 - W^2 + 2 i D w_k W) + i W theta^2
 * (Erturk & Inman's single-mode FRF; theta = 0: Q/A = -gamma / (w_k^2 - W^2 + 2 i D w_k W)) */
static void continuous_frf(double omega_k, double damping, double gamma, double theta, double c_p, double r_l,
                           double big_omega, double complex *q_per_a, double complex *v_per_a)
{
    const double complex mech = omega_k * omega_k - big_omega * big_omega + 2.0 * UNIT_I * damping * omega_k * big_omega;
    if (theta == 0.0) {
        *q_per_a = -gamma / mech;
        *v_per_a = 0.0;
        return;
    }
    {
        const double complex admittance = UNIT_I * big_omega * c_p + (r_l > 0.0 ? 1.0 / r_l : 0.0);
        const double complex den = admittance * mech + UNIT_I * big_omega * theta * theta;
        *q_per_a = -gamma * admittance / den;
        *v_per_a = -gamma * UNIT_I * big_omega * theta / den;
    }
}

/* One step of the documented scheme for a single mode with a resistor,
 * written here from docs/model.md 5 and 11 (the equations at the top of
 * ref_step.c) without the reference's matrices: x = (q, u, v), a = the
 * step's mean base acceleration. */
typedef struct scalar_scheme {
    double omega, damping, gamma, theta, r_l, dt;
    double decay, gain, mean, rise; /* exact factors of C_p v' + v/R = i over dt */
} scalar_scheme;

static void scalar_scheme_init(scalar_scheme *s, double omega, double damping, double gamma, double theta, double c_p,
                               double r_l, double dt)
{
    const double x = dt / (r_l * c_p);
    s->omega = omega;
    s->damping = damping;
    s->gamma = gamma;
    s->theta = theta;
    s->r_l = r_l;
    s->dt = dt;
    s->decay = exp(-x);
    s->gain = -expm1(-x);
    s->mean = s->gain / x;
    s->rise = 1.0 - s->mean;
}

static void scalar_scheme_step(const scalar_scheme *s, double a, double x[3])
{
    const double dt = s->dt, th = s->theta;
    const double q_m = x[0] + 0.5 * dt * x[1];
    /* u_E = u + dt (-gamma a - w^2 q_M - 2 D w u) - th dt (mean v + rise R th (u + u_E) / 2) */
    const double k = th * th * dt * s->rise * s->r_l / 2.0;
    const double u_e = (x[1] + dt * (-s->gamma * a - s->omega * s->omega * q_m - 2.0 * s->damping * s->omega * x[1])
                        - th * dt * s->mean * x[2] - k * x[1])
                       / (1.0 + k);
    x[2] = s->decay * x[2] + s->gain * s->r_l * th * 0.5 * (x[1] + u_e);
    x[0] = q_m + 0.5 * dt * u_e;
    x[1] = u_e;
}

/* The scheme's steady state x_n = Re(X z^n), z = e^(i W dt), under the step
 * means a_n = Re(A_n z^n): X = (z I - T)^-1 b A_n, T and b from the scheme. */
static void scalar_scheme_steady(const scalar_scheme *s, double complex a_n, double big_omega, double complex x_out[3])
{
    double complex m[3][4];
    const double complex z = cexp(UNIT_I * big_omega * s->dt);
    int i, j, r;

    for (j = 0; j < 3; ++j) {
        double x[3] = { 0.0, 0.0, 0.0 };
        x[j] = 1.0;
        scalar_scheme_step(s, 0.0, x);
        for (i = 0; i < 3; ++i)
            m[i][j] = (i == j ? z : 0.0) - x[i];
    }
    {
        double x[3] = { 0.0, 0.0, 0.0 };
        scalar_scheme_step(s, 1.0, x);
        for (i = 0; i < 3; ++i)
            m[i][3] = x[i] * a_n;
    }
    for (i = 0; i < 3; ++i) { /* Gauss-Jordan with partial pivoting */
        int pivot = i;
        for (r = i + 1; r < 3; ++r)
            if (cabs(m[r][i]) > cabs(m[pivot][i]))
                pivot = r;
        for (j = 0; j < 4; ++j) {
            const double complex swap = m[i][j];
            m[i][j] = m[pivot][j];
            m[pivot][j] = swap;
        }
        for (r = 0; r < 3; ++r)
            if (r != i) {
                const double complex f = m[r][i] / m[i][i];
                for (j = i; j < 4; ++j)
                    m[r][j] -= f * m[i][j];
            }
    }
    for (i = 0; i < 3; ++i)
        x_out[i] = m[i][3] / m[i][i];
}

static void test_linear_beam_in_the_base_frame_reaches_the_harmonic_steady_state(void **state)
{
    static ref_scene scene;
    static ref_state st;
    const double frequency = 125.0, damping = 0.01;
    scene_params p = floating_one_mode(damping, frequency);
    ref_step_options options;
    const double big_omega = 2.0 * (double)REF_PI * frequency;
    const int steps = 50000, window = 4000; /* 1 s; the last 10 periods (400 steps each) */
    double complex q_per_a, v_per_a, measured = 0.0, want;
    double error;
    int n;
    (void)state;

    build(&scene, &p);
    ref_step_default_options(&options);
    ref_state_init(&scene, &st);
    for (n = 1; n <= steps; ++n) {
        ref_step_report report;
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        assert_int_equal(report.active, 0);
        if (n > steps - window)
            measured += st.q[0] * cexp(-UNIT_I * big_omega * scene.dt_sub * n);
    }
    measured *= 2.0 / window;
    continuous_frf(scene.modes.omega[0], damping, scene.modes.gamma[0], 0.0, 0.0, 0.0, big_omega, &q_per_a, &v_per_a);
    want = q_per_a * -p.acceleration; /* ddw0 = -a cos(W t): A = -a */
    error = cabs(measured - want) / cabs(want);
    print_message("load none, from rest, 1 s: Q = %.6e %+.6e i, analytic %.6e %+.6e i, relative error %.2e "
                  "((w_1 dt)^2 = %.2e; transient left e^(-D w_1 t) = %.1e)\n",
                  creal(measured), cimag(measured), creal(want), cimag(want), error,
                  pow(scene.modes.omega[0] * scene.dt_sub, 2.0), exp(-damping * scene.modes.omega[0] * 0.92));
    /* the scheme's frequency error (w dt)^2 / 24 times w_1^2 / |w_1^2 - W^2| ~ 1.3:
     * 6e-5; the transient left after 0.92 s: e^(-15) ~ 3e-7; bound 1e-3 (docs/model.md 11) */
    assert_close("|Q - Q_analytic| / |Q_analytic|", error, 0.0, 1e-3, 0.0);
}

/* d phi_1 / dx at x (second-order differences of phi, h = 1e-5 in xi: error
 * ~ h^2 phi''' ~ 1e-8 relative); one-sided at the clamp */
static double slope_by_differences(const ref_scene *scene, double x)
{
    const long double h = 1e-5L, xi = (long double)x / scene->length;
    long double a[3], b[3], c[3];
    if (xi - h < 0.0L) {
        ref_modes_shape(&scene->modes, 0, xi, a);
        ref_modes_shape(&scene->modes, 0, xi + h, b);
        ref_modes_shape(&scene->modes, 0, xi + 2.0L * h, c);
        return (double)((-3.0L * a[0] + 4.0L * b[0] - c[0]) / (2.0L * h) / scene->length);
    }
    ref_modes_shape(&scene->modes, 0, xi - h, a);
    ref_modes_shape(&scene->modes, 0, xi + h, b);
    return (double)((b[0] - a[0]) / (2.0L * h) / scene->length);
}

static void test_single_mode_voltage_frf_matches_erturk_inman(void **state)
{
    /* R_l C_p = 18 us .. 1.8 s; f below, near and at 0.96 f_1 */
    static const double resistances[] = { 1e3, 1e4, 71e3, 1e6, 1e8 };
    static const double frequencies[] = { 125.0, 200.0, 250.0 };
    const double damping = 0.001; /* docs/model.md 8 */
    double worst_physics = 0.0, worst_power = 0.0, worst_scheme = 0.0;
    size_t ir, jf;
    (void)state;

    for (jf = 0; jf < sizeof frequencies / sizeof frequencies[0]; ++jf)
        for (ir = 0; ir < sizeof resistances / sizeof resistances[0]; ++ir) {
            static ref_scene scene;
            static ref_state st;
            const double frequency = frequencies[jf], r_l = resistances[ir];
            scene_params p = floating_one_mode(damping, frequency);
            const double big_omega = 2.0 * (double)REF_PI * frequency;
            const int steps = 4000; /* 10, 16 and 20 whole periods */
            ref_step_options options;
            scalar_scheme scheme;
            double complex x[3], q_per_a, v_per_a, a_n, v_want;
            double deviation = 0.0, physics, power, power_want, resonance, tau, bound;
            int n;

            p.load = SCENE_LOAD_RESISTOR;
            p.resistance = r_l;
            build(&scene, &p);
            ref_step_default_options(&options);
            /* theta_1 = Theta (phi_1'(x_2) - phi_1'(x_1)), docs/model.md 11 */
            assert_close("theta_1", scene.theta[0],
                         p.coupling * (slope_by_differences(&scene, p.patch_end) - slope_by_differences(&scene, 0.0)),
                         0.0, 1e-6);

            /* the scheme's own steady state, started there: the reference must stay on it */
            scalar_scheme_init(&scheme, scene.modes.omega[0], damping, scene.modes.gamma[0], scene.theta[0],
                               p.capacitance, r_l, scene.dt_sub);
            a_n = -p.acceleration * (double)scene.step_sinc * cexp(0.5 * UNIT_I * big_omega * scene.dt_sub);
            scalar_scheme_steady(&scheme, a_n, big_omega, x);
            ref_state_init(&scene, &st);
            st.q[0] = creal(x[0]);
            st.u[0] = creal(x[1]);
            st.voltage = creal(x[2]);
            for (n = 1; n <= steps; ++n) {
                ref_step_report report;
                const double complex zn = cexp(UNIT_I * big_omega * scene.dt_sub * n);
                assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
                assert_int_equal(report.active, 0);
                if (fabs(st.voltage - creal(x[2] * zn)) > deviation)
                    deviation = fabs(st.voltage - creal(x[2] * zn));
            }
            deviation /= cabs(x[2]);
            power = st.load_energy / (steps * scene.dt_sub);
            /* the scheme's steady state against the continuous FRF */
            continuous_frf(scene.modes.omega[0], damping, scene.modes.gamma[0], scene.theta[0], p.capacitance, r_l,
                           big_omega, &q_per_a, &v_per_a);
            v_want = v_per_a * -p.acceleration;
            physics = cabs(x[2] - v_want) / cabs(v_want);
            power_want = 0.5 * cabs(v_want) * cabs(v_want) / r_l;
            print_message("f = %3.0f Hz, R_l = %5.0e Ohm: |V| = %.6f V (analytic %.6f V): scheme vs analytic %.2e; "
                          "mean power %.4e W (analytic %.4e W): %.2e; reference vs scheme %.1e\n",
                          frequency, r_l, cabs(x[2]), cabs(v_want), physics, power, power_want,
                          fabs(power / power_want - 1.0), deviation);
            if (physics > worst_physics)
                worst_physics = physics;
            if (fabs(power / power_want - 1.0) > worst_power)
                worst_power = fabs(power / power_want - 1.0);
            if (deviation > worst_scheme)
                worst_scheme = deviation;
            /* docs/model.md 11: O((w dt)^2), about 1e-3 at dt = 2e-5. Derived: the
             * scheme's frequency error, at most (w_1 dt)^2/12 + D w_1 dt (see the free
             * mode test), changes the mechanical impedance by twice that, amplified
             * near the resonance by w_1^2 / |w_1^2 - W^2| (13 at 250 Hz); 3.2e-4 at
             * 125 Hz. When R_l C_p < 5 dt the voltage sampled at the step's end lags
             * by up to dt/2 (v_E follows the step's constant current at once): add
             * W dt / 2. The mean voltage, which drives the beam and the load, has no
             * such lag: the load power (quadratic: twice the bound) has none. */
            resonance = fmax(1.0, pow(scene.modes.omega[0], 2.0) / fabs(pow(scene.modes.omega[0], 2.0)
                                                                        - big_omega * big_omega));
            tau = r_l * p.capacitance;
            bound = 2.0 * (pow(scene.modes.omega[0] * scene.dt_sub, 2.0) / 12.0 + damping * scene.modes.omega[0] * scene.dt_sub)
                    * resonance;
            assert_close("|V_scheme - V_analytic| / |V_analytic|", physics, 0.0,
                         bound + (tau < 5.0 * scene.dt_sub ? 0.5 * big_omega * scene.dt_sub : 0.0), 0.0);
            assert_close("mean load power / analytic - 1", power / power_want - 1.0, 0.0, 2.0 * bound, 0.0);
            /* rounding only: the reference is the documented scheme */
            assert_close("|v_reference - v_scheme| / |V|", deviation, 0.0, 1e-10, 0.0);
        }
    print_message("voltage FRF: worst scheme vs analytic %.2e (power %.2e), worst reference vs scheme %.2e\n",
                  worst_physics, worst_power, worst_scheme);
}

/* ---- energy balance (docs/model.md 11) ------------------------------------- */

/* Kinetic + bending + stretching + gravity + patch energy in the base frame,
 * and the part of it the midpoint scheme keeps exactly: the bending term
 * evaluated at q_M instead of (q_B + q_E)/2 gives, per step and mode,
 * omega^2 (dt/4)(u_E - u_B) . (dt/2)(u_B + u_E) = (omega dt)^2/8 (u_E^2 - u_B^2),
 * which telescopes: E_mod = E - dt^2/8 sum omega_k^2 u_k^2 (leapfrog's modified
 * energy). The stretching force at q_M leaves an O(dt^2) error that does not
 * telescope. */
static void stored_energy(const ref_scene *s, const ref_state *st, double *energy, double *modified)
{
    double e = 0.0, correction = 0.0;
    int k;
    for (k = 0; k < s->n_modes; ++k) {
        const double w2 = s->modes.omega[k] * s->modes.omega[k];
        e += 0.5 * st->u[k] * st->u[k] + 0.5 * w2 * st->q[k] * st->q[k];
        correction += w2 * st->u[k] * st->u[k];
    }
    e += ref_dynamics_stretching_energy(s, st->q);
    e += 0.5 * s->slider_mass * (st->u[s->i_x] * st->u[s->i_x] + st->u[s->i_z] * st->u[s->i_z])
         + 0.5 * s->slider_inertia * st->u[s->i_beta] * st->u[s->i_beta];
    e -= s->slider_mass * (s->gravity[0] * st->q[s->i_x] + s->gravity[1] * st->q[s->i_z]);
    if (s->load != REF_LOAD_NONE)
        e += 0.5 * s->capacitance * st->voltage * st->voltage;
    *energy = e;
    *modified = e - s->dt_sub * s->dt_sub / 8.0 * correction;
}

static void test_energy_balance_with_contacts_and_a_resistor(void **state)
{
    static ref_scene scene;
    static ref_state st;
    scene_params p = load_fig6();
    ref_step_options options;
    const int steps = 25000; /* 0.5 s of fig6 */
    double e0, m0, input = 0.0, damping = 0.0, contacts = 0.0, load = 0.0, e_max = 0.0;
    double worst = 0.0, worst_modified = 0.0, correction_max = 0.0;
    long contact_steps = 0;
    int n, k;
    (void)state;

    p.load = SCENE_LOAD_RESISTOR;
    p.resistance = 71e3;
    build(&scene, &p);
    ref_step_default_options(&options);
    ref_state_init(&scene, &st);
    stored_energy(&scene, &st, &e0, &m0);
    for (n = 1; n <= steps; ++n) {
        double u_b[REF_MAX_Q], e, m, sum_b = 0.0, sum_e = 0.0, balance, correction = 0.0;
        ref_step_report report;
        for (k = 0; k < scene.n_q; ++k)
            u_b[k] = st.u[k];
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        contact_steps += report.active > 0;
        /* P_in = -a (sum gamma_k u_k + m u_z) with the step's trapezoidal velocity
         * (the scheme's dq / dt) */
        for (k = 0; k < scene.n_modes; ++k) {
            const double omega = scene.modes.omega[k];
            sum_b += scene.modes.gamma[k] * u_b[k];
            sum_e += scene.modes.gamma[k] * st.u[k];
            damping += 2.0 * scene.damping * omega * u_b[k] * 0.5 * (u_b[k] + st.u[k]) * scene.dt_sub;
            correction += omega * omega * st.u[k] * st.u[k];
        }
        sum_b += scene.slider_mass * u_b[scene.i_z];
        sum_e += scene.slider_mass * st.u[scene.i_z];
        input += -report.base_accel * 0.5 * (sum_b + sum_e) * scene.dt_sub;
        contacts += report.contact_work;
        load += report.load_energy;
        stored_energy(&scene, &st, &e, &m);
        balance = input - damping + contacts - load;
        if (fabs(e - e0 - balance) > worst)
            worst = fabs(e - e0 - balance);
        if (fabs(m - m0 - balance) > worst_modified)
            worst_modified = fabs(m - m0 - balance);
        if (e - e0 > e_max)
            e_max = e - e0;
        correction = scene.dt_sub * scene.dt_sub / 8.0 * correction;
        if (correction > correction_max)
            correction_max = correction;
    }
    print_message("fig6 + 71 kOhm, 0.5 s (%ld contact steps): input %.4e J, damping %.4e J, contacts %.4e J, "
                  "load %.4e J, max stored %.4e J; |balance error| %.3e J (dt^2/8 sum w^2 u^2 up to %.3e J), "
                  "with leapfrog's modified energy %.3e J = %.2e of the input\n",
                  contact_steps, input, damping, -contacts, load, e_max, worst, correction_max, worst_modified,
                  worst_modified / input);
    assert_true(contact_steps > 1000);
    assert_true(load > 0.0 && load < input);
    /* the energy itself: off by the telescoping leapfrog term (bounded by the
     * largest dt^2/8 sum w^2 u^2) plus the modified balance below */
    assert_close("stored + dissipated + load vs input", worst, 0.0, correction_max + 2.0 * worst_modified + 1e-12 * input, 0.0);
    /* the modified energy: the patch's coupling and the load are exact (the
     * circuit is solved exactly for the step's current, and the patch's work
     * uses the same trapezoidal velocity), contacts and damping are counted as
     * the step applies them; only the stretching force's midpoint error and
     * rounding remain: 1.9e-7 of the input over 0.5 s (see the message), bound
     * 2e-6. An O(dt) coupling error (the force from v_B instead of the step's
     * mean v) leaves ~3e-4 */
    assert_close("modified energy balance", worst_modified, 0.0, 2e-6 * input, 0.0);
}

/* ---- the circuit: stability for every R_l, the rectifier -------------------- */

static void test_no_load_resistance_destabilises_the_step(void **state)
{
    static const double resistances[] = { 1.0, 1e2, 1e4, 1e6, 1e8, 1e10, 1e12 };
    size_t i;
    (void)state;

    for (i = 0; i < sizeof resistances / sizeof resistances[0]; ++i) {
        static ref_scene scene;
        static ref_state st;
        /* at the short-circuit resonance f_1, the harshest drive */
        scene_params p = floating_one_mode(0.001, 260.28054);
        ref_step_options options;
        double worst = 0.0, energy = 0.0;
        int n;

        p.load = SCENE_LOAD_RESISTOR;
        p.resistance = resistances[i];
        build(&scene, &p);
        ref_step_default_options(&options);
        ref_state_init(&scene, &st);
        for (n = 1; n <= 10000; ++n) {
            const double t = n * scene.dt_sub, omega = scene.modes.omega[0];
            ref_step_report report;
            double ratio;
            assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
            /* from rest, dE/dt <= gamma a |u| <= gamma a sqrt(2E) for the mode and
             * the patch, whatever R_l (damping and the load only take energy):
             * sqrt(2E) <= gamma a t. The scheme keeps this up to leapfrog's
             * modified energy, a factor 1 + (omega dt)^2/8 */
            energy = 0.5 * st.u[0] * st.u[0] + 0.5 * omega * omega * st.q[0] * st.q[0]
                     + 0.5 * p.capacitance * st.voltage * st.voltage;
            ratio = sqrt(2.0 * energy) / (scene.modes.gamma[0] * p.acceleration * t);
            if (ratio > worst)
                worst = ratio;
        }
        print_message("R_l = %5.0e Ohm (x = dt / R_l C_p = %.1e): max sqrt(2E) / (gamma a t) = %.6f, |v| = %.3e V, "
                      "load %.3e J\n",
                      resistances[i], scene.dt_sub / (resistances[i] * p.capacitance), worst, fabs(st.voltage),
                      st.load_energy);
        assert_true(isfinite(energy) && st.load_energy >= 0.0);
        assert_close("sqrt(2E) / (gamma a t)", worst, 0.0, 1.0 + pow(scene.modes.omega[0] * scene.dt_sub, 2.0) / 8.0 + 1e-9,
                     0.0);
    }
}

static void test_rectifier_charges_the_storage_monotonically_toward_its_limit(void **state)
{
    static ref_scene scene;
    static ref_state st;
    const double frequency = 125.0, diode_drop = 0.1, damping = 0.01;
    scene_params p = floating_one_mode(damping, frequency);
    ref_step_options options;
    enum { STEPS = 100000, SAMPLES = 20 }; /* 2 s, V_s every 0.1 s */
    double sample[SAMPLES + 1];
    double complex q_per_a, v_per_a;
    double limit, v_oc, scheme, tail, charge = 0.0, worst_clamp = 0.0, worst_reverse = 0.0, v_s_max = 0.0;
    long conducting = 0;
    int n, k;
    (void)state;

    /* the amplitude ramps from 0 to 14 m/s^2 over 0.3 s (40 periods), then
     * holds: the beam follows without a transient that would overshoot */
    p.load = SCENE_LOAD_RECTIFIER;
    p.storage_capacitance = 100.0 * p.capacitance;
    p.storage_resistance = 1e12; /* R_s C_s = 1.8e6 s: a leak of 1e-6 in 2 s */
    p.diode_drop = diode_drop;
    snprintf(p.schedule, sizeof p.schedule, "0:%.17g:0, 0.3:%.17g:14", frequency, frequency);
    build(&scene, &p);
    ref_step_default_options(&options);
    ref_state_init(&scene, &st);
    sample[0] = 0.0;
    for (n = 1; n <= STEPS; ++n) {
        const double v_s_b = st.storage_voltage;
        ref_step_report report;
        assert_int_equal(ref_step(&scene, &options, &st, &report), 0);
        assert_int_equal(report.active, 0);
        assert_true(report.solved && report.converged);
        /* the bridge never conducts backwards, and only through the branch of
         * the patch voltage's sign; while it conducts its reverse voltage
         * V_s + 2 V_f - sigma v is zero (complementarity, at the step's end) */
        assert_true(report.bridge_charge >= 0.0);
        if (report.bridge_charge > 0.0) {
            const double reverse = st.storage_voltage + 2.0 * diode_drop - report.bridge_branch * st.voltage;
            ++conducting;
            assert_true(report.bridge_branch * st.voltage > 0.0);
            if (fabs(reverse) > worst_reverse)
                worst_reverse = fabs(reverse);
        }
        charge += report.bridge_charge;
        /* V_s never falls but by the R_s leak (the exact factor e^(-dt / R_s C_s)) */
        assert_true(st.storage_voltage >= (double)scene.storage.decay * v_s_b * (1.0 - 1e-15));
        /* the diodes clamp |v| to V_s + 2 V_f at every step's end */
        if (fabs(st.voltage) - (st.storage_voltage + 2.0 * diode_drop) > worst_clamp)
            worst_clamp = fabs(st.voltage) - (st.storage_voltage + 2.0 * diode_drop);
        if (st.storage_voltage > v_s_max)
            v_s_max = st.storage_voltage;
        if (n % (STEPS / SAMPLES) == 0)
            sample[n / (STEPS / SAMPLES)] = st.storage_voltage;
    }
    /* the limit: once no current flows the patch is open, the beam settles in
     * the open-circuit steady state and v swings +-|V_oc| about zero, so
     * V_s -> |V_oc| - 2 V_f (the FRF of docs/model.md 11 with 1/R = 0) */
    continuous_frf(scene.modes.omega[0], damping, scene.modes.gamma[0], scene.theta[0], p.capacitance, 0.0,
                   2.0 * (double)REF_PI * frequency, &q_per_a, &v_per_a);
    v_oc = cabs(v_per_a) * 14.0;
    limit = v_oc - 2.0 * diode_drop;
    /* the scheme's error of |V_oc| (as in the FRF test, resonance factor 1.3 at 125 Hz) */
    scheme = 2.0 * (pow(scene.modes.omega[0] * scene.dt_sub, 2.0) / 12.0 + damping * scene.modes.omega[0] * scene.dt_sub)
             * 1.3 * v_oc;
    print_message("rectifier: V_s every 0.1 s:");
    for (k = 1; k <= SAMPLES; ++k)
        print_message(" %.4f", sample[k]);
    print_message(" V\nlimit |V_oc| - 2 V_f = %.6f V (scheme error up to %.1e V); C_s V_s / sum Q - 1 = %.2e; "
                  "conducting in %ld of %d steps; max |v| - (V_s + 2 V_f) = %.2e V, conducting: max |reverse "
                  "voltage| = %.2e V\n",
                  limit, scheme, p.storage_capacitance * st.storage_voltage / charge - 1.0, conducting, (int)STEPS,
                  worst_clamp, worst_reverse);
    /* rounding of volts: 1e-12 of |V_oc| */
    assert_close("clamp |v| <= V_s + 2 V_f", fmax(worst_clamp, 0.0), 0.0, 1e-12 * v_oc, 0.0);
    assert_close("conducting: V_s + 2 V_f - sigma v = 0", worst_reverse, 0.0, 1e-12 * v_oc, 0.0);
    /* charge conservation: all of sum Q is on C_s (R_s leaks 1e-6 of it in 2 s) */
    assert_close("C_s V_s = sum Q", p.storage_capacitance * st.storage_voltage, charge, 0.0, 2e-6);
    /* toward the limit: once the drive holds (t >= 0.4 s) each 0.1 s adds less
     * than the one before (a geometric approach, ratio ~0.6) ... */
    for (k = 5; k <= SAMPLES; ++k)
        assert_true(sample[k] - sample[k - 1] < sample[k - 1] - sample[k - 2]);
    /* ... so what is left after 2 s is at most the last increment times
     * ratio / (1 - ratio) < 2 increments; never above the limit */
    tail = 2.0 * (sample[SAMPLES] - sample[SAMPLES - 1]);
    assert_true(v_s_max <= limit + scheme);
    assert_close("V_s at 2 s vs its limit", st.storage_voltage, limit, scheme + tail, 0.0);
}

/* ---- measured base acceleration (docs/model.md 10) ------------------------- */

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(text, f);
    return fclose(f);
}

static void test_replay_reader_reports_file_and_line(void **state)
{
    static const char *const bad[] = { "1.0\n2.0\nabc\n", "1.0\n# fine\n\nnan\n", "1.0\n2.0 3.0\n", "1e999\n",
                                       "inf\n" };
    static const unsigned long bad_line[] = { 3, 4, 2, 1, 1 };
    char path[64], err[512], want[80];
    double *values;
    uint64_t count;
    unsigned long lines;
    size_t i;
    (void)state;

    snprintf(path, sizeof path, "/tmp/bs-ref-replay-%ld.txt", (long)getpid());
    assert_int_equal(write_text(path, "# measured, m/s^2\n1.5\n  -2e-1  # with a comment\n\n+3\n"), 0);
    assert_int_equal(ref_replay_read(path, &values, &count, &lines, err, sizeof err), 0);
    assert_int_equal(count, 3);
    assert_int_equal(lines, 5);
    assert_close("value 1", values[0], 1.5, 0.0, 0.0);
    assert_close("value 2", values[1], -0.2, 0.0, 0.0);
    assert_close("value 3", values[2], 3.0, 0.0, 0.0);
    free(values);
    for (i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        assert_int_equal(write_text(path, bad[i]), 0);
        assert_int_equal(ref_replay_read(path, &values, &count, &lines, err, sizeof err), -1);
        assert_null(values);
        snprintf(want, sizeof want, "%s:%lu:", path, bad_line[i]);
        if (!strstr(err, want)) {
            print_error("expected '%s' in: %s\n", want, err);
            fail();
        }
    }
    remove(path);
    assert_int_equal(ref_replay_read(path, &values, &count, &lines, err, sizeof err), -1);
    assert_non_null(strstr(err, path));
}

/* The last CSV row's w_sensor, z_r, v of a run of scene for 0.01 s. */
static void run_last_row(const ref_scene *scene, const double *base_accel, uint64_t count, double last[3])
{
    ref_run_options options;
    ref_run_result result;
    char line[512], *field;
    FILE *csv = tmpfile();
    int column;

    assert_non_null(csv);
    options.t_end = 0.01;
    options.every = 1;
    options.csv = csv;
    options.periods = NULL;
    options.base_accel = base_accel;
    options.base_accel_count = count;
    ref_step_default_options(&options.step);
    assert_int_equal(ref_run(scene, &options, &result), 0);
    rewind(csv);
    while (fgets(line, sizeof line, csv))
        ;
    fclose(csv);
    for (column = 0, field = strtok(line, ","); field; field = strtok(NULL, ","), ++column) {
        if (column == 1)
            last[0] = strtod(field, NULL);
        if (column == 3)
            last[1] = strtod(field, NULL);
        if (column == 8)
            last[2] = strtod(field, NULL);
    }
}

static void test_replayed_base_acceleration_drives_the_step_like_the_scene(void **state)
{
    static ref_scene scene, sub2;
    static ref_state st;
    static double accel[500];
    scene_params p = load_fig6();
    ref_step_options options;
    double from_scene[3], replayed[3];
    int n, k;
    (void)state;

    p.load = SCENE_LOAD_RESISTOR;
    build(&scene, &p);
    /* the scene's own step means, replayed: the same run to the last bit */
    for (n = 0; n < 500; ++n)
        accel[n] = ref_scene_step_accel(&scene, (uint64_t)n);
    run_last_row(&scene, NULL, 0, from_scene);
    run_last_row(&scene, accel, 500, replayed);
    for (k = 0; k < 3; ++k)
        assert_close("replayed = scene excitation", replayed[k], from_scene[k], 0.0, 0.0);
    /* K = 2 substeps: each value is held for both substeps of its outer step */
    {
        char err[256];
        if (ref_scene_init(&sub2, &p, 2, err, sizeof err) != 0) {
            print_error("%s\n", err);
            fail();
        }
    }
    run_last_row(&sub2, accel, 500, replayed);
    ref_step_default_options(&options);
    ref_state_init(&sub2, &st);
    for (n = 0; n < 500; ++n)
        for (k = 0; k < 2; ++k) {
            ref_step_report report;
            assert_int_equal(ref_step_with_accel(&sub2, &options, accel[n], &st, &report), 0);
        }
    /* the CSV prints 10 significant digits */
    assert_close("K = 2: w_sensor", replayed[0], ref_scene_sensor(&sub2, st.q), 1e-18, 1e-9);
    assert_close("K = 2: z_r", replayed[1], st.q[sub2.i_z], 0.0, 1e-9);
    assert_close("K = 2: v", replayed[2], st.voltage, 1e-15, 1e-9);
    /* too few values: the run refuses to start */
    {
        ref_run_options options_few;
        ref_run_result result;
        options_few.t_end = 0.01;
        options_few.every = 1;
        options_few.csv = options_few.periods = NULL;
        options_few.base_accel = accel;
        options_few.base_accel_count = 499;
        ref_step_default_options(&options_few.step);
        assert_int_equal(ref_run(&scene, &options_few, &result), -1);
        assert_int_equal(result.steps, 0);
    }
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
        cmocka_unit_test(test_step_mean_of_the_harmonic_is_the_closed_form_and_the_schedule_quadrature),
        cmocka_unit_test(test_schedule_cycles_are_continuous_and_integrate_a_linear_ramp),
        cmocka_unit_test(test_linear_beam_in_the_base_frame_reaches_the_harmonic_steady_state),
        cmocka_unit_test(test_single_mode_voltage_frf_matches_erturk_inman),
        cmocka_unit_test(test_energy_balance_with_contacts_and_a_resistor),
        cmocka_unit_test(test_no_load_resistance_destabilises_the_step),
        cmocka_unit_test(test_rectifier_charges_the_storage_monotonically_toward_its_limit),
        cmocka_unit_test(test_replay_reader_reports_file_and_line),
        cmocka_unit_test(test_replayed_base_acceleration_drives_the_step_like_the_scene),
        cmocka_unit_test(test_free_mode_oscillates_at_omega_with_decay_d),
        cmocka_unit_test(test_dropped_slider_rebounds_with_restitution),
        cmocka_unit_test(test_slider_on_tilted_beam_sticks_above_tan_theta_and_slides_below),
        cmocka_unit_test(test_slider_rides_a_rigid_beam_shaken_below_g),
        cmocka_unit_test(test_end_stop_returns_the_slider_with_restitution),
        cmocka_unit_test(test_contact_solvers_reproduce_fc2d_cases),
    };
    return cmocka_run_group_tests_name("reference", tests, NULL, NULL);
}
