/* map_case.c - one case of a map (map_case.h): scene, run, outcome, row.
 *
 * The run is run_scene's, as `beamslider run` does it; its per-period rows
 * (run_periods_header) go to memory (open_memstream) and give the outcome
 * and the settled figures (outcome.h). The settled position s_settled and
 * amplitude amp_h are means over the settled window, the run's last 10 s
 * or the whole run if shorter (window_s says which); s_end is s at t_end
 * (what `run` calls s_final).
 */
#define _POSIX_C_SOURCE 200809L /* open_memstream */

#include "map_case.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "outcome.h"
#include "run.h"
#include "scene_build.h"

/* A status as one word for a CSV column. */
static const char *status_word(bs_status status)
{
    switch (status) {
    case BS_OK: return "ok";
    case BS_E_UNSTABLE: return "unstable";
    case BS_E_NONFINITE: return "nonfinite";
    case BS_E_ESCAPED: return "escaped";
    case BS_E_SCENE: return "scene";
    case BS_E_ARGUMENT: return "argument";
    default: return "error";
    }
}

uint32_t map_row_check(const char *text, size_t length)
{
    uint32_t hash = 2166136261u;
    size_t i;
    for (i = 0; i < length; ++i) {
        hash ^= (unsigned char)text[i];
        hash *= 16777619u;
    }
    return hash;
}

void map_case_header(const map_grid *grid, char *out, size_t size)
{
    size_t used = (size_t)snprintf(out, size, "case,point,repeat");
    int v;
    for (v = 0; v < grid->vary_count && used < size; ++v)
        used += (size_t)snprintf(out + used, size - used, ",%s", grid->vary[v].name);
    if (used < size)
        snprintf(out + used, size - used, ",%s,wall_s,check\n", MAP_RUN_COLUMNS);
}

/* The per-period rows of a run (t,amp_h,s,ds) as three arrays. */
typedef struct periods {
    double *t, *amp, *s;
    size_t count;
} periods;

static int read_periods(const char *text, periods *p)
{
    size_t lines = 0, n = 0;
    const char *c;

    for (c = text; *c; ++c)
        lines += *c == '\n';
    p->t = malloc((lines + 1) * sizeof *p->t);
    p->amp = malloc((lines + 1) * sizeof *p->amp);
    p->s = malloc((lines + 1) * sizeof *p->s);
    if (!p->t || !p->amp || !p->s)
        return -1;
    c = strchr(text, '\n'); /* after the header */
    while (c && c[1]) {
        double t, amp, s;
        if (sscanf(c + 1, "%lf,%lf,%lf", &t, &amp, &s) == 3) {
            p->t[n] = t;
            p->amp[n] = amp;
            p->s[n] = s;
            ++n;
        }
        c = strchr(c + 1, '\n');
    }
    p->count = n;
    return 0;
}

static void free_periods(periods *p)
{
    free(p->t);
    free(p->amp);
    free(p->s);
}

/* Appends printf text to row; returns the new length (size on overflow). */
#if defined(__GNUC__)
static size_t put(char *row, size_t used, size_t size, const char *format, ...)
    __attribute__((format(printf, 4, 5)));
#endif
static size_t put(char *row, size_t used, size_t size, const char *format, ...)
{
    va_list args;
    int n;
    if (used >= size)
        return size;
    va_start(args, format);
    n = vsnprintf(row + used, size - used, format, args);
    va_end(args);
    return n < 0 || (size_t)n >= size - used ? size : used + (size_t)n;
}

/* A number as a column: nan where there is none. */
static size_t put_number(char *row, size_t used, size_t size, const char *format, double value)
{
    if (!isfinite(value))
        return put(row, used, size, ",nan");
    return put(row, used, size, format, value);
}

/* What one case builds: its scene as read, the core scene, the modal data. */
typedef struct case_scene {
    scene_file file;
    bs_scene scene;
    scene_model model;
} case_scene;

/* Builds case c's scene into w and runs it; the per-period rows give the
 * outcome. *built: the scene built (else err says why, and the case is a
 * fault). 0, or -1 when out of memory (err says so). */
static int run_case(const map_grid *grid, const scene_file *base, long c, case_scene *w, run_result *result,
                    outcome_figures *figures, int *built, char *err, size_t err_size)
{
    run_options options;
    outcome_input input;
    periods trajectory;
    char *text = NULL;
    size_t text_size = 0;
    FILE *memory;

    memset(result, 0, sizeof *result);
    memset(&trajectory, 0, sizeof trajectory);
    memset(&input, 0, sizeof input);
    result->status = BS_E_SCENE;
    *built = map_case_scene(grid, base, c, &w->file, err, err_size) == 0
             && scene_build(&w->file, &w->scene, &w->model, err, err_size) == 0;
    if (*built) {
        memory = open_memstream(&text, &text_size);
        if (!memory) {
            snprintf(err, err_size, "case %ld: out of memory", c);
            return -1;
        }
        memset(&options, 0, sizeof options);
        options.model = (bs_model)w->file.params.model;
        options.s0 = w->file.params.s0;
        options.t_end = w->file.params.t_end;
        options.dt = w->file.params.dt;
        options.solver = scene_solver(&w->file.params);
        options.every = 1;
        options.periods = memory;
        run_scene(&w->scene, &options, result); /* result->status says how it ended */
        if (fclose(memory) != 0 || result->write_failed || result->out_of_memory
            || read_periods(text, &trajectory) != 0) {
            snprintf(err, err_size, "case %ld: out of memory for its run", c);
            free(text);
            free_periods(&trajectory);
            return -1;
        }
        free(text);
        input.stop_min = (double)w->scene.stop_min / (double)w->scene.length;
        input.stop_max = (double)w->scene.stop_max / (double)w->scene.length;
    }
    input.t = trajectory.t;
    input.amp_h = trajectory.amp;
    input.s = trajectory.s;
    input.periods = trajectory.count;
    input.s0 = w->file.params.s0;
    input.completed = *built && result->status == BS_OK;
    input.duration = result->t;
    outcome_classify(&input, figures);
    free_periods(&trajectory);
    return 0;
}

int map_case_run(const map_grid *grid, const scene_file *base, long c, char *row, size_t size, char *err,
                 size_t err_size)
{
    case_scene *w = calloc(1, sizeof *w); /* large: on the heap, one per case (cases run in threads) */
    const long point = map_case_point(grid, c);
    run_result result;
    outcome_figures figures;
    size_t used;
    int v, built;

    if (!w) {
        snprintf(err, err_size, "case %ld: out of memory", c);
        return -1;
    }
    if (run_case(grid, base, c, w, &result, &figures, &built, err, err_size) != 0) {
        free(w);
        return -1;
    }
    used = put(row, 0, size, "%ld,%ld,%d", c, point, map_case_repeat(grid, c));
    for (v = 0; v < grid->vary_count; ++v)
        used = put(row, used, size, ",%s", grid->vary[v].values[map_point_value(grid, point, v)]);
    used = put(row, used, size, ",%.9g,%s,%s", w->file.params.s0, status_word(result.status),
               outcome_name(figures.outcome));
    used = put_number(row, used, size, ",%.9g", figures.s_settled);
    used = put_number(row, used, size, ",%.6g", figures.window > 0.0 ? figures.window : (double)NAN);
    used = put_number(row, used, size, ",%.9g", built ? result.s_final : (double)NAN);
    used = put_number(row, used, size, ",%.9g", built ? result.s_min : (double)NAN);
    used = put_number(row, used, size, ",%.6f", built ? result.t_s_min : (double)NAN);
    used = put_number(row, used, size, ",%.6g", figures.amp_settled);
    used = put_number(row, used, size, ",%.6g", figures.amp_max);
    used = put_number(row, used, size, ",%.6g", figures.v_last);
    used = put_number(row, used, size, ",%.6g", figures.v_peak);
    used = put(row, used, size, ",%d", figures.falls);
    used = put_number(row, used, size, ",%.6g", result.transducer ? result.power_last : (double)NAN);
    used = put_number(row, used, size, ",%.6g", result.transducer ? result.energy : (double)NAN);
    used = put(row, used, size, ",%llu,%llu,%d,%d,%08x,%.4g,", (unsigned long long)result.steps,
               (unsigned long long)result.solve.unconverged_steps, result.solve.max_sweeps,
               result.solve.max_systems, (unsigned)result.hash, result.wall_s);
    used = put(row, used, size, "%08x\n", (unsigned)map_row_check(row, used));
    free(w);
    if (used >= size) {
        snprintf(err, err_size, "case %ld: its row is longer than %lu characters", c, (unsigned long)size);
        return -1;
    }
    return 0;
}

/* What each result column (MAP_RUN_COLUMNS, in order) of a row read back
 * must hold. A map's folder is input: a row's check tells a whole line from
 * a torn one, not a row map_case_run wrote from one edited or written by
 * another program, and the merged tables are made of these columns (a
 * count of 100 digits in unconverged_steps gave a map.csv that map-plot
 * refuses; found by tests/fuzz/fuzz_map.c). */
typedef enum column_kind {
    COLUMN_NUMBER,        /* a finite number */
    COLUMN_NUMBER_OR_NAN, /* a finite number, or nan (none) */
    COLUMN_STATUS,        /* a word of status_word */
    COLUMN_OUTCOME,       /* a class name (outcome.h) */
    COLUMN_COUNT,         /* an integer in [0, 2^53] (steps: at most 2^53 a run) */
    COLUMN_HASH           /* 8 lower-case hex digits */
} column_kind;

static const struct result_column {
    const char *name;
    column_kind kind;
} result_columns[] = {
    { "s0", COLUMN_NUMBER },
    { "status", COLUMN_STATUS },
    { "outcome", COLUMN_OUTCOME },
    { "s_settled", COLUMN_NUMBER_OR_NAN },
    { "window_s", COLUMN_NUMBER_OR_NAN },
    { "s_end", COLUMN_NUMBER_OR_NAN },
    { "s_min", COLUMN_NUMBER_OR_NAN },
    { "t_s_min", COLUMN_NUMBER_OR_NAN },
    { "amp_h", COLUMN_NUMBER_OR_NAN },
    { "amp_max_h", COLUMN_NUMBER_OR_NAN },
    { "v_last", COLUMN_NUMBER_OR_NAN },
    { "v_peak", COLUMN_NUMBER_OR_NAN },
    { "cycles", COLUMN_COUNT },
    { "power_w", COLUMN_NUMBER_OR_NAN },
    { "energy_j", COLUMN_NUMBER_OR_NAN },
    { "steps", COLUMN_COUNT },
    { "unconverged_steps", COLUMN_COUNT },
    { "max_pgs_iters", COLUMN_COUNT },
    { "max_systems", COLUMN_COUNT },
    { "hash", COLUMN_HASH },
};
#define RESULT_COLUMNS ((int)(sizeof result_columns / sizeof result_columns[0]))

/* 1 if text (length characters) is what kind allows. */
static int column_holds(column_kind kind, const char *text, size_t length)
{
    static const char *const statuses[] = { "ok", "unstable", "nonfinite", "escaped", "scene", "argument", "error" };
    char copy[64], *end;
    size_t i;
    if (length == 0 || length >= sizeof copy)
        return 0;
    memcpy(copy, text, length);
    copy[length] = '\0';
    switch (kind) {
    case COLUMN_NUMBER_OR_NAN:
        if (!strcmp(copy, "nan"))
            return 1;
        /* fall through */
    case COLUMN_NUMBER: {
        const double x = strtod(copy, &end);
        return !*end && isfinite(x) && strspn(copy, "+-.0123456789eE") == length;
    }
    case COLUMN_STATUS:
        for (i = 0; i < sizeof statuses / sizeof statuses[0]; ++i)
            if (!strcmp(copy, statuses[i]))
                return 1;
        return 0;
    case COLUMN_OUTCOME:
        return outcome_from_name(copy) >= 0;
    case COLUMN_COUNT:
        return strspn(copy, "0123456789") == length
               && (length < 16 || (length == 16 && strcmp(copy, "9007199254740992") <= 0)); /* exactly, not rounded */
    case COLUMN_HASH:
        return length == 8 && strspn(copy, "0123456789abcdef") == 8;
    }
    return 0;
}

/* 1 if the result columns from at on hold what they must (and the table
 * above names MAP_RUN_COLUMNS' columns in order). */
static int result_columns_hold(const char *at)
{
    const char *name = MAP_RUN_COLUMNS;
    int i;
    for (i = 0; i < RESULT_COLUMNS; ++i) {
        const size_t n = strcspn(at, ","), name_length = strcspn(name, ",");
        if (name_length != strlen(result_columns[i].name) || strncmp(name, result_columns[i].name, name_length)
            || !column_holds(result_columns[i].kind, at, n) || at[n] != ',')
            return 0;
        at += n + 1;
        name += name_length + (name[name_length] == ',');
    }
    return *name == '\0';
}

/* The number of columns of grid's rows. */
static int column_count(const map_grid *grid)
{
    const char *c;
    int n = 3 + grid->vary_count + 1 + 2; /* case,point,repeat, varied, the first result, wall_s, check */
    for (c = MAP_RUN_COLUMNS; *c; ++c)
        n += *c == ',';
    return n;
}

int map_row_valid(const map_grid *grid, const char *line, size_t length, long *c)
{
    const char *check, *at;
    char *end;
    unsigned long stored;
    long point;
    int repeat, columns = 1, v;
    size_t i;

    if (length < 12 || line[length - 1] != '\n' || memchr(line, '\0', length))
        return 0; /* a NUL byte: not text (a reader taking the row as a string would cut it there) */
    for (i = 0; i + 1 < length; ++i)
        columns += line[i] == ',';
    if (columns != column_count(grid))
        return 0;
    check = line + length - 9; /* 8 hex digits and the newline, after the last comma */
    if (check[-1] != ',')
        return 0;
    stored = strtoul(check, &end, 16);
    if (end != line + length - 1 || stored != map_row_check(line, (size_t)(check - line)))
        return 0;
    *c = strtol(line, &end, 10);
    if (*end != ',' || *c < 0 || *c >= grid->cases)
        return 0;
    point = strtol(end + 1, &end, 10);
    if (*end != ',' || point != map_case_point(grid, *c))
        return 0;
    repeat = (int)strtol(end + 1, &end, 10);
    if (*end != ',' || repeat != map_case_repeat(grid, *c))
        return 0;
    at = end + 1;
    for (v = 0; v < grid->vary_count; ++v) {
        const char *value = grid->vary[v].values[map_point_value(grid, point, v)];
        const size_t n = strlen(value);
        if (strncmp(at, value, n) || at[n] != ',')
            return 0;
        at += n + 1;
    }
    return result_columns_hold(at);
}
