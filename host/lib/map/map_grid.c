/* map_grid.c - the cases of a map (map_grid.h). */
#include "map_grid.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_values.h"

void map_grid_init(map_grid *grid)
{
    memset(grid, 0, sizeof *grid);
    grid->repeat = 1;
    grid->points = 1;
    grid->cases = 1;
}

void map_grid_free(map_grid *grid)
{
    int v;
    for (v = 0; v < grid->vary_count; ++v)
        free(grid->vary[v].values);
    map_grid_init(grid);
}

/* A number of a range ("FROM", "TO", "STEP") or -1 with err. */
static int range_number(const char *spec, const char *text, size_t length, const char *what, double *out,
                        char *err, size_t size)
{
    char number[64];
    char *end;

    if (length == 0 || length >= sizeof number) {
        snprintf(err, size, "--vary %s: %s is %s; expected FROM:TO:STEP, such as 90:140:1", spec, what,
                 length ? "too long" : "empty");
        return -1;
    }
    memcpy(number, text, length);
    number[length] = '\0';
    errno = 0;
    *out = strtod(number, &end);
    if (*end || !isfinite(*out)) {
        snprintf(err, size, "--vary %s: %s %s is not a finite number", spec, what, number);
        return -1;
    }
    return 0;
}

/* Checks value on a copy of base through the scene reader and stores its
 * canonical text in out. 0 or -1 with err. */
static int check_value(const scene_file *base, const map_vary *vary, const char *spec, const char *value,
                       char *out, char *err, size_t size)
{
    scene_file *scratch; /* large: on the heap */
    char assignment[MAP_FIELD + 256];
    char why[1024];

    if (strlen(value) >= 200) {
        snprintf(err, size, "--vary %s: value %.40s... too long", spec, value);
        return -1;
    }
    if (!(scratch = malloc(sizeof *scratch))) {
        snprintf(err, size, "--vary %s: out of memory", spec);
        return -1;
    }
    snprintf(assignment, sizeof assignment, "%s=%s", vary->name, value);
    *scratch = *base;
    if (scene_set_assignment(scratch, "--vary", assignment, why, sizeof why) != 0) {
        const char *detail = strstr(why, ": [");
        snprintf(err, size, "--vary %s: value %s%s", spec, value, detail ? detail : why);
        free(scratch);
        return -1;
    }
    scene_value_text(&scratch->params, &scene_fields[vary->field], out, MAP_VALUE);
    free(scratch);
    return 0;
}

static void add_value(map_vary *vary, const char *text)
{
    strcpy(vary->values[vary->count++], text);
}

static int compare_values(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* A value given twice would run a grid point twice: sorted, so that 100 000
 * values take a moment, not minutes. 0, or -1 with err. */
static int check_distinct(const map_vary *vary, const char *spec, char *err, size_t size)
{
    const char **sorted = malloc((size_t)vary->count * sizeof *sorted);
    int i, status = 0;
    if (!sorted) {
        snprintf(err, size, "--vary %s: out of memory", spec);
        return -1;
    }
    for (i = 0; i < vary->count; ++i)
        sorted[i] = vary->values[i];
    qsort(sorted, (size_t)vary->count, sizeof *sorted, compare_values);
    for (i = 1; i < vary->count && status == 0; ++i)
        if (!strcmp(sorted[i - 1], sorted[i])) {
            snprintf(err, size, "--vary %s: value %s given twice (a grid point would run twice)", spec, sorted[i]);
            status = -1;
        }
    free(sorted);
    return status;
}

/* The grid points of the fields varied so far times count, checked against
 * MAP_MAX_CASES before any value is allocated or checked. 0, or -1 with err. */
static int check_points(const map_grid *grid, const char *spec, double count, char *err, size_t size)
{
    double points = count;
    int v;
    for (v = 0; v < grid->vary_count; ++v)
        points *= grid->vary[v].count;
    if (count > (double)MAP_MAX_VALUES) {
        snprintf(err, size, "--vary %s: %.6g values, at most %d a field", spec, count, MAP_MAX_VALUES);
        return -1;
    }
    if (points > (double)MAP_MAX_CASES) {
        snprintf(err, size, "--vary %s: %.6g grid points with the fields varied before it, more than a map may "
                 "have (at most %ld cases: grid points times --repeat)", spec, points, MAP_MAX_CASES);
        return -1;
    }
    return 0;
}

/* FROM:TO:STEP into vary's values. */
static int parse_range(const map_grid *grid, const scene_file *base, map_vary *vary, const char *spec,
                       const char *text, char *err, size_t size)
{
    const char *colon1 = strchr(text, ':');
    const char *colon2 = colon1 ? strchr(colon1 + 1, ':') : NULL;
    const field_spec *f = &scene_fields[vary->field];
    double from, to, step, intervals;
    long n, i;

    if (!colon2 || strchr(colon2 + 1, ':')) {
        snprintf(err, size, "--vary %s: expected FROM:TO:STEP, such as 90:140:1, or a list v1,v2,...", spec);
        return -1;
    }
    if (f->kind != FIELD_REAL && f->kind != FIELD_INT) {
        snprintf(err, size, "--vary %s: [%s] %s is a choice: give its values as a list, such as %s=%s,%s", spec,
                 f->section, f->key, vary->name, f->choices[0], f->choices[1]);
        return -1;
    }
    if (range_number(spec, text, (size_t)(colon1 - text), "FROM", &from, err, size) != 0
        || range_number(spec, colon1 + 1, (size_t)(colon2 - colon1 - 1), "TO", &to, err, size) != 0
        || range_number(spec, colon2 + 1, strlen(colon2 + 1), "STEP", &step, err, size) != 0)
        return -1;
    if (from == to) {
        snprintf(err, size, "--vary %s: empty range: FROM equals TO (one value is --set %s=%g)", spec,
                 vary->name, from);
        return -1;
    }
    if (from > to) {
        snprintf(err, size, "--vary %s: inverted range: FROM %g is above TO %g", spec, from, to);
        return -1;
    }
    if (!(step > 0.0)) {
        snprintf(err, size, "--vary %s: STEP must be above 0", spec);
        return -1;
    }
    intervals = (to - from) / step;
    if (!(intervals + 1.0 <= (double)MAP_MAX_VALUES)) { /* before it becomes a count: 1:1e300:1e-300 is inf */
        snprintf(err, size, "--vary %s: %.6g values, at most %d a field", spec, intervals + 1.0, MAP_MAX_VALUES);
        return -1;
    }
    n = (long)floor(intervals + 0.5);
    if (check_points(grid, spec, (double)n + 1.0, err, size) != 0)
        return -1;
    if (n < 1 || fabs(intervals - (double)n) > 1e-9 * (double)n) {
        snprintf(err, size, "--vary %s: STEP does not divide TO - FROM = %g (%.6g steps); choose TO on the grid",
                 spec, to - from, intervals);
        return -1;
    }
    vary->values = malloc((size_t)(n + 1) * sizeof *vary->values);
    if (!vary->values) {
        snprintf(err, size, "--vary %s: out of memory", spec);
        return -1;
    }
    for (i = 0; i <= n; ++i) {
        char value[64];
        char canonical[MAP_VALUE];
        /* 12 digits: FROM + i STEP as the user means it (0.1 * 3 is 0.30000000000000004) */
        snprintf(value, sizeof value, "%.12g", i == n ? to : from + (double)i * step);
        if (check_value(base, vary, spec, value, canonical, err, size) != 0)
            return -1;
        add_value(vary, canonical);
    }
    return check_distinct(vary, spec, err, size); /* 12 digits can make two steps one value */
}

/* v1,v2,... into vary's values. */
static int parse_list(const map_grid *grid, const scene_file *base, map_vary *vary, const char *spec,
                      const char *text, char *err, size_t size)
{
    const char *at = text;
    size_t count = 1;
    const char *c;

    for (c = text; *c; ++c)
        count += *c == ',';
    if (check_points(grid, spec, (double)count, err, size) != 0)
        return -1;
    vary->values = malloc(count * sizeof *vary->values);
    if (!vary->values) {
        snprintf(err, size, "--vary %s: out of memory", spec);
        return -1;
    }
    for (;;) {
        const size_t length = strcspn(at, ",");
        char value[256];
        char canonical[MAP_VALUE];
        if (length == 0) {
            snprintf(err, size, "--vary %s: an empty value in the list", spec);
            return -1;
        }
        if (length >= sizeof value) {
            snprintf(err, size, "--vary %s: value %.40s... too long", spec, at);
            return -1;
        }
        memcpy(value, at, length);
        value[length] = '\0';
        if (check_value(base, vary, spec, value, canonical, err, size) != 0)
            return -1;
        add_value(vary, canonical);
        if (!at[length])
            return check_distinct(vary, spec, err, size);
        at += length + 1;
    }
}

int map_grid_add(map_grid *grid, const scene_file *base, const char *spec, char *err, size_t size)
{
    const char *equals = strchr(spec, '=');
    map_vary *vary;
    int v;

    if (grid->vary_count >= MAP_MAX_VARY) {
        snprintf(err, size, "--vary %s: at most %d fields can be varied", spec, MAP_MAX_VARY);
        return -1;
    }
    vary = &grid->vary[grid->vary_count];
    memset(vary, 0, sizeof *vary);
    if (!equals || equals == spec) {
        snprintf(err, size, "--vary %s: expected section.key=FROM:TO:STEP or section.key=v1,v2,..., such as "
                 "excitation.frequency=90:140:1", spec);
        return -1;
    }
    if ((size_t)(equals - spec) >= sizeof vary->name
        || (vary->field = scene_field_named(spec, (size_t)(equals - spec), NULL, NULL)) < 0) {
        snprintf(err, size, "--vary %s: unknown field %.*s (beamslider fields lists every field)", spec,
                 (int)(equals - spec), spec);
        return -1;
    }
    snprintf(vary->name, sizeof vary->name, "%.*s", (int)(equals - spec), spec);
    if (scene_fields[vary->field].kind == FIELD_TEXT) {
        snprintf(err, size, "--vary %s: [%s] %s is a text; a map varies numbers and choices", spec,
                 scene_fields[vary->field].section, scene_fields[vary->field].key);
        return -1;
    }
    for (v = 0; v < grid->vary_count; ++v)
        if (grid->vary[v].field == vary->field) {
            snprintf(err, size, "--vary %s: %s is varied twice", spec, vary->name);
            return -1;
        }
    if (base->set_file[vary->field] == SCENE_BY_OPTION) {
        snprintf(err, size, "--vary %s: %s is also set by %s: vary it or set it, not both", spec, vary->name,
                 base->set_option[vary->field]);
        return -1;
    }
    if (!equals[1]) {
        snprintf(err, size, "--vary %s: no values (an empty range)", spec);
        return -1;
    }
    if ((strchr(equals + 1, ':') ? parse_range(grid, base, vary, spec, equals + 1, err, size)
                                 : parse_list(grid, base, vary, spec, equals + 1, err, size)) != 0) {
        free(vary->values);
        vary->values = NULL;
        return -1;
    }
    ++grid->vary_count;
    return 0;
}

int map_grid_finish(map_grid *grid, int repeat, char *err, size_t size)
{
    double points = 1.0;
    int v;

    if (repeat < 1 || repeat > MAP_MAX_REPEAT) {
        snprintf(err, size, "--repeat %d: allowed: an integer in [1, %d]", repeat, MAP_MAX_REPEAT);
        return -1;
    }
    for (v = 0; v < grid->vary_count; ++v)
        points *= grid->vary[v].count;
    if (points * repeat > (double)MAP_MAX_CASES) {
        snprintf(err, size, "--repeat %d: %.6g grid points times %d repeats, more than a map may have (at most %ld "
                 "cases)", repeat, points, repeat, MAP_MAX_CASES);
        return -1;
    }
    grid->repeat = repeat;
    grid->points = (long)points;
    grid->cases = grid->points * repeat;
    return 0;
}

long map_case_point(const map_grid *grid, long c)
{
    return c / grid->repeat;
}

int map_case_repeat(const map_grid *grid, long c)
{
    return (int)(c % grid->repeat);
}

int map_point_value(const map_grid *grid, long point, int v)
{
    int w;
    for (w = grid->vary_count - 1; w > v; --w) /* the last field varies fastest */
        point /= grid->vary[w].count;
    return (int)(point % grid->vary[v].count);
}

int map_case_scene(const map_grid *grid, const scene_file *base, long c, scene_file *out, char *err,
                   size_t size)
{
    const long point = map_case_point(grid, c);
    const int repeat = map_case_repeat(grid, c);
    char assignment[MAP_FIELD + MAP_VALUE + 8];
    int v;

    *out = *base;
    for (v = 0; v < grid->vary_count; ++v) {
        snprintf(assignment, sizeof assignment, "%s=%s", grid->vary[v].name,
                 grid->vary[v].values[map_point_value(grid, point, v)]);
        if (scene_set_assignment(out, "--vary", assignment, err, size) != 0)
            return -1;
    }
    if (repeat > 0) {
        char start[MAP_VALUE];
        scene_number_text(out->params.s0 + repeat * MAP_PERTURBATION, start, sizeof start);
        snprintf(assignment, sizeof assignment, "run.s0=%s", start);
        if (scene_set_assignment(out, "--repeat", assignment, err, size) != 0)
            return -1;
    }
    return 0;
}

int map_shard_has(long c, int index, int count)
{
    return c % count == index - 1;
}

int map_shard_parse(const char *text, int *index, int *count, char *err, size_t size)
{
    const char *slash;
    char *end;
    long i, n;

    errno = 0;
    i = strtol(text, &end, 10);
    if (end == text || *end != '/') {
        snprintf(err, size, "--shard %s: expected I/N, such as 1/4 (the first of four shards)", text);
        return -1;
    }
    slash = end;
    n = strtol(slash + 1, &end, 10);
    if (end == slash + 1 || *end || errno || n < 1 || n > 100000) {
        snprintf(err, size, "--shard %s: N must be an integer in [1, 100000]", text);
        return -1;
    }
    if (i < 1 || i > n) {
        snprintf(err, size, "--shard %ld/%ld: shard index out of range; allowed: 1 to %ld", i, n, n);
        return -1;
    }
    *index = (int)i;
    *count = (int)n;
    return 0;
}
