/* map_pool.h - runs a list of a map's cases on worker threads
 * (docs/maps.md section 4).
 *
 * Threads of the calling process, never a fork of it: the caller may be a
 * Python or Octave process whose copy would run its own atexit handlers and
 * flush its buffers twice. Nothing of a case is shared: each case builds its
 * own scene and runs its own sim (run_scene keeps no state between calls).
 * Each worker takes the next case from a counter shared by all (an atomic
 * add), so a slow case holds up one worker only, runs it and appends its row
 * to a result file of its own (map_store.h). The calling thread waits,
 * telling the progress hook how many cases are done ten times a second. A
 * kill of the process stops every worker with it.
 */
#ifndef MAP_POOL_H
#define MAP_POOL_H

#include <stddef.h>
#include "map_grid.h"
#include "progress_hook.h"

#define MAP_MAX_JOBS 1024

typedef struct map_pool_options {
    const char *dir;          /* the map's folder (claimed) */
    const map_grid *grid;
    const scene_file *base;   /* the scene after --set */
    const long *cases;        /* the cases to run, count of them */
    long count;
    int jobs;                 /* worker threads, 1 .. MAP_MAX_JOBS */
    progress_hook progress;   /* NULL, or told the part of the cases done */
    void *progress_context;
} map_pool_options;

typedef struct map_pool_result {
    long done;                /* cases run and appended */
    int failed_workers;       /* workers that stopped on an error */
    double wall_s;
} map_pool_result;

/* Runs the cases. 0 when every case was run and appended, -1 otherwise
 * (err says why: the first failing worker's reason, with its result file,
 * and how many cases were run). */
int map_pool_run(const map_pool_options *options, map_pool_result *result, char *err, size_t size);

#endif
