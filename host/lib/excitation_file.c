/* excitation_file.c - a recorded base acceleration: reading it (CSV, WAV)
 * and the mean of each step (excitation_file.h; docs/twin.md, "Recorded base
 * acceleration", states the format and the numerics).
 *
 * Step means. In sample units u = (t + latency - t0) fs the record is the
 * polyline through (j, x_j), j = 0 .. n - 1, and step k = 1, 2, ... spans
 *   [A, B] = [((k - 1) dt + latency - t0) fs, (k dt + latency - t0) fs],
 *   mean_k = integral_A^B x(u) du / (B - A).
 * On a piece [p, q] within [j, j + 1] the line's integral is (q - p) times
 * its value at (p + q) / 2, so the mean is exact for the polyline whether a
 * step spans many samples or a sample interval many steps. For a smooth
 * signal it differs from the signal's own mean by at most max|x''| / (8 fs^2)
 * (the error of linear interpolation; the trapezoid rule's max|x''| / (12 fs^2)
 * when sample and step times coincide). A and B are formed from k, never
 * accumulated, and may miss the record's ends by rounding only: COVER_SLACK
 * samples are accepted there.
 */
#define _POSIX_C_SOURCE 200809L /* open, fstat */

#include "excitation_file.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define CSV_TITLE "# beamslider base acceleration"
#define CSV_LINE 256          /* a CSV line holds at most CSV_LINE - 1 characters before its end */
#define TIME_TOLERANCE 0.01   /* a time column may miss t0 + k / fs by this many sample periods */
#define COVER_SLACK 1e-6      /* samples a step may reach past the record's ends (rounding) */

/* ---- the file's bytes */

/* The whole of a regular file (a FIFO or a device would never end) into
 * *bytes (malloc'd, at least one byte allocated); 0 or -1. */
static int read_bytes(const char *path, unsigned char **bytes, size_t *size, char *err, size_t err_size)
{
    struct stat info;
    const int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    size_t done = 0;

    *bytes = NULL;
    if (fd < 0) {
        snprintf(err, err_size, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (fstat(fd, &info) != 0) {
        snprintf(err, err_size, "%s: cannot read: %s", path, strerror(errno));
    } else if (!S_ISREG(info.st_mode)) {
        snprintf(err, err_size, "%s: not a regular file", path);
    } else if ((unsigned long long)info.st_size >= (size_t)-1
               || !(*bytes = malloc((size_t)info.st_size + 1))) {
        snprintf(err, err_size, "%s: %lld bytes: out of memory", path, (long long)info.st_size);
    } else {
        *size = (size_t)info.st_size;
        while (done < *size) {
            const ssize_t got = read(fd, *bytes + done, *size - done);
            if (got <= 0) {
                snprintf(err, err_size, "%s: cannot read: %s", path,
                         got < 0 ? strerror(errno) : "the file shrank while being read");
                break;
            }
            done += (size_t)got;
        }
        if (done == *size) {
            close(fd);
            return 0;
        }
        free(*bytes);
        *bytes = NULL;
    }
    close(fd);
    return -1;
}

/* Appends a sample, growing the array by doubling; 0 or -1 (out of memory). */
static int append(excitation_file *r, size_t *capacity, double value)
{
    if (r->samples == *capacity) {
        const size_t grown = *capacity ? 2 * *capacity : 4096;
        double *more = grown > (size_t)-1 / sizeof *more ? NULL : realloc(r->accel, grown * sizeof *more);
        if (!more)
            return -1;
        r->accel = more;
        *capacity = grown;
    }
    r->accel[r->samples++] = value;
    return 0;
}

/* ---- CSV */

typedef struct csv_reader {
    const char *path;
    const unsigned char *at, *end;
    int line;                 /* of text */
    char text[CSV_LINE];      /* the line, without its end (\n or \r\n) */
} csv_reader;

/* The next line into in->text: 1, 0 at the end, -1 with err filled. */
static int next_line(csv_reader *in, char *err, size_t err_size)
{
    size_t length = 0;
    if (in->at == in->end)
        return 0;
    ++in->line;
    while (in->at < in->end && *in->at != '\n') {
        if (*in->at == '\0') {
            snprintf(err, err_size, "%s:%d: a NUL byte: not a text file", in->path, in->line);
            return -1;
        }
        if (length == CSV_LINE - 1) {
            snprintf(err, err_size, "%s:%d: longer than %d characters", in->path, in->line, CSV_LINE - 1);
            return -1;
        }
        in->text[length++] = (char)*in->at++;
    }
    if (in->at < in->end)
        ++in->at; /* '\n' */
    if (length > 0 && in->text[length - 1] == '\r')
        --length;
    while (length > 0 && (in->text[length - 1] == ' ' || in->text[length - 1] == '\t'))
        --length;
    in->text[length] = '\0';
    return 1;
}

static const char *skip_blanks(const char *text)
{
    while (*text == ' ' || *text == '\t')
        ++text;
    return text;
}

/* text is a finite number followed by unit (NULL: by nothing), blanks
 * allowed between; 0 or -1. */
static int number_in(const char *text, const char *unit, double *value)
{
    char *end;
    const char *rest;
    text = skip_blanks(text);
    *value = strtod(text, &end);
    if (end == text || !isfinite(*value))
        return -1;
    rest = skip_blanks(end);
    if (unit) {
        if (strncmp(rest, unit, strlen(unit)) != 0)
            return -1;
        rest = skip_blanks(rest + strlen(unit));
    }
    return *rest == '\0' ? 0 : -1;
}

/* The header being read: which fields were set, and to what. */
typedef struct csv_header {
    int has_rate, has_unit, has_t0;
    double rate, unit, t0; /* unit: m/s^2 per unit of the values */
} csv_header;

/* A comment line of the header (text after '#'). A comment "key = value"
 * with key a word of lower-case letters, digits and '_' is a field; any
 * other comment is free text. 0 or -1 with err filled. */
static int header_line(const csv_reader *in, const char *text, csv_header *h, char *err, size_t err_size)
{
    char key[32];
    size_t n = 0;
    const char *value;

    text = skip_blanks(text);
    while (n < sizeof key - 1 && ((text[n] >= 'a' && text[n] <= 'z') || (text[n] >= '0' && text[n] <= '9')
                                  || text[n] == '_'))
        ++n;
    value = skip_blanks(text + n);
    if (n == 0 || *value != '=')
        return 0;
    memcpy(key, text, n);
    key[n] = '\0';
    ++value;
    if (!strcmp(key, "sample_rate")) {
        if (h->has_rate) {
            snprintf(err, err_size, "%s:%d: sample_rate given twice", in->path, in->line);
            return -1;
        }
        h->has_rate = 1;
        if (number_in(value, "Hz", &h->rate) != 0 || !(h->rate > 0.0)) {
            snprintf(err, err_size, "%s:%d: sample_rate must be a finite number > 0 followed by Hz, not '%s'",
                     in->path, in->line, skip_blanks(value));
            return -1;
        }
    } else if (!strcmp(key, "unit")) {
        value = skip_blanks(value);
        if (h->has_unit) {
            snprintf(err, err_size, "%s:%d: unit given twice", in->path, in->line);
            return -1;
        }
        h->has_unit = 1;
        if (!strcmp(value, "m/s^2")) {
            h->unit = 1.0;
        } else if (!strcmp(value, "g")) {
            h->unit = EXCITATION_G;
        } else {
            snprintf(err, err_size, "%s:%d: unit must be m/s^2 or g (%.5f m/s^2), not '%s'", in->path, in->line,
                     EXCITATION_G, value);
            return -1;
        }
    } else if (!strcmp(key, "t0")) {
        if (h->has_t0) {
            snprintf(err, err_size, "%s:%d: t0 given twice", in->path, in->line);
            return -1;
        }
        h->has_t0 = 1;
        if (number_in(value, "s", &h->t0) != 0) {
            snprintf(err, err_size, "%s:%d: t0 must be a finite number followed by s, not '%s'", in->path,
                     in->line, skip_blanks(value));
            return -1;
        }
    } else {
        snprintf(err, err_size, "%s:%d: unknown header field '%s' (known: sample_rate, unit, t0)", in->path,
                 in->line, key);
        return -1;
    }
    return 0;
}

/* The values of a data line, split at commas: 1 (acceleration) or 2 (time,
 * acceleration) into values; their count, or -1 with err filled. */
static int data_line(csv_reader *in, double values[2], char *err, size_t err_size)
{
    char *field = in->text;
    int count = 0;

    for (;;) {
        char *comma = strchr(field, ',');
        if (comma)
            *comma = '\0';
        if (count == 2) {
            snprintf(err, err_size, "%s:%d: more than 2 values: a line holds the acceleration, or the time and "
                     "the acceleration", in->path, in->line);
            return -1;
        }
        if (*skip_blanks(field) == '\0') {
            snprintf(err, err_size, "%s:%d: empty value", in->path, in->line);
            return -1;
        }
        if (number_in(field, NULL, &values[count]) != 0) {
            snprintf(err, err_size, "%s:%d: '%s' is not a finite number", in->path, in->line,
                     skip_blanks(field));
            return -1;
        }
        ++count;
        if (!comma)
            return count;
        field = comma + 1;
    }
}

/* A time column must give t0 + k / fs for sample k; t0 is the header's or,
 * without one, the first time. 0 or -1 with err filled. */
static int check_time(const csv_reader *in, const csv_header *h, excitation_file *r, double t,
                      double t_previous, char *err, size_t err_size)
{
    const double period = 1.0 / h->rate;
    const double expected = r->t0 + (double)r->samples * period;
    if (r->samples == 0 && !h->has_t0) {
        r->t0 = t;
        return 0;
    }
    if (fabs(t - expected) <= TIME_TOLERANCE * period)
        return 0;
    if (r->samples == 0)
        snprintf(err, err_size, "%s:%d: the first time is %.9g s, the header's t0 %.9g s", in->path, in->line,
                 t, r->t0);
    else if (t - t_previous > 1.5 * period)
        snprintf(err, err_size, "%s:%d: a gap: t = %.9g s follows t = %.9g s, samples are 1/sample_rate = "
                 "%.9g s apart", in->path, in->line, t, t_previous, period);
    else
        snprintf(err, err_size, "%s:%d: t = %.9g s, expected %.9g s (t0 + %lu / sample_rate): samples must be "
                 "1/sample_rate = %.9g s apart, to within %g %% of that", in->path, in->line, t, expected,
                 (unsigned long)r->samples, period, 100.0 * TIME_TOLERANCE);
    return -1;
}

/* The header must have set the rate and the unit before the first value. */
static int check_header(const csv_reader *in, const csv_header *h, char *err, size_t err_size)
{
    const char *missing = !h->has_rate ? "sample_rate = ... Hz" : !h->has_unit ? "unit = m/s^2 (or g)" : NULL;
    if (!missing)
        return 0;
    snprintf(err, err_size, "%s: the header (the comment lines before line %d) has no line '# %s'", in->path,
             in->line, missing);
    return -1;
}

static int read_csv(const char *path, const unsigned char *bytes, size_t size, const excitation_file_options *o,
                    excitation_file *r, char *err, size_t err_size)
{
    csv_reader in;
    csv_header h;
    size_t capacity = 0;
    int columns = 0, status;
    double t_previous = 0.0;

    if (o->has_scale || o->channel) {
        snprintf(err, err_size, "%s: %s is for WAV files; this CSV record states its unit in its header", path,
                 o->has_scale ? "--scale" : "--channel");
        return -1;
    }
    in.path = path;
    in.at = bytes;
    in.end = bytes + size;
    in.line = 0;
    memset(&h, 0, sizeof h);
    if ((status = next_line(&in, err, err_size)) < 0)
        return -1;
    if (status == 0 || strcmp(in.text, CSV_TITLE) != 0) {
        snprintf(err, err_size, "%s:1: not a base acceleration record: a CSV record begins with the line '%s' "
                 "(docs/twin.md), a WAV file with RIFF", path, CSV_TITLE);
        return -1;
    }
    while ((status = next_line(&in, err, err_size)) > 0) {
        double values[2];
        int count;
        if (in.text[0] == '#') {
            if (r->samples > 0) {
                snprintf(err, err_size, "%s:%d: a comment after the first value (comments belong to the "
                         "header)", path, in.line);
                return -1;
            }
            if (header_line(&in, in.text + 1, &h, err, err_size) != 0)
                return -1;
            continue;
        }
        if (r->samples == 0) {
            if (check_header(&in, &h, err, err_size) != 0)
                return -1;
            r->rate = h.rate;
            r->t0 = h.t0;
        }
        if ((count = data_line(&in, values, err, err_size)) < 0)
            return -1;
        if (columns == 0)
            columns = count;
        if (count != columns) {
            snprintf(err, err_size, "%s:%d: %d value(s), the lines before hold %d", path, in.line, count,
                     columns);
            return -1;
        }
        if (count == 2) {
            if (check_time(&in, &h, r, values[0], t_previous, err, err_size) != 0)
                return -1;
            t_previous = values[0];
        }
        if (append(r, &capacity, values[count - 1] * h.unit) != 0) {
            snprintf(err, err_size, "%s:%d: out of memory", path, in.line);
            return -1;
        }
    }
    if (status < 0)
        return -1;
    if (r->samples == 0) {
        ++in.line; /* "before line n + 1": the end */
        if (check_header(&in, &h, err, err_size) == 0)
            snprintf(err, err_size, "%s: no samples", path);
        return -1;
    }
    return 0;
}

/* ---- WAV (RIFF, little-endian) */

static unsigned le16(const unsigned char *b)
{
    return (unsigned)b[0] | (unsigned)b[1] << 8;
}

static unsigned long le32(const unsigned char *b)
{
    return (unsigned long)b[0] | (unsigned long)b[1] << 8 | (unsigned long)b[2] << 16
           | (unsigned long)b[3] << 24;
}

/* A chunk id for a message: printable ASCII, '?' for any other byte. */
static void chunk_name(const unsigned char *id, char name[5])
{
    int i;
    for (i = 0; i < 4; ++i)
        name[i] = id[i] >= 0x20 && id[i] < 0x7f ? (char)id[i] : '?';
    name[4] = '\0';
}

/* Sample value of a frame, full scale 1: PCM integers of n bits over 2^(n-1),
 * floats as stored. */
static double wav_value(const unsigned char *b, int is_float, unsigned bits)
{
    if (is_float) {
        const uint32_t word = (uint32_t)le32(b);
        float value;
        memcpy(&value, &word, sizeof value);
        return (double)value;
    }
    if (bits == 16)
        return (double)(int16_t)le16(b) / 32768.0;
    if (bits == 24) {
        const long word = (long)((unsigned long)b[0] | (unsigned long)b[1] << 8 | (unsigned long)b[2] << 16);
        return (double)(word >= 0x800000L ? word - 0x1000000L : word) / 8388608.0;
    }
    return (double)(int32_t)(uint32_t)le32(b) / 2147483648.0;
}

/* The samples of the 'fmt ' chunk's format from the 'data' chunk; 0 or -1. */
static int wav_samples(const char *path, const unsigned char *fmt, unsigned long fmt_size,
                       const unsigned char *data, unsigned long data_size, const excitation_file_options *o,
                       excitation_file *r, char *err, size_t err_size)
{
    unsigned tag, channels, block, bits, channel;
    unsigned long rate, frames, k;
    int is_float;

    if (fmt_size < 16) {
        snprintf(err, err_size, "%s: the 'fmt ' chunk has %lu bytes, fewer than 16", path, fmt_size);
        return -1;
    }
    tag = le16(fmt);
    channels = le16(fmt + 2);
    rate = le32(fmt + 4);
    block = le16(fmt + 12);
    bits = le16(fmt + 14);
    if (tag == 0xFFFEu) { /* WAVE_FORMAT_EXTENSIBLE: the format is the sub-format GUID's first two bytes */
        if (fmt_size < 40) {
            snprintf(err, err_size, "%s: an extensible 'fmt ' chunk of %lu bytes, fewer than 40", path,
                     fmt_size);
            return -1;
        }
        tag = le16(fmt + 24);
    }
    is_float = tag == 3;
    if (tag != 1 && tag != 3) {
        snprintf(err, err_size, "%s: sample format 0x%04x: only PCM integers (1) and IEEE floats (3) are read",
                 path, tag);
        return -1;
    }
    if (is_float ? bits != 32 : bits != 16 && bits != 24 && bits != 32) {
        snprintf(err, err_size, "%s: %u-bit %s samples: read are 16-, 24- and 32-bit integers and 32-bit "
                 "floats", path, bits, is_float ? "float" : "integer");
        return -1;
    }
    if (channels == 0 || rate == 0) {
        snprintf(err, err_size, "%s: %s 0 in the 'fmt ' chunk", path,
                 channels == 0 ? "channel count" : "sample rate");
        return -1;
    }
    if (block != channels * (bits / 8)) {
        snprintf(err, err_size, "%s: block align %u, not %u channel(s) of %u bits", path, block, channels,
                 bits);
        return -1;
    }
    if (data_size % block != 0) {
        snprintf(err, err_size, "%s: truncated: the 'data' chunk holds %lu bytes, not whole %u-byte frames",
                 path, data_size, block);
        return -1;
    }
    frames = data_size / block;
    if (frames == 0) {
        snprintf(err, err_size, "%s: no samples", path);
        return -1;
    }
    if (channels > 1 && o->channel == 0) {
        snprintf(err, err_size, "%s has %u channels: choose one with --channel N (1 to %u)", path, channels,
                 channels);
        return -1;
    }
    if ((unsigned)o->channel > channels) {
        snprintf(err, err_size, "%s: --channel %d, but the file has %u channel(s)", path, o->channel, channels);
        return -1;
    }
    r->accel = malloc(frames * sizeof *r->accel);
    if (!r->accel) {
        snprintf(err, err_size, "%s: %lu samples: out of memory", path, frames);
        return -1;
    }
    channel = o->channel > 0 ? (unsigned)o->channel - 1 : 0;
    for (k = 0; k < frames; ++k) {
        const double value = wav_value(data + k * block + channel * (bits / 8), is_float, bits);
        if (!isfinite(value)) {
            snprintf(err, err_size, "%s: sample %lu (from 0; channel %u) is not a finite number", path, k,
                     channel + 1);
            return -1;
        }
        r->accel[k] = value * o->scale;
    }
    r->samples = frames;
    r->rate = (double)rate;
    r->t0 = 0.0;
    return 0;
}

/* Walks the chunks (skipping unknown ones, each padded to an even size)
 * within the RIFF size, which the file must hold. */
static int read_wav(const char *path, const unsigned char *bytes, size_t size, const excitation_file_options *o,
                    excitation_file *r, char *err, size_t err_size)
{
    const unsigned char *fmt = NULL, *data = NULL;
    unsigned long fmt_size = 0, data_size = 0, riff_size;
    size_t at, end;

    if (!o->has_scale) {
        snprintf(err, err_size, "%s is a WAV file: give --scale S, the acceleration of full scale [m/s^2]",
                 path);
        return -1;
    }
    if (size < 12 || memcmp(bytes + 8, "WAVE", 4) != 0) {
        snprintf(err, err_size, "%s: a RIFF file, but not WAVE", path);
        return -1;
    }
    riff_size = le32(bytes + 4);
    if (riff_size < 4 || riff_size > size - 8) {
        snprintf(err, err_size, "%s: truncated: the RIFF header declares %lu bytes after it, the file holds "
                 "%lu", path, riff_size, (unsigned long)(size - 8));
        return -1;
    }
    end = (size_t)riff_size + 8;
    for (at = 12; at < end; ) {
        unsigned long chunk_size;
        char name[5];
        if (end - at < 8) {
            snprintf(err, err_size, "%s: truncated: %lu bytes at byte %lu, too few for a chunk header", path,
                     (unsigned long)(end - at), (unsigned long)at);
            return -1;
        }
        chunk_name(bytes + at, name);
        chunk_size = le32(bytes + at + 4);
        if (chunk_size > end - at - 8) {
            snprintf(err, err_size, "%s: truncated: chunk '%s' at byte %lu declares %lu bytes, %lu follow",
                     path, name, (unsigned long)at, chunk_size, (unsigned long)(end - at - 8));
            return -1;
        }
        if (!memcmp(bytes + at, "fmt ", 4) || !memcmp(bytes + at, "data", 4)) {
            const int is_fmt = bytes[at] == 'f';
            if (is_fmt ? fmt != NULL : data != NULL) {
                snprintf(err, err_size, "%s: a second '%s' chunk at byte %lu", path, name, (unsigned long)at);
                return -1;
            }
            if (is_fmt) {
                fmt = bytes + at + 8;
                fmt_size = chunk_size;
            } else {
                data = bytes + at + 8;
                data_size = chunk_size;
            }
        }
        at += 8 + (size_t)chunk_size + (chunk_size & 1u); /* past the pad byte of an odd size */
    }
    if (!fmt || !data) {
        snprintf(err, err_size, "%s: no '%s' chunk", path, !fmt ? "fmt " : "data");
        return -1;
    }
    return wav_samples(path, fmt, fmt_size, data, data_size, o, r, err, err_size);
}

/* ---- the record */

int excitation_file_read(const char *path, const excitation_file_options *options, excitation_file *record,
                         char *err, size_t err_size)
{
    unsigned char *bytes;
    size_t size;
    int status;

    memset(record, 0, sizeof *record);
    record->path = path;
    record->latency = options->latency;
    if (!(options->latency >= 0.0 && isfinite(options->latency))) {
        snprintf(err, err_size, "latency %g s: must be finite and >= 0", options->latency);
        return -1;
    }
    if (options->has_scale && !(options->scale > 0.0 && isfinite(options->scale))) {
        snprintf(err, err_size, "scale %g m/s^2: must be finite and > 0", options->scale);
        return -1;
    }
    if (read_bytes(path, &bytes, &size, err, err_size) != 0)
        return -1;
    if (size >= 4 && !memcmp(bytes, "RIFF", 4)) {
        record->format = "wav";
        status = read_wav(path, bytes, size, options, record, err, err_size);
    } else {
        record->format = "csv";
        status = read_csv(path, bytes, size, options, record, err, err_size);
    }
    free(bytes);
    if (status != 0)
        excitation_file_free(record);
    return status;
}

void excitation_file_free(excitation_file *record)
{
    free(record->accel);
    record->accel = NULL;
    record->samples = 0;
}

/* ---- step means */

/* Step k's span [a, b] in samples from sample 0. */
static void step_span(const excitation_file *r, double dt, uint64_t k, double *a, double *b)
{
    const double shift = r->latency - r->t0;
    *a = ((double)(k - 1) * dt + shift) * r->rate;
    *b = ((double)k * dt + shift) * r->rate;
}

/* 1 if steps 1 .. steps (>= 1) lie within the record. */
static int covers(const excitation_file *r, double dt, uint64_t steps)
{
    double a, b;
    step_span(r, dt, 1, &a, &b);
    if (a < -COVER_SLACK)
        return 0;
    step_span(r, dt, steps, &a, &b);
    return b <= (double)(r->samples - 1) + COVER_SLACK;
}

uint64_t excitation_file_steps(const excitation_file *r, double dt)
{
    /* the time the record reaches, less the latency: an estimate, then the test itself */
    const double reach = r->t0 + ((double)(r->samples - 1) + COVER_SLACK) / r->rate - r->latency;
    uint64_t steps = reach >= dt ? (uint64_t)(reach / dt) : 0;
    if (steps > 0 && !covers(r, dt, 1))
        return 0; /* the record begins after t = latency */
    while (steps > 0 && !covers(r, dt, steps))
        --steps;
    return steps;
}

/* Integral of the polyline through x[0 .. samples - 1] over [lo, hi] (sample
 * units, 0 <= lo <= hi <= samples - 1, samples >= 2). */
static double polyline_integral(const double *x, size_t samples, double lo, double hi)
{
    size_t j = (size_t)lo;
    double sum = 0.0, p = lo;
    if (j > samples - 2)
        j = samples - 2; /* lo at the last sample */
    for (; p < hi; ++j) {
        const double q = fmin(hi, (double)(j + 1));
        sum += (q - p) * (x[j] + (x[j + 1] - x[j]) * (0.5 * (p + q) - (double)j));
        p = q;
    }
    return sum;
}

int excitation_file_means(const excitation_file *r, double dt, uint64_t steps, double *means, char *err,
                          size_t err_size)
{
    const double last = (double)(r->samples - 1);
    uint64_t k;

    if (steps > 0 && !covers(r, dt, steps)) {
        snprintf(err, err_size, "%s covers t = %.9g .. %.9g s (%.9g s: %lu samples at %g Hz); the run needs "
                 "t = %.9g .. %.9g s (t_end %.9g s, latency %.9g s)", r->path, r->t0, r->t0 + last / r->rate,
                 last / r->rate, (unsigned long)r->samples, r->rate, r->latency,
                 (double)steps * dt + r->latency, (double)steps * dt, r->latency);
        return -1;
    }
    for (k = 1; k <= steps; ++k) {
        double a, b, lo, hi;
        step_span(r, dt, k, &a, &b);
        lo = fmax(a, 0.0); /* within COVER_SLACK (covers) */
        hi = fmin(b, last);
        means[k - 1] = polyline_integral(r->accel, r->samples, lo, hi) / (hi - lo);
    }
    return 0;
}
