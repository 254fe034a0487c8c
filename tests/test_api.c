/* test_api.c - the public API's contract (core/include/beamslider.h): version
 * and build check, what every function does with a NULL or never-initialised
 * sim, the contact-solve options, the beam read-out, and the slider held on
 * the beam (BS_E_ESCAPED, and set_state taking every state a step produces). */
#include "support.h"

#include "bs_observer.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_sim sim;

static void load(const char *path)
{
    support_load(path, &file, &scene, &model);
}

static void test_version_matches_the_macros(void **state)
{
    char expected[32];
    (void)state;
    snprintf(expected, sizeof expected, "%d.%d.%d", BS_VERSION_MAJOR, BS_VERSION_MINOR, BS_VERSION_PATCH);
    assert_string_equal(bs_version(), expected);
    assert_string_equal(BS_VERSION_STRING, expected);
    assert_int_equal(BS_VERSION_NUMBER, BS_VERSION_MAJOR * 10000 + BS_VERSION_MINOR * 100 + BS_VERSION_PATCH);
}

/* The library refuses a caller whose view of the build differs: another
 * precision, version, switch or struct size (a float program linked to a
 * double library; the real link of that case is tests/consumer). */
static void test_a_caller_built_differently_is_refused(void **state)
{
    const uint32_t tag = BS_BUILD_TAG;
    const char *field = NULL;
    (void)state;
    load("configs/fig6.ini");
    assert_int_equal(bs_build_check(), BS_OK);
    assert_int_equal(bs_build_check_(tag ^ 1u, sizeof(bs_sim), sizeof(bs_scene)), BS_E_BUILD);     /* precision */
    assert_int_equal(bs_build_check_(tag ^ (1u << 2), sizeof(bs_sim), sizeof(bs_scene)), BS_E_BUILD); /* a switch */
    assert_int_equal(bs_build_check_(tag + (1u << 16), sizeof(bs_sim), sizeof(bs_scene)), BS_E_BUILD); /* minor */
    assert_int_equal(bs_build_check_(tag, sizeof(bs_sim) - 8, sizeof(bs_scene)), BS_E_BUILD);
    assert_int_equal(bs_build_check_(tag, sizeof(bs_sim), sizeof(bs_scene) / 2), BS_E_BUILD);
    assert_int_equal(bs_sim_init_(tag ^ 1u, sizeof(bs_sim), sizeof(bs_scene), &sim, &scene, BS_MODEL_FREE,
                                  BS_R(0.3)),
                     BS_E_BUILD);
    assert_int_equal(bs_scene_check_(tag, sizeof(bs_scene) + 4, &scene, &field), BS_E_BUILD);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
}

/* An observer compiled with other table sizes (BS_OBSERVER_MAPS,
 * BS_OBSERVER_MAX_LATENCY) or another build than the library is refused,
 * and its memory is not written. */
static void test_an_observer_built_differently_is_refused(void **state)
{
    static bs_observer obs;
    static bs_observer_gains gains;
    const uint32_t tag = BS_BUILD_TAG, maps_one = ((uint32_t)1 << 16) | (BS_OBSERVER_TAG & 0xffffu);
    (void)state;
    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    memset(&obs, 0x5a, sizeof obs);
    assert_int_equal(bs_observer_init_(tag, maps_one, sizeof obs, sizeof gains, &obs, &sim, &gains, NULL), BS_E_BUILD);
    assert_int_equal(bs_observer_init_(tag, BS_OBSERVER_TAG + 1, sizeof obs, sizeof gains, &obs, &sim, &gains, NULL),
                     BS_E_BUILD); /* another latency */
    assert_int_equal(bs_observer_init_(tag ^ 1u, BS_OBSERVER_TAG, sizeof obs, sizeof gains, &obs, &sim, &gains, NULL),
                     BS_E_BUILD); /* another precision */
    assert_int_equal(bs_observer_init_(tag, BS_OBSERVER_TAG, sizeof obs, sizeof gains - 4, &obs, &sim, &gains, NULL),
                     BS_E_BUILD);
    assert_int_equal(bs_observer_init_(tag, BS_OBSERVER_TAG, sizeof obs + 8, sizeof gains, &obs, &sim, &gains, NULL),
                     BS_E_BUILD);
    assert_true(obs.ready == 0x5a5a5a5au); /* not written */
    assert_int_equal(bs_observer_init(NULL, &sim, &gains, NULL), BS_E_NULL);
    assert_int_equal(bs_observer_init(&obs, &sim, &gains, NULL), BS_E_ARGUMENT); /* zero gains: this build's, refused */
}

/* Every function answers a NULL or never-initialised sim without touching
 * it: a status, or the documented value of a read function. */
static void check_refused(const bs_sim *bad, bs_status expected)
{
    bs_real q[BS_MAX_MODES] = { 0 }, pose[3] = { BS_R(0.05), 0, 0 }, w, slope;
    bs_step_report report;
    bs_solver_options options = bs_solver_defaults();
    bs_monitor monitor;

    assert_int_equal(bs_sim_step((bs_sim *)bad), expected);
    assert_int_equal(bs_sim_set_solver((bs_sim *)bad, &options), expected);
    assert_int_equal(bs_sim_get_solver(bad, &options), expected);
    assert_int_equal(bs_sim_set_pcs_position((bs_sim *)bad, BS_R(0.5)), expected);
    assert_int_equal(bs_sim_set_contact_laws((bs_sim *)bad, BS_R(0.1), BS_R(0.0)), expected);
    assert_int_equal(bs_sim_get_contact_laws(bad, &w, &slope), expected);
    assert_int_equal(bs_sim_get_report(bad, &report), expected);
    assert_int_equal(bs_sim_get_state(bad, q, q, pose, pose), expected);
    assert_int_equal(bs_sim_set_state((bs_sim *)bad, q, q, pose, pose), expected);
    assert_int_equal(bs_sim_beam_at(bad, BS_R(0.05), &w, &slope), expected);
    assert_int_equal(bs_monitor_init(&monitor, bad), expected);
    assert_int_equal(bs_monitor_update(&monitor, bad), expected);
    assert_true(isnan((double)bs_sim_sensor(bad)));
    assert_true(isnan((double)bs_sim_position(bad)));
    assert_true(isnan((double)bs_sim_phase(bad)));
    assert_true(isnan((double)bs_sim_time(bad)));
    assert_int_equal(bs_sim_steps(bad), 0);
    assert_int_equal(bs_sim_hash(bad), 0);
}

static void test_null_and_uninitialised_sims_are_refused(void **state)
{
    static bs_sim never;           /* zeroed: never initialised */
    bs_sim garbage;
    (void)state;
    check_refused(NULL, BS_E_NULL);
    check_refused(&never, BS_E_UNINITIALISED);
    memset(&garbage, 0xa5, sizeof garbage); /* stack garbage: not ready either */
    check_refused(&garbage, BS_E_UNINITIALISED);

    /* a sim whose last init failed is not ready, even if it ran before */
    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_step(&sim), BS_OK);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.99)), BS_E_ARGUMENT);
    check_refused(&sim, BS_E_UNINITIALISED);

    /* NULL out-arguments of a ready sim */
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_get_report(&sim, NULL), BS_E_NULL);
    assert_int_equal(bs_sim_set_solver(&sim, NULL), BS_E_NULL);
    assert_int_equal(bs_sim_get_solver(&sim, NULL), BS_E_NULL);
    assert_int_equal(bs_monitor_init(NULL, &sim), BS_E_NULL);
    assert_int_equal(bs_monitor_update(NULL, &sim), BS_E_NULL);
    assert_int_equal(bs_sim_get_state(&sim, NULL, NULL, NULL, NULL), BS_OK); /* NULL parts: skipped */
    assert_string_equal(bs_status_text((bs_status)42), "unknown status");
}

static void test_every_status_has_a_text(void **state)
{
    int s;
    (void)state;
    for (s = BS_OK; s >= BS_E_UNINITIALISED; --s)
        assert_string_not_equal(bs_status_text((bs_status)s), "unknown status");
}

/* Field by field: the struct has padding, which memcmp would read. */
static void assert_same_options(const bs_solver_options *a, const bs_solver_options *b)
{
    assert_int_equal(a->max_sweeps, b->max_sweeps);
    assert_true(a->tol_rel == b->tol_rel);
    assert_true(a->tol_abs == b->tol_abs);
    assert_int_equal(a->measure_residual, b->measure_residual);
}

static void test_solver_options_are_checked_and_kept(void **state)
{
    bs_solver_options options = bs_solver_defaults(), bad, got;
    (void)state;
    assert_int_equal(options.max_sweeps, BS_SOLVER_DEFAULT_MAX_SWEEPS);
    assert_true(options.tol_rel == (bs_real)BS_SOLVER_DEFAULT_TOL_REL);
    assert_true(options.tol_abs == (bs_real)BS_SOLVER_DEFAULT_TOL_ABS);
    assert_int_equal(options.measure_residual, 1);
    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_get_solver(&sim, &got), BS_OK);
    assert_same_options(&got, &options);

#define EXPECT_REFUSED(change)                                                      \
    do {                                                                            \
        bad = options;                                                              \
        change;                                                                     \
        assert_int_equal(bs_sim_set_solver(&sim, &bad), BS_E_ARGUMENT);             \
        assert_int_equal(bs_sim_get_solver(&sim, &got), BS_OK);                     \
        assert_same_options(&got, &options);                            \
    } while (0)
    EXPECT_REFUSED(bad.max_sweeps = 0);
    EXPECT_REFUSED(bad.max_sweeps = BS_SOLVER_MAX_SWEEPS + 1);
    EXPECT_REFUSED(bad.tol_rel = BS_R(-1e-9));
    EXPECT_REFUSED(bad.tol_rel = (bs_real)NAN);
    EXPECT_REFUSED(bad.tol_abs = (bs_real)INFINITY);
    EXPECT_REFUSED(bad.measure_residual = 2);
#undef EXPECT_REFUSED
    options.max_sweeps = 7;
    options.tol_rel = BS_R(1e-3);
    assert_int_equal(bs_sim_set_solver(&sim, &options), BS_OK);
    assert_int_equal(bs_sim_get_solver(&sim, &got), BS_OK);
    assert_same_options(&got, &options);
}

/* With the residual off, a step with one contact (solved exactly) reports no
 * residual but its exactness; a step with two reports none either when the
 * laws hold by sign, else the residual its search needed anyway. The cap
 * holds with it on. */
static void test_solver_options_take_effect(void **state)
{
    bs_solver_options options = bs_solver_defaults();
    int n, single = 0, pairs = 0;
    (void)state;
    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    options.measure_residual = 0;
    assert_int_equal(bs_sim_set_solver(&sim, &options), BS_OK);
    for (n = 0; n < 20000; ++n) {
        bs_step_report report;
        unsigned bits, count = 0;
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        report = support_report(&sim);
        for (bits = report.active; bits; bits >>= 1)
            count += bits & 1u;
        if (count == 1) {
            ++single;
            assert_true(report.residual == BS_R(-1.0));
            assert_int_equal(report.converged, 1);
        } else if (count == 2) {
            ++pairs;
            assert_true(report.residual >= BS_R(0.0) || (report.residual == BS_R(-1.0) && report.converged == 1));
            assert_true(report.converged == 0 || report.converged == 1);
        }
    }
    assert_true(single > 1000 && pairs > 1000);
    options.max_sweeps = 1;
    options.measure_residual = 1;
    assert_int_equal(bs_sim_set_solver(&sim, &options), BS_OK);
    for (n = 0; n < 5000; ++n) {
        bs_step_report report;
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        report = support_report(&sim);
        assert_true(report.sweeps <= 1);
        assert_true(report.converged == 0 || report.converged == 1);
        assert_true(report.residual >= BS_R(0.0));
    }
}

/* The beam read-out: at 4L/7 it is the sensor signal (to the mode-shape fit
 * and rounding), inside a clamp it is 0, and x must be a number. */
static void test_beam_at_matches_the_sensor(void **state)
{
    bs_real w, slope;
    int n;
    (void)state;
    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    for (n = 0; n < 3000; ++n)
        assert_int_equal(bs_sim_step(&sim), BS_OK);
    assert_int_equal(bs_sim_beam_at(&sim, scene.length * BS_R(4.0) / BS_R(7.0), &w, &slope), BS_OK);
    assert_close("w(4L/7) against the sensor", w, bs_sim_sensor(&sim), 0.0,
                 BS_REAL_FLOAT ? 1e-4 : 1e-7);
    assert_true(slope != BS_R(0.0));
    assert_int_equal(bs_sim_beam_at(&sim, -scene.length, &w, &slope), BS_OK);
    assert_true(w == BS_R(0.0) && slope == BS_R(0.0));
    assert_int_equal(bs_sim_beam_at(&sim, (bs_real)NAN, &w, &slope), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_beam_at(&sim, BS_R(0.01), NULL, NULL), BS_OK);
}

/* The time is steps times dt, from 0 at the start; a changed frequency
 * goes through bs_sim_set_excitation, and the same change made in a copy of
 * the scene is refused with a field text that says so. */
static void test_time_and_a_changed_frequency(void **state)
{
    static bs_scene copy;
    const char *field = NULL;
    uint64_t n;
    (void)state;
    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_true(bs_sim_time(&sim) == BS_R(0.0));
    for (n = 1; n <= 2500; ++n) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        if (n % 500 == 0)
            assert_true(bs_sim_time(&sim) == (bs_real)n * scene.dt);
    }
    assert_close("t after 2500 steps", bs_sim_time(&sim), 2500.0 * (double)scene.dt, 0.0, SUPPORT_EPS);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(110.0), scene.base_accel), BS_OK);
    assert_int_equal(bs_sim_step(&sim), BS_OK);
    copy = scene;
    copy.frequency = BS_R(110.0);
    assert_int_equal(bs_scene_check(&copy, &field), BS_E_SCENE);
    assert_non_null(strstr(field, "bs_sim_set_excitation"));
    assert_non_null(strstr(field, "build the scene again"));
}

/* A slider thrown against the left clamp stop: every state the steps
 * produce, some of them a hair inside the stop (Moreau lets a contact be
 * penetrated by about |u| dt), is taken back by bs_sim_set_state. */
static void test_states_at_a_clamp_stop_can_be_set_again(void **state)
{
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES], pose[3], velocity[3];
    int n, inside = 0;
    (void)state;
    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_get_state(&sim, q, u, pose, velocity), BS_OK);
    pose[0] = scene.stop_min + BS_R(1e-4);
    velocity[0] = BS_R(-0.3); /* into the stop */
    assert_int_equal(bs_sim_set_state(&sim, q, u, pose, velocity), BS_OK);
    for (n = 0; n < 4000; ++n) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_get_state(&sim, q, u, pose, velocity), BS_OK);
        inside += pose[0] < scene.stop_min;
        assert_int_equal(bs_sim_set_state(&sim, q, u, pose, velocity), BS_OK);
    }
    print_message("%d of 4000 states a hair inside the stop\n", inside);
    assert_true(inside > 0);
    /* beyond the band of h/2 the state is refused, within it taken */
    pose[0] = scene.stop_min - scene.half_thickness * BS_R(1.001);
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, pose, NULL), BS_E_ARGUMENT);
    pose[0] = scene.stop_max + scene.half_thickness * BS_R(1.001);
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, pose, NULL), BS_E_ARGUMENT);
    pose[0] = scene.stop_min - scene.half_thickness * BS_R(0.999);
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, pose, NULL), BS_OK);
}

/* A slider the contacts do not hold is a fault, not a run that ends "ok":
 * fig6 without the hardening term shaken at 1e5 m/s^2 throws it off the
 * beam within 2 ms (79 steps, either precision); a slider placed below the
 * beam, or pushed through a clamp stop, is refused at the next step. Each
 * leaves the state as it was. */
static void test_a_slider_that_leaves_the_beam_is_a_fault(void **state)
{
    bs_real pose[3], velocity[3] = { 0 };
    bs_status status = BS_OK;
    uint32_t hash;
    int n;
    (void)state;
    load("configs/fig6.ini");
    file.params.stretching = 0;
    file.params.acceleration = 100000.0;
    support_build(&file, &scene, &model);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    for (n = 0; n < 5000 && status == BS_OK; ++n) {
        hash = bs_sim_hash(&sim);
        status = bs_sim_step(&sim);
    }
    print_message("a = 1e5 m/s^2 without stretching: %s after %d steps\n", bs_status_text(status), n);
    assert_int_equal(status, BS_E_ESCAPED);
    assert_int_equal(bs_sim_hash(&sim), hash);

    load("configs/fig6.ini");
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_get_state(&sim, NULL, NULL, pose, NULL), BS_OK);
    pose[1] -= BS_R(0.01); /* the slot 1 cm below the beam: its top corners under the beam */
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, pose, NULL), BS_OK);
    hash = bs_sim_hash(&sim);
    assert_int_equal(bs_sim_step(&sim), BS_E_ESCAPED);
    assert_int_equal(bs_sim_hash(&sim), hash);

    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_get_state(&sim, NULL, NULL, pose, NULL), BS_OK);
    pose[0] = scene.stop_min - scene.half_thickness * BS_R(0.99);
    velocity[0] = BS_R(-1e3) * scene.half_thickness / scene.dt; /* through the stop in one step */
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, pose, velocity), BS_OK);
    hash = bs_sim_hash(&sim);
    status = bs_sim_step(&sim);
    assert_true(status == BS_E_ESCAPED);
    assert_int_equal(bs_sim_hash(&sim), hash);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_matches_the_macros),
        cmocka_unit_test(test_a_caller_built_differently_is_refused),
        cmocka_unit_test(test_an_observer_built_differently_is_refused),
        cmocka_unit_test(test_null_and_uninitialised_sims_are_refused),
        cmocka_unit_test(test_every_status_has_a_text),
        cmocka_unit_test(test_solver_options_are_checked_and_kept),
        cmocka_unit_test(test_solver_options_take_effect),
        cmocka_unit_test(test_beam_at_matches_the_sensor),
        cmocka_unit_test(test_time_and_a_changed_frequency),
        cmocka_unit_test(test_states_at_a_clamp_stop_can_be_set_again),
        cmocka_unit_test(test_a_slider_that_leaves_the_beam_is_a_fault),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
