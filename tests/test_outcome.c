/* test_outcome.c - the outcome classes of a free run (host/lib/map/outcome.c):
 * each rule of outcome.h on a made-up trajectory that just meets it and one
 * that just misses it, the rules' order, the 1 s averages and the settled
 * figures. (The six scenarios of the papers are classified from real runs
 * by tests/check_map.sh.) */
#include "support.h"

#include <math.h>
#include <string.h>
#include "outcome.h"

#define RATE 100.0           /* periods per second of the made-up runs */
#define MAX_PERIODS 20000

static double t[MAX_PERIODS], amp[MAX_PERIODS], s[MAX_PERIODS];

/* A trajectory of duration seconds: amplitude and position as functions of t. */
typedef double (*curve)(double time);

static outcome_input make(double duration, curve amplitude, curve position, double s0)
{
    outcome_input in;
    size_t i;
    memset(&in, 0, sizeof in);
    in.periods = (size_t)(duration * RATE + 0.5);
    assert_true(in.periods <= MAX_PERIODS);
    for (i = 0; i < in.periods; ++i) {
        t[i] = (double)(i + 1) / RATE;
        amp[i] = amplitude(t[i]);
        s[i] = position(t[i]);
    }
    in.t = t;
    in.amp_h = amp;
    in.s = s;
    in.s0 = s0;
    in.stop_min = 0.0357;
    in.stop_max = 1.0 - 0.0357;
    in.completed = 1;
    return in;
}

static outcome_class classify(const outcome_input *in, outcome_figures *f)
{
    return outcome_classify(in, f);
}

/* ---- trivial adaptation: a monotone walk up to the high branch */
static double rising_amp(double time) { return time < 5.0 ? 0.1 + 0.16 * time : 0.9; }
static double walking_up(double time) { return 0.3 + 0.07 * (1.0 - exp(-time / 20.0)); }
static double walking_up_with_retreat(double time)
{
    return walking_up(time) - (time > 30.0 && time < 40.0 ? 0.012 * sin((time - 30.0) * 3.14159265 / 10.0) : 0.0);
}

static void test_a_monotone_walk_to_the_high_branch_is_trivial(void **state)
{
    outcome_figures f;
    outcome_input in = make(60.0, rising_amp, walking_up, 0.3);
    (void)state;
    assert_int_equal(classify(&in, &f), OUTCOME_TRIVIAL);
    assert_int_equal(f.rises, 1);
    assert_int_equal(f.falls, 0);
    assert_true(f.retreat < 1e-9);
    assert_close("amp_settled", f.amp_settled, 0.9, 1e-12, 0.0);
    /* mean s over the periods that end in the last 10 s: [50, 60] */
    {
        double mean = 0.0;
        int i, n = 0;
        for (i = 4999; i < 6000; ++i, ++n)
            mean += walking_up((double)(i + 1) / RATE);
        assert_close("s_settled", f.s_settled, mean / n, 1e-12, 0.0);
    }
    /* a retreat of about 0.01 against the walk: not one way only */
    in = make(60.0, rising_amp, walking_up_with_retreat, 0.3);
    assert_int_equal(classify(&in, &f), OUTCOME_OTHER);
    assert_true(f.retreat > OUTCOME_WALK);
}

/* ---- signature move: drift to the clamp on the low branch, jump, walk back */
static double signature_amp(double time) { return time < 8.0 ? 0.15 : 1.2; }
static double signature_s(double time) { return time < 8.0 ? 0.3 - 0.005 * time : 0.26 + 0.002 * (time - 8.0); }
static double small_drift_s(double time) { return time < 8.0 ? 0.3 - 0.0005 * time : 0.296 + 0.002 * (time - 8.0); }

static void test_drift_jump_and_walk_back_is_a_signature_move(void **state)
{
    outcome_figures f;
    outcome_input in = make(40.0, signature_amp, signature_s, 0.3);
    (void)state;
    assert_int_equal(classify(&in, &f), OUTCOME_SIGNATURE);
    assert_true(f.first_fall > 0.035 && f.first_fall < 0.041);
    assert_true(f.walk_back > 0.05);
    assert_close("v_last [1/s]", f.v_last, 0.002, 1e-9, 1e-6);
    assert_close("v_peak [1/s]", f.v_peak, -0.005, 1e-9, 0.05);
    /* a drift of 0.004 toward the clamp is not counted: one way, so trivial */
    in = make(40.0, signature_amp, small_drift_s, 0.3);
    assert_int_equal(classify(&in, &f), OUTCOME_TRIVIAL);
    assert_true(f.first_fall < OUTCOME_WALK);
}

/* ---- relaxation oscillation: two cycles and more */
static double cycling_amp(double time) { return fmod(time, 20.0) < 10.0 ? 0.1 : 1.1; }
static double one_cycle_amp(double time) { return time > 10.0 && time < 20.0 ? 1.1 : 0.1; }
static double still(double time) { (void)time; return 0.3; }

static void test_repeated_cycles_are_a_relaxation_oscillation(void **state)
{
    outcome_figures f;
    outcome_input in = make(60.0, cycling_amp, still, 0.3);
    (void)state;
    assert_int_equal(classify(&in, &f), OUTCOME_RELAXATION);
    assert_int_equal(f.rises, 3);
    assert_int_equal(f.falls, 2); /* the last rise has no fall inside the run */
    in = make(60.0, one_cycle_amp, still, 0.3);
    assert_int_equal(classify(&in, &f), OUTCOME_OTHER);
    assert_int_equal(f.falls, 1);
}

/* ---- self-damping: the amplitude never leaves the low branch and dies */
static double dying_amp(double time) { return 0.06 * exp(-time / 10.0); }
static double low_amp(double time) { (void)time; return 0.06; }
static double drifting_down(double time) { return 0.3 - 0.002 * time; }

static void test_a_tiny_dying_amplitude_is_self_damping(void **state)
{
    outcome_figures f;
    outcome_input in = make(60.0, dying_amp, drifting_down, 0.3);
    (void)state;
    assert_int_equal(classify(&in, &f), OUTCOME_SELF_DAMPING);
    assert_true(f.amp_max < OUTCOME_LOW);
    assert_true(f.amp_settled < OUTCOME_DAMPED);
    /* low, but not dying below 0.05 h */
    in = make(60.0, low_amp, drifting_down, 0.3);
    assert_int_equal(classify(&in, &f), OUTCOME_OTHER);
}

/* ---- a stop, a fault, and a run too short for the rules */
static double to_the_stop(double time) { return time < 30.0 ? 0.3 - 0.009 * time : 0.0357 + 0.004; }
static double near_the_stop(double time) { return time < 30.0 ? 0.3 - 0.008 * time : 0.0357 + 0.006; }

static void test_stop_and_fault_come_first(void **state)
{
    outcome_figures f;
    outcome_input in = make(60.0, dying_amp, to_the_stop, 0.3);
    (void)state;
    assert_int_equal(classify(&in, &f), OUTCOME_STOP);
    in = make(60.0, dying_amp, near_the_stop, 0.3);
    assert_int_equal(classify(&in, &f), OUTCOME_SELF_DAMPING);
    /* the right-hand stop too */
    in = make(60.0, rising_amp, walking_up, 0.3);
    in.stop_max = 0.37;
    assert_int_equal(classify(&in, &f), OUTCOME_STOP);
    /* a run that stopped is a fault, whatever it did before */
    in = make(60.0, cycling_amp, still, 0.3);
    in.completed = 0;
    assert_int_equal(classify(&in, &f), OUTCOME_FAULT);
    in.periods = 0;
    assert_int_equal(classify(&in, &f), OUTCOME_FAULT);
    assert_true(isnan(f.s_settled));
}

static double tiny_amp(double time) { (void)time; return 0.01; }

static void test_a_run_without_a_1_s_average_is_other(void **state)
{
    outcome_figures f;
    outcome_input in = make(0.9, rising_amp, walking_up, 0.3);
    (void)state;
    assert_int_equal(classify(&in, &f), OUTCOME_OTHER);
    assert_int_equal(f.averages, 0);
    in = make(1.0, tiny_amp, still, 0.3); /* one window: t = 0.5 (the periods end at 0.01 .. 1 s) */
    assert_int_equal(classify(&in, &f), OUTCOME_SELF_DAMPING);
    assert_int_equal(f.averages, 1);
}

static void test_names_read_back(void **state)
{
    int k;
    (void)state;
    for (k = 0; k < OUTCOME_CLASSES; ++k) {
        assert_int_equal(outcome_from_name(outcome_name((outcome_class)k)), k);
        assert_null(strchr(outcome_name((outcome_class)k), ','));
    }
    assert_int_equal(outcome_from_name("chaos"), -1);
    assert_string_equal(outcome_label(OUTCOME_SIGNATURE), "signature move");
}

/* The table (outcome_classes.h): every class a colour "#rrggbb" of its own
 * and a rule in words, the precedences 1 .. N each once, and the class that
 * always holds (other) tried last. */
static void test_the_class_table_is_whole(void **state)
{
    int k, j, seen[OUTCOME_CLASSES + 1] = { 0 };
    (void)state;
    for (k = 0; k < OUTCOME_CLASSES; ++k) {
        const char *colour = outcome_colour((outcome_class)k);
        assert_int_equal(strlen(colour), 7);
        assert_int_equal(colour[0], '#');
        assert_int_equal(strspn(colour + 1, "0123456789abcdef"), 6);
        assert_true(strlen(outcome_rule((outcome_class)k)) > 10);
        for (j = 0; j < k; ++j)
            assert_string_not_equal(colour, outcome_colour((outcome_class)j));
    }
    assert_string_equal(outcome_colour((outcome_class)OUTCOME_CLASSES), "?");
#define SEEN(id, name, label, colour, precedence, rule) \
    assert_true(precedence >= 1 && precedence <= OUTCOME_CLASSES && !seen[precedence]++);
    OUTCOME_CLASS_TABLE(SEEN)
#undef SEEN
#define LAST(id, name, label, colour, precedence, rule) \
    if (OUTCOME_##id == OUTCOME_OTHER)                   \
        assert_int_equal(precedence, OUTCOME_CLASSES);
    OUTCOME_CLASS_TABLE(LAST)
#undef LAST
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_monotone_walk_to_the_high_branch_is_trivial),
        cmocka_unit_test(test_drift_jump_and_walk_back_is_a_signature_move),
        cmocka_unit_test(test_repeated_cycles_are_a_relaxation_oscillation),
        cmocka_unit_test(test_a_tiny_dying_amplitude_is_self_damping),
        cmocka_unit_test(test_stop_and_fault_come_first),
        cmocka_unit_test(test_a_run_without_a_1_s_average_is_other),
        cmocka_unit_test(test_names_read_back),
        cmocka_unit_test(test_the_class_table_is_whole),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
