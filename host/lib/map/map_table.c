/* map_table.c - a map's merged tables (map_table.h). */
#define _POSIX_C_SOURCE 200809L /* fsync, getpid, gethostname */

#include "map_table.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "map_case.h"
#include "outcome.h"

/* The index of result column name among MAP_RUN_COLUMNS (0: s0). */
static int result_column(const char *name)
{
    const char *at = MAP_RUN_COLUMNS;
    const size_t n = strlen(name);
    int index = 0;
    for (;;) {
        if (!strncmp(at, name, n) && (at[n] == ',' || !at[n]))
            return index;
        at = strchr(at, ',');
        if (!at)
            return -1;
        ++at;
        ++index;
    }
}

/* Column i (0-based) of row as text: its start, its length in *length. */
static const char *column(const char *row, int i, size_t *length)
{
    while (i-- > 0) {
        row = strchr(row, ',');
        if (!row)
            return NULL;
        ++row;
    }
    *length = strcspn(row, ",\n");
    return row;
}

static double number_at(const char *row, int i)
{
    size_t length;
    const char *text = column(row, i, &length);
    return text ? strtod(text, NULL) : (double)NAN;
}

static void varied_header(FILE *out, const map_grid *grid)
{
    int v;
    for (v = 0; v < grid->vary_count; ++v)
        fprintf(out, ",%s", grid->vary[v].name);
}

int map_table_runs(FILE *out, const map_grid *grid, char *const *row)
{
    long c;
    fprintf(out, "case,point,repeat");
    varied_header(out, grid);
    fprintf(out, ",%s\n", MAP_RUN_COLUMNS);
    for (c = 0; c < grid->cases; ++c) {
        /* the row without its last two columns (wall_s, check) */
        const char *end = row[c] + strlen(row[c]);
        int commas = 0;
        while (end > row[c] && commas < 2)
            commas += *--end == ',';
        fprintf(out, "%.*s\n", (int)(end - row[c]), row[c]);
    }
    return ferror(out) ? -1 : 0;
}

/* Mean, sample standard deviation, least and largest of the finite values. */
typedef struct spread {
    double sum, sum_sq, low, high;
    int n;
} spread;

static void spread_add(spread *s, double value)
{
    if (!isfinite(value))
        return;
    if (s->n == 0 || value < s->low)
        s->low = value;
    if (s->n == 0 || value > s->high)
        s->high = value;
    s->sum += value;
    s->sum_sq += value * value;
    ++s->n;
}

static double spread_mean(const spread *s)
{
    return s->n > 0 ? s->sum / s->n : (double)NAN;
}

static double spread_sd(const spread *s)
{
    double variance;
    if (s->n < 2)
        return (double)NAN;
    variance = (s->sum_sq - s->sum * s->sum / s->n) / (s->n - 1);
    return variance > 0.0 ? sqrt(variance) : 0.0;
}

static void put(FILE *out, const char *format, double value)
{
    if (isfinite(value))
        fprintf(out, format, value);
    else
        fputs(",nan", out);
}

/* The result columns of map.csv after the outcome class, in order. */
static const char *const point_columns[] = { "s_settled_mean", "s_settled_sd", "s_settled_min", "s_settled_max",
                                             "amp_h_mean", "amp_h_sd", "v_last_mean", "v_peak_mean",
                                             "power_w_mean", "power_w_sd", "unconverged_steps", "window_s", NULL };

int map_table_points_header(const map_grid *grid, char *out, size_t size)
{
    size_t used = (size_t)snprintf(out, size, "point");
    int k;
    for (k = 0; k < grid->vary_count && used < size; ++k)
        used += (size_t)snprintf(out + used, size - used, ",%s", grid->vary[k].name);
    if (used < size)
        used += (size_t)snprintf(out + used, size - used, ",repeats,outcome,agreement");
    for (k = 0; k < OUTCOME_CLASSES && used < size; ++k)
        used += (size_t)snprintf(out + used, size - used, ",frac_%s", outcome_name((outcome_class)k));
    for (k = 0; point_columns[k] && used < size; ++k)
        used += (size_t)snprintf(out + used, size - used, ",%s", point_columns[k]);
    return used < size ? 0 : -1;
}

/* A number column of map.csv: a finite number or nan, nothing else. */
static int number_column(const char *text, size_t length, double *value)
{
    char copy[64], *end;
    if (length == 3 && !strncmp(text, "nan", 3)) {
        *value = (double)NAN;
        return 0;
    }
    if (length == 0 || length >= sizeof copy || strspn(text, "+-.0123456789eE") < length)
        return -1;
    memcpy(copy, text, length);
    copy[length] = '\0';
    *value = strtod(copy, &end);
    return *end || !isfinite(*value) ? -1 : 0;
}

int map_table_point_parse(const map_grid *grid, long point, const char *line, map_point_figures *figures,
                          char *why, size_t size)
{
    const char *at = line;
    double fraction[OUTCOME_CLASSES + 1], number[sizeof point_columns / sizeof *point_columns - 1];
    const int columns = 1 + grid->vary_count + 3 + OUTCOME_CLASSES
                        + (int)(sizeof point_columns / sizeof *point_columns) - 1;
    size_t n;
    char *end;
    int k, c, count = 1;

    for (n = 0; line[n]; ++n)
        count += line[n] == ',';
    if (count != columns) {
        snprintf(why, size, "%d columns, the header has %d", count, columns);
        return -1;
    }
    n = strcspn(at, ",");
    if (strtol(at, &end, 10) != point || end != at + n || n == 0 || *at == '-' || *at == '+') {
        snprintf(why, size, "expected the row of grid point %ld (rows in point order, one each)", point);
        return -1;
    }
    at += n + (at[n] == ',');
    for (k = 0; k < grid->vary_count; ++k) {
        const char *value = grid->vary[k].values[map_point_value(grid, point, k)];
        n = strcspn(at, ",");
        if (n != strlen(value) || strncmp(at, value, n) || !at[n]) {
            snprintf(why, size, "expected %s = %s at grid point %ld", grid->vary[k].name, value, point);
            return -1;
        }
        at += n + 1;
    }
    n = strcspn(at, ",");
    if (strtol(at, &end, 10) != grid->repeat || end != at + n || !at[n]) {
        snprintf(why, size, "expected %d repeats (the identity's)", grid->repeat);
        return -1;
    }
    at += n + 1;
    n = strcspn(at, ",");
    for (figures->outcome = 0; figures->outcome < OUTCOME_CLASSES; ++figures->outcome)
        if (n == strlen(outcome_name((outcome_class)figures->outcome))
            && !strncmp(at, outcome_name((outcome_class)figures->outcome), n))
            break;
    if (figures->outcome == OUTCOME_CLASSES || !at[n]) {
        snprintf(why, size, "the outcome is not a class name (docs/maps.md section 2)");
        return -1;
    }
    at += n + 1;
    for (k = 0; k <= OUTCOME_CLASSES; ++k) { /* agreement, then each class's fraction */
        n = strcspn(at, ",");
        if (number_column(at, n, &fraction[k]) != 0 || !(fraction[k] >= 0.0 && fraction[k] <= 1.0) || !at[n]) {
            snprintf(why, size, "column %s is not a fraction in [0, 1]",
                     k ? "frac_..." : "agreement");
            return -1;
        }
        at += n + 1;
    }
    for (c = 0; point_columns[c]; ++c) {
        n = strcspn(at, ",");
        if (number_column(at, n, &number[c]) != 0) {
            snprintf(why, size, "column %s is not a number (or nan)", point_columns[c]);
            return -1;
        }
        at += n + (at[n] == ',');
    }
    figures->point = point;
    figures->agreement = fraction[0];
    figures->s_settled_mean = number[0];
    figures->s_settled_sd = number[1];
    figures->amp_h_mean = number[4];
    figures->power_w_mean = number[8];
    figures->window_s = number[11];
    return 0;
}

int map_table_points(FILE *out, const map_grid *grid, char *const *row)
{
    const int base = 3 + grid->vary_count; /* the first result column, s0 */
    const int col_status = base + result_column("status");
    const int col_outcome = base + result_column("outcome");
    const int col_s = base + result_column("s_settled");
    const int col_window = base + result_column("window_s");
    const int col_amp = base + result_column("amp_h");
    const int col_v = base + result_column("v_last");
    const int col_peak = base + result_column("v_peak");
    const int col_power = base + result_column("power_w");
    const int col_unconverged = base + result_column("unconverged_steps");
    long point;
    int k, v;

    char header[MAP_POINTS_HEADER];
    if (map_table_points_header(grid, header, sizeof header) != 0)
        return -1;
    fprintf(out, "%s\n", header);
    for (point = 0; point < grid->points; ++point) {
        int count[OUTCOME_CLASSES];
        spread s, amp, speed, peak, power, window;
        double unconverged = 0.0;
        int r, most = 0;
        memset(count, 0, sizeof count);
        memset(&s, 0, sizeof s);
        amp = speed = peak = power = window = s;
        for (r = 0; r < grid->repeat; ++r) {
            const char *text = row[point * grid->repeat + r];
            char name[32];
            size_t length;
            const char *word = column(text, col_outcome, &length);
            int outcome;
            snprintf(name, sizeof name, "%.*s", word ? (int)length : 0, word ? word : "");
            outcome = outcome_from_name(name);
            ++count[outcome >= 0 ? outcome : OUTCOME_OTHER];
            unconverged += number_at(text, col_unconverged);
            word = column(text, col_status, &length);
            if (!word || length != 2 || strncmp(word, "ok", 2))
                continue; /* a fault has no settled figures */
            spread_add(&s, number_at(text, col_s));
            spread_add(&amp, number_at(text, col_amp));
            spread_add(&speed, number_at(text, col_v));
            spread_add(&peak, number_at(text, col_peak));
            spread_add(&power, number_at(text, col_power));
            spread_add(&window, number_at(text, col_window));
        }
        for (k = 1; k < OUTCOME_CLASSES; ++k)
            if (count[k] > count[most])
                most = k;
        fprintf(out, "%ld", point);
        for (v = 0; v < grid->vary_count; ++v)
            fprintf(out, ",%s", grid->vary[v].values[map_point_value(grid, point, v)]);
        fprintf(out, ",%d,%s,%.4g", grid->repeat, outcome_name((outcome_class)most),
                (double)count[most] / grid->repeat);
        for (k = 0; k < OUTCOME_CLASSES; ++k)
            fprintf(out, ",%.4g", (double)count[k] / grid->repeat);
        put(out, ",%.6g", spread_mean(&s));
        put(out, ",%.3g", spread_sd(&s));
        put(out, ",%.6g", s.n ? s.low : (double)NAN);
        put(out, ",%.6g", s.n ? s.high : (double)NAN);
        put(out, ",%.6g", spread_mean(&amp));
        put(out, ",%.3g", spread_sd(&amp));
        put(out, ",%.4g", spread_mean(&speed));
        put(out, ",%.4g", spread_mean(&peak));
        put(out, ",%.6g", spread_mean(&power));
        put(out, ",%.3g", spread_sd(&power));
        fprintf(out, ",%.0f", unconverged);
        put(out, ",%.6g", window.n ? window.low : (double)NAN);
        fputc('\n', out);
    }
    return ferror(out) ? -1 : 0;
}

/* Writes one table by print into dir/name, aside then renamed. */
static int write_table(const char *dir, const char *name, int (*print)(FILE *, const map_grid *, char *const *),
                       const map_grid *grid, char *const *row, char *err, size_t size)
{
    char path[4200], aside[4400], host[64];
    FILE *out;
    int failed;

    /* aside under a name of this process alone: shards on other machines,
     * with the same PID, may write the same table into the same folder */
    if (gethostname(host, sizeof host) != 0)
        strcpy(host, "host");
    host[sizeof host - 1] = '\0';
    snprintf(path, sizeof path, "%s/%s", dir, name);
    snprintf(aside, sizeof aside, "%s/.%s.%s.%ld", dir, name, host, (long)getpid());
    out = fopen(aside, "w");
    if (!out) {
        snprintf(err, size, "cannot write %s: %s", aside, strerror(errno));
        return -1;
    }
    failed = print(out, grid, row) != 0;
    failed |= fflush(out) != 0 || fsync(fileno(out)) != 0;
    failed |= fclose(out) != 0;
    if (failed || rename(aside, path) != 0) {
        snprintf(err, size, "cannot write %s: %s", path, strerror(errno));
        unlink(aside);
        return -1;
    }
    return 0;
}

int map_tables_write(const char *dir, const map_grid *grid, char *const *row, char *err, size_t size)
{
    if (write_table(dir, MAP_RUNS_TABLE, map_table_runs, grid, row, err, size) != 0)
        return -1;
    return write_table(dir, MAP_POINTS_TABLE, map_table_points, grid, row, err, size);
}
