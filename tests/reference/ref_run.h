/* ref_run.h - a run of the reference model with the CSV outputs of
 * `beamslider run` (host/lib/run.c formats) and a summary. */
#ifndef REF_RUN_H
#define REF_RUN_H

#include <stdint.h>
#include <stdio.h>
#include "ref_step.h"

#define REF_AMP_PERIODS 25   /* amp_final_h: mean over the last 25 periods */

typedef struct ref_run_options {
    double t_end;            /* [s]; round(t_end / dt) outer steps */
    long every;              /* steps CSV: a row every this many outer steps */
    FILE *csv;               /* NULL: none */
    FILE *periods;           /* NULL: none */
    ref_step_options step;
} ref_run_options;

typedef struct ref_run_result {
    int failed;              /* 1: a step failed (solve or non-finite state) */
    int write_failed;
    uint64_t steps;          /* outer steps done */
    double t;
    double s_final, s_min, t_s_min;
    double amp_final_h;
    int amp_periods;
    uint64_t periods;
    double wall_s;
    uint64_t contact_steps;  /* Moreau steps with a contact */
    uint64_t total_iters;
    long max_iters;
    uint64_t exhaustive_steps, ambiguous_steps, unconverged_steps;
    double max_residual_rel;
} ref_run_result;

/* Steps CSV: t, w(4L/7) [m], s = x_C/L, z_C [m], beta [rad], contact bit mask
 * (bits 0-3 P1..P4, 4-5 end stops), solver iterations, residual [N s]. */
extern const char ref_run_csv_header[];
extern const char ref_run_periods_header[];

/* Runs the scene from docs/model.md 6's initial state. Returns 0, or -1 when a
 * step failed or an output could not be written. */
int ref_run(const ref_scene *scene, const ref_run_options *options, ref_run_result *result);

#endif
