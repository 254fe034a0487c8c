/* map_pool.h - runs a list of a map's cases on worker processes
 * (docs/maps.md section 4).
 *
 * Processes, not threads: run_scene keeps its bs_sim in a static (host/lib/
 * run.c), and a process that fails takes no other case with it. Each worker
 * takes the next case from a counter shared by all (an atomic add in shared
 * memory), so a slow case holds up one worker only, runs it and appends its
 * row to a result file of its own (map_store.h). The parent draws the
 * progress bar and waits. On Linux a worker dies with its parent (a kill -9
 * of the command stops the map instead of leaving workers running).
 */
#ifndef MAP_POOL_H
#define MAP_POOL_H

#include <stddef.h>
#include "map_grid.h"

typedef struct map_pool_options {
    const char *dir;          /* the map's folder (claimed) */
    const map_grid *grid;
    const scene_file *base;   /* the scene after --set */
    const long *cases;        /* the cases to run, count of them */
    long count;
    int jobs;                 /* worker processes, >= 1 */
    int show_progress;        /* a progress bar with ETA on a terminal */
} map_pool_options;

typedef struct map_pool_result {
    long done;                /* cases run and appended */
    int failed_workers;       /* workers that stopped on an error (they said why on stderr) */
    double wall_s;
} map_pool_result;

/* Runs the cases. 0 when every case was run and appended, -1 otherwise
 * (err says why). */
int map_pool_run(const map_pool_options *options, map_pool_result *result, char *err, size_t size);

#endif
