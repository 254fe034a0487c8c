/* test_checkpoint.c - checkpoints (core/src/bs_checkpoint.c): a restored sim
 * continues bit for bit like the one saved, with contacts under way, a
 * changed excitation, a measured input and a transducer; a checkpoint of
 * another size, build, scene or model, or a damaged one, is refused with its
 * own status and changes nothing; the states the step produces at a clamp
 * stop are restorable. */
#include "support.h"

#include <float.h>
#include <math.h>
#include <string.h>

static scene_file file;
static bs_scene scene, resistor_scene, other_scene;
static scene_model model;
static bs_sim sim, copy;
static unsigned char buffer[BS_CHECKPOINT_SIZE + 16];

/* FNV-1a, as the checkpoint's trailer: lets a test forge a checkpoint whose
 * checksum holds, so that the check behind it is the one exercised. */
static uint32_t fnv(const unsigned char *bytes, size_t size)
{
    uint32_t hash = 2166136261u;
    size_t i;
    for (i = 0; i < size; ++i) {
        hash ^= bytes[i];
        hash *= 16777619u;
    }
    return hash;
}

static void reseal(unsigned char *bytes)
{
    const uint32_t checksum = fnv(bytes, BS_CHECKPOINT_SIZE - 4);
    memcpy(bytes + BS_CHECKPOINT_SIZE - 4, &checksum, 4);
}

static void run(bs_sim *s, long steps)
{
    long k;
    for (k = 0; k < steps; ++k)
        assert_int_equal(bs_sim_step(s), BS_OK);
}

/* Saves sim after `before` steps, runs it `after` more, then restores the
 * checkpoint into a fresh sim of the same scene and runs that `after`
 * steps: both must agree bit for bit at every check. */
static void check_continuation(const bs_scene *sc, long before, long after)
{
    long k;
    assert_int_equal(bs_sim_init(&sim, sc, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    run(&sim, before);
    assert_int_equal(bs_sim_save(&sim, buffer, sizeof buffer), BS_OK);
    assert_int_equal(bs_sim_init(&copy, sc, BS_MODEL_FREE, BS_R(0.7)), BS_OK);
    assert_int_equal(bs_sim_restore(&copy, buffer, sizeof buffer), BS_OK);
    assert_int_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
    assert_true(bs_sim_steps(&copy) == bs_sim_steps(&sim));
    for (k = 0; k < after; ++k) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step(&copy), BS_OK);
        if (k % 500 == 499)
            assert_int_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
    }
    assert_true(bs_sim_position(&copy) == bs_sim_position(&sim));
    assert_true(bs_sim_sensor(&copy) == bs_sim_sensor(&sim));
}

/* fig6 after 0.5 s: the slider is in contact most steps, the warm start and
 * the shape caches are in use, x_C has a compensated part. */
static void test_restored_run_continues_bit_for_bit(void **state)
{
    bs_step_report a, b;
    (void)state;
    check_continuation(&scene, 25000, 10000);
    assert_int_equal(bs_sim_get_report(&sim, &a), BS_OK);
    assert_int_equal(bs_sim_get_report(&copy, &b), BS_OK);
    assert_true(a.active == b.active && a.sweeps == b.sweeps && a.residual == b.residual);
}

/* The transducer's voltage and energy are state too. */
static void test_transducer_state_is_restored(void **state)
{
    bs_transducer_output a, b;
    (void)state;
    check_continuation(&resistor_scene, 20000, 5000);
    assert_int_equal(bs_sim_get_transducer(&sim, &a), BS_OK);
    assert_int_equal(bs_sim_get_transducer(&copy, &b), BS_OK);
    assert_true(a.present == 1 && a.voltage != BS_R(0.0));
    assert_true(a.voltage == b.voltage && a.energy == b.energy && a.power == b.power);
}

/* The excitation as set at run time (frequency, amplitude, phase) and the
 * measured input's last value come back; so does a run on measured input. */
static void test_excitation_settings_are_restored(void **state)
{
    bs_real f, a;
    long k;
    (void)state;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    run(&sim, 3000);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(117.25), BS_R(3.5)), BS_OK);
    run(&sim, 777);
    assert_int_equal(bs_sim_step_measured(&sim, BS_R(-2.5)), BS_OK);
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_restore(&copy, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_get_excitation(&copy, &f, &a), BS_OK);
    assert_true(f == BS_R(117.25) && a == BS_R(3.5));
    assert_true(bs_sim_phase(&copy) == bs_sim_phase(&sim));
    assert_true(bs_sim_base_acceleration(&copy) == BS_R(-2.5));
    for (k = 0; k < 2000; ++k) {
        const bs_real input = (bs_real)(k % 7) - BS_R(3.0);
        assert_int_equal(bs_sim_step_measured(&sim, input), BS_OK);
        assert_int_equal(bs_sim_step_measured(&copy, input), BS_OK);
    }
    run(&sim, 1000);
    run(&copy, 1000);
    assert_int_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
}

/* The contact laws as set at run time come back, and the run goes on with
 * them: with the scene's laws it would part from the saved sim. */
static void test_contact_laws_are_restored(void **state)
{
    bs_real mu, e_n;
    long k;
    (void)state;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    run(&sim, 3000);
    assert_int_equal(bs_sim_set_contact_laws(&sim, BS_R(0.21), BS_R(0.35)), BS_OK);
    run(&sim, 500);
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_restore(&copy, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_get_contact_laws(&copy, &mu, &e_n), BS_OK);
    assert_true(mu == BS_R(0.21) && e_n == BS_R(0.35));
    for (k = 0; k < 5000; ++k) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_step(&copy), BS_OK);
    }
    assert_int_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_restore(&copy, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_set_contact_laws(&copy, scene.mu, scene.e_n), BS_OK);
    run(&copy, 5000);
    assert_int_not_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
}

/* Every refusal leaves the target as it was (its hash and its step count). */
static void expect_refused(const unsigned char *bytes, size_t size, bs_status want)
{
    const uint32_t hash = bs_sim_hash(&copy);
    const uint64_t steps = bs_sim_steps(&copy);
    assert_int_equal(bs_sim_restore(&copy, bytes, size), want);
    assert_int_equal(bs_sim_hash(&copy), hash);
    assert_true(bs_sim_steps(&copy) == steps);
}

static void test_bad_checkpoints_are_refused_and_change_nothing(void **state)
{
    unsigned char forged[sizeof buffer];
    uint32_t word;
    bs_real nan = BS_R(0.0);
    size_t at;
    (void)state;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    run(&sim, 2000);
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE - 1), BS_E_CHECKPOINT_SIZE);
    assert_int_equal(bs_sim_save(&sim, NULL, BS_CHECKPOINT_SIZE), BS_E_NULL);
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.6)), BS_OK);
    run(&copy, 10);

    expect_refused(buffer, BS_CHECKPOINT_SIZE - 1, BS_E_CHECKPOINT_SIZE); /* truncated */
    expect_refused(buffer, 3, BS_E_CHECKPOINT_SIZE);
    assert_int_equal(bs_sim_restore(&copy, NULL, BS_CHECKPOINT_SIZE), BS_E_NULL);

    memcpy(forged, buffer, sizeof forged); /* another byte order, or not a checkpoint */
    forged[0] ^= 0xffu;
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_DAMAGED);
    memcpy(forged, buffer, sizeof forged); /* one bit of the state flipped */
    forged[BS_CHECKPOINT_SIZE / 2] ^= 0x10u;
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_DAMAGED);

    memcpy(forged, buffer, sizeof forged); /* another build: precision, switches or modes */
    memcpy(&word, forged + 8, 4);
    word ^= 1u << 15;
    memcpy(forged + 8, &word, 4);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_BUILD);
    memcpy(forged, buffer, sizeof forged); /* another version */
    memcpy(&word, forged + 12, 4);
    word += 1;
    memcpy(forged + 12, &word, 4);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_BUILD);
    memcpy(forged, buffer, sizeof forged); /* a checkpoint that records another size */
    memcpy(&word, forged + 20, 4);
    word += 8;
    memcpy(forged + 20, &word, 4);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SIZE);

    /* a state no step produces: x_C = NaN behind a valid checksum */
    at = 6 * 4 + 5 * 4 + 3 * 8 + (5 + 2 * BS_MAX_MODES) * sizeof(bs_real);
    nan = nan / nan;
    memcpy(forged, buffer, sizeof forged);
    memcpy(forged + at, &nan, sizeof nan);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);

    /* another scene (one friction coefficient apart), another model */
    assert_int_equal(bs_sim_init(&copy, &other_scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    expect_refused(buffer, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_PCS, BS_R(0.3)), BS_OK);
    expect_refused(buffer, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);

    /* the untouched checkpoint still restores, into a larger buffer too */
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_restore(&copy, buffer, sizeof buffer), BS_OK);
    assert_int_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
}

/* The slider driven hard into the left clamp stop ends its steps a hair
 * beyond it (Moreau's step penetrates by about |u| dt): such a state must
 * save and restore, and continue identically. */
static void test_state_beyond_a_clamp_stop_restores(void **state)
{
    bs_real slider[3], velocity[3] = {BS_R(-2.0), BS_R(0.0), BS_R(0.0)};
    int beyond = 0;
    long k;
    (void)state;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_get_state(&sim, NULL, NULL, slider, NULL), BS_OK);
    slider[0] = scene.stop_min + BS_R(3e-6); /* x_M = stop - 17 um: the impact ends the step beyond it */
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, slider, velocity), BS_OK);
    for (k = 0; k < 20 && !beyond; ++k) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_get_state(&sim, NULL, NULL, slider, NULL), BS_OK);
        beyond = slider[0] < scene.stop_min;
    }
    print_message("%s: x_C - stop_min = %.3e m after %ld steps\n", BS_REAL_NAME,
                  (double)(slider[0] - scene.stop_min), k);
    assert_true(beyond);
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    assert_int_equal(bs_sim_restore(&copy, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    run(&sim, 500);
    run(&copy, 500);
    assert_int_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
}

/* Offsets in a checkpoint (core/src/bs_checkpoint.c, "Layout"): the header,
 * model and report counts (u32), step, phase, phase_step_half (u64), then the
 * reals in order. */
#define AT_COUNTS (6 * 4 + 4)
#define AT_STEP (6 * 4 + 5 * 4)
#define AT_PHASE_STEP (AT_STEP + 2 * 8)
#define AT_REALS (AT_STEP + 3 * 8)
enum {
    REAL_X_PCS = 0, REAL_FREQUENCY = 1, REAL_AMPLITUDE = 2, REAL_STEP_ACCEL = 3, REAL_BASE_ACCEL = 4,
    REAL_MU = 5, REAL_E_N = 6, REAL_Q = 7, REAL_U = 7 + BS_MAX_MODES, REAL_SLIDER = 7 + 2 * BS_MAX_MODES,
    REAL_X_LOW = 13 + 2 * BS_MAX_MODES, REAL_PERCUSSION = 14 + 2 * BS_MAX_MODES,
    REAL_RESIDUAL = REAL_PERCUSSION + BS_MAX_CONTACTS * BS_ROWS
};

/* buffer with real number `index` replaced by value, resealed: refused as
 * a state this sim cannot take, and nothing changes. */
static void expect_real_refused(int index, bs_real value, const char *what)
{
    unsigned char forged[sizeof buffer];
    memcpy(forged, buffer, sizeof forged);
    memcpy(forged + AT_REALS + (size_t)index * sizeof(bs_real), &value, sizeof value);
    reseal(forged);
    print_message("refused: %s\n", what);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);
}

static bs_real saved_real(int index)
{
    bs_real value;
    memcpy(&value, buffer + AT_REALS + (size_t)index * sizeof(bs_real), sizeof value);
    return value;
}

/* A checksum recomputed after an edit passes the damage check: what stands
 * behind it are the setters' rules and the step's invariants, each tried
 * here on its own. */
static void test_edited_checkpoints_break_no_rule(void **state)
{
    unsigned char forged[sizeof buffer];
    uint64_t word64;
    uint32_t word;
    unsigned active;
    bs_step_report report;
    int k, idle = -1;
    (void)state;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_set_excitation(&sim, BS_R(118.0), BS_R(12.0)), BS_OK);
    do { /* a step with a contact, so that its percussions are not all 0 */
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(bs_sim_get_report(&sim, &report), BS_OK);
    } while (report.active == 0 || (report.active & 0xfu) == 0xfu);
    active = report.active;
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.6)), BS_OK);

    /* bs_sim_set_state's rules: the slider's position band */
    expect_real_refused(REAL_SLIDER, scene.stop_min - BS_R(2.0) * scene.half_thickness, "x_C before the left stop");
    expect_real_refused(REAL_SLIDER, scene.length, "x_C at the right clamp");
    expect_real_refused(REAL_U + 1, (bs_real)INFINITY, "an infinite modal velocity");
    expect_real_refused(REAL_Q + BS_MAX_MODES - 1, BS_R(1e-3), "a mode the scene does not have");
    expect_real_refused(REAL_X_LOW, BS_R(1e-3) * saved_real(REAL_SLIDER), "x_C's remainder above its ulp");
    /* bs_sim_set_excitation's rules and what it derives */
    expect_real_refused(REAL_FREQUENCY, BS_R(-118.0), "a negative frequency");
    expect_real_refused(REAL_FREQUENCY, BS_R(1.0) / scene.dt, "a frequency beyond Nyquist");
    expect_real_refused(REAL_FREQUENCY, BS_R(119.0), "a frequency its phase step does not match");
    expect_real_refused(REAL_AMPLITUDE, BS_R(-12.0), "a negative amplitude");
    expect_real_refused(REAL_AMPLITUDE, BS_R(13.0), "an amplitude its step amplitude does not match");
    expect_real_refused(REAL_STEP_ACCEL, BS_R(2.0) * saved_real(REAL_STEP_ACCEL), "a step amplitude off");
    expect_real_refused(REAL_X_PCS, BS_R(2.0) * scene.length, "a PCS position off the beam");
    /* bs_sim_set_contact_laws's rules */
    expect_real_refused(REAL_MU, BS_R(-0.1), "a negative friction coefficient");
    expect_real_refused(REAL_MU, (bs_real)NAN, "a friction coefficient not a number");
    expect_real_refused(REAL_E_N, BS_R(1.5), "a restitution above 1");
    memcpy(forged, buffer, sizeof forged); /* a super-Nyquist phase step behind a matching frequency */
    word64 = (uint64_t)1 << 62;
    memcpy(forged + AT_PHASE_STEP, &word64, 8);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);
    /* the step count at its maximum: one more step would wrap it */
    memcpy(forged, buffer, sizeof forged);
    word64 = UINT64_MAX;
    memcpy(forged + AT_STEP, &word64, 8);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);
    /* the report and the percussions as the step leaves them */
    for (k = 0; k < BS_CORNERS && idle < 0; ++k)
        if (!(active >> k & 1u))
            idle = k;
    assert_true(idle >= 0);
    expect_real_refused(REAL_PERCUSSION + BS_ROWS * idle, BS_R(1e-6), "a percussion at a contact not active");
    expect_real_refused(REAL_RESIDUAL, BS_R(-2.0), "a negative residual");
    memcpy(forged, buffer, sizeof forged); /* converged = 2 */
    word = 2;
    memcpy(forged + AT_COUNTS + 3 * 4, &word, 4);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);
    memcpy(forged, buffer, sizeof forged); /* a seventh contact */
    word = 1u << BS_MAX_CONTACTS;
    memcpy(forged + AT_COUNTS, &word, 4);
    reseal(forged);
    expect_refused(forged, BS_CHECKPOINT_SIZE, BS_E_CHECKPOINT_SCENE);

    /* and the checkpoint as saved restores */
    assert_int_equal(bs_sim_restore(&copy, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_hash(&copy), bs_sim_hash(&sim));
}

/* A failed step changes nothing, its report included: a checkpoint taken
 * after it restores. */
static void test_failed_step_leaves_a_restorable_sim(void **state)
{
    bs_real u[BS_MAX_MODES] = {BS_R(0.0)};
    bs_step_report before, after;
    (void)state;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    run(&sim, 300);
    assert_int_equal(bs_sim_get_report(&sim, &before), BS_OK);
    u[0] = BS_R(1e18); /* beyond the explicit limit at the midpoint: BS_E_UNSTABLE or worse */
    assert_int_equal(bs_sim_set_state(&sim, NULL, u, NULL, NULL), BS_OK);
    assert_true(bs_sim_step(&sim) != BS_OK);
    assert_int_equal(bs_sim_get_report(&sim, &after), BS_OK);
    assert_true(after.active == before.active && after.sweeps == before.sweeps && after.systems == before.systems
                && after.converged == before.converged);
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    assert_int_equal(bs_sim_restore(&copy, buffer, BS_CHECKPOINT_SIZE), BS_OK);
}

/* A contact problem that overflows (the fuzzed scene of the seed
 * tests/fuzz/corpus/fuzz_step/regress-restore-nan-residual: a slider mass of
 * 1 / DBL_MAX, which bs_scene_check takes, gives an infinite Delassus
 * diagonal) leaves an unconverged report whose residual is not a number, or
 * infinite, after a step that returns BS_OK with a finite state. Such a
 * checkpoint restores (restore refused it: found by fuzz_step); such a
 * residual in a report that says converged is no step's. */
static void test_unconverged_report_that_is_not_a_number_restores(void **state)
{
    static const struct {
        double residual;
        uint32_t converged;
        bs_status status;
    } reports[] = {
        { (double)NAN, 0, BS_OK },
        { (double)INFINITY, 0, BS_OK },
        { (double)NAN, 1, BS_E_CHECKPOINT_SCENE },
        { (double)INFINITY, 1, BS_E_CHECKPOINT_SCENE },
        { -(double)INFINITY, 0, BS_E_CHECKPOINT_SCENE },
    };
    unsigned char forged[sizeof buffer];
    size_t k;
    (void)state;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    run(&sim, 400);
    assert_int_equal(bs_sim_save(&sim, buffer, BS_CHECKPOINT_SIZE), BS_OK);
    for (k = 0; k < sizeof reports / sizeof reports[0]; ++k) {
        const bs_real residual = (bs_real)reports[k].residual;
        memcpy(forged, buffer, sizeof forged);
        memcpy(forged + AT_REALS + (size_t)REAL_RESIDUAL * sizeof(bs_real), &residual, sizeof residual);
        memcpy(forged + AT_COUNTS + 3 * 4, &reports[k].converged, 4);
        reseal(forged);
        assert_int_equal(bs_sim_init(&copy, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
        print_message("residual %g, converged %u\n", (double)residual, (unsigned)reports[k].converged);
        assert_int_equal(bs_sim_restore(&copy, forged, BS_CHECKPOINT_SIZE), reports[k].status);
    }
}

static void test_scene_hash_tells_scenes_apart(void **state)
{
    (void)state;
    assert_true(bs_scene_hash(&scene) != bs_scene_hash(&other_scene));
    assert_true(bs_scene_hash(&scene) != bs_scene_hash(&resistor_scene));
    assert_true(bs_scene_hash(&scene) == bs_scene_hash(&scene));
    assert_true(bs_scene_hash(NULL) == 0);
}

static int setup(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    file.params.load = SCENE_LOAD_RESISTOR;
    support_build(&file, &resistor_scene, &model);
    file.params.load = SCENE_LOAD_NONE;
    file.params.mu *= 1.25;
    support_build(&file, &other_scene, &model);
    file.params.mu /= 1.25;
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_restored_run_continues_bit_for_bit),
        cmocka_unit_test(test_transducer_state_is_restored),
        cmocka_unit_test(test_excitation_settings_are_restored),
        cmocka_unit_test(test_contact_laws_are_restored),
        cmocka_unit_test(test_bad_checkpoints_are_refused_and_change_nothing),
        cmocka_unit_test(test_state_beyond_a_clamp_stop_restores),
        cmocka_unit_test(test_edited_checkpoints_break_no_rule),
        cmocka_unit_test(test_failed_step_leaves_a_restorable_sim),
        cmocka_unit_test(test_unconverged_report_that_is_not_a_number_restores),
        cmocka_unit_test(test_scene_hash_tells_scenes_apart),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
