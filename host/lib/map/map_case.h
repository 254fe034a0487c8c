/* map_case.h - one case of a map: its scene, its run and its result row
 * (docs/maps.md section 3 lists the columns).
 *
 * A row is one line of comma-separated text:
 *   case,point,repeat,<one column per varied field>,MAP_RUN_COLUMNS,wall_s,check
 * check is the FNV-1a (32 bits, 8 hex digits) of everything before it,
 * so that a torn or damaged line is told from a whole one; wall_s is the
 * only column that differs between two runs of the same case, and the
 * merged tables leave it and check out.
 */
#ifndef MAP_CASE_H
#define MAP_CASE_H

#include <stddef.h>
#include <stdint.h>
#include "map_grid.h"

/* The result columns after the varied fields (docs/maps.md section 3). */
#define MAP_RUN_COLUMNS                                                                                   \
    "s0,status,outcome,s_settled,window_s,s_end,s_min,t_s_min,amp_h,amp_max_h,v_last,v_peak,cycles,power_w,"  \
    "energy_j,"                                                                                                  \
    "steps,unconverged_steps,max_pgs_iters,max_systems,hash"
#define MAP_ROW 2048 /* a row's characters at most, with its newline */

/* Runs case c of grid on base and writes its row (with the newline) into
 * row. A case whose scene does not build or whose run stops is a row too
 * (status, outcome fault): it would do the same again. Returns 0, or -1
 * when the row could not be made (out of memory; err says why). */
int map_case_run(const map_grid *grid, const scene_file *base, long c, char *row, size_t size, char *err,
                 size_t err_size);

/* The header line of the rows (with the newline) into out. */
void map_case_header(const map_grid *grid, char *out, size_t size);

/* The check of a row's text up to and including its last comma. */
uint32_t map_row_check(const char *text, size_t length);

/* 1 if line (length characters, with its newline) is a whole row of grid:
 * text (no NUL byte), the right number of columns, its check, case < cases,
 * point and repeat and the varied values those of the case, and in each
 * result column what map_case_run writes there (a finite number, or nan
 * where there may be none; a status word; a class name; a count up to 2^53;
 * 8 hex digits of the hash). *c is its case. */
int map_row_valid(const map_grid *grid, const char *line, size_t length, long *c);

#endif
