/* outcome.h - what a free run did, as one of a few classes, by documented
 * rules on its per-period trajectory (docs/maps.md section 2).
 *
 * The rules are those of docs/validation.md section 7 (which the papers'
 * six scenarios are checked against), plus a fault and a slider at a clamp
 * stop. They work on the 1 s centred moving averages A(t) of the amplitude
 * (w(4L/7) / h, per excitation period) and S(t) of the position s, over the
 * periods whose whole window lies in the run:
 *   rise:  A goes above OUTCOME_HIGH (0.5 h), from the start or from below
 *          OUTCOME_LOW; fall: A goes back below OUTCOME_LOW (0.25 h);
 *          a rise and a fall are one cycle.
 * In this order, the first that holds (the rules are the rows of
 * outcome_classes.h, tried by their precedence):
 *   fault                   the run stopped before t_end (a core status)
 *   slider at a stop        the mean s over the last OUTCOME_WINDOW (10 s)
 *                           lies within OUTCOME_WALK (0.005) of a clamp stop
 *   relaxation oscillation  at least two complete cycles
 *   signature move          no fall; before the first rise S fell more than
 *                           OUTCOME_WALK below s0, after it S walks back more
 *                           than OUTCOME_WALK above its minimum
 *   trivial adaptation      no fall; S walks one way only (its largest
 *                           retreat against its way below OUTCOME_WALK) and
 *                           the mean amplitude over the last 10 s is above
 *                           OUTCOME_HIGH
 *   self-damping            A never exceeds OUTCOME_LOW and the mean
 *                           amplitude over the last 10 s is below
 *                           OUTCOME_DAMPED (0.05 h)
 *   other                   none of these (a run too short for a 1 s
 *                           average, a single cycle, an amplitude between
 *                           the branches, ...)
 * (A rise is also needed for trivial adaptation: with a 1 s average above
 * 0.5 h it always happens.)
 * The thresholds are those docs/validation.md chose for the scenarios;
 * they were frozen before the maps of docs/maps.md were run.
 */
#ifndef OUTCOME_H
#define OUTCOME_H

#include <stddef.h>
#include "outcome_classes.h"

#define OUTCOME_LOW 0.25     /* [h] the low branch stays below */
#define OUTCOME_HIGH 0.5     /* [h] the high branch stays above */
#define OUTCOME_DAMPED 0.05  /* [h] self-damped: the last 10 s below */
#define OUTCOME_WALK 0.005   /* smallest walk of s counted (a sweep grid step) */
#define OUTCOME_WINDOW 10.0  /* [s] the settled figures: the run's last 10 s */
#define OUTCOME_AVERAGE 1.0  /* [s] the moving average's window */

#define OUTCOME_ENUM(id, name, label, colour, precedence, rule) OUTCOME_##id,
typedef enum outcome_class {
    OUTCOME_CLASS_TABLE(OUTCOME_ENUM)
    OUTCOME_CLASSES          /* the number of classes */
} outcome_class;
#undef OUTCOME_ENUM

/* A run's per-period trajectory (run_periods_header: t, amp_h, s; t the
 * end of each period) and what the rules need besides. */
typedef struct outcome_input {
    const double *t, *amp_h, *s;
    size_t periods;
    double s0;                /* the start */
    double stop_min, stop_max; /* the clamp stops as s (x_C / L) */
    int completed;            /* 1: the run reached t_end */
    double duration;          /* the run's simulated time [s] (0: the last period's end) */
} outcome_input;

/* The figures the rules use, and the class. */
typedef struct outcome_figures {
    outcome_class outcome;
    double s_settled;     /* mean s over the settled window */
    double amp_settled;   /* mean amplitude [h] over the settled window */
    double window;        /* the settled window [s]: the run's last OUTCOME_WINDOW (10 s), or the
                             whole run if shorter (0 without a period) */
    double amp_max;       /* largest A [h] (0 when the run has no 1 s average) */
    int averages;         /* 1 s averages (periods whose window lies in the run) */
    int rises, falls;     /* of A; cycles = falls */
    double first_fall;    /* how far S fell below s0 before the first rise */
    double walk_back;     /* how far S rose above its minimum after the first rise */
    double retreat;       /* the smaller of S's largest drop below its running
                             maximum and largest rise above its running minimum */
    double v_last;        /* transport speed over the last 10 s [1/s]: change of S
                             over that span / the span (0 without two averages) */
    double v_peak;        /* the fastest transport: the largest |S(t + 1 s) - S(t)| / 1 s,
                             with its sign [1/s] */
} outcome_figures;

/* Applies the rules; returns the class (also in figures). The arrays may
 * be empty (periods 0): then only fault, stop or other. */
outcome_class outcome_classify(const outcome_input *input, outcome_figures *figures);

/* The class's name in tables ("trivial", "signature", "relaxation",
 * "self_damping", "stop", "fault", "other"), in prose, its colour in
 * map-plot and its rule in words (outcome_classes.h); "?" for a value
 * that is no class. */
const char *outcome_name(outcome_class outcome);
const char *outcome_label(outcome_class outcome);
const char *outcome_colour(outcome_class outcome);
const char *outcome_rule(outcome_class outcome);

/* The class of a table name, -1 if none. */
int outcome_from_name(const char *name);

#endif
