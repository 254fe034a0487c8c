/* map_table.h - a map's merged tables (docs/maps.md section 3).
 *
 * DIR/runs.csv: one row per case, in case order, the result rows without
 * wall_s and check: the same bytes whatever the number of workers, shards
 * or resumes that made them. DIR/map.csv: one row per grid point, over its
 * repeats: the class most of them ended in (ties: the first in the class
 * order of outcome.h) and the fraction that did (agreement), the fraction
 * of every class, and mean, sample standard deviation, least and largest
 * s_final, mean and standard deviation of amp_h and of power_w, the mean
 * transport speeds; means over the repeats that did not fault (nan if
 * none).
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

#endif
