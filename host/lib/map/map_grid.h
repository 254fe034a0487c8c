/* map_grid.h - the cases of a map: the grid of varied fields, the repeats,
 * and the shards (docs/maps.md section 1).
 *
 * --vary section.key=FROM:TO:STEP or =v1,v2,... names a field of the scene
 * table and its values; the grid is their product, the last --vary varying
 * fastest. Each grid point runs `repeat` times: repeat r starts at
 * s0 + r MAP_PERTURBATION (the ensembles of docs/baseline.md and
 * docs/accuracy.md start 1e-5 L apart), so that a chaotic outcome shows as a
 * spread. Case c is point c / repeat, repeat c % repeat. Every value is
 * checked by the scene reader itself (scene_set_assignment), as a file's
 * would be.
 */
#ifndef MAP_GRID_H
#define MAP_GRID_H

#include <stddef.h>
#include "scene_ini.h"

#define MAP_MAX_VARY 6          /* varied fields */
#define MAP_MAX_CASES 1000000L  /* grid points times repeats */
#define MAP_MAX_REPEAT 1000
#define MAP_MAX_VALUES 100000   /* values of one field */
#define MAP_PERTURBATION 1e-5   /* repeat r starts at s0 + r * 1e-5 */
#define MAP_VALUE 48            /* a value's canonical text, with its NUL */
#define MAP_FIELD (2 * SCENE_NAME) /* "section.key" */

typedef struct map_vary {
    int field;                  /* index into scene_fields */
    char name[MAP_FIELD];       /* "section.key" */
    int count;                  /* values */
    char (*values)[MAP_VALUE];  /* canonical texts (scene_value_text), in grid order */
} map_vary;

typedef struct map_grid {
    map_vary vary[MAP_MAX_VARY];
    int vary_count;
    int repeat;                 /* K >= 1 */
    long points;                /* product of the value counts (1 without --vary) */
    long cases;                 /* points * repeat */
} map_grid;

/* An empty grid (one point, one repeat). */
void map_grid_init(map_grid *grid);
void map_grid_free(map_grid *grid);

/* Adds --vary spec ("section.key=FROM:TO:STEP" or "section.key=v1,v2,...")
 * to the grid. FROM:TO:STEP needs a number or integer field, FROM < TO and
 * a STEP > 0 that divides TO - FROM (to 1e-9 relative); its values are
 * FROM + i STEP rounded to 12 significant digits. A list needs distinct
 * values. Each value is checked on a copy of base as the scene reader checks
 * a file's value. Refused: an unknown or a text field, a field varied twice
 * or also set by --set, an empty or inverted range, more than MAP_MAX_VARY
 * fields. 0, or -1 with the reason in err (naming the option). */
int map_grid_add(map_grid *grid, const scene_file *base, const char *spec, char *err, size_t size);

/* Sets repeat and counts the cases: 0, or -1 when there are more than
 * MAP_MAX_CASES or repeat is outside 1 .. MAP_MAX_REPEAT. */
int map_grid_finish(map_grid *grid, int repeat, char *err, size_t size);

/* The grid point and repeat of case c, and the value index of field v at a point. */
long map_case_point(const map_grid *grid, long c);
int map_case_repeat(const map_grid *grid, long c);
int map_point_value(const map_grid *grid, long point, int v);

/* The scene of case c: base with the point's values and the repeat's start
 * (origins "--vary", "--repeat" in messages). 0, or -1 with err. */
int map_case_scene(const map_grid *grid, const scene_file *base, long c, scene_file *out, char *err,
                   size_t size);

/* 1 if case c belongs to shard index (1 .. count) of count: cases are dealt
 * out in turn, c % count == index - 1, so that every shard gets a like mix
 * of cheap and dear cases. */
int map_shard_has(long c, int index, int count);

/* Parses "I/N" (1 <= I <= N <= 100000): 0, or -1 with err. */
int map_shard_parse(const char *text, int *index, int *count, char *err, size_t size);

#endif
