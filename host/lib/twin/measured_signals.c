/* measured_signals.c - reading and writing the measured-signals format
 * (measured_signals.h states the grammar; docs/twin.md, "Measured signals
 * file"). One table of header keys; every value parsed exactly, with its
 * unit: "50 kHz" is not read as 50 Hz, "1e-6" without its unit is refused.
 * The writer writes the keys of the same table, so what it writes is what
 * the reader takes (tests/test_measured.c reads back what it wrote).
 */
#define _POSIX_C_SOURCE 200809L /* fseeko, ftello */

#include "measured_signals.h"

#include "out_text.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TIME_TOLERANCE 0.01 /* a row's t may miss k / rate by this many sample periods */

typedef enum key_id {
    KEY_RATE, KEY_SIGNAL, KEY_SIGNAL_UNIT, KEY_ACCEL_UNIT, KEY_LATENCY, KEY_NOISE, KEY_ACCEL_NOISE, KEY_PLANT, KEYS
} key_id;

static const char *const key_names[KEYS] = {
    "sample_rate", "signal", "signal_unit", "base_accel_unit", "latency", "noise", "accel_noise", "plant"
};
#define KNOWN_KEYS "sample_rate, signal, signal_unit, base_accel_unit, latency, noise, accel_noise, plant"

static const char *const signal_names[2] = { "deflection", "voltage" };
static const char *const signal_units[2] = { "m", "V" };

const char *measured_signal_name(int signal)
{
    return signal == MEASURED_VOLTAGE ? signal_names[1] : signal_names[0];
}

/* What the header said, and where. */
typedef struct header_state {
    long line[KEYS];          /* where each key was given; 0: not given */
    int signal_unit;          /* -1: not given; else the signal it names */
    int noise_unit;           /* the signal whose unit the noise was given in */
} header_state;

/* The next line into m->text, trailing blanks removed: 1, 0, -1. */
static int next_line(measured_reader *m, char *err, size_t err_size)
{
    const int status = input_lines_next(&m->lines, m->text, sizeof m->text, err, err_size);
    if (status > 0)
        input_trim_end(m->text);
    return status;
}

/* One of choices (count of them) exactly: its index, or -1. */
static int choice_in(const char *text, const char *const *choices, int count)
{
    int i;
    for (i = 0; i < count; ++i)
        if (!strcmp(text, choices[i]))
            return i;
    return -1;
}

#define FAIL(...)                                                                           \
    do {                                                                                    \
        char what_[1024];                                                                   \
        snprintf(what_, sizeof what_, __VA_ARGS__);                                         \
        snprintf(err, err_size, "%s:%ld: %s", m->path, m->lines.line, what_);               \
        return -1;                                                                          \
    } while (0)

/* A header field: "key = value" in text (after '#'). */
static int header_field(measured_reader *m, header_state *h, const char *text, char *err, size_t err_size)
{
    measured_header *out = &m->header;
    const char *equals = strchr(text, '=');
    const char *value = input_skip_blanks(equals + 1);
    char key[32];
    size_t n;
    int id, which;
    double number;

    text = input_skip_blanks(text);
    n = strspn(text, "abcdefghijklmnopqrstuvwxyz0123456789_");
    if (n == 0 || n >= sizeof key || input_skip_blanks(text + n) != equals)
        FAIL("a header line with '=' is a field '# key = value' (key: lower-case letters, digits and _; "
             "known: %s); a free comment holds no '='", KNOWN_KEYS);
    memcpy(key, text, n);
    key[n] = '\0';
    for (id = 0; id < KEYS && strcmp(key, key_names[id]); ++id)
        ;
    if (id == KEYS)
        FAIL("unknown header field '%s' (known: %s)", key, KNOWN_KEYS);
    if (h->line[id])
        FAIL("%s given twice (first at line %ld)", key, h->line[id]);
    h->line[id] = m->lines.line;
    switch ((key_id)id) {
    case KEY_RATE:
        if (input_number(value, "Hz", &out->rate) != 0)
            FAIL("sample_rate must be a finite number followed by Hz, not '%s'", value);
        if (!(out->rate >= MEASURED_RATE_MIN && out->rate <= MEASURED_RATE_MAX))
            FAIL("sample_rate %g Hz is out of range; allowed: %g .. %g Hz", out->rate, MEASURED_RATE_MIN,
                 MEASURED_RATE_MAX);
        break;
    case KEY_SIGNAL:
        if ((out->signal = choice_in(value, signal_names, 2)) < 0)
            FAIL("signal must be deflection or voltage, not '%s'", value);
        break;
    case KEY_SIGNAL_UNIT:
        if ((h->signal_unit = choice_in(value, signal_units, 2)) < 0)
            FAIL("signal_unit must be m (deflection) or V (voltage), not '%s'", value);
        break;
    case KEY_ACCEL_UNIT:
        if (strcmp(value, "m/s^2") != 0)
            FAIL("base_accel_unit must be m/s^2, not '%s'", value);
        break;
    case KEY_LATENCY:
        if (input_number(value, "s", &out->latency) != 0 || !(out->latency >= 0.0))
            FAIL("latency must be a finite number >= 0 followed by s, not '%s'", value);
        break;
    case KEY_NOISE:
        for (which = 0; which < 2 && input_number(value, signal_units[which], &number) != 0; ++which)
            ;
        if (which == 2 || !(number > 0.0))
            FAIL("noise must be a finite number > 0 followed by the signal's unit (m or V), not '%s'", value);
        out->noise = number;
        h->noise_unit = which;
        break;
    case KEY_ACCEL_NOISE:
        if (input_number(value, "m/s^2", &out->accel_noise) != 0 || !(out->accel_noise >= 0.0))
            FAIL("accel_noise must be a finite number >= 0 followed by m/s^2, not '%s'", value);
        break;
    case KEY_PLANT:
    case KEYS:
        break;
    }
    return 0;
}

/* At the column line: the required fields given, the units agreeing with
 * the signal. */
static int header_complete(measured_reader *m, const header_state *h, char *err, size_t err_size)
{
    const measured_header *out = &m->header;
    const char *missing = !h->line[KEY_RATE] ? "sample_rate = ... Hz" : !h->line[KEY_SIGNAL] ? "signal = "
                                                                                                 "deflection (or "
                                                                                                 "voltage)"
                                                                                             : NULL;
    if (missing) {
        snprintf(err, err_size, "%s: the header (the lines before line %ld) has no line '# %s'", m->path,
                 m->lines.line, missing);
        return -1;
    }
    if (h->line[KEY_SIGNAL_UNIT] && h->signal_unit != out->signal) {
        snprintf(err, err_size, "%s:%ld: signal_unit = %s, but signal = %s is in %s", m->path,
                 h->line[KEY_SIGNAL_UNIT], signal_units[h->signal_unit], signal_names[out->signal],
                 signal_units[out->signal]);
        return -1;
    }
    if (h->line[KEY_NOISE] && h->noise_unit != out->signal) {
        snprintf(err, err_size, "%s:%ld: noise is given in %s, but signal = %s is in %s", m->path, h->line[KEY_NOISE],
                 signal_units[h->noise_unit], signal_names[out->signal], signal_units[out->signal]);
        return -1;
    }
    return 0;
}

/* The title, the header and the column line. */
static int read_header(measured_reader *m, char *err, size_t err_size)
{
    header_state h;
    const size_t title = strlen(MEASURED_TITLE);
    int status;

    memset(&h, 0, sizeof h);
    h.signal_unit = -1;
    m->header.rate = 0.0;
    m->header.signal = -1;
    m->header.noise = m->header.accel_noise = m->header.latency = (double)NAN;
    m->header.has_truth = 0;
    if ((status = next_line(m, err, err_size)) < 0)
        return -1;
    if (status == 0 || strncmp(m->text, MEASURED_TITLE, title) != 0
        || (m->text[title] != '\0' && m->text[title] != ' ')) {
        snprintf(err, err_size, "%s:1: not a measured-signals file: line 1 must be '%s' (docs/twin.md, \"Measured "
                 "signals file\")", m->path, MEASURED_TITLE);
        return -1;
    }
    while ((status = next_line(m, err, err_size)) > 0) {
        if (m->text[0] != '#')
            break;
        if (strchr(m->text, '=') && header_field(m, &h, m->text + 1, err, err_size) != 0)
            return -1;
    }
    if (status < 0)
        return -1;
    if (status == 0) {
        snprintf(err, err_size, "%s: no column line t,base_accel,signal[,s_true] (the file ends at line %ld)",
                 m->path, m->lines.line);
        return -1;
    }
    if (!strcmp(m->text, "t,base_accel,signal,s_true"))
        m->header.has_truth = 1;
    else if (strcmp(m->text, "t,base_accel,signal") != 0) {
        snprintf(err, err_size, "%s:%ld: expected the column line t,base_accel,signal[,s_true], got '%s'%s", m->path,
                 m->lines.line, m->text, m->text[0] ? "" : " (an empty line)");
        return -1;
    }
    return header_complete(m, &h, err, err_size);
}

int measured_open(measured_reader *m, const char *path, char *err, size_t err_size)
{
    const int is_stdin = !strcmp(path, "-");
    memset(m, 0, sizeof *m);
    m->path = is_stdin ? "standard input" : path;
    if (is_stdin)
        m->file = stdin;
    else if (input_file_open(path, INPUT_MEASURED, &m->file, NULL, err, err_size) != 0)
        return -1;
    input_lines_start(&m->lines, m->file, m->path, is_stdin ? 0 : input_kind_max_bytes(INPUT_MEASURED));
    if (read_header(m, err, err_size) != 0) {
        measured_close(m);
        return -1;
    }
    m->rows_at = m->lines.line;
    m->rows_offset = is_stdin ? -1 : (long long)ftello(m->file);
    return 0;
}

static const char *const column_names[4] = { "t", "base_accel", "signal", "s_true" };

int measured_next(measured_reader *m, measured_row *row, char *err, size_t err_size)
{
    const int columns = m->header.has_truth ? 4 : 3;
    const uint64_t k = m->rows + 1;
    double value[4], expected;
    char *field;
    int status, i;

    if ((status = next_line(m, err, err_size)) <= 0) {
        if (status == 0 && m->rows == 0) {
            snprintf(err, err_size, "%s: no rows after the column line (line %ld)", m->path, m->rows_at);
            return -1;
        }
        return status;
    }
    if (m->text[0] == '#')
        FAIL("a comment after the column line (comments belong to the header)");
    for (field = m->text, i = 0;; ++i) {
        char *comma = strchr(field, ',');
        if (comma)
            *comma = '\0';
        if (i == columns)
            FAIL("more than %d values: the column line names %d", columns, columns);
        if (*input_skip_blanks(field) == '\0')
            FAIL("empty value in column %s", column_names[i]);
        if (input_number(field, NULL, &value[i]) != 0)
            FAIL("%s '%s' is not a finite number", column_names[i], input_skip_blanks(field));
        if (!comma)
            break;
        field = comma + 1;
    }
    if (i + 1 < columns)
        FAIL("%d values: the column line names %d", i + 1, columns);
    /* row k holds t = k / rate: a missing, repeated or misplaced row is a
     * gap or another rate, and the twin would run on a shifted signal */
    expected = (double)k / m->header.rate;
    if (!(fabs(value[0] - expected) <= TIME_TOLERANCE / m->header.rate))
        FAIL("t = %.10g s, expected %.10g s (row %llu at sample_rate = %g Hz): a gap, a repeated row or another "
             "sample rate", value[0], expected, (unsigned long long)k, m->header.rate);
    row->t = value[0];
    row->base_accel = value[1];
    row->signal = value[2];
    row->s_true = columns == 4 ? value[3] : (double)NAN;
    m->rows = k;
    return 1;
}

int measured_rewind(measured_reader *m, char *err, size_t err_size)
{
    if (m->rows_offset < 0 || fseeko(m->file, (off_t)m->rows_offset, SEEK_SET) != 0) {
        snprintf(err, err_size, "%s: cannot be read twice", m->path);
        return -1;
    }
    m->rows = 0;
    m->lines.line = m->rows_at;
    m->lines.bytes = m->rows_offset;
    return 0;
}

void measured_close(measured_reader *m)
{
    if (m->file && m->file != stdin)
        fclose(m->file);
    m->file = NULL;
}

int measured_write_header(FILE *out, const measured_header *h, const char *plant)
{
    const int signal = h->signal == MEASURED_VOLTAGE ? MEASURED_VOLTAGE : MEASURED_DEFLECTION;
    int failed = fprintf(out, "%s (docs/twin.md, \"Observer\")\n", MEASURED_TITLE) < 0;
    if (plant) {
        char *line = malloc(strlen(plant) + 1);
        if (!line)
            return -1;
        strcpy(line, plant);
        failed |= fprintf(out, "# %s = %s\n", key_names[KEY_PLANT], out_text_one_line(line)) < 0;
        free(line);
    }
    failed |= fprintf(out, "# %s = %.12g Hz\n# %s = %s\n# %s = %s\n# %s = m/s^2\n", key_names[KEY_RATE], h->rate,
                      key_names[KEY_SIGNAL], signal_names[signal], key_names[KEY_SIGNAL_UNIT], signal_units[signal],
                      key_names[KEY_ACCEL_UNIT]) < 0;
    if (!isnan(h->latency))
        failed |= fprintf(out, "# %s = %.9g s\n", key_names[KEY_LATENCY], h->latency) < 0;
    if (!isnan(h->noise))
        failed |= fprintf(out, "# %s = %.9g %s\n", key_names[KEY_NOISE], h->noise, signal_units[signal]) < 0;
    if (!isnan(h->accel_noise))
        failed |= fprintf(out, "# %s = %.9g m/s^2\n", key_names[KEY_ACCEL_NOISE], h->accel_noise) < 0;
    failed |= fprintf(out, "%s,%s,%s%s%s\n", column_names[0], column_names[1], column_names[2],
                      h->has_truth ? "," : "", h->has_truth ? column_names[3] : "") < 0;
    return failed ? -1 : 0;
}

int measured_write_row(FILE *out, const measured_row *row, int has_truth)
{
    if (has_truth)
        return fprintf(out, "%.12g,%.9g,%.9g,%.9g\n", row->t, row->base_accel, row->signal, row->s_true) < 0 ? -1 : 0;
    return fprintf(out, "%.12g,%.9g,%.9g\n", row->t, row->base_accel, row->signal) < 0 ? -1 : 0;
}
