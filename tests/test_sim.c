/* test_sim.c - the simulator's contract (core/src/bs_sim.c, core/src/bs_scene.c):
 * input checks, the explicit stability limit, errors that keep the last good
 * state, determinism, the exact excitation phase, unbiased float drift and
 * the PCS kinematics. */
#include "support.h"

#include <float.h>
#include <math.h>
#include <string.h>

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_sim sim;
static bs_sim other;

static void load_fig6(void)
{
    support_load("configs/fig6.ini", &file, &scene, &model);
}

static void test_init_refuses_bad_arguments(void **state)
{
    (void)state;
    load_fig6();
    assert_int_equal(bs_sim_init(NULL, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_E_NULL);
    assert_int_equal(bs_sim_init(&sim, NULL, BS_MODEL_FREE, BS_R(0.3)), BS_E_NULL);
    assert_int_equal(bs_sim_init(&sim, &scene, (bs_model)7, BS_R(0.3)), BS_E_ARGUMENT);
    /* free slider: the slot corners must be between the clamps, s0 in [B/2L, 1 - B/2L] */
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.01)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.99)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.04)), BS_OK);
    /* PCS: any prescribed position on [0, 1] */
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_PCS, BS_R(0.0)), BS_OK);
    assert_int_equal(bs_sim_set_pcs_position(&sim, BS_R(0.5)), BS_OK);
    assert_int_equal(bs_sim_set_pcs_position(&sim, BS_R(1.5)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_PCS, BS_R(-0.1)), BS_E_ARGUMENT);
}

/* The contact laws a twin sets while it runs: taken from the next step on,
 * refused outside their range (nothing changes), and what the build lacks
 * refused too. */
static void test_contact_laws_are_settable(void **state)
{
    bs_real mu = BS_R(-1.0), e_n = BS_R(-1.0);
    uint32_t before;
    (void)state;
    load_fig6();
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_init(&other, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_get_contact_laws(&sim, &mu, &e_n), BS_OK);
    assert_true(mu == scene.mu && e_n == scene.e_n);
    assert_int_equal(bs_sim_get_contact_laws(&sim, NULL, NULL), BS_OK);
    assert_int_equal(bs_sim_set_contact_laws(&sim, BS_R(-0.01), BS_R(0.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_contact_laws(&sim, (bs_real)NAN, BS_R(0.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_contact_laws(&sim, (bs_real)INFINITY, BS_R(0.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_contact_laws(&sim, BS_R(0.1), BS_R(1.01)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_contact_laws(&sim, BS_R(0.1), BS_R(-0.01)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_set_contact_laws(&sim, BS_R(0.1), (bs_real)NAN), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_get_contact_laws(&sim, &mu, &e_n), BS_OK);
    assert_true(mu == scene.mu && e_n == scene.e_n);
    /* the scene's own laws change nothing; others change the run */
    assert_int_equal(bs_sim_set_contact_laws(&sim, scene.mu, scene.e_n), BS_OK);
    for (int k = 0; k < 20000; ++k) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step(&other), BS_OK);
    }
    assert_int_equal(bs_sim_hash(&sim), bs_sim_hash(&other));
    before = bs_sim_hash(&sim);
    assert_int_equal(bs_sim_set_contact_laws(&sim, BS_R(2.0) * scene.mu, BS_R(0.0)), BS_OK);
    assert_int_equal(bs_sim_get_contact_laws(&sim, &mu, &e_n), BS_OK);
    assert_true(mu == BS_R(2.0) * scene.mu && e_n == BS_R(0.0));
    assert_int_equal(bs_sim_hash(&sim), before); /* from the next step on */
    for (int k = 0; k < 20000; ++k) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step(&other), BS_OK);
    }
    assert_int_not_equal(bs_sim_hash(&sim), bs_sim_hash(&other));
}

/* Each broken field is refused, and bs_scene_check names it. */
static void test_scene_check_names_the_bad_field(void **state)
{
    static bs_scene bad;
    const char *field = NULL;
    (void)state;
    load_fig6();
#define EXPECT_BAD(assignment, status, name)                                   \
    do {                                                                       \
        bad = scene;                                                           \
        assignment;                                                            \
        field = NULL;                                                          \
        assert_int_equal(bs_scene_check(&bad, &field), status);                \
        assert_non_null(field);                                                \
        assert_string_equal(field, name);                                      \
        assert_int_equal(bs_sim_init(&sim, &bad, BS_MODEL_FREE, BS_R(0.3)), status); \
    } while (0)
    EXPECT_BAD(bad.n_modes = BS_MAX_MODES + 1, BS_E_SCENE, "n_modes");
    EXPECT_BAD(bad.n_modes = -1, BS_E_SCENE, "n_modes");
    EXPECT_BAD(bad.omega_sq[2] = (bs_real)NAN, BS_E_SCENE, "omega_sq");
    EXPECT_BAD(bad.omega_sq[0] = 0, BS_E_SCENE, "omega_sq");
    EXPECT_BAD(bad.shape_coef[3][1][2] = (bs_real)INFINITY, BS_E_SCENE, "shape_coef");
    EXPECT_BAD(bad.mu = BS_R(-0.1), BS_E_SCENE, "mu");
    EXPECT_BAD(bad.e_n = BS_R(1.5), BS_E_SCENE, "e_n");
    EXPECT_BAD(bad.mass_inv = 0, BS_E_SCENE, "mass_inv");
    EXPECT_BAD(bad.corner[0][1] = bad.corner[1][1], BS_E_SCENE, "corner"); /* slot thinner than the beam */
    EXPECT_BAD(bad.dt = 0, BS_E_SCENE, "dt");
    EXPECT_BAD(bad.base_accel = BS_R(-1.0), BS_E_SCENE, "base_accel");
    EXPECT_BAD(bad.phase_step_half *= 2, BS_E_SCENE,
               "frequency/phase_step_half (derived together with dt: for another frequency call "
               "bs_sim_set_excitation on the sim, for another dt build the scene again)"); /* not f dt / 2 */
    EXPECT_BAD(bad.frequency *= BS_R(1.1), BS_E_SCENE,
               "frequency/phase_step_half (derived together with dt: for another frequency call "
               "bs_sim_set_excitation on the sim, for another dt build the scene again)"); /* a copy's frequency */
    EXPECT_BAD((bad.dt = BS_R(1e-4), bad.phase_step_half *= 5), BS_E_UNSTABLE, "dt"); /* omega_5 dt = 2.2 */
#undef EXPECT_BAD
    assert_int_equal(bs_scene_check(&scene, &field), BS_OK);
}

/* At the limit: omega_5 dt = 1.99 is accepted, 2.01 refused. */
static void test_explicit_limit_is_refused_up_front(void **state)
{
    const double omega_max = 2.0 * 3.14159265358979323846 * 3500.1239;
    char err[1024];
    (void)state;
    load_fig6();
    file.params.dt = 1.99 / omega_max;
    assert_int_equal(scene_build(&file, &scene, &model, err, sizeof err), 0);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    file.params.dt = 2.01 / omega_max;
    assert_int_equal(scene_build(&file, &scene, &model, err, sizeof err), -1);
    assert_non_null(strstr(err, "explicit limit"));
}

/* A state the cubic stiffening pushes past omega dt < 2, and a state that
 * overflows: the step refuses and leaves the state as it was. */
static void test_failing_step_keeps_last_good_state(void **state)
{
    bs_real q[BS_MAX_MODES] = { 0 }, u[BS_MAX_MODES] = { 0 };
    uint32_t hash;
    (void)state;
    load_fig6();
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    q[0] = BS_R(0.05); /* w ~ 0.6 m: stretching stiffness far above omega_5^2 */
    assert_int_equal(bs_sim_set_state(&sim, q, NULL, NULL, NULL), BS_OK);
    hash = bs_sim_hash(&sim);
    assert_int_equal(bs_sim_step(&sim), BS_E_UNSTABLE);
    assert_int_equal(bs_sim_hash(&sim), hash);

    /* without stretching, so that the stability bound stays finite: a
     * velocity whose elastic force omega_5^2 (dt/2) u overflows; its
     * midpoint deflection already puts the beam across the slot, which the
     * step reports as the slider leaving the beam */
    memset(scene.stretch, 0, sizeof scene.stretch);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK); /* the step reads a copy */
    q[0] = 0;
    u[4] = (bs_real)(BS_REAL_FLOAT ? 1e35 : 1e306);
    assert_int_equal(bs_sim_set_state(&sim, q, u, NULL, NULL), BS_OK);
    hash = bs_sim_hash(&sim);
    assert_int_equal(bs_sim_step(&sim), BS_E_ESCAPED);
    assert_int_equal(bs_sim_hash(&sim), hash);

    /* PCS (no clamp stops; the kinematics ignore x_C): a slider velocity
     * whose end-of-step position overflows */
    {
        bs_real velocity[3] = { 0 };
        assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_PCS, BS_R(0.3)), BS_OK);
        velocity[0] = (bs_real)(BS_REAL_FLOAT ? 3e38 : 1.7e308);
        assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, NULL, velocity), BS_OK);
        hash = bs_sim_hash(&sim);
        assert_int_equal(bs_sim_step(&sim), BS_E_NONFINITE);
        assert_int_equal(bs_sim_hash(&sim), hash);
    }

    u[0] = (bs_real)NAN;
    assert_int_equal(bs_sim_set_state(&sim, NULL, u, NULL, NULL), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_hash(&sim), hash);
}

/* Two sims of the same scene, stepped alternately (any hidden shared state
 * would show), end in the same state bit for bit; so does a re-run. */
static void test_same_scene_gives_identical_state_hash(void **state)
{
    uint32_t first;
    int n;
    (void)state;
    load_fig6();
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_init(&other, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    for (n = 0; n < 50000; ++n) { /* 1 s: thousands of contact steps */
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step(&other), BS_OK);
    }
    first = bs_sim_hash(&sim);
    assert_int_equal(bs_sim_hash(&other), first);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    for (n = 0; n < 50000; ++n)
        assert_int_equal(bs_sim_step(&sim), BS_OK);
    assert_int_equal(bs_sim_hash(&sim), first);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.31)), BS_OK); /* and it can differ */
    for (n = 0; n < 50000; ++n)
        assert_int_equal(bs_sim_step(&sim), BS_OK);
    assert_int_not_equal(bs_sim_hash(&sim), first);
}

/* Free flight on a rigid beam: no contact, so steps are cheap. */
static void rigid_free_flight(void)
{
    load_fig6();
    file.params.gravity = 0.0;
    file.params.play_ratio = 2.0;
    support_build(&file, &scene, &model);
    scene.n_modes = 0;
}

/* docs/model.md 9.1: after 60 s (3e6 steps) and 600 s the phase is exact to the
 * resolution of the reported fraction (2^-24 turns). */
static void test_excitation_phase_is_exact_after_long_runs(void **state)
{
    long n;
    (void)state;
    rigid_free_flight();
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    for (n = 1; n <= 30000000; ++n) {
        bs_sim_step(&sim);
        if (n == 3000000 || n == 30000000) {
            const double turns = (double)n * file.params.frequency * file.params.dt;
            double distance = fabs((double)bs_sim_phase(&sim) - (turns - floor(turns)));
            distance = fmin(distance, 1.0 - distance); /* on the circle */
            assert_close("phase error [turns]", distance, 0.0, 1.2e-7, 0.0);
        }
    }
}

/* docs/model.md 9.2: x_C advancing by a fraction of its ulp per step (float:
 * 2e-9 m on 0.07 m, ulp 7.5e-9 m) still moves exactly as far as the sum of
 * the increments. */
static void test_slow_drift_is_not_lost_to_rounding(void **state)
{
    const bs_real velocity[3] = { BS_R(1e-4), 0, 0 };
    const long steps = 1000000;
    double expected;
    bs_real pose[3];
    long n;
    (void)state;
    rigid_free_flight();
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, NULL, velocity), BS_OK);
    bs_sim_get_state(&sim, NULL, NULL, pose, NULL);
    /* the increment the core adds each step, dt/2 (u_B + u_E), in bs_real */
    expected = (double)pose[0] + (double)steps * (double)(BS_R(0.5) * scene.dt * (velocity[0] + velocity[0]));
    for (n = 0; n < steps; ++n)
        assert_int_equal(bs_sim_step(&sim), BS_OK);
    assert_close("x_C after 1e6 steps [m]", (double)bs_sim_position(&sim) * (double)scene.length, expected,
                 4.0 * SUPPORT_EPS * expected, 0.0);
}

/* PCS: the contact kinematics use the prescribed position only, so the
 * beam's motion cannot depend on where the state's x_C has drifted. */
static void test_pcs_kinematics_ignore_the_drifting_x(void **state)
{
    bs_real pose[3], q_a[BS_MAX_MODES], q_b[BS_MAX_MODES];
    int n, k;
    (void)state;
    load_fig6();
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_PCS, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_init(&other, &scene, BS_MODEL_PCS, BS_R(0.3)), BS_OK);
    bs_sim_get_state(&other, NULL, NULL, pose, NULL);
    pose[0] = BS_R(0.8) * scene.length; /* far from the prescribed 0.3 L */
    assert_int_equal(bs_sim_set_state(&other, NULL, NULL, pose, NULL), BS_OK);
    for (n = 0; n < 20000; ++n) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step(&other), BS_OK);
    }
    assert_true(support_report(&sim).active != 0 || support_report(&other).active == 0);
    bs_sim_get_state(&sim, q_a, NULL, NULL, NULL);
    bs_sim_get_state(&other, q_b, NULL, NULL, NULL);
    for (k = 0; k < scene.n_modes; ++k)
        assert_true(q_a[k] == q_b[k]);
    assert_true(fabs((double)bs_sim_position(&other) - 0.8) < 0.05); /* it drifted from 0.8, not 0.3 */
}

/* The host's maximum sizes (20 modes, 128 shape pieces, 6 contacts) stay
 * within the budget docs/design.md section 1 states: a bs_sim of at most
 * 12 KB in double and 6 KB in float (since 0.8.0 it holds the step's
 * prepared constants, S among them: 3.2 KB of the double figure at 20
 * modes). */
static void test_state_fits_its_budget(void **state)
{
    (void)state;
    print_message("sizeof(bs_sim) = %lu B, sizeof(bs_scene) = %lu B (%s)\n", (unsigned long)sizeof(bs_sim),
                  (unsigned long)sizeof(bs_scene), BS_REAL_NAME);
    assert_true(sizeof(bs_sim) <= (BS_REAL_FLOAT ? 6144u : 12288u));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_init_refuses_bad_arguments),
        cmocka_unit_test(test_contact_laws_are_settable),
        cmocka_unit_test(test_scene_check_names_the_bad_field),
        cmocka_unit_test(test_explicit_limit_is_refused_up_front),
        cmocka_unit_test(test_failing_step_keeps_last_good_state),
        cmocka_unit_test(test_same_scene_gives_identical_state_hash),
        cmocka_unit_test(test_excitation_phase_is_exact_after_long_runs),
        cmocka_unit_test(test_slow_drift_is_not_lost_to_rounding),
        cmocka_unit_test(test_pcs_kinematics_ignore_the_drifting_x),
        cmocka_unit_test(test_state_fits_its_budget),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
