/* outcome.c - the outcome classes of a free run (outcome.h states the rules;
 * docs/maps.md section 2 why these). The 1 s averages follow
 * host/reports/figures/smooth.awk and the figures scenario.awk, which
 * docs/validation.md section 7 uses on the same scenarios. */
#include "outcome.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The table's columns, by class. */
#define OUTCOME_NAME(id, name, label, colour, precedence, rule) #name,
#define OUTCOME_LABEL(id, name, label, colour, precedence, rule) label,
#define OUTCOME_COLOUR(id, name, label, colour, precedence, rule) colour,
#define OUTCOME_PRECEDENCE(id, name, label, colour, precedence, rule) precedence,
#define OUTCOME_RULE(id, name, label, colour, precedence, rule) rule,
static const char *const names[OUTCOME_CLASSES] = { OUTCOME_CLASS_TABLE(OUTCOME_NAME) };
static const char *const labels[OUTCOME_CLASSES] = { OUTCOME_CLASS_TABLE(OUTCOME_LABEL) };
static const char *const colours[OUTCOME_CLASSES] = { OUTCOME_CLASS_TABLE(OUTCOME_COLOUR) };
static const int precedences[OUTCOME_CLASSES] = { OUTCOME_CLASS_TABLE(OUTCOME_PRECEDENCE) };
static const char *const rules[OUTCOME_CLASSES] = { OUTCOME_CLASS_TABLE(OUTCOME_RULE) };

static int is_class(outcome_class outcome)
{
    return outcome >= 0 && outcome < OUTCOME_CLASSES;
}

const char *outcome_name(outcome_class outcome)
{
    return is_class(outcome) ? names[outcome] : "?";
}

const char *outcome_label(outcome_class outcome)
{
    return is_class(outcome) ? labels[outcome] : "?";
}

const char *outcome_colour(outcome_class outcome)
{
    return is_class(outcome) ? colours[outcome] : "?";
}

const char *outcome_rule(outcome_class outcome)
{
    return is_class(outcome) ? rules[outcome] : "?";
}

int outcome_from_name(const char *name)
{
    int i;
    for (i = 0; i < OUTCOME_CLASSES; ++i)
        if (!strcmp(name, names[i]))
            return i;
    return -1;
}

/* Means of amp_h and s over the periods that end within the settled
 * window, the last OUTCOME_WINDOW seconds (scenario.awk's amp_last10), or
 * the whole run when it is shorter. */
static void last_window(const outcome_input *in, outcome_figures *f)
{
    const double from = in->t[in->periods - 1] - OUTCOME_WINDOW;
    double amp = 0.0, s = 0.0;
    size_t i, n = 0;

    for (i = 0; i < in->periods; ++i)
        if (in->t[i] >= from) {
            amp += in->amp_h[i];
            s += in->s[i];
            ++n;
        }
    f->amp_settled = amp / (double)n;
    f->s_settled = s / (double)n;
    {
        const double duration = in->duration > 0.0 ? in->duration : in->t[in->periods - 1];
        f->window = duration < OUTCOME_WINDOW ? duration : OUTCOME_WINDOW;
    }
}

/* The figures of the 1 s centred moving averages: a running window
 * [t - 1/2, t + 1/2] over the periods, kept only where it lies inside
 * [0, t_last] (smooth.awk). */
static void averaged_figures(const outcome_input *in, outcome_figures *f)
{
    const double half = 0.5 * OUTCOME_AVERAGE;
    const double t_last = in->t[in->periods - 1];
    double sum_a = 0.0, sum_s = 0.0;
    double run_max = 0.0, run_min = 0.0, min_after = HUGE_VAL;
    double drop = 0.0, rise = 0.0;
    double *s_avg = malloc(in->periods * sizeof *s_avg);
    double *t_avg = malloc(in->periods * sizeof *t_avg);
    size_t lo = 0, hi = 0, i, n = 0, back = 0;
    int high = 0;

    if (!s_avg || !t_avg) { /* out of memory: no averages, as for a short run */
        free(s_avg);
        free(t_avg);
        return;
    }
    for (i = 0; i < in->periods; ++i) {
        double a, s;
        while (hi < in->periods && in->t[hi] <= in->t[i] + half) {
            sum_a += in->amp_h[hi];
            sum_s += in->s[hi];
            ++hi;
        }
        while (in->t[lo] < in->t[i] - half) {
            sum_a -= in->amp_h[lo];
            sum_s -= in->s[lo];
            ++lo;
        }
        if (in->t[i] - half < 0.0 || in->t[i] + half > t_last)
            continue;
        a = sum_a / (double)(hi - lo);
        s = sum_s / (double)(hi - lo);
        if (n == 0)
            run_max = run_min = s;
        t_avg[n] = in->t[i];
        s_avg[n++] = s;
        ++f->averages;
        if (a > f->amp_max)
            f->amp_max = a;
        if (!high && a > OUTCOME_HIGH) {
            high = 1;
            ++f->rises;
        } else if (high && a < OUTCOME_LOW) {
            high = 0;
            ++f->falls;
        }
        if (s > run_max)
            run_max = s;
        if (s < run_min)
            run_min = s;
        if (run_max - s > drop)
            drop = run_max - s;
        if (s - run_min > rise)
            rise = s - run_min;
        if (f->rises == 0 && in->s0 - s > f->first_fall)
            f->first_fall = in->s0 - s;
        if (f->rises >= 1) {
            if (s < min_after)
                min_after = s;
            if (s - min_after > f->walk_back)
                f->walk_back = s - min_after;
        }
    }
    f->retreat = drop < rise ? drop : rise;
    if (n >= 2) {
        /* the last 10 s: from the first average at or after t_end - 10 s - 1/2 */
        size_t from = 0;
        while (from + 1 < n && t_avg[from] < t_avg[n - 1] - OUTCOME_WINDOW)
            ++from;
        f->v_last = (s_avg[n - 1] - s_avg[from]) / (t_avg[n - 1] - t_avg[from]);
        for (i = 0; i < n; ++i) {
            double v;
            while (back + 1 < n && t_avg[back] < t_avg[i] - OUTCOME_AVERAGE)
                ++back;
            if (back >= i || t_avg[i] - t_avg[back] < 0.5 * OUTCOME_AVERAGE)
                continue;
            v = (s_avg[i] - s_avg[back]) / (t_avg[i] - t_avg[back]);
            if (fabs(v) > fabs(f->v_peak))
                f->v_peak = v;
        }
    }
    free(s_avg);
    free(t_avg);
}

/* The rules of outcome_classes.h, one function a class (holds_NAME): each
 * is asked only after every class of a higher precedence failed. */
static int holds_fault(const outcome_input *in, const outcome_figures *f)
{
    (void)f;
    return !in->completed;
}

static int holds_stop(const outcome_input *in, const outcome_figures *f)
{
    return in->periods > 0
           && (fabs(f->s_settled - in->stop_min) <= OUTCOME_WALK || fabs(f->s_settled - in->stop_max) <= OUTCOME_WALK);
}

static int holds_relaxation(const outcome_input *in, const outcome_figures *f)
{
    (void)in;
    return f->averages > 0 && f->falls >= 2;
}

static int holds_signature(const outcome_input *in, const outcome_figures *f)
{
    (void)in;
    return f->averages > 0 && f->falls == 0 && f->rises >= 1 && f->first_fall > OUTCOME_WALK
           && f->walk_back > OUTCOME_WALK;
}

static int holds_trivial(const outcome_input *in, const outcome_figures *f)
{
    (void)in;
    return f->averages > 0 && f->falls == 0 && f->rises >= 1 && f->retreat < OUTCOME_WALK
           && f->amp_settled > OUTCOME_HIGH;
}

static int holds_self_damping(const outcome_input *in, const outcome_figures *f)
{
    (void)in;
    return f->averages > 0 && f->amp_max < OUTCOME_LOW && f->amp_settled < OUTCOME_DAMPED;
}

static int holds_other(const outcome_input *in, const outcome_figures *f)
{
    (void)in;
    (void)f;
    return 1;
}

#define OUTCOME_HOLDS(id, name, label, colour, precedence, rule) holds_##name,
static int (*const holds[OUTCOME_CLASSES])(const outcome_input *, const outcome_figures *) = {
    OUTCOME_CLASS_TABLE(OUTCOME_HOLDS)
};

outcome_class outcome_classify(const outcome_input *in, outcome_figures *f)
{
    int rank, k;
    memset(f, 0, sizeof *f);
    f->s_settled = f->amp_settled = (double)NAN;
    if (in->periods > 0) {
        last_window(in, f);
        averaged_figures(in, f);
    }
    f->outcome = OUTCOME_OTHER;
    for (rank = 1; rank <= OUTCOME_CLASSES; ++rank)
        for (k = 0; k < OUTCOME_CLASSES; ++k)
            if (precedences[k] == rank && holds[k](in, f)) {
                f->outcome = (outcome_class)k;
                return f->outcome;
            }
    return f->outcome;
}
