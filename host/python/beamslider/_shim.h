/* _shim.h - the C side of the Python package (host/python, docs/python.md):
 * what cffi cannot call as it stands (the core's and the host library's
 * macros, which pass this build's struct sizes and tag: bspy_sim_init and
 * the others) and the loops that run many steps in one call into the
 * caller's arrays (a call from Python costs about as much as a step in C:
 * one call a step would halve the speed).
 *
 * This file is read twice: by the C compiler (_shim.c, and the module cffi
 * generates) and, its '#' lines dropped, by cffi's cdef (build_ffi.py), so
 * that the declarations Python sees are the ones compiled. Keep it to
 * typedefs and prototypes cffi understands (no macros, no inline code).
 *
 * Every call here runs with the GIL released (cffi's API mode releases it
 * around each C call); none touches Python objects. Columns and estimates
 * are the caller's arrays (numpy buffers): a NULL column is skipped, and no
 * loop writes more than room rows.
 */
#ifndef BSPY_SHIM_H
#define BSPY_SHIM_H

#include <stddef.h>
#include <stdint.h>
#include "beamslider.h"
#include "beamslider_host.h"
#include "bs_observer.h"

/* A sim's rows: the columns of `beamslider run --out` (host/lib/run/run.c),
 * each NULL or an array of room values. */
typedef struct bspy_rows {
    double *t;              /* step * dt [s] */
    double *s;              /* x_C / L */
    double *w_sensor;       /* w(4L/7) [m] */
    double *z_r;            /* slider height relative to the base [m] */
    double *beta;           /* slider rotation [rad] */
    uint32_t *contacts;     /* bs_step_report.active: bit i, contact i took part */
    int32_t *sweeps;        /* bs_step_report.sweeps */
    double *residual;       /* bs_step_report.residual [N s] (-1: not measured) */
    double *v;              /* transducer: patch voltage [V] */
    double *p;              /* power into the load over the step [W] */
    double *v_s;            /* storage voltage [V] */
    uint64_t room;          /* rows each column holds */
    uint64_t rows;          /* rows written */
} bspy_rows;

/* An observer's estimates after its steps (bs_observer_estimate), each NULL
 * or an array of room values. */
typedef struct bspy_estimates {
    double *t;              /* step * dt [s] */
    double *s;
    double *s_sigma;
    double *s_error;
    double *amplitude;      /* [m] */
    double *power;          /* [W] */
    double *phase_error;    /* [rad] */
    double *frequency;      /* [Hz] */
    double *innovation;
    uint32_t *outliers;
    int32_t *health;
    uint64_t room;
    uint64_t rows;
} bspy_estimates;

/* The build tag and precision this module was compiled with, and the
 * library's check of them (BS_OK or BS_E_BUILD). */
uint32_t bspy_build_tag(void);
int bspy_real_is_float(void);
int bspy_build_check(void);

/* bs_host_scene_load (text NULL) or bs_host_scene_parse (path: the name). */
int bspy_scene_load(const char *path, const char *text, const char *const *overrides, int count,
                    bs_host_scene **scene, bs_host_error *error);

/* bs_sim_init, then the scene's solver settings (as bs_host_run starts). */
int bspy_sim_init(bs_sim *sim, const bs_host_scene *scene, int model, double s0);

/* n steps under the sim's harmonic excitation, a row after every every-th
 * step (every >= 1). *done: the steps taken; returns BS_OK or the status of
 * the step that failed (the sim keeps its last good state). */
int bspy_sim_steps(bs_sim *sim, uint64_t n, double dt, long every, bspy_rows *rows, uint64_t *done);

/* n steps under the measured base accelerations accel[0 .. n) [m/s^2]
 * (bs_sim_step_measured), rows as bspy_sim_steps. */
int bspy_sim_steps_measured(bs_sim *sim, const double *accel, uint64_t n, double dt, long every, bspy_rows *rows,
                            uint64_t *done);

/* bs_observer_init. */
int bspy_observer_init(bs_observer *obs, const bs_sim *sim, const bs_observer_gains *gains,
                       const bs_observer_options *options);

/* n observer steps: bs_observer_step(accel[i], measurement[i]), or
 * bs_observer_predict(accel[i]) where measurement[i] is NaN (a lost
 * sample); an estimate row after every every-th step. As bspy_sim_steps. */
int bspy_observer_steps(bs_observer *obs, bs_sim *sim, const double *accel, const double *measurement, uint64_t n,
                        double dt, long every, bspy_estimates *out, uint64_t *done);

/* bs_host_twin_design. */
int bspy_twin_design(const bs_host_scene *scene, const bs_host_twin_options *options, bs_observer_gains *gains,
                     bs_host_error *error);

/* bs_host_run with a row (bspy_rows) at step 0 and every every-th step,
 * progress as bs_host_run_options, the run stopped where *stop became
 * nonzero (the progress callback sets it), and the JSON summary `beamslider
 * run` prints in *summary (NULL if none; free it with bspy_free). Returns
 * the bs_host_status. */
int bspy_run(const bs_host_scene *scene, long every, bspy_rows *rows, bs_host_progress progress, void *context,
             int *stop, bs_host_run_result *result, char **summary, bs_host_error *error);

/* bs_host_sweep over the grid from, to, step (bs_host_sweep_options),
 * points[0 .. room), *done the points done, the JSON summary `beamslider
 * sweep` prints in *summary (free it with bspy_free). */
int bspy_sweep(const bs_host_scene *scene, double from, double to, double step, int down, int hold, int record,
               bs_host_sweep_point *points, int room, bs_host_progress progress, void *context, int *done,
               char **summary, bs_host_error *error);

/* The grid points of a sweep, or -1 (bs_host_sweep_points). */
int bspy_sweep_points(double from, double to, double step);

/* A measured-signals file (docs/twin.md) read whole by the library's reader:
 * *rows holds *count rows of t, base_accel, signal, s_true (free it with
 * bspy_free). Returns the bs_host_status. */
int bspy_measured_read(const char *path, bs_host_measured_header *header, double **rows, uint64_t *count,
                       bs_host_error *error);

void bspy_free(void *memory);

#endif
