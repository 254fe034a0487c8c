/* map_run.c - a map command's work (map_run.h). */
#include "map_run.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "map_case.h"
#include "map_pool.h"
#include "map_store.h"
#include "map_table.h"
#include "scene_build.h"
#include "scene_values.h"

/* Appends a line to warnings. */
#if defined(__GNUC__)
static void warn(char *warnings, size_t size, const char *format, ...) __attribute__((format(printf, 3, 4)));
#endif
static void warn(char *warnings, size_t size, const char *format, ...)
{
    size_t used;
    va_list args;
    if (!warnings || size == 0)
        return;
    used = strlen(warnings);
    if (used + 1 >= size)
        return;
    va_start(args, format);
    vsnprintf(warnings + used, size - used, format, args);
    va_end(args);
    used = strlen(warnings);
    if (used + 1 < size)
        strcpy(warnings + used, "\n");
}

/* What a check builds: large, on the heap. */
typedef struct case_build {
    scene_file file;
    bs_scene scene;
    scene_model model;
} case_build;

/* Every case's scene must build (a derived check, such as s0 within the
 * clamp stops, can fail for a combination of values): checked before
 * anything is written. The repeats differ only in s0, and the start range
 * is an interval, so the first and last repeat of each point suffice (one
 * when there is one). A build is a modal analysis and a shape fit, some
 * milliseconds: a map of 100 000 points takes minutes, so it tells its
 * progress. */
static int check_cases(const map_grid *grid, const scene_file *base, const map_run_options *o, char *err,
                       size_t size)
{
    case_build *b = malloc(sizeof *b);
    char why[2048], detail[80];
    long point;
    int status = MAP_DONE;

    if (!b) {
        snprintf(err, size, "out of memory");
        return MAP_E_FAILED;
    }
    for (point = 0; point < grid->points && status == MAP_DONE; ++point) {
        int k;
        if (o->progress) {
            snprintf(detail, sizeof detail, "%ld/%ld points", point, grid->points);
            o->progress(o->progress_context, (double)point / (double)grid->points, detail);
        }
        for (k = 0; k < (grid->repeat > 1 ? 2 : 1) && status == MAP_DONE; ++k) {
            const long c = point * grid->repeat + (k ? grid->repeat - 1 : 0);
            if (map_case_scene(grid, base, c, &b->file, why, sizeof why) != 0
                || scene_build(&b->file, &b->scene, &b->model, why, sizeof why) != 0) {
                snprintf(err, size, "case %ld (grid point %ld, repeat %d) cannot run: %s", c, point,
                         map_case_repeat(grid, c), why);
                status = MAP_E_INPUT;
            }
        }
    }
    free(b);
    return status;
}

int map_run_grid(const scene_file *base, const map_run_options *o, map_grid *grid, char *err, size_t size)
{
    int i;
    map_grid_init(grid);
    for (i = 0; i < o->vary_count; ++i)
        if (map_grid_add(grid, base, o->vary[i], err, size) != 0)
            return MAP_E_INPUT;
    if (map_grid_finish(grid, o->repeat, err, size) != 0)
        return MAP_E_INPUT;
    return check_cases(grid, base, o, err, size);
}

int map_run_merge(const char *dir, const map_grid *grid, summary_map *m, int report_missing, char *err,
                  size_t size, char *warnings, size_t warnings_size)
{
    map_found found;

    if (map_found_read(dir, grid, &found, err, size) != 0)
        return MAP_E_INPUT; /* a result file refused: bad input */
    m->done_total = found.done;
    m->torn = found.torn;
    m->invalid = found.invalid;
    m->complete = found.done == grid->cases;
    if (found.differing > 0)
        warn(warnings, warnings_size, "%s: %ld case(s) were run twice with different results (the first row of "
             "each is kept)", dir, found.differing);
    if (m->complete && map_tables_write(dir, grid, found.row, err, size) != 0) {
        map_found_free(&found, grid->cases);
        return MAP_E_FAILED;
    }
    map_found_free(&found, grid->cases);
    if (!m->complete && report_missing) {
        snprintf(err, size, "%s: %ld of %ld cases are not done yet (run the map command, or each of its shards, "
                 "again to finish them)", dir, grid->cases - found.done, grid->cases);
        return MAP_E_FAILED;
    }
    return MAP_DONE;
}

/* The cases of this shard not done yet, into pending; the counts into m. */
static int pending_cases(const map_grid *grid, const map_run_options *o, summary_map *m, long **pending, char *err,
                         size_t size)
{
    map_found found;
    long c;

    if (map_found_read(o->dir, grid, &found, err, size) != 0)
        return MAP_E_INPUT; /* a result file refused: bad input, as for map-merge */
    *pending = malloc((size_t)grid->cases * sizeof **pending);
    if (!*pending) {
        snprintf(err, size, "out of memory for %ld cases", grid->cases);
        map_found_free(&found, grid->cases);
        return MAP_E_FAILED;
    }
    for (c = 0; c < grid->cases; ++c)
        if (map_shard_has(c, o->shard_index, o->shard_count)) {
            ++m->shard_cases;
            if (found.row[c])
                ++m->skipped;
            else
                (*pending)[m->run++] = c;
        }
    map_found_free(&found, grid->cases);
    return MAP_DONE;
}

int map_run_cases(const scene_file *base, const map_grid *grid, const map_run_options *o, summary_map *m,
                  char *err, size_t size, char *warnings, size_t warnings_size)
{
    unsigned char skip[SCENE_MAX_FIELDS];
    map_pool_options pool;
    map_pool_result done;
    char *identity;
    long *pending = NULL;
    int i, status = MAP_DONE, merged;

    if (warnings && warnings_size)
        *warnings = '\0';
    memset(m, 0, sizeof *m);
    m->grid = grid;
    m->dir = o->dir;
    m->shard_index = o->shard_index;
    m->shard_count = o->shard_count;
    identity = map_identity_text(grid, base, o->scene_path, o->command ? o->command : "");
    if (!identity) {
        snprintf(err, size, "out of memory");
        return MAP_E_FAILED;
    }
    switch (map_dir_claim(o->dir, identity, err, size)) {
    case 0:
        break;
    case 1:
        warn(warnings, warnings_size, "%s", err);
        break;
    default:
        free(identity);
        return MAP_E_INPUT;
    }
    free(identity);
    memset(skip, 0, sizeof skip);
    for (i = 0; i < grid->vary_count; ++i)
        skip[grid->vary[i].field] = 1;
    m->fields_hash = scene_values_hash(&base->params, skip);
    if ((status = pending_cases(grid, o, m, &pending, err, size)) != MAP_DONE)
        return status;
    pool.dir = o->dir;
    pool.grid = grid;
    pool.base = base;
    pool.cases = pending;
    pool.count = m->run;
    pool.jobs = o->jobs < m->run ? o->jobs : (int)m->run;
    pool.progress = o->progress;
    pool.progress_context = o->progress_context;
    m->jobs = pool.jobs;
    if (m->run > 0 && map_pool_run(&pool, &done, err, size) != 0)
        status = MAP_E_FAILED;
    m->wall_s = m->run > 0 ? done.wall_s : 0.0;
    m->run = m->run > 0 ? done.done : 0;
    free(pending);
    {
        char merge_err[2048];
        merged = map_run_merge(o->dir, grid, m, 0, merge_err, sizeof merge_err, warnings, warnings_size);
        if (merged != MAP_DONE && status == MAP_DONE) {
            snprintf(err, size, "%s", merge_err);
            status = MAP_E_FAILED;
        } else if (merged != MAP_DONE) { /* both failed: the pool's reason first, the merge's after it */
            const size_t used = strlen(err);
            snprintf(err + used, size - used, "; %s", merge_err);
        }
    }
    return status;
}
