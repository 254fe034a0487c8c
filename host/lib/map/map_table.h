/* map_table.h - a map's merged tables (docs/maps.md section 3).
 *
 * DIR/runs.csv: one row per case, in case order, the result rows without
 * wall_s and check: the same bytes whatever the number of workers, shards
 * or resumes that made them. DIR/map.csv: one row per grid point, over its
 * repeats: the class most of them ended in (ties: the first in the class
 * order of outcome.h) and the fraction that did (agreement), the fraction
 * of every class, and mean, sample standard deviation, least and largest
 * s_settled, mean and standard deviation of amp_h and of power_w, the mean
 * transport speeds, the shortest settled window (window_s); means over the
 * repeats that did not fault (nan if none).
 */
#ifndef MAP_TABLE_H
#define MAP_TABLE_H

#include <stddef.h>
#include <stdio.h>
#include "map_grid.h"

#define MAP_RUNS_TABLE "runs.csv"
#define MAP_POINTS_TABLE "map.csv"

/* Writes both tables of rows (row[c]: case c's row, all present) into
 * dir, each written aside and renamed into place. 0, or -1 with err. */
int map_tables_write(const char *dir, const map_grid *grid, char *const *row, char *err, size_t size);

/* The tables into open files (the same text). 0, or -1 on a write error. */
int map_table_runs(FILE *out, const map_grid *grid, char *const *row);
int map_table_points(FILE *out, const map_grid *grid, char *const *row);

/* map.csv's header line for grid, without its newline, into out. 0, or -1
 * if it does not fit size (MAP_POINTS_HEADER always does). */
#define MAP_POINTS_HEADER 2048
int map_table_points_header(const map_grid *grid, char *out, size_t size);

/* What map-plot draws of one grid point. */
typedef struct map_point_figures {
    long point;
    int outcome;                  /* outcome_class */
    double agreement;
    double s_settled_mean, s_settled_sd, amp_h_mean, power_w_mean; /* NAN: none */
    double window_s;              /* the shortest settled window of its runs [s]; NAN: none */
} map_point_figures;

/* Reads line (one row of map.csv without its newline), which must be the row
 * of grid point `point` as map_table_points writes it: the point, its varied
 * values, the repeats, a class name, fractions in [0, 1], numbers or nan,
 * and no more columns. map.csv is input to map-plot (a folder can be cut
 * short or edited), so anything else is refused. 0, or -1 with why. */
int map_table_point_parse(const map_grid *grid, long point, const char *line, map_point_figures *figures,
                          char *why, size_t size);

#endif
