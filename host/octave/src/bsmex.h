/* bsmex.h - the MEX gateway of beamslider (host/octave): what its files share.
 *
 * One gateway, beamslider_mex, built by make.m with Octave's `mkoctfile --mex`
 * or MATLAB's `mex` from the same C99 sources: it calls only the mx and mex
 * functions both provide (no interleaved-complex API, no C++ API). It wraps
 * libbeamslider-host and the core; it computes no physics of its own.
 *
 *   bsmex_main.c   the command table (run, sim init|step|step_measured|excite|
 *                  info|beam, version) and mexFunction
 *   bsmex_args.c   reading arguments (text, numbers, name/value options, the
 *                  'set' overrides) and raising errors
 *   bsmex_series.c the time series of a run or of steps (one table of columns)
 *   bsmex_run.c    beamslider_run: bs_host_run, its series, periods and summary
 *   bsmex_sim.c    beamslider_sim: a sim stepped from the language
 *   bsmex_state.c  its state as a uint8 array, and the scene it names (a
 *                  one-scene cache)
 *
 * Memory: whatever lives only for one call comes from mxMalloc (MATLAB and
 * Octave free it when an error unwinds the call); what the library or the C
 * library allocates (a bs_host_scene, a temporary file) the call hands to
 * bsmex_hold_*, and the gateway releases it when the call returns, or at the
 * start of the next call (or when the gateway is unloaded) when an error
 * unwound it: any
 * function may raise an error at any point without leaking.
 */
#ifndef BSMEX_H
#define BSMEX_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "mex.h"
#include "beamslider_host.h"

/* ---- errors ---------------------------------------------------------------- */

/* Raises the error id ("beamslider:usage", ...) with the text format makes:
 * never returns. */
void bsmex_fail(const char *id, const char *format, ...);

/* Raises the library's error with its text, its id from its status
 * (beamslider:input, :failed, :memory, :build, :null). Never returns. */
void bsmex_fail_host(const bs_host_error *error);

/* ---- what a call holds outside mxMalloc (bsmex_main.c) ------------------------ */

void bsmex_hold_scene(bs_host_scene *scene);
void bsmex_hold_file(FILE *file);

/* Frees what was held (at a call's end or start, and at exit). */
void bsmex_release(void);

/* ---- arguments ------------------------------------------------------------- */

/* A row of characters as a C string (mxMalloc'd); what names it in the error. */
char *bsmex_text(const mxArray *value, const char *what);

/* A real, finite, double scalar. */
double bsmex_number(const mxArray *value, const char *what);

/* A whole number in [low, high] (a real double scalar). */
uint64_t bsmex_count(const mxArray *value, const char *what, uint64_t low, uint64_t high);

#define BSMEX_MAX_OVERRIDES 256

/* Scene overrides "section.key=value", as --set takes them (mxMalloc'd texts). */
typedef struct bsmex_overrides {
    const char *text[BSMEX_MAX_OVERRIDES];
    int count;
} bsmex_overrides;

/* The options a scene is read with, and a run's: name/value pairs after the
 * scene ('t_end', 's0', 'dt', 'model': their fields; 'set': a cell of field
 * names and values; 'every', only where every_allowed). *every stays as it
 * is unless given. */
void bsmex_options(int count, const mxArray *const *pairs, bsmex_overrides *overrides, long *every,
                   int every_allowed);

/* Loads the scene file at path with the overrides; raises the library's
 * error (file, line, field, range) on failure. The caller owns the scene
 * (bsmex_hold_scene, or the sim's cache). */
bs_host_scene *bsmex_scene_load(const char *path, const bsmex_overrides *overrides);

/* ---- time series ----------------------------------------------------------- */

#define BSMEX_COLUMNS 11

/* Rows of what a run's CSV holds (t, w_sensor, s, z_r, beta, contacts,
 * pgs_iters, pgs_residual; v, p, v_s with a transducer), as columns. */
typedef struct bsmex_series {
    size_t rows, room;
    int columns;                        /* 8, or 11 with a transducer */
    mxArray *array[BSMEX_COLUMNS];
    double *column[BSMEX_COLUMNS];
} bsmex_series;

/* Room for room rows (a scene with a transducer: transducer nonzero). */
void bsmex_series_start(bsmex_series *series, size_t room, int transducer);

/* One row of sim at time t [s]; rows beyond the room are dropped (the
 * callers size it exactly). */
void bsmex_series_add(bsmex_series *series, const bs_sim *sim, double t);

/* Adds the columns as fields of the 1x1 struct out, cut to the rows taken;
 * the series is spent. */
void bsmex_series_finish(bsmex_series *series, mxArray *out);

/* Sets field name of the 1x1 struct out (added when missing) to value. */
void bsmex_field(mxArray *out, const char *name, mxArray *value);

/* ---- the stepping state (bsmex_state.c) -------------------------------------- */

/* A state array read: its checkpoint (inside the array), the scene's path
 * and overrides (mxMalloc'd). */
typedef struct bsmex_state {
    const unsigned char *checkpoint;
    const char *path;
    bsmex_overrides overrides;
} bsmex_state;

/* Reads array; raises beamslider:state for one that is not a state of this
 * build. */
void bsmex_state_read(const mxArray *array, bsmex_state *state);

/* A new state array: sim's checkpoint, path and overrides. */
mxArray *bsmex_state_write(const bs_sim *sim, const char *path, const bsmex_overrides *overrides);

/* The scene of path and overrides: the cached one while its file holds the
 * same bytes, or loaded (and cached; the cache owns it). */
const bs_host_scene *bsmex_state_scene(const char *path, const bsmex_overrides *overrides);

/* Empties the scene cache (at exit). */
void bsmex_state_forget(void);

/* path made absolute against the working folder, so that a later call from
 * another folder finds the same file (mxMalloc'd). */
char *bsmex_absolute_path(const char *path);

/* ---- commands (nin arguments after the command's name) ----------------------- */

void bsmex_run(int nlhs, mxArray *plhs[], int nin, const mxArray *in[]);
void bsmex_sim(int nlhs, mxArray *plhs[], int nin, const mxArray *in[]);

#endif
