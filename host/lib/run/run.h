/* run.h - one free or PCS run of a scene, with CSV output and summary. */
#ifndef RUN_H
#define RUN_H

#include <stdint.h>
#include <stdio.h>
#include "beamslider.h"
#include "progress_hook.h"
#include "schedule.h"
#include "solve_tally.h"

#define RUN_AMP_PERIODS 25 /* amplitude: mean over the last 25 excitation periods */
#define RUN_POWER_WINDOW 10.0 /* [s] harvested power: also the mean over the run's last 10 s */

typedef struct run_options {
    bs_model model;
    double s0;           /* start position (PCS: prescribed position) */
    double t_end;        /* [s] */
    double dt;           /* the scene's step in double (time = step * dt) [s] */
    bs_solver_options solver; /* contact-solve settings */
    long every;          /* CSV row (and on_step) every this many steps, >= 1 */
    FILE *csv;           /* NULL: no CSV */
    /* NULL, or called after step 0 (the start) and every `every` steps with
     * the sim, the step number and its time step * dt [s]; nonzero stops the
     * run there (result->stopped) */
    int (*on_step)(void *context, const bs_sim *sim, uint64_t step, double t);
    void *on_step_context;
    FILE *periods;       /* NULL: no per-period CSV (run_periods_header) */
    progress_hook progress; /* NULL, or told the part of the steps done */
    void *progress_context;
    const schedule *excitation_schedule; /* NULL or no points: the scene's constant excitation */
    /* NULL: the harmonic excitation (the scene's or the schedule's); else a
     * measured one: base_accel(source, &mean) gives the mean base acceleration
     * of each step in turn [m/s^2] (bs_sim_step_measured), 0 or -1 (the run
     * then stops with input_failed set; the source says why) */
    int (*base_accel)(void *source, double *mean);
    void *base_accel_source;
} run_options;

typedef struct run_result {
    bs_status status;          /* BS_OK, or why the run stopped */
    int write_failed;          /* an output could not be written */
    int write_errno;           /* errno of the first failed write */
    int input_failed;          /* the measured excitation could not be read on */
    int stopped;               /* on_step asked to stop */
    int out_of_memory;         /* no room for the sim: nothing was run */
    uint64_t steps;            /* steps completed */
    double t;                  /* simulated time reached [s] */
    double s_final;
    double s_min, t_s_min;     /* turning point toward the clamp */
    double amp_final_h;        /* mean half peak-to-peak of w(4L/7) / h, last RUN_AMP_PERIODS periods */
    int amp_periods;           /* periods behind amp_final_h */
    double wall_s;
    solve_tally solve;         /* the contact solves */
    uint32_t hash;             /* bs_sim_hash of the final state */
    int transducer;            /* 1: the scene has a transducer, and the figures below are set */
    double energy;             /* into its load over the run [J] */
    double power_mean;         /* energy / t [W] (0 after no step) */
    double power_window;       /* the window of power_last: the last RUN_POWER_WINDOW s, or the
                                  whole run if it is shorter [s] */
    double power_last;         /* mean power into the load over that window [W]; NaN unless
                                  the run completed */
} run_result;

/* The steps of a run: round(t_end / dt), and at most 2^53 (the scene's
 * check, host/lib/scene/scene_build.c): a larger quotient, or one that is not a
 * number, gives 2^53 without converting it. */
uint64_t run_step_count(double t_end, double dt);

/* Takes step number step (1, 2, ...) under the harmonic excitation: the
 * scene's, or plan's frequency and amplitude at the step's midpoint (plan
 * NULL or without points: the scene's), handed to the sim when they change
 * (*frequency, *amplitude: what the sim has; -1 before the first step). The
 * one place a scheduled excitation is stepped: `run`, `twin-plant` and the
 * reports take the same base acceleration sample for sample. */
bs_status run_step_harmonic(bs_sim *sim, const schedule *plan, double dt, uint64_t step, double *frequency,
                            double *amplitude);

/* Runs scene from rest for run_step_count(t_end, dt) steps. Returns 0 when
 * the run completed and its CSV was written, -1 otherwise (result says why).
 * Holds no state between calls: runs may go on in several threads at once. */
int run_scene(const bs_scene *scene, const run_options *options, run_result *result);

/* CSV header lines of run_scene's step rows and per-period rows; with a
 * transducer the step rows end in run_transducer_columns. */
extern const char run_csv_header[];
extern const char run_transducer_columns[];
extern const char run_periods_header[];

#endif
