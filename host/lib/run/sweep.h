/* sweep.h - quasi-static PCS sweep with continuation (docs/model.md 6).
 *
 * One bs_sim in the PCS model, started from rest at the first grid point. At
 * each grid point s~ the prescribed position is moved (bs_sim_set_pcs_position,
 * the state is kept), `hold` excitation periods are integrated and `record`
 * more are measured. Periods are counted where the excitation phase wraps
 * (bs_monitor), so every grid point starts at the same excitation phase and
 * lasts an exact number of periods.
 */
#ifndef SWEEP_H
#define SWEEP_H

#include <stdint.h>
#include <stdio.h>
#include "beamslider.h"
#include "progress_hook.h"
#include "solve_tally.h"

#define SWEEP_MAX_POINTS 100001

/* One grid point of a sweep. */
typedef struct sweep_point {
    double s;                 /* prescribed position s~ = x / L */
    double amp_h;             /* mean over the recorded periods of the per-period half
                                 peak-to-peak of w(4L/7), / h */
    double v_mean;            /* x_C displacement over the recorded periods / (L N_rec),
                                 positive toward the beam centre */
    solve_tally solve;        /* the contact solves (hold + record) */
    uint64_t steps;           /* steps at this point (hold + record periods) */
} sweep_point;

typedef struct sweep_options {
    double from, to, step;    /* grid from + i step, i = 0 .. n-1; 0 <= from < to <= 1 */
    int down;                 /* 0: from -> to; 1: to -> from */
    int hold, record;         /* excitation periods per point: hold >= 0, record >= 1 */
    double dt;                /* the scene's step in double [s] (trace times) */
    bs_solver_options solver; /* contact-solve settings */
    FILE *csv;                /* NULL or one row per point (sweep_csv_header) */
    sweep_point *points;      /* NULL or room for sweep_grid_size() points, in sweep order */
    FILE *trace;              /* NULL or per-step rows (sweep_trace_header) at trace_index */
    int trace_index;          /* grid index i of the traced point (s = from + i step) */
    int trace_periods;        /* traced: the first trace_periods recorded periods, 1 .. record */
    progress_hook progress;   /* NULL, or told the part of the points done */
    void *progress_context;
} sweep_options;

typedef struct sweep_result {
    bs_status status;         /* BS_OK, or why the sweep stopped */
    int write_failed;         /* an output could not be written */
    int write_errno;          /* errno of the first failed write */
    int points_done;          /* complete grid points */
    uint64_t steps;
    solve_tally solve;        /* the contact solves of all points */
    double wall_s;
} sweep_result;

/* Number of grid points, or -1 when the grid is not valid: 0 <= from < to
 * <= 1, step > 0 dividing to - from (to 1e-9 relative), at most
 * SWEEP_MAX_POINTS points. */
int sweep_grid_size(double from, double to, double step);

/* s~ of grid index i (the same value in both directions). */
double sweep_grid_s(const sweep_options *options, int index);

/* Grid index of s, or -1 when s is not a grid point (to 1e-9 of step). */
int sweep_grid_index(const sweep_options *options, double s);

/* Runs the sweep on a PCS sim of scene. Returns 0 when every point completed
 * and every output was written, -1 otherwise (result says why). */
int sweep_run(const bs_scene *scene, const sweep_options *options, sweep_result *result);

/* CSV header lines of the per-point rows and of the trace rows. The trace
 * columns: period (periods since the trace started, with the phase fraction),
 * t [s] since the trace started, w(4L/7) / h, beta, alpha = atan w'(x~) at
 * the prescribed position, beta + alpha (the slider's rotation relative to
 * the beam; beta is clockwise, alpha counter-clockwise), active contacts
 * (bit mask, bits 0-3 = P1..P4). */
extern const char sweep_csv_header[];
extern const char sweep_trace_header[];

#endif
