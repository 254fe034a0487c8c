/* ref_replay.c - reads a measured base acceleration (docs/model.md 10; see
 * ref_replay.h). Values are read with strtod (so "1e-3", "+2", " -0.5 " are
 * numbers); a value must be finite: NaN or inf in a measurement is an error
 * to report, not a number to integrate. */
#include "ref_replay.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REF_REPLAY_LINE 4096

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/* Appends value to the growing array; 0 or -1 (out of memory). */
static int append(double value, double **values, uint64_t *count, uint64_t *capacity)
{
    if (*count == *capacity) {
        const uint64_t grown = *capacity ? 2 * *capacity : 4096;
        double *more;
        if (grown > SIZE_MAX / sizeof **values)
            return -1;
        more = realloc(*values, (size_t)grown * sizeof **values);
        if (!more)
            return -1;
        *values = more;
        *capacity = grown;
    }
    (*values)[(*count)++] = value;
    return 0;
}

/* One line: 1 and *value for a number, 0 for a blank or comment line, -1 for bad text. */
static int parse_line(char *line, double *value)
{
    char *hash = strchr(line, '#'), *p = line, *end;
    if (hash)
        *hash = '\0';
    while (is_blank(*p))
        ++p;
    if (*p == '\0')
        return 0;
    errno = 0;
    *value = strtod(p, &end);
    if (end == p || errno == ERANGE || !isfinite(*value))
        return -1;
    while (is_blank(*end))
        ++end;
    return *end == '\0' ? 1 : -1;
}

int ref_replay_read(const char *path, double **values, uint64_t *count, unsigned long *lines, char *err,
                    size_t err_size)
{
    static char line[REF_REPLAY_LINE];
    FILE *f = fopen(path, "r");
    uint64_t capacity = 0;
    unsigned long number = 0;
    int status = 0;

    *values = NULL;
    *count = 0;
    if (!f) {
        snprintf(err, err_size, "--base-accel %s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    while (status == 0 && fgets(line, sizeof line, f)) {
        char text[48];
        double value;
        int kind;
        ++number;
        if (!strchr(line, '\n') && !feof(f)) {
            snprintf(err, err_size, "--base-accel %s:%lu: line longer than %d characters", path, number,
                     REF_REPLAY_LINE - 1);
            status = -1;
            break;
        }
        /* the line as typed, shortened for the message */
        strncpy(text, line, sizeof text - 1);
        text[sizeof text - 1] = '\0';
        text[strcspn(text, "\r\n")] = '\0';
        kind = parse_line(line, &value);
        if (kind < 0) {
            snprintf(err, err_size,
                     "--base-accel %s:%lu: '%s' is not one finite number (a mean base acceleration in m/s^2)", path,
                     number, text);
            status = -1;
        } else if (kind > 0 && append(value, values, count, &capacity) != 0) {
            snprintf(err, err_size, "--base-accel %s:%lu: out of memory", path, number);
            status = -1;
        }
    }
    if (status == 0 && ferror(f)) {
        snprintf(err, err_size, "--base-accel %s: read error after line %lu", path, number);
        status = -1;
    }
    fclose(f);
    if (lines)
        *lines = number;
    if (status != 0) {
        free(*values);
        *values = NULL;
        *count = 0;
    }
    return status;
}
