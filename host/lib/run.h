/* run.h - one free or PCS run of a scene, with CSV output and summary. */
#ifndef RUN_H
#define RUN_H

#include <stdint.h>
#include <stdio.h>
#include "beamslider.h"
#include "solve_tally.h"

#define RUN_AMP_PERIODS 25 /* amplitude: mean over the last 25 excitation periods */

typedef struct run_options {
    bs_model model;
    double s0;           /* start position (PCS: prescribed position) */
    double t_end;        /* [s] */
    double dt;           /* the scene's step in double (time = step * dt) [s] */
    bs_solver_options solver; /* contact-solve settings */
    long every;          /* CSV row every this many steps */
    FILE *csv;           /* NULL: no CSV */
    FILE *periods;       /* NULL: no per-period CSV (run_periods_header) */
    int show_progress;   /* progress bar on a terminal */
} run_options;

typedef struct run_result {
    bs_status status;          /* BS_OK, or why the run stopped */
    int write_failed;          /* an output could not be written */
    int write_errno;           /* errno of the first failed write */
    uint64_t steps;            /* steps completed */
    double t;                  /* simulated time reached [s] */
    double s_final;
    double s_min, t_s_min;     /* turning point toward the clamp */
    double amp_final_h;        /* mean half peak-to-peak of w(4L/7) / h, last RUN_AMP_PERIODS periods */
    int amp_periods;           /* periods behind amp_final_h */
    double wall_s;
    solve_tally solve;         /* the contact solves */
    uint32_t hash;             /* bs_sim_hash of the final state */
} run_result;

/* Runs scene from rest for round(t_end / dt) steps. Returns 0 when the run
 * completed and its CSV was written, -1 otherwise (result says why). */
int run_scene(const bs_scene *scene, const run_options *options, run_result *result);

/* CSV header lines of run_scene's step rows and per-period rows. */
extern const char run_csv_header[];
extern const char run_periods_header[];

#endif
