/* map_summary.h - the one-line JSON summaries `map` and `map-merge` print on
 * stdout, written by the one JSON writer (out_json.h). */
#ifndef MAP_SUMMARY_H
#define MAP_SUMMARY_H

#include <stdio.h>
#include "map_grid.h"
#include "scene_ini.h"

/* What one map command did (beamslider map, docs/maps.md). */
typedef struct summary_map {
    const map_grid *grid;
    const char *dir;
    int shard_index, shard_count;  /* 1/1 without --shard */
    int jobs;                      /* workers started */
    long shard_cases;              /* cases of this shard */
    long skipped;                  /* of those, found done in dir */
    long run;                      /* run by this command */
    long done_total;               /* cases of the whole map done now */
    long torn, invalid;            /* lines of the result files ignored */
    int complete;                  /* every case done: the tables were written */
    double wall_s;                 /* the workers' time */
    unsigned long long fields_hash; /* the map identity's hash of the scene (without the varied fields) */
} summary_map;

/* The summary of a map command over the scene file (after --set): the
 * scene, the --set fields, the grid (varied fields and their value counts,
 * repeats), the cases, wall time and cases per second, the fields hash of
 * the map's identity, version and revision. 0 or -1. */
int summary_print_map(FILE *out, const scene_file *file, const summary_map *map);

/* The summary of map-merge: scene (the identity's name), the grid, the
 * cases done, the lines ignored, complete, the folder (map->dir), version
 * and revision. 0 or -1. */
int summary_print_merge(FILE *out, const char *scene, const summary_map *map);

#endif
