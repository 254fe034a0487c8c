/* test_beam.c - the beam alone: a free mode oscillates at omega_k and decays
 * with D, exactly as the Moreau midpoint map predicts.
 *
 * Without contact, one mode of the step is linear (the cubic term is ~1e-12
 * of the linear one at the amplitude used):
 *   q_M = q + h/2 u,  u' = u + h (-w^2 q_M - 2 D w u),  q' = q_M + h/2 u'
 *   [q'; u'] = [[1 - w^2 h^2/2, h (1 - D w h - w^2 h^2/4)], [-w^2 h, 1 - 2 D w h - w^2 h^2/2]] [q; u]
 * with eigenvalues r exp(+-i theta): discrete frequency theta / h and decay
 * rate -ln(r) / h. The simulated signal must follow them to measurement
 * precision, and the continuous values w sqrt(1 - D^2), D w to the scheme's
 * O((w h)^2 + D w h) error.
 */
#include "support.h"

#include <complex.h>
#include <math.h>

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_sim sim;

typedef struct measured {
    double omega;   /* from the mean period between upward zero crossings */
    double decay;   /* from the ratio of the first and last peak */
} measured;

static measured simulate_mode(int k, double h)
{
    const double q0 = 1e-9; /* w(x) ~ 10 nm: no contact; stretching shifts omega by 3e-11 */
    const int periods = 40;
    const double omega = model.modes.omega[k];
    const long steps = (long)(periods * 2.0 * 3.14159265358979323846 / omega / h);
    bs_real q[BS_MAX_MODES] = { 0 };
    double prev2 = 0.0, prev = q0, first_cross = -1.0, last_cross = -1.0;
    double first_peak = 0.0, last_peak = 0.0, t_first_peak = -1.0, t_last_peak = -1.0;
    int crossings = 0;
    long n;
    measured m;

    q[k] = (bs_real)q0;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    assert_int_equal(bs_sim_set_state(&sim, q, NULL, NULL, NULL), BS_OK);
    for (n = 1; n <= steps; ++n) {
        double value;
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(support_report(&sim).active, 0); /* truly free */
        bs_sim_get_state(&sim, q, NULL, NULL, NULL);
        value = (double)q[k];
        if (prev < 0.0 && value >= 0.0) { /* upward crossing, linear interpolation */
            const double t = h * ((double)(n - 1) + prev / (prev - value));
            if (first_cross < 0.0)
                first_cross = t;
            else
                ++crossings;
            last_cross = t;
        }
        if (n >= 2 && prev > prev2 && prev >= value) { /* peak at n-1, parabolic interpolation */
            const double curvature = prev2 - 2.0 * prev + value;
            const double offset = 0.5 * (prev2 - value) / curvature;
            const double peak = prev - 0.25 * (prev2 - value) * offset;
            const double t = h * ((double)(n - 1) + offset);
            if (t_first_peak < 0.0) {
                t_first_peak = t;
                first_peak = peak;
            }
            t_last_peak = t;
            last_peak = peak;
        }
        prev2 = prev;
        prev = value;
    }
    assert_true(crossings >= periods - 2);
    m.omega = 2.0 * 3.14159265358979323846 * crossings / (last_cross - first_cross);
    m.decay = log(first_peak / last_peak) / (t_last_peak - t_first_peak);
    return m;
}

static void test_free_modes_follow_the_discrete_map_and_the_continuous_law(void **state)
{
    const double h = 2e-6;
    int k;
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    file.params.acceleration = 0.0;
    file.params.gravity = 0.0;
    file.params.play_ratio = 2.0; /* 0.5 mm clearance above and below */
    file.params.dt = h;
    support_build(&file, &scene, &model);

    for (k = 0; k < 5; ++k) {
        const double w = sqrt((double)scene.omega_sq[k]); /* what the core integrates */
        const double d = file.params.damping_ratio;
        const double a11 = 1 - w * w * h * h / 2, a12 = h * (1 - d * w * h - w * w * h * h / 4);
        const double a21 = -w * w * h, a22 = 1 - 2 * d * w * h - w * w * h * h / 2;
        const double trace = a11 + a22, det = a11 * a22 - a12 * a21;
        const double complex lambda = 0.5 * trace + 0.5 * csqrt(trace * trace - 4 * det);
        const double omega_map = carg(lambda) / h, decay_map = -log(cabs(lambda)) / h;
        const double wh = w * h;
        const measured m = simulate_mode(k, h);

        print_message("mode %d, %s: omega %.6f rad/s (map %.6f, omega_k sqrt(1-D^2) %.6f), "
                      "decay %.5f 1/s (map %.5f, D omega_k %.5f)\n", k + 1, BS_REAL_NAME, m.omega, omega_map,
                      w * sqrt(1 - d * d), m.decay, decay_map, d * w);
        /* the scheme, to measurement precision (float: the signal has 24 bits) */
        assert_close("omega: simulated vs discrete map", m.omega, omega_map, 0.0,
                     BS_REAL_FLOAT ? 1e-5 : 1e-7);
        assert_close("decay: simulated vs discrete map", m.decay, decay_map, 0.0,
                     BS_REAL_FLOAT ? 2e-2 : 1e-4);
        /* the physics: omega_k sqrt(1 - D^2) and D omega_k, to the scheme's error:
         * (omega h)^2 / 24 from the leapfrog, D omega h from damping taken at u_B */
        assert_close("omega: discrete vs omega_k sqrt(1 - D^2)", omega_map, w * sqrt(1 - d * d), 0.0,
                     wh * wh / 12.0 + 2.0 * d * wh);
        assert_close("decay: discrete vs D omega_k", decay_map, d * w, 0.0, wh * wh);
        assert_close("omega_k vs docs/model.md", w, model.modes.omega[k], 0.0, 2.0 * SUPPORT_EPS);
    }
}

/* The linearly implicit step, one mode, no contact: with
 * g = 1 / (1 + theta h c + theta^2 h^2 w^2), c = 2 D w,
 *   u' = u + g h (-c u - w^2 (q + theta h u)),   q' = q + h ((1 - theta) u + theta u'). */
static void implicit_map(double w, double d, double h, double theta, double *omega, double *decay)
{
    const double c = 2.0 * d * w;
    const double g = 1.0 / (1.0 + theta * h * c + theta * theta * h * h * w * w);
    const double a21 = -g * h * w * w, a22 = 1.0 - g * h * c - g * theta * h * h * w * w;
    const double a11 = 1.0 + h * theta * a21, a12 = h * (1.0 - theta) + h * theta * a22;
    const double trace = a11 + a22, det = a11 * a22 - a12 * a21;
    const double complex lambda = 0.5 * trace + 0.5 * csqrt(trace * trace - 4 * det);
    *omega = carg(lambda) / h;
    *decay = -log(cabs(lambda)) / h;
}

static void test_implicit_modes_follow_their_discrete_map(void **state)
{
    static const double thetas[] = { 0.5, 0.75 };
    unsigned t;
    int k;
    (void)state;
    for (t = 0; t < 2; ++t) {
        const double h = 2e-6;
        support_load("configs/fig6.ini", &file, &scene, &model);
        file.params.acceleration = 0.0;
        file.params.gravity = 0.0;
        file.params.play_ratio = 2.0;
        file.params.dt = h;
        file.params.implicit = 1;
        file.params.theta = thetas[t];
        support_build(&file, &scene, &model);
        for (k = 0; k < 5; k += 2) {
            const double w = sqrt((double)scene.omega_sq[k]);
            double omega_map, decay_map;
            const measured m = simulate_mode(k, h);
            implicit_map(w, file.params.damping_ratio, h, thetas[t], &omega_map, &decay_map);
            print_message("implicit theta %.2f mode %d, %s: omega %.6f (map %.6f), decay %.5f (map %.5f)\n",
                          thetas[t], k + 1, BS_REAL_NAME, m.omega, omega_map, m.decay, decay_map);
            assert_close("implicit omega vs its map", m.omega, omega_map, 0.0, BS_REAL_FLOAT ? 1e-5 : 1e-7);
            assert_close("implicit decay vs its map", m.decay, decay_map, 0.0, BS_REAL_FLOAT ? 2e-2 : 1e-4);
            /* trapezoidal frequency error: w h / 2 = tan(w_h h / 2), (w h)^2 / 12 relative */
            assert_close("implicit omega vs omega_k", omega_map, w, 0.0, (w * h) * (w * h) / 6.0 + 2.0 * thetas[t] * w * h);
        }
    }
}

/* Where the explicit step is refused (omega_5 dt = 4), the implicit one runs
 * a free vibration of all five modes without growth. */
static void test_implicit_step_is_stable_beyond_the_explicit_limit(void **state)
{
    const double h = 4.0 / (2.0 * 3.14159265358979323846 * 3500.1239);
    bs_real q[BS_MAX_MODES] = { 0 };
    double largest = 0.0, first = 0.0;
    int k, n;
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    file.params.acceleration = 0.0;
    file.params.gravity = 0.0;
    file.params.play_ratio = 2.0;
    file.params.dt = h;
    file.params.damping_ratio = 0.0;
    file.params.implicit = 1;
    support_build(&file, &scene, &model);
    for (k = 0; k < 5; ++k)
        q[k] = (bs_real)1e-9;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    assert_int_equal(bs_sim_set_state(&sim, q, NULL, NULL, NULL), BS_OK);
    for (n = 0; n < 20000; ++n) {
        bs_real u[BS_MAX_MODES];
        double energy = 0.0;
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        bs_sim_get_state(&sim, q, u, NULL, NULL);
        for (k = 0; k < 5; ++k) /* the trapezoidal rule keeps this quadratic form for D = 0 */
            energy += (double)u[k] * (double)u[k] + (double)scene.omega_sq[k] * (double)q[k] * (double)q[k];
        if (n == 0)
            first = energy;
        largest = fmax(largest, energy);
    }
    assert_close("largest energy / first", largest / first, 1.0, 0.0, BS_REAL_FLOAT ? 1e-3 : 1e-6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_free_modes_follow_the_discrete_map_and_the_continuous_law),
        cmocka_unit_test(test_implicit_modes_follow_their_discrete_map),
        cmocka_unit_test(test_implicit_step_is_stable_beyond_the_explicit_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
