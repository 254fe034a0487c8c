/* solve_tally.h - what the contact solves of a run did, step report by step
 * report: the figures the JSON summaries and the sweep CSV end with. */
#ifndef SOLVE_TALLY_H
#define SOLVE_TALLY_H

#include <stdint.h>
#include "beamslider.h"

typedef struct solve_tally {
    uint64_t contact_steps;     /* steps with at least one active contact */
    uint64_t unconverged_steps; /* contact steps the solve reported unconverged */
    uint64_t sweeps;            /* Gauss-Seidel sweeps over the contact steps */
    uint64_t systems;           /* active-set systems over the contact steps */
    int max_sweeps;             /* most sweeps in one step */
    int max_systems;            /* most systems in one step */
} solve_tally;

void solve_tally_clear(solve_tally *tally);

/* Counts the report of one step (nothing when no contact was active). */
void solve_tally_add(solve_tally *tally, const bs_step_report *report);

/* Adds the counts of part to tally. */
void solve_tally_merge(solve_tally *tally, const solve_tally *part);

/* Mean sweeps and systems per contact step (0 without contact steps). */
double solve_tally_mean_sweeps(const solve_tally *tally);
double solve_tally_mean_systems(const solve_tally *tally);

#endif
