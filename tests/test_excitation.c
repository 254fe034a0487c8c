/* test_excitation.c - the base excitation (core/src/bs_excitation.c, the
 * excitation functions of core/src/bs_sim.c and the step's two inputs):
 * the harmonic step mean against its closed form, a measured input that
 * replays the harmonic bit for bit, run-time frequency and amplitude with a
 * continuous phase, and inputs that are refused without a trace. */
#include "support.h"

#include <math.h>
#include <string.h>

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_sim sim;
static bs_sim twin;

static void start(bs_sim *s)
{
    assert_int_equal(bs_sim_init(s, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
}

/* The mean base acceleration of step k (t_B = k dt) for f, a, from the phase
 * phi_B at its start [turns]: (dw0/dt(t_E) - dw0/dt(t_B)) / dt in long double. */
static long double step_mean(long double phi_b, long double f, long double a, long double dt)
{
    const long double two_pi = 6.283185307179586476925286766559L;
    const long double omega = two_pi * f;
    return -a * (sinl(two_pi * phi_b + omega * dt) - sinl(two_pi * phi_b)) / (omega * dt);
}

/* Each step of the harmonic excitation uses the mean of -a cos(Omega t) over
 * the step (docs/model.md 10), to the precision's rounding. */
static void test_harmonic_step_uses_the_mean_over_the_step(void **state)
{
    const long double dt = (long double)file.params.dt, f = (long double)file.params.frequency;
    const long double a = (long double)file.params.acceleration;
    double worst = 0.0;
    long k;
    (void)state;
    start(&sim);
    assert_true(bs_sim_base_acceleration(&sim) == BS_R(0.0));
    for (k = 0; k < 2000; ++k) { /* a few periods */
        const long double phi_b = fmodl((long double)k * f * dt, 1.0L);
        const long double want = step_mean(phi_b, f, a, dt);
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        worst = fmax(worst, fabs((double)((long double)bs_sim_base_acceleration(&sim) - want)));
    }
    print_message("%s: 2000 steps, worst |mean - closed form| = %.2e m/s^2 (a = %g)\n", BS_REAL_NAME, worst,
                  (double)a);
    assert_true(worst <= (BS_REAL_FLOAT ? 4e-6 : 1e-12) * (double)a);
}

/* A measured input that is the harmonic's own step means gives the same run,
 * bit for bit: the step sees the excitation only through that number. */
static void test_measured_replay_of_the_harmonic_is_identical(void **state)
{
    long k;
    (void)state;
    start(&sim);
    start(&twin);
    for (k = 0; k < 30000; ++k) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step_measured(&twin, bs_sim_base_acceleration(&sim)), BS_OK);
        if (k % 1000 == 999)
            assert_int_equal(bs_sim_hash(&twin), bs_sim_hash(&sim));
    }
    assert_true(bs_sim_position(&twin) == bs_sim_position(&sim));
}

/* A new frequency changes the phase's advance, never the phase: a ramp or a
 * step has no jump. The step after the change advances by the new f dt. */
static void test_new_frequency_keeps_the_phase_continuous(void **state)
{
    const double dt = file.params.dt;
    bs_real f, a, before, after;
    long k;
    (void)state;
    start(&sim);
    for (k = 0; k < 137; ++k)
        assert_int_equal(bs_sim_step(&sim), BS_OK);
    before = bs_sim_phase(&sim);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(110.0), BS_R(7.0)), BS_OK);
    assert_true(bs_sim_phase(&sim) == before);
    assert_int_equal(bs_sim_get_excitation(&sim, &f, &a), BS_OK);
    assert_true(f == BS_R(110.0) && a == BS_R(7.0));
    assert_int_equal(bs_sim_step(&sim), BS_OK);
    after = bs_sim_phase(&sim);
    assert_close("phase advance [turns]", (double)after - (double)before, 110.0 * dt, 1e-7, 0.0);
    /* and the step mean is the new sine's, amplitude 7 */
    assert_close("step mean", (double)bs_sim_base_acceleration(&sim),
                 (double)step_mean((long double)before, 110.0L, 7.0L, (long double)dt), 1e-5, 1e-5);
}

/* Bad inputs are refused and leave everything as it was. */
static void test_bad_excitation_inputs_change_nothing(void **state)
{
    const double dt = file.params.dt;
    uint32_t hash;
    bs_real f, a;
    (void)state;
    start(&sim);
    assert_int_equal(bs_sim_step(&sim), BS_OK);
    hash = bs_sim_hash(&sim);
    assert_int_equal(bs_sim_step_measured(&sim, (bs_real)NAN), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_step_measured(&sim, (bs_real)INFINITY), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(0.0), BS_R(1.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(-5.0), BS_R(1.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_excitation(&sim, (bs_real)(0.5001 / dt), BS_R(1.0)), BS_E_ARGUMENT); /* > Nyquist */
    assert_int_equal(bs_sim_set_excitation(&sim, (bs_real)NAN, BS_R(1.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(124.0), BS_R(-1.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(124.0), (bs_real)INFINITY), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_hash(&sim), hash);
    assert_int_equal(bs_sim_get_excitation(&sim, &f, &a), BS_OK);
    assert_true(f == (bs_real)file.params.frequency && a == (bs_real)file.params.acceleration);
    assert_int_equal(bs_sim_step_measured(NULL, BS_R(0.0)), BS_E_NULL);
    assert_int_equal(bs_sim_set_excitation(NULL, BS_R(124.0), BS_R(1.0)), BS_E_NULL);
    assert_int_equal(bs_sim_get_excitation(NULL, &f, &a), BS_E_NULL);
    assert_true(isnan((double)bs_sim_base_acceleration(NULL)));
}

/* With no base motion, the slider's height is its height: a measured zero
 * and a harmonic of amplitude 0 are the same run. */
static void test_zero_excitation_two_ways(void **state)
{
    long k;
    (void)state;
    start(&sim);
    start(&twin);
    assert_int_equal(bs_sim_set_excitation(&sim, (bs_real)file.params.frequency, BS_R(0.0)), BS_OK);
    for (k = 0; k < 5000; ++k) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step_measured(&twin, BS_R(0.0)), BS_OK);
    }
    assert_int_equal(bs_sim_hash(&twin) == bs_sim_hash(&sim), 0); /* the phase differs: hashes do */
    {
        bs_real p1[3], p2[3], q1[BS_MAX_MODES], q2[BS_MAX_MODES];
        int i;
        bs_sim_get_state(&sim, q1, NULL, p1, NULL);
        bs_sim_get_state(&twin, q2, NULL, p2, NULL);
        for (i = 0; i < 3; ++i)
            assert_true(p1[i] == p2[i]);
        for (i = 0; i < scene.n_modes; ++i)
            assert_true(q1[i] == q2[i]);
    }
}

static int setup(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_harmonic_step_uses_the_mean_over_the_step),
        cmocka_unit_test(test_measured_replay_of_the_harmonic_is_identical),
        cmocka_unit_test(test_new_frequency_keeps_the_phase_continuous),
        cmocka_unit_test(test_bad_excitation_inputs_change_nothing),
        cmocka_unit_test(test_zero_excitation_two_ways),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
