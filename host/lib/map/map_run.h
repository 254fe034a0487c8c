/* map_run.h - what `beamslider map` and `map-merge` do, as the library's
 * calls (docs/maps.md): the grid checked before anything is written, the
 * folder claimed, the cases of this shard not done yet run on worker
 * threads (map_pool.h), and the merged tables written once every case is
 * done. The CLI (host/cli/cli_map.c) parses the options, prints the
 * messages and picks the exit status; a bridge calls the same.
 *
 * Outcomes: MAP_DONE (0); MAP_E_INPUT: bad input (a --vary, a case whose
 * scene does not build, another map in the folder, a result file refused;
 * nothing was written); MAP_E_FAILED: the work failed (a worker could not
 * write, the tables could not be written, cases are missing). err says
 * why; warnings (NULL or size 0: none kept) collects what the CLI prints as
 * warnings, one per line.
 */
#ifndef MAP_RUN_H
#define MAP_RUN_H

#include <stddef.h>
#include "map_grid.h"
#include "map_summary.h"
#include "progress_hook.h"

enum { MAP_DONE = 0, MAP_E_INPUT = -1, MAP_E_FAILED = -2 };

typedef struct map_run_options {
    const char *dir;               /* the map's folder */
    const char *const *vary;       /* --vary specs, vary_count of them (0 .. MAP_MAX_VARY) */
    int vary_count;
    int repeat;                    /* 1 .. MAP_MAX_REPEAT */
    int jobs;                      /* worker threads, at most this many (no more than the cases) */
    int shard_index, shard_count;  /* 1/1: every case */
    const char *scene_path;        /* informational, for the identity's info lines */
    const char *command;           /* informational: the command line (NULL: none) */
    progress_hook progress;        /* NULL, or told how far the checks, then the cases, are */
    void *progress_context;
} map_run_options;

/* The grid of options over base, every case's scene checked to build
 * (the first and last repeat of each point: the repeats differ only in s0).
 * grid must be freed with map_grid_free, also on failure. MAP_DONE or
 * MAP_E_INPUT with err ("case 3 (grid point 1, repeat 1) cannot run: ..."). */
int map_run_grid(const scene_file *base, const map_run_options *options, map_grid *grid, char *err,
                 size_t size);

/* Runs the map of grid over base in options->dir: claims the folder, runs
 * this shard's cases not done yet, merges when every case is done; fills
 * the summary. MAP_DONE, MAP_E_INPUT or MAP_E_FAILED with err. */
int map_run_cases(const scene_file *base, const map_grid *grid, const map_run_options *options,
                  summary_map *summary, char *err, size_t size, char *warnings, size_t warnings_size);

/* Reads dir's rows and writes the tables when every case is done (the
 * counts into summary: done_total, torn, invalid, complete). MAP_DONE;
 * MAP_E_INPUT (a result file refused); MAP_E_FAILED (tables not written,
 * or, when report_missing, cases not done). */
int map_run_merge(const char *dir, const map_grid *grid, summary_map *summary, int report_missing, char *err,
                  size_t size, char *warnings, size_t warnings_size);

#endif
