/* summary.h - the one-line JSON summaries `run`, `sweep`, `map` and
 * `map-merge` print on stdout, written by the one JSON writer (out_json.h:
 * every text escaped and UTF-8, numbers in the formats the summaries always
 * had (README.md's example line), a number that is not finite as null).
 */
#ifndef SUMMARY_H
#define SUMMARY_H

#include <stdio.h>
#include "beamslider.h"
#include "excitation_file.h"
#include "map_grid.h"
#include "run.h"
#include "scene_ini.h"
#include "sweep.h"

/* Writes the summary of a run of scene (file: the scene as read, with the
 * command line's overrides) and a newline to out. It echoes the scene's
 * name, every field the command line set ("set": {"section.key": value}),
 * the hashes of the core scene and of every resolved field ("scene_hash",
 * "fields_hash"), the version and the source revision. record: the recorded
 * excitation the run replayed, NULL for the harmonic one (the scene's, or
 * its schedule). Returns 0, or -1 when it could not be built (out of
 * memory) or written. */
int summary_print_run(FILE *out, const scene_file *file, const bs_scene *scene,
                      const excitation_file *record, const run_result *result);

/* The same for a sweep over options. */
int summary_print_sweep(FILE *out, const scene_file *file, const bs_scene *scene,
                        const sweep_options *options, const sweep_result *result);

/* What one map command did (beamslider map, docs/maps.md). */
typedef struct summary_map {
    const map_grid *grid;
    const char *dir;
    int shard_index, shard_count;  /* 1/1 without --shard */
    int jobs;                      /* worker processes started */
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
