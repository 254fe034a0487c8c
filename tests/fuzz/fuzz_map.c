/* fuzz_map.c - libFuzzer target: a map folder as map-merge and map-plot
 * read it (host/lib/map/map_store.c map_identity_read and map_found_read,
 * host/lib/map/map_case.c map_row_valid, host/lib/map/map_table.c, and
 * map-plot's reader host/lib/map/map_plot.c map_plot_read).
 *
 * Input: one flags byte, then the folder's files separated by lines "@@":
 * map-identity.txt, runs-a.csv, runs-b.csv, map.csv (a part not given: no
 * such file). Flag bit 0: every line of the result files gets its check
 * column recomputed (re-sealed), so that the row checks behind the checksum
 * are reached, not only the checksum.
 * The contract checked:
 *   - nothing crashes, hangs, leaks or reads out of bounds;
 *   - every reader answers 0 or -1 with a message;
 *   - an identity read back gives a grid within the documented limits
 *     (fields, values, repeats, cases) and a scene name of one line;
 *   - the rows found are each a valid row of their case, counted as done;
 *   - a complete folder merges (map_table_points, map_table_runs) into a
 *     map.csv that map-plot's parser reads back row by row: what map-merge
 *     writes, map-plot takes;
 *   - map-plot's reading of the fuzzed map.csv writes only cells of its
 *     grid.
 */
#define _POSIX_C_SOURCE 200809L /* open_memstream */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fuzz_check.h"
#include "fuzz_files.h"
#include "input_file.h"
#include "map_case.h"
#include "map_store.h"
#include "map_table.h"
#include "map_plot.h"
#include "outcome.h"

#define PARTS 4
static const char *const part_names[PARTS] = { MAP_IDENTITY_FILE, "runs-a.csv", "runs-b.csv", MAP_POINTS_TABLE };

/* data with the check of every line re-sealed, into out (size at least
 * 2 size + 16): each line's text after its last comma replaced by the
 * check of what precedes it. The new size. */
static size_t reseal(const uint8_t *data, size_t size, uint8_t *out)
{
    size_t at = 0, used = 0;
    while (at < size) {
        const uint8_t *end = memchr(data + at, '\n', size - at);
        const size_t length = end ? (size_t)(end - (data + at)) : size - at;
        const uint8_t *comma = NULL;
        size_t i;
        for (i = 0; i < length; ++i)
            if (data[at + i] == ',')
                comma = data + at + i;
        if (end && comma) {
            const size_t keep = (size_t)(comma - (data + at)) + 1;
            memcpy(out + used, data + at, keep);
            used += keep;
            used += (size_t)sprintf((char *)out + used, "%08lx",
                                    (unsigned long)map_row_check((const char *)data + at, keep));
        } else {
            memcpy(out + used, data + at, length);
            used += length;
        }
        if (end)
            out[used++] = '\n';
        at += length + (end != NULL);
    }
    return used;
}

static void check_grid(const map_grid *grid, const char *scene)
{
    long points = 1;
    int v, k;
    if (grid->vary_count < 0 || grid->vary_count > MAP_MAX_VARY || grid->repeat < 1
        || grid->repeat > MAP_MAX_REPEAT)
        fuzz_fail("map_identity_read gave a grid beyond its limits");
    for (v = 0; v < grid->vary_count; ++v) {
        if (grid->vary[v].count < 1 || grid->vary[v].count > MAP_MAX_VALUES)
            fuzz_fail("map_identity_read gave a field with a count of values beyond its limits");
        for (k = 0; k < grid->vary[v].count; ++k) {
            const size_t length = strnlen(grid->vary[v].values[k], MAP_VALUE);
            if (length == 0 || length == MAP_VALUE)
                fuzz_fail("map_identity_read gave an empty or unterminated value");
        }
        points *= grid->vary[v].count;
        if (points > MAP_MAX_CASES)
            fuzz_fail("map_identity_read gave a grid of more points than a map may have");
    }
    if (grid->points != points || grid->cases != points * grid->repeat || grid->cases > MAP_MAX_CASES)
        fuzz_fail("map_identity_read counted the grid wrongly");
    for (k = 0; k < SCENE_TEXT && scene[k]; ++k)
        if ((unsigned char)scene[k] < 0x20 || scene[k] == 0x7f)
            fuzz_fail("map_identity_read gave a scene name with a control character");
    if (k == SCENE_TEXT)
        fuzz_fail("map_identity_read gave an unterminated scene name");
}

/* A complete folder's tables, merged in memory: map-plot's parser takes
 * every row map_table_points writes. */
static void check_merge(const map_grid *grid, char *const *row)
{
    char *text = NULL, why[256], header[MAP_POINTS_HEADER];
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    char *line, *next;
    long point = -1;

    if (!out)
        fuzz_fail("open_memstream failed");
    if (map_table_runs(out, grid, row) != 0)
        fuzz_fail("map_table_runs failed in memory");
    fclose(out);
    free(text);
    text = NULL;
    out = open_memstream(&text, &size);
    if (!out)
        fuzz_fail("open_memstream failed");
    if (map_table_points(out, grid, row) != 0)
        fuzz_fail("map_table_points failed in memory");
    fclose(out);
    if (map_table_points_header(grid, header, sizeof header) != 0)
        fuzz_fail("map_table_points_header does not fit its documented size");
    for (line = text; *line; line = next, ++point) {
        next = strchr(line, '\n');
        if (!next)
            fuzz_fail("map_table_points wrote a line without its end");
        *next++ = '\0';
        if (point < 0) {
            if (strcmp(line, header) != 0)
                fuzz_fail("map_table_points wrote another header than map_table_points_header");
            continue;
        }
        {
            map_point_figures figures;
            if (map_table_point_parse(grid, point, line, &figures, why, sizeof why) != 0) {
                fprintf(stderr, "map.csv row of point %ld: %s: %s\n", point, why, line);
                fuzz_fail("map-plot's parser refuses a row map-merge wrote");
            }
        }
    }
    if (point != grid->points)
        fuzz_fail("map_table_points wrote another number of rows than the grid has points");
    free(text);
}

/* map-plot's reading of the folder's map.csv (host/lib/map/map_plot.c
 * map_plot_read) over the first two varied fields, the others at their first
 * value: it answers 0 or -1 with a message, and writes only the cells of its
 * grid (ASan sees a write past them). */
static void read_table(const char *dir, const map_grid *grid)
{
    char why[1024];
    map_plot plot;
    size_t cells, k;
    int v;

    memset(&plot, 0, sizeof plot);
    plot.grid = grid;
    plot.vx = 0;
    plot.vy = grid->vary_count > 1 ? 1 : 0;
    for (v = 0; v < MAP_MAX_VARY; ++v)
        plot.at_index[v] = v == plot.vx || v == plot.vy ? -1 : 0;
    cells = grid->vary_count > 0 ? (size_t)grid->vary[plot.vx].count * (size_t)grid->vary[plot.vy].count : 1;
    plot.cells = malloc(cells * MAP_PLOT_FIGURES * sizeof *plot.cells);
    if (!plot.cells)
        return;
    for (k = 0; k < cells * MAP_PLOT_FIGURES; ++k)
        plot.cells[k] = (double)NAN;
    plot.scene = "fuzz";
    why[0] = '\0';
    fuzz_check_message(map_plot_read(dir, &plot, why, sizeof why), why, sizeof why);
    free(plot.cells);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t sealed[2 * 4096 + 64];
    static const char mark[] = "\n@@\n";
    const unsigned flags = size > 0 ? data[0] : 0;
    const uint8_t *at = data + (size > 0), *end = data + size;
    const char *dir = fuzz_folder_make();
    char err[1024], scene[SCENE_TEXT];
    map_grid grid;
    map_found found;
    int part, status, more = 1;
    long c, done = 0;

    for (part = 0; part < PARTS; ++part) {
        const char *path = fuzz_path(part_names[part]);
        const uint8_t *stop = end;
        const uint8_t *p;
        if (!more) {
            unlink(path);
            continue;
        }
        for (p = at; p + 4 <= end; ++p)
            if (!memcmp(p, mark, 4)) {
                stop = p + 1; /* the part keeps its last line end */
                break;
            }
        if ((flags & 1) && (part == 1 || part == 2) && (size_t)(stop - at) <= 4096)
            fuzz_write(path, sealed, reseal(at, (size_t)(stop - at), sealed));
        else
            fuzz_write(path, at, (size_t)(stop - at));
        more = stop != end;
        at = more ? stop + 3 : end;
    }

    err[0] = '\0';
    status = map_identity_read(dir, &grid, scene, err, sizeof err);
    fuzz_check_message(status, err, sizeof err);
    if (status != 0)
        return 0;
    check_grid(&grid, scene);

    err[0] = '\0';
    status = map_found_read(dir, &grid, &found, err, sizeof err);
    fuzz_check_message(status, err, sizeof err);
    if (status == 0) {
        for (c = 0; c < grid.cases; ++c) {
            long case_of_row;
            if (!found.row[c])
                continue;
            ++done;
            if (!map_row_valid(&grid, found.row[c], strlen(found.row[c]), &case_of_row) || case_of_row != c)
                fuzz_fail("map_found_read kept a row that is not a valid row of its case");
        }
        if (done != found.done || found.torn < 0 || found.invalid < 0 || found.differing > found.duplicates)
            fuzz_fail("map_found_read counted its rows wrongly");
        if (found.done == grid.cases)
            check_merge(&grid, found.row);
        map_found_free(&found, grid.cases);
    }
    read_table(dir, &grid);
    map_grid_free(&grid);
    return 0;
}
