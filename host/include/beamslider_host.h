/* beamslider_host.h - libbeamslider-host: beamslider in a host program.
 *
 * What `beamslider` does, as calls: scenes read from INI files (or text) at
 * run time with `--set`-style overrides, the modal precomputation, runs,
 * quasi-static sweeps and maps of a scene, the digital twin's design and its
 * measured-signals format. The core (beamslider.h) runs the built scene:
 *
 *     bs_host_scene *scene;
 *     bs_host_error error;
 *     if (bs_host_scene_load("fig6.ini", NULL, 0, &scene, &error) != BS_HOST_OK)
 *         fprintf(stderr, "%s\n", error.text);   // "fig6.ini:12: [numerics] dt = 0: ..."
 *     bs_sim_init(&sim, bs_host_scene_core(scene), ...);   // or bs_host_run(scene, ...)
 *     bs_host_scene_free(scene);
 *
 * (README.md, "Use it as a library", has a whole program and how to build
 * it with pkg-config and CMake.)
 *
 * Errors come back as values: a bs_host_status and, in a bs_host_error, the
 * text `beamslider` prints for the same input (file, line, field, value,
 * allowed range). The library never prints, never exits and keeps no
 * mutable static state: any function may be called from several threads at
 * once on different objects, and a bs_host_scene may be read (run, swept,
 * mapped, designed for) by several threads at once, but not while
 * bs_host_scene_set changes it. Work that takes long reports its progress
 * through a callback; maps run on threads of the calling process, never a
 * fork of it. Every figure is in SI units (s is x_C / L).
 *
 * The library is built for one precision of the core: link
 * libbeamslider-host-double with the headers of include/beamslider-double/
 * (pkg-config beamslider-host-double), or the float ones. A program
 * compiled against the other precision's headers is refused with
 * BS_HOST_E_BUILD by bs_host_scene_load and bs_host_scene_parse (macros
 * that pass this program's view of the core, as bs_sim_init does).
 */
#ifndef BEAMSLIDER_HOST_H
#define BEAMSLIDER_HOST_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "beamslider.h"
#include "bs_observer.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- statuses and errors ----------------------------------------------- */

typedef enum bs_host_status {
    BS_HOST_OK = 0,
    BS_HOST_E_INPUT = -1,   /* bad input: a scene, an override, an option, a file read (`beamslider`
                               exits 2); nothing was written */
    BS_HOST_E_FAILED = -2,  /* the work failed: a run stopped (the result says how), an output could
                               not be written (`beamslider` exits 1) */
    BS_HOST_E_MEMORY = -3,  /* out of memory */
    BS_HOST_E_BUILD = -4,   /* this program was compiled against the headers of another build (the
                               other precision, another BS_OBSERVER_MAPS) */
    BS_HOST_E_NULL = -5     /* a NULL argument where one is needed */
} bs_host_status;

#define BS_HOST_ERROR_TEXT 4096

/* Why a call failed: its status and the message `beamslider` prints for it
 * (without "beamslider: error: "). Empty text after BS_HOST_OK. */
typedef struct bs_host_error {
    bs_host_status status;
    char text[BS_HOST_ERROR_TEXT];
} bs_host_error;

/* Short English text of a status ("bad input", ...). */
const char *bs_host_status_text(bs_host_status status);

/* Called now and then (from the thread that called the work, a few times a
 * second at most) with the part done in [0, 1] and a short text of where
 * the work is (NULL: none). */
typedef void (*bs_host_progress)(void *context, double fraction, const char *detail);

/* ---- scenes ------------------------------------------------------------ */

/* A scene as read and built: the file (with its [scene] base), the
 * overrides, where each field was set, the core's bs_scene and the modal
 * data. Opaque; made by bs_host_scene_load or _parse, freed by
 * bs_host_scene_free. */
typedef struct bs_host_scene bs_host_scene;

/* Reads the scene file at path (relative paths from the working folder; a
 * [scene] base relative to the file) and applies overrides, each a text
 * "section.key=value" checked as `--set` checks it (NULL or none: count 0),
 * then builds the core scene. BS_HOST_OK with *scene; else the error
 * (BS_HOST_E_INPUT: the message names the file and line, or the override,
 * the field, the value and the allowed range) and *scene NULL. */
#define bs_host_scene_load(path, overrides, count, scene, error)                                               \
    bs_host_scene_load_(BS_BUILD_TAG, sizeof(bs_sim), sizeof(bs_scene), (path), (overrides), (count), (scene), \
                        (error))
bs_host_status bs_host_scene_load_(uint32_t tag, size_t sim_size, size_t scene_size, const char *path,
                                   const char *const *overrides, int count, bs_host_scene **scene,
                                   bs_host_error *error);

/* The same from text, an INI file's contents; name stands for the file in
 * messages and is the default [scene] name (a [scene] base is read relative
 * to name's folder). */
#define bs_host_scene_parse(name, text, overrides, count, scene, error)                                       \
    bs_host_scene_parse_(BS_BUILD_TAG, sizeof(bs_sim), sizeof(bs_scene), (name), (text), (overrides), (count), \
                         (scene), (error))
bs_host_status bs_host_scene_parse_(uint32_t tag, size_t sim_size, size_t scene_size, const char *name,
                                    const char *text, const char *const *overrides, int count,
                                    bs_host_scene **scene, bs_host_error *error);

/* One more override, "section.key=value" (such as "numerics.dt=1e-5" or
 * "excitation.frequency=110"), and the scene built again: the way to change
 * dt or anything else of a built scene (beamslider.h, bs_scene_check). On
 * an error the scene is unchanged. A bs_sim initialised from the old core
 * scene must be initialised again. */
bs_host_status bs_host_scene_set(bs_host_scene *scene, const char *override, bs_host_error *error);

void bs_host_scene_free(bs_host_scene *scene);

/* The core scene, for bs_sim_init; it lives as long as the bs_host_scene
 * (until bs_host_scene_set or _free). */
const bs_scene *bs_host_scene_core(const bs_host_scene *scene);

/* What the scene file says about its run. */
typedef struct bs_host_setup {
    const char *name;           /* [scene] name (lives as long as the scene) */
    bs_model model;             /* [run] model */
    double s0;                  /* [run] s0: x_C / L at the start (PCS: the prescribed position) */
    double t_end;               /* [run] t_end [s] */
    double dt;                  /* [numerics] dt [s] */
    uint64_t steps;             /* the run's steps: round(t_end / dt) */
    double frequency;           /* [excitation] frequency [Hz] */
    double acceleration;        /* [excitation] acceleration [m/s^2] */
    int has_schedule;           /* 1: [excitation] schedule varies them (bs_host_run steps it) */
    bs_solver_options solver;   /* [solver]: give it to bs_sim_set_solver */
} bs_host_setup;

void bs_host_scene_setup(const bs_host_scene *scene, bs_host_setup *setup);

/* Field "section.key"'s value as canonical text (the shortest that reads
 * back exactly: "0.3", "124", "free"). BS_HOST_OK, or BS_HOST_E_INPUT for a
 * field that is none (error says so). */
bs_host_status bs_host_scene_value(const bs_host_scene *scene, const char *field, char *out, size_t size,
                                   bs_host_error *error);

/* The modal precomputation (docs/model.md 3, 8), in double. */
typedef struct bs_host_modes {
    int n;                              /* modes */
    double frequency[BS_MAX_MODES];     /* f_k [Hz] */
    double lambda[BS_MAX_MODES];        /* roots of the frequency equation */
    double gamma[BS_MAX_MODES];         /* rho A L int phi_k [sqrt(kg)] */
    double phi_sensor[BS_MAX_MODES];    /* phi_k(4/7) [1/sqrt(kg)] */
    double kappa;                       /* k_r L / EI */
    double width;                       /* b [m] */
    double k_axial;                     /* (L / EA + 1 / k_t)^-1 [N/m] */
    int shape_pieces;                   /* of the mode-shape table */
    double fit_error_phi, fit_error_slope; /* relative errors of the fitted shapes */
} bs_host_modes;

void bs_host_scene_modes(const bs_host_scene *scene, bs_host_modes *modes);

/* The first natural frequency [Hz] of the beam with the slider rigidly
 * attached at s (Rayleigh-Ritz on the scene's modes), and the s in
 * [B/2L, 1/2] where it equals frequency (-1: nowhere there). */
double bs_host_attached_frequency(const bs_host_scene *scene, double s);
double bs_host_attached_position(const bs_host_scene *scene, double frequency);

/* ---- runs ---------------------------------------------------------------- */

/* How bs_host_run runs the scene (model, s0, t_end, dt and the solver are
 * the scene's: change them with bs_host_scene_set). */
typedef struct bs_host_run_options {
    long every;                 /* on_step and CSV rows every this many steps (>= 1) */
    FILE *csv;                  /* NULL, or `beamslider run --out`'s rows */
    FILE *periods;              /* NULL, or `beamslider run --periods`' rows */
    FILE *summary;              /* NULL, or the one-line JSON summary `beamslider run` prints (also
                                   after a run that stopped; the Python and Octave bridges read it) */
    /* NULL, or called after the start (step 0) and every `every` steps with
     * the sim (read it with the core's functions), the step and its time
     * [s]; return nonzero to stop the run there */
    int (*on_step)(void *context, const bs_sim *sim, uint64_t step, double t);
    void *on_step_context;
    bs_host_progress progress;  /* NULL, or told the part of the steps done */
    void *progress_context;
} bs_host_run_options;

/* every 1, nothing else. */
void bs_host_run_defaults(bs_host_run_options *options);

/* What a run did (the figures of `beamslider run`'s JSON summary). */
typedef struct bs_host_run_result {
    bs_status status;           /* BS_OK, or the core's reason the run stopped */
    int stopped;                /* on_step asked to stop */
    uint64_t steps;             /* steps completed */
    double t;                   /* the time reached [s] */
    double s_final;             /* s at the end */
    double s_min, t_s_min;      /* the turning point toward the clamp and its time [s] */
    double amp_final_h;         /* mean half peak-to-peak of w(4L/7) / h over the last 25 periods */
    int amp_periods;            /* the periods behind it */
    uint32_t hash;              /* bs_sim_hash of the final state */
    int transducer;             /* the scene has one; then: */
    double energy;              /* into its load [J] */
    double power_mean;          /* energy / t [W] */
    double power_last;          /* over the last 10 s (or the run) [W]; NaN unless completed */
    uint64_t contact_steps, unconverged_steps;
    int max_sweeps, max_systems;
    double wall_s;
} bs_host_run_result;

/* Runs the scene from rest: BS_HOST_OK when it completed (and its outputs
 * were written); BS_HOST_E_FAILED when it stopped (result->status: a core
 * status, with the step in error's text; result->stopped: on_step stopped
 * it) or a write failed; BS_HOST_E_MEMORY. result holds what was done. */
bs_host_status bs_host_run(const bs_host_scene *scene, const bs_host_run_options *options,
                           bs_host_run_result *result, bs_host_error *error);

/* ---- quasi-static sweeps (docs/model.md 6) -------------------------------- */

typedef struct bs_host_sweep_point {
    double s;                   /* the prescribed position s~ */
    double amp_h;               /* mean half peak-to-peak of w(4L/7) / h over the recorded periods */
    double v_mean;              /* x_C displacement / (L periods), positive toward the centre */
} bs_host_sweep_point;

typedef struct bs_host_sweep_options {
    double from, to, step;      /* the grid from + i step, 0 <= from < to <= 1 (0, 0.5, 0.005) */
    int down;                   /* 0: from -> to; 1: to -> from */
    int hold, record;           /* excitation periods held, then recorded, per point (100, 25) */
    FILE *csv;                  /* NULL, or `beamslider sweep --out`'s rows */
    FILE *summary;              /* NULL, or the one-line JSON summary `beamslider sweep` prints */
    bs_host_sweep_point *points; /* NULL, or room for point_room points, filled in sweep order */
    int point_room;
    bs_host_progress progress;
    void *progress_context;
} bs_host_sweep_options;

/* `beamslider sweep`'s defaults. */
void bs_host_sweep_defaults(bs_host_sweep_options *options);

/* The number of grid points of options, or -1 when the grid is not one. */
int bs_host_sweep_points(const bs_host_sweep_options *options);

/* Sweeps the scene (PCS model; a scene with an [excitation] schedule is
 * refused). BS_HOST_OK; BS_HOST_E_INPUT (a bad grid, too few points of
 * room); BS_HOST_E_FAILED (a point stopped, a write failed). *points_done:
 * the complete points. */
bs_host_status bs_host_sweep(const bs_host_scene *scene, const bs_host_sweep_options *options, int *points_done,
                             bs_host_error *error);

/* ---- maps (docs/maps.md) ------------------------------------------------- */

typedef struct bs_host_map_options {
    const char *dir;            /* the map's folder (made with the folders above it) */
    const char *const *vary;    /* "section.key=FROM:TO:STEP" or "section.key=v1,v2,...", vary_count */
    int vary_count;
    int repeat;                 /* starts per grid point (1) */
    int jobs;                   /* worker threads (1) */
    int shard_index, shard_count; /* this shard of the cases (1, 1) */
    bs_host_progress progress;
    void *progress_context;
} bs_host_map_options;

void bs_host_map_defaults(bs_host_map_options *options);

typedef struct bs_host_map_result {
    long points, cases;         /* of the grid */
    long shard_cases, skipped, run; /* this shard's, found done, run now */
    long done;                  /* cases of the whole map done */
    int complete;               /* every case done: DIR/runs.csv and DIR/map.csv written */
    int jobs;
    double wall_s;
    char warnings[1024];        /* what `beamslider map` prints as warnings, one a line */
} bs_host_map_result;

/* Runs the map of the scene in options->dir as `beamslider map` does
 * (resumable: the cases done are skipped). BS_HOST_OK; BS_HOST_E_INPUT
 * (a --vary, a case that cannot run, another map in the folder: nothing
 * written); BS_HOST_E_FAILED. */
bs_host_status bs_host_map(const bs_host_scene *scene, const bs_host_map_options *options,
                           bs_host_map_result *result, bs_host_error *error);

/* ---- the digital twin (docs/twin.md, "Observer") --------------------------- */

typedef struct bs_host_twin_options {
    int signal;                 /* BS_SIGNAL_DEFLECTION or BS_SIGNAL_VOLTAGE (resistor load only) */
    double noise;               /* the signal's noise standard deviation [m or V], > 0 (no default) */
    double force_noise;         /* process noise [N/sqrt(Hz)] (1e-3) */
    double accel_noise;         /* the base acceleration's noise [m/s^2] (0) */
    double latency;             /* the signal lags the acceleration by this much [s] (0) */
    int map_count;              /* response maps at map_frequency[]; 0: from the scene */
    double map_frequency[BS_OBSERVER_MAPS];
    int friction_count;         /* each at map_friction[] (mu, ascending), followed at the twin's mu;
                                   0: at the scene's mu */
    double map_friction[BS_OBSERVER_MAPS];
    bs_host_progress progress;
    void *progress_context;
} bs_host_twin_options;

/* The defaults, with noise as given. */
void bs_host_twin_defaults(bs_host_twin_options *options, double noise);

/* Designs the observer's constants for the scene (Kalman gains, response
 * maps; `beamslider twin-gains`) into the caller's gains. A macro: the
 * library checks that this program's bs_observer_gains is its own
 * (BS_HOST_E_BUILD otherwise). BS_HOST_OK, BS_HOST_E_INPUT (an option out
 * of range, maps too dear), BS_HOST_E_FAILED (a map's sweep stopped). */
#define bs_host_twin_design(scene, options, gains, error) \
    bs_host_twin_design_(BS_OBSERVER_TAG, sizeof(bs_observer_gains), (scene), (options), (gains), (error))
bs_host_status bs_host_twin_design_(uint32_t observer_tag, size_t gains_size, const bs_host_scene *scene,
                                    const bs_host_twin_options *options, bs_observer_gains *gains,
                                    bs_host_error *error);

/* gains as a C header (`beamslider twin-gains`): a static const
 * bs_observer_gains named name (a C identifier), after a comment holding
 * comment. BS_HOST_OK, BS_HOST_E_INPUT (a bad name), BS_HOST_E_FAILED. */
bs_host_status bs_host_twin_header(FILE *out, const bs_observer_gains *gains, const char *name, const char *comment,
                                   bs_host_error *error);

/* The measured-signals format (docs/twin.md, "Measured signals file"). */
enum { BS_HOST_DEFLECTION = 0, BS_HOST_VOLTAGE = 1 };

typedef struct bs_host_measured_header {
    double rate;                /* sample rate [Hz] = 1 / dt */
    int signal;                 /* BS_HOST_DEFLECTION or BS_HOST_VOLTAGE */
    double noise;               /* [m or V]; NaN: not given */
    double accel_noise;         /* [m/s^2]; NaN: not given */
    double latency;             /* [s], informative; NaN: not given */
    int has_truth;              /* the rows hold s_true */
} bs_host_measured_header;

typedef struct bs_host_measured_row {
    double t;                   /* k / rate [s] */
    double base_accel;          /* the mean over the sample period [m/s^2] */
    double signal;              /* [m or V] */
    double s_true;              /* NaN without truth */
} bs_host_measured_row;

/* A stream being read (opaque). */
typedef struct bs_host_measured bs_host_measured;

/* Opens path ("-": standard input) and reads its header. BS_HOST_OK with
 * *reader and the header; BS_HOST_E_INPUT ("FILE:LINE: what is wrong"). */
bs_host_status bs_host_measured_open(const char *path, bs_host_measured **reader, bs_host_measured_header *header,
                                     bs_host_error *error);

/* The next row: 1; 0 at the end; -1 with the error (BS_HOST_E_INPUT). */
int bs_host_measured_next(bs_host_measured *reader, bs_host_measured_row *row, bs_host_error *error);

void bs_host_measured_close(bs_host_measured *reader);

/* The writer: the title and header (plant: free text, made one line; NULL:
 * none), then rows. BS_HOST_OK, or BS_HOST_E_FAILED on a write error. */
bs_host_status bs_host_measured_write_header(FILE *out, const bs_host_measured_header *header, const char *plant);
bs_host_status bs_host_measured_write_row(FILE *out, const bs_host_measured_row *row, int has_truth);

#ifdef __cplusplus
}
#endif

#endif
