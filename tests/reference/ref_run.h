/* ref_run.h - a run of the reference model with the CSV outputs of
 * `beamslider run` (host/lib/run/run.c formats, plus the transducer's columns)
 * and a summary. */
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
    const double *base_accel; /* NULL: the scene's excitation; else the mean base acceleration of
                                 outer step n (1-based) is base_accel[n - 1] [m/s^2], held for its
                                 K substeps (docs/model.md 10); at least round(t_end / dt) values */
    uint64_t base_accel_count;
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
    /* transducer (docs/model.md 11) */
    double load_energy;      /* energy into the load R_l or R_s [J] */
    double voltage_final;    /* v at the end [V] */
    double voltage_max;      /* max |v| over the run's outer steps [V] */
    double storage_voltage_final; /* V_s at the end [V] (rectifier) */
    uint64_t bridge_steps;   /* Moreau steps in which the bridge conducted (Q > 0) */
} ref_run_result;

/* Steps CSV: t, w(4L/7) [m], s = x_C/L, z_r = z_C - w0 [m], beta [rad],
 * contact bit mask (bits 0-3 P1..P4, 4-5 end stops), solver iterations,
 * residual [N s]; with a transducer also v [V] (patch voltage), p [W] (mean
 * power into the load R_l or R_s over the outer step) and v_s [V] (storage
 * voltage; 0 with a resistor). */
extern const char ref_run_csv_header[];
extern const char ref_run_csv_header_transducer[];
extern const char ref_run_periods_header[];

/* Runs the scene from docs/model.md 6's initial state (base frame,
 * docs/model.md 10). Returns 0, or -1 when a step failed or an output could
 * not be written (or base_accel holds too few values: r->failed). */
int ref_run(const ref_scene *scene, const ref_run_options *options, ref_run_result *result);

#endif
