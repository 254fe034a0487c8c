/* excitation_file.c - a recorded base acceleration: reading it (CSV, WAV),
 * streaming, and the mean of each step (excitation_file.h; docs/twin.md,
 * "Recorded base acceleration", states the format and the numerics).
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
 *
 * Streaming. Step k + 1 starts where step k ends (B_k and A_(k+1) are the
 * same expression), so the pieces of the steps run through the samples in
 * order and only the two samples of the current piece are needed: the means
 * engine pulls samples one by one and keeps the last two. No count derived
 * from the file (samples, steps) is converted to an integer or used to size
 * anything before it is known to be in range; nothing is sized by it at all.
 */
#define _POSIX_C_SOURCE 200809L /* fseeko */

#include "excitation_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CSV_TITLE "# beamslider base acceleration"
#define TIME_TOLERANCE 0.01   /* a time column may miss t0 + k / fs by this many sample periods */
#define COVER_SLACK 1e-6      /* samples a step may reach past the record's ends (rounding) */

/* ---- CSV */

/* The next line of the record into s->text, trailing blanks removed: 1, 0
 * at the end, -1 with err filled. */
static int next_line(excitation_source *s, char *err, size_t err_size)
{
    const int status = input_lines_next(&s->lines, s->text, sizeof s->text, err, err_size);
    if (status > 0)
        input_trim_end(s->text);
    return status;
}

/* The header being read: which fields were set, and to what. */
typedef struct csv_header {
    int has_rate, has_unit, has_t0;
    double rate, unit, t0; /* unit: m/s^2 per unit of the values */
} csv_header;

/* t0 (of the header, or the first time of a time column) within its range;
 * 0 or -1 with err filled. */
static int check_t0(const excitation_source *s, const char *what, double t0, char *err, size_t err_size)
{
    if (fabs(t0) <= EXCITATION_T0_MAX)
        return 0;
    snprintf(err, err_size, "%s:%ld: %s %g s is out of range; allowed: %g .. %g s", s->path, s->lines.line, what, t0,
             -EXCITATION_T0_MAX, EXCITATION_T0_MAX);
    return -1;
}

/* A comment line of the header (text after '#'). A comment "key = value"
 * with key a word of lower-case letters, digits and '_' is a field; any
 * other comment is free text. 0 or -1 with err filled. */
static int header_line(const excitation_source *s, const char *text, csv_header *h, char *err, size_t err_size)
{
    const char *path = s->path;
    const long line = s->lines.line;
    char key[32];
    size_t n = 0;
    const char *value;

    text = input_skip_blanks(text);
    while (n < sizeof key - 1 && ((text[n] >= 'a' && text[n] <= 'z') || (text[n] >= '0' && text[n] <= '9')
                                  || text[n] == '_'))
        ++n;
    value = input_skip_blanks(text + n);
    if (n == 0 || *value != '=')
        return 0;
    memcpy(key, text, n);
    key[n] = '\0';
    ++value;
    if (!strcmp(key, "sample_rate")) {
        if (h->has_rate) {
            snprintf(err, err_size, "%s:%ld: sample_rate given twice", path, line);
            return -1;
        }
        h->has_rate = 1;
        if (input_number(value, "Hz", &h->rate) != 0 || !(h->rate > 0.0)) {
            snprintf(err, err_size, "%s:%ld: sample_rate must be a finite number > 0 followed by Hz, not '%s'",
                     path, line, input_skip_blanks(value));
            return -1;
        }
        if (!(h->rate >= EXCITATION_RATE_MIN && h->rate <= EXCITATION_RATE_MAX)) {
            snprintf(err, err_size, "%s:%ld: sample_rate %g Hz is out of range; allowed: %g .. %g Hz", path, line,
                     h->rate, EXCITATION_RATE_MIN, EXCITATION_RATE_MAX);
            return -1;
        }
    } else if (!strcmp(key, "unit")) {
        value = input_skip_blanks(value);
        if (h->has_unit) {
            snprintf(err, err_size, "%s:%ld: unit given twice", path, line);
            return -1;
        }
        h->has_unit = 1;
        if (!strcmp(value, "m/s^2")) {
            h->unit = 1.0;
        } else if (!strcmp(value, "g")) {
            h->unit = EXCITATION_G;
        } else {
            snprintf(err, err_size, "%s:%ld: unit must be m/s^2 or g (%.5f m/s^2), not '%s'", path, line,
                     EXCITATION_G, value);
            return -1;
        }
    } else if (!strcmp(key, "t0")) {
        if (h->has_t0) {
            snprintf(err, err_size, "%s:%ld: t0 given twice", path, line);
            return -1;
        }
        h->has_t0 = 1;
        if (input_number(value, "s", &h->t0) != 0) {
            snprintf(err, err_size, "%s:%ld: t0 must be a finite number followed by s, not '%s'", path, line,
                     input_skip_blanks(value));
            return -1;
        }
        return check_t0(s, "t0", h->t0, err, err_size);
    } else {
        snprintf(err, err_size, "%s:%ld: unknown header field '%s' (known: sample_rate, unit, t0)", path, line, key);
        return -1;
    }
    return 0;
}

/* The values of the data line in s->text, split at commas: 1 (acceleration)
 * or 2 (time, acceleration) into values; their count, or -1 with err filled. */
static int data_line(excitation_source *s, double values[2], char *err, size_t err_size)
{
    char *field = s->text;
    int count = 0;

    for (;;) {
        char *comma = strchr(field, ',');
        if (comma)
            *comma = '\0';
        if (count == 2) {
            snprintf(err, err_size, "%s:%ld: more than 2 values: a line holds the acceleration, or the time and "
                     "the acceleration", s->path, s->lines.line);
            return -1;
        }
        if (*input_skip_blanks(field) == '\0') {
            snprintf(err, err_size, "%s:%ld: empty value", s->path, s->lines.line);
            return -1;
        }
        if (input_number(field, NULL, &values[count]) != 0) {
            snprintf(err, err_size, "%s:%ld: '%s' is not a finite number", s->path, s->lines.line, input_skip_blanks(field));
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
static int check_time(excitation_source *s, double t, char *err, size_t err_size)
{
    const double period = 1.0 / s->rate;
    const double expected = s->t0 + (double)s->samples * period;
    if (s->samples == 0 && !s->has_t0) {
        s->t0 = t;
        return check_t0(s, "the first time (t0)", t, err, err_size);
    }
    if (fabs(t - expected) <= TIME_TOLERANCE * period)
        return 0;
    if (s->samples == 0)
        snprintf(err, err_size, "%s:%ld: the first time is %.9g s, the header's t0 %.9g s", s->path, s->lines.line,
                 t, s->t0);
    else if (t - s->t_previous > 1.5 * period)
        snprintf(err, err_size, "%s:%ld: a gap: t = %.9g s follows t = %.9g s, samples are 1/sample_rate = "
                 "%.9g s apart", s->path, s->lines.line, t, s->t_previous, period);
    else
        snprintf(err, err_size, "%s:%ld: t = %.9g s, expected %.9g s (t0 + %llu / sample_rate): samples must be "
                 "1/sample_rate = %.9g s apart, to within %g %% of that", s->path, s->lines.line, t, expected,
                 (unsigned long long)s->samples, period, 100.0 * TIME_TOLERANCE);
    return -1;
}

/* The header must have set the rate and the unit before the first value. */
static int check_header(const excitation_source *s, const csv_header *h, long line, char *err, size_t err_size)
{
    const char *missing = !h->has_rate ? "sample_rate = ... Hz" : !h->has_unit ? "unit = m/s^2 (or g)" : NULL;
    if (!missing)
        return 0;
    snprintf(err, err_size, "%s: the header (the comment lines before line %ld) has no line '# %s'", s->path, line,
             missing);
    return -1;
}

/* The sample of the data line in s->text (sample s->samples); 0 or -1. */
static int csv_value(excitation_source *s, double *value, char *err, size_t err_size)
{
    double values[2];
    int count;

    if ((count = data_line(s, values, err, err_size)) < 0)
        return -1;
    if (s->columns == 0)
        s->columns = count;
    if (count != s->columns) {
        snprintf(err, err_size, "%s:%ld: %d value(s), the lines before hold %d", s->path, s->lines.line, count,
                 s->columns);
        return -1;
    }
    if (count == 2) {
        if (check_time(s, values[0], err, err_size) != 0)
            return -1;
        s->t_previous = values[0];
    }
    *value = values[count - 1] * s->unit;
    if (!isfinite(*value)) {
        snprintf(err, err_size, "%s:%ld: %g g is %g m/s^2: beyond the range of double", s->path, s->lines.line,
                 values[count - 1], *value);
        return -1;
    }
    return 0;
}

/* The next sample of a CSV record. */
static int next_csv(excitation_source *s, double *value, char *err, size_t err_size)
{
    int status;
    if (s->pending) {
        s->pending = 0;
        *value = s->pending_value;
        return 1;
    }
    if ((status = next_line(s, err, err_size)) <= 0)
        return status;
    if (s->text[0] == '#') {
        snprintf(err, err_size, "%s:%ld: a comment after the first value (comments belong to the header)", s->path,
                 s->lines.line);
        return -1;
    }
    return csv_value(s, value, err, err_size) == 0 ? 1 : -1;
}

/* The header, and the first sample (pending). */
static int open_csv(excitation_source *s, const excitation_file_options *o, char *err, size_t err_size)
{
    csv_header h;
    int status;

    if (o->has_scale || o->channel) {
        snprintf(err, err_size, "%s: %s is for WAV files; this CSV record states its unit in its header", s->path,
                 o->has_scale ? "--scale" : "--channel");
        return -1;
    }
    memset(&h, 0, sizeof h);
    if ((status = next_line(s, err, err_size)) < 0)
        return -1;
    if (status == 0 || strcmp(s->text, CSV_TITLE) != 0) {
        snprintf(err, err_size, "%s:1: not a base acceleration record: a CSV record begins with the line '%s' "
                 "(docs/twin.md), a WAV file with RIFF", s->path, CSV_TITLE);
        return -1;
    }
    while ((status = next_line(s, err, err_size)) > 0 && s->text[0] == '#')
        if (header_line(s, s->text + 1, &h, err, err_size) != 0)
            return -1;
    if (status < 0)
        return -1;
    /* the end, or the first data line: "before line n" (n + 1 at the end) */
    if (check_header(s, &h, s->lines.line + (status == 0), err, err_size) != 0)
        return -1;
    if (status == 0) {
        snprintf(err, err_size, "%s: no samples", s->path);
        return -1;
    }
    s->rate = h.rate;
    s->unit = h.unit;
    s->t0 = h.t0;
    s->has_t0 = h.has_t0;
    s->first_line = s->lines.line;
    /* the first sample now: a time column's first time is t0 */
    if (csv_value(s, &s->pending_value, err, err_size) != 0)
        return -1;
    s->pending = 1;
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

/* The format of the 'fmt ' chunk (its first fmt_read bytes in fmt, of
 * fmt_size) for frames in data_size bytes; 0 or -1. */
static int wav_format(excitation_source *s, const unsigned char *fmt, unsigned long fmt_size,
                      unsigned long data_size, const excitation_file_options *o, char *err, size_t err_size)
{
    const char *path = s->path;
    unsigned tag, channels, block, bits;
    unsigned long rate;

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
            snprintf(err, err_size, "%s: an extensible 'fmt ' chunk of %lu bytes, fewer than 40", path, fmt_size);
            return -1;
        }
        tag = le16(fmt + 24);
    }
    s->is_float = tag == 3;
    if (tag != 1 && tag != 3) {
        snprintf(err, err_size, "%s: sample format 0x%04x: only PCM integers (1) and IEEE floats (3) are read",
                 path, tag);
        return -1;
    }
    if (s->is_float ? bits != 32 : bits != 16 && bits != 24 && bits != 32) {
        snprintf(err, err_size, "%s: %u-bit %s samples: read are 16-, 24- and 32-bit integers and 32-bit "
                 "floats", path, bits, s->is_float ? "float" : "integer");
        return -1;
    }
    if (channels == 0 || rate == 0) {
        snprintf(err, err_size, "%s: %s 0 in the 'fmt ' chunk", path, channels == 0 ? "channel count" : "sample rate");
        return -1;
    }
    if (block != channels * (bits / 8)) {
        snprintf(err, err_size, "%s: block align %u, not %u channel(s) of %u bits", path, block, channels, bits);
        return -1;
    }
    if (data_size % block != 0) {
        snprintf(err, err_size, "%s: truncated: the 'data' chunk holds %lu bytes, not whole %u-byte frames", path,
                 data_size, block);
        return -1;
    }
    if (data_size == 0) {
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
    s->frames = data_size / block;
    s->block = block;
    s->bits = bits;
    s->channel = o->channel > 0 ? (unsigned)o->channel - 1 : 0;
    s->scale = o->scale;
    s->rate = (double)rate; /* an integer below 2^32: within [EXCITATION_RATE_MIN, EXCITATION_RATE_MAX] */
    s->t0 = 0.0;
    return 0;
}

/* Walks the chunks (skipping unknown ones, each padded to an even size)
 * within the RIFF size, which the file (of size bytes) must hold, and
 * leaves the file at the first frame. */
static int open_wav(excitation_source *s, long long size, const excitation_file_options *o, char *err,
                    size_t err_size)
{
    const char *path = s->path;
    unsigned char head[12], chunk[8], fmt[40];
    unsigned long fmt_size = 0, data_size = 0, riff_size;
    long long at, end, data_at = -1;
    int has_fmt = 0;

    if (!o->has_scale) {
        snprintf(err, err_size, "%s is a WAV file: give --scale S, the acceleration of full scale [m/s^2]", path);
        return -1;
    }
    if (size < 12 || fread(head, 1, 12, s->file) != 12 || memcmp(head + 8, "WAVE", 4) != 0) {
        snprintf(err, err_size, "%s: a RIFF file, but not WAVE", path);
        return -1;
    }
    riff_size = le32(head + 4);
    if (riff_size < 4 || (long long)riff_size > size - 8) {
        snprintf(err, err_size, "%s: truncated: the RIFF header declares %lu bytes after it, the file holds %lld",
                 path, riff_size, size - 8);
        return -1;
    }
    end = (long long)riff_size + 8;
    for (at = 12; at < end;) {
        unsigned long chunk_size;
        char name[5];
        if (end - at < 8) {
            snprintf(err, err_size, "%s: truncated: %lld bytes at byte %lld, too few for a chunk header", path,
                     end - at, at);
            return -1;
        }
        if (fseeko(s->file, (off_t)at, SEEK_SET) != 0 || fread(chunk, 1, 8, s->file) != 8) {
            snprintf(err, err_size, "%s: cannot read the chunk at byte %lld", path, at);
            return -1;
        }
        chunk_name(chunk, name);
        chunk_size = le32(chunk + 4);
        if ((long long)chunk_size > end - at - 8) {
            snprintf(err, err_size, "%s: truncated: chunk '%s' at byte %lld declares %lu bytes, %lld follow", path,
                     name, at, chunk_size, end - at - 8);
            return -1;
        }
        if (!memcmp(chunk, "fmt ", 4) || !memcmp(chunk, "data", 4)) {
            const int is_fmt = chunk[0] == 'f';
            if (is_fmt ? has_fmt : data_at >= 0) {
                snprintf(err, err_size, "%s: a second '%s' chunk at byte %lld", path, name, at);
                return -1;
            }
            if (is_fmt) {
                const size_t want = chunk_size < sizeof fmt ? (size_t)chunk_size : sizeof fmt;
                if (fread(fmt, 1, want, s->file) != want) {
                    snprintf(err, err_size, "%s: cannot read the 'fmt ' chunk", path);
                    return -1;
                }
                has_fmt = 1;
                fmt_size = chunk_size;
            } else {
                data_at = at + 8;
                data_size = chunk_size;
            }
        }
        at += 8 + (long long)chunk_size + (long long)(chunk_size & 1u); /* past the pad byte of an odd size */
    }
    if (!has_fmt || data_at < 0) {
        snprintf(err, err_size, "%s: no '%s' chunk", path, !has_fmt ? "fmt " : "data");
        return -1;
    }
    if (wav_format(s, fmt, fmt_size, data_size, o, err, err_size) != 0)
        return -1;
    if (fseeko(s->file, (off_t)data_at, SEEK_SET) != 0) {
        snprintf(err, err_size, "%s: cannot read the 'data' chunk", path);
        return -1;
    }
    return 0;
}

/* The next frame's sample of the chosen channel. */
static int next_wav(excitation_source *s, double *value, char *err, size_t err_size)
{
    const unsigned width = s->bits / 8, from = s->channel * width;
    unsigned char bytes[256], sample[4];
    unsigned done = 0;

    if (s->samples == s->frames)
        return 0;
    while (done < s->block) { /* the frame, keeping the channel's bytes */
        const unsigned n = s->block - done < sizeof bytes ? s->block - done : (unsigned)sizeof bytes;
        unsigned i;
        if (fread(bytes, 1, n, s->file) != n) {
            snprintf(err, err_size, "%s: sample %llu: cannot read (the file shrank?)", s->path,
                     (unsigned long long)s->samples);
            return -1;
        }
        for (i = 0; i < n; ++i)
            if (done + i >= from && done + i < from + width)
                sample[done + i - from] = bytes[i];
        done += n;
    }
    *value = wav_value(sample, s->is_float, s->bits);
    if (!isfinite(*value)) {
        snprintf(err, err_size, "%s: sample %llu (from 0; channel %u) is not a finite number", s->path,
                 (unsigned long long)s->samples, s->channel + 1);
        return -1;
    }
    *value *= s->scale;
    if (!isfinite(*value)) {
        snprintf(err, err_size, "%s: sample %llu (from 0; channel %u) times --scale %g is beyond the range of "
                 "double", s->path, (unsigned long long)s->samples, s->channel + 1, s->scale);
        return -1;
    }
    return 1;
}

/* ---- a record's samples, in order */

static void source_close(excitation_source *s)
{
    if (s->file)
        fclose(s->file);
    s->file = NULL;
}

/* Opens path and reads its header (CSV: up to the first data line). */
static int source_open(excitation_source *s, const char *path, const excitation_file_options *o,
                       input_identity *identity, char *err, size_t err_size)
{
    unsigned char magic[4];
    int status;

    memset(s, 0, sizeof *s);
    s->path = path;
    s->latency = o->latency;
    if (input_file_open(path, INPUT_RECORD, &s->file, identity, err, err_size) != 0)
        return -1;
    s->is_wav = fread(magic, 1, 4, s->file) == 4 && !memcmp(magic, "RIFF", 4);
    rewind(s->file);
    input_lines_start(&s->lines, s->file, path, input_kind_max_bytes(INPUT_RECORD));
    status = s->is_wav ? open_wav(s, (long long)identity->size, o, err, err_size) : open_csv(s, o, err, err_size);
    if (status != 0)
        source_close(s);
    return status;
}

/* excitation_sample_fn of a source: the next sample, counted. */
static int source_next(void *source, double *value, char *err, size_t err_size)
{
    excitation_source *s = source;
    const int status = s->is_wav ? next_wav(s, value, err, err_size) : next_csv(s, value, err, err_size);
    if (status > 0)
        ++s->samples;
    return status;
}

/* Where samples first .. last are, for a message: "lines L1 .. L2" or
 * "samples first .. last (from 0)". */
static void samples_place(const excitation_source *s, uint64_t first, uint64_t last, char *out, size_t size)
{
    if (s->is_wav)
        snprintf(out, size, "samples %llu .. %llu (from 0)", (unsigned long long)first, (unsigned long long)last);
    else
        snprintf(out, size, "lines %lld .. %lld", (long long)s->first_line + (long long)first,
                 (long long)s->first_line + (long long)last);
}

/* ---- step means */

void excitation_means_start(excitation_means *m, double rate, double t0, double latency, double dt,
                            excitation_sample_fn next, void *source)
{
    memset(m, 0, sizeof *m);
    m->rate = rate;
    m->t0 = t0;
    m->latency = latency;
    m->dt = dt;
    m->next = next;
    m->source = source;
}

/* Step k's span [a, b] in samples from sample 0. */
static void step_span(const excitation_means *m, uint64_t k, double *a, double *b)
{
    const double shift = m->latency - m->t0;
    *a = ((double)(k - 1) * m->dt + shift) * m->rate;
    *b = ((double)k * m->dt + shift) * m->rate;
}

/* One more sample into the window: 1, 0 at the end, -1. */
static int pull(excitation_means *m, char *err, size_t err_size)
{
    double value;
    int status;
    if (m->ended)
        return 0;
    status = m->next(m->source, &value, err, err_size);
    if (status <= 0) {
        m->ended = status == 0;
        return status;
    }
    m->x[0] = m->x[1];
    m->x[1] = value;
    ++m->have;
    return 1;
}

int excitation_means_next(excitation_means *m, double *mean, char *err, size_t err_size)
{
    const uint64_t k = m->step + 1;
    double a, b, lo, hi, p, sum = 0.0;
    uint64_t j;

    step_span(m, k, &a, &b);
    if (k == 1 && a < -COVER_SLACK)
        return 0; /* the record begins after t = latency */
    lo = fmax(a, 0.0); /* within COVER_SLACK */
    /* up to the sample at or before lo (a double compared, never converted, until it is within the samples) */
    while (!m->ended && (double)m->have - 1.0 < lo)
        if (pull(m, err, err_size) < 0)
            return -1;
    if (m->have == 0 || (m->ended && !(b <= (double)(m->have - 1) + COVER_SLACK)))
        return 0;
    hi = m->ended ? fmin(b, (double)(m->have - 1)) : b;
    /* the piece [j, j + 1] holding lo; the window then holds x[j] or x[j + 1] (have <= j + 2) */
    j = lo < (double)(m->have - 1) ? (uint64_t)lo : m->have - 1;
    m->first = j;
    for (p = lo; p < hi; ++j) {
        double q;
        while (m->have < j + 2) {
            const int status = pull(m, err, err_size);
            if (status < 0)
                return -1;
            if (status == 0)
                break;
        }
        if (m->have < j + 2) { /* the record ends at sample j <= p: at most COVER_SLACK short */
            if (!(b <= (double)j + COVER_SLACK))
                return 0;
            hi = fmin(b, (double)j);
            break;
        }
        q = fmin(hi, (double)(j + 1));
        sum += (q - p) * (m->x[0] + (m->x[1] - m->x[0]) * (0.5 * (p + q) - (double)j));
        p = q;
    }
    m->last = j < m->have ? j : m->have - 1;
    m->step = k;
    *mean = sum / (hi - lo);
    return 1;
}

/* ---- the first pass: everything checked, nothing kept */

typedef struct first_pass {
    excitation_source source;
    excitation_means means;
    const excitation_run *run;
} first_pass;

/* excitation_sample_fn of the first pass: the source's next sample; with
 * no step count given, a record whose samples so far already reach past
 * EXCITATION_MAX_STEPS steps is refused at once (not after 2^53 means). */
static int first_pass_next(void *context, double *value, char *err, size_t err_size)
{
    first_pass *f = context;
    const excitation_source *s = &f->source;
    const int status = source_next(&f->source, value, err, err_size);
    if (status > 0 && f->run->steps == 0) {
        const double reach = s->t0 + (double)(s->samples - 1) / s->rate - s->latency;
        if (reach / f->run->dt > EXCITATION_MAX_STEPS) {
            snprintf(err, err_size, "%s: the record reaches t = %g s (sample %llu at %g Hz from t = %g s, latency "
                     "%g s): more than 2^53 steps of dt = %g s; allowed: at most %g s (give --t-end)", s->path,
                     reach, (unsigned long long)(s->samples - 1), s->rate, s->t0, s->latency, f->run->dt,
                     EXCITATION_MAX_STEPS * f->run->dt);
            return -1;
        }
    }
    return status;
}

/* A step mean the core cannot take: not finite, or beyond +-max_mean. */
static void mean_refused(const first_pass *f, double mean, char *err, size_t err_size)
{
    const excitation_source *s = &f->source;
    const excitation_means *m = &f->means;
    char place[96];
    samples_place(s, m->first, m->last, place, sizeof place);
    snprintf(err, err_size, "%s: step %llu (t = %g .. %g s) reads %s, whose mean base acceleration is %g m/s^2: "
             "%s; allowed: a finite mean within +-%g m/s^2 (the range of [excitation] acceleration)",
             s->path, (unsigned long long)m->step, (double)(m->step - 1) * f->run->dt, (double)m->step * f->run->dt,
             place, mean,
             isfinite(mean) ? "beyond the core's range" : "not a finite number (the values or their differences "
                                                          "overflow)",
             f->run->max_mean);
}

int excitation_file_read(const char *path, const excitation_file_options *options, const excitation_run *run,
                         excitation_file *record, char *err, size_t err_size)
{
    first_pass *f;
    excitation_source *s;
    double mean = 0.0;
    uint64_t count = 0;
    int status = 1;

    memset(record, 0, sizeof *record);
    record->path = path;
    record->latency = options->latency;
    record->options = *options;
    if (!(options->latency >= 0.0 && isfinite(options->latency))) {
        snprintf(err, err_size, "latency %g s: must be finite and >= 0", options->latency);
        return -1;
    }
    if (options->has_scale && !(options->scale > 0.0 && isfinite(options->scale))) {
        snprintf(err, err_size, "scale %g m/s^2: must be finite and > 0", options->scale);
        return -1;
    }
    if (run && (!(run->dt > 0.0 && isfinite(run->dt)) || !(run->max_mean > 0.0)
                || (double)run->steps > EXCITATION_MAX_STEPS)) {
        snprintf(err, err_size, "%s: internal: dt %g s, %llu steps, largest mean %g", path, run->dt,
                 (unsigned long long)run->steps, run->max_mean);
        return -1;
    }
    f = malloc(sizeof *f); /* a few hundred bytes, whatever the record */
    if (!f) {
        snprintf(err, err_size, "%s: out of memory", path);
        return -1;
    }
    s = &f->source;
    f->run = run;
    if (source_open(s, path, options, &record->identity, err, err_size) != 0) {
        free(f);
        return -1;
    }
    if (run)
        excitation_means_start(&f->means, s->rate, s->t0, s->latency, run->dt, first_pass_next, f);
    while (run && (run->steps == 0 || count < run->steps)
           && (status = excitation_means_next(&f->means, &mean, err, err_size)) > 0) {
        if (!(fabs(mean) <= run->max_mean)) {
            mean_refused(f, mean, err, err_size);
            status = -1;
            break;
        }
        ++count;
    }
    if (!run || (run->steps > 0 && count == run->steps))
        status = 1;
    if (status >= 0) { /* every value after the run's last step is checked too */
        double value;
        while ((status = source_next(s, &value, err, err_size)) > 0)
            ;
    }
    source_close(s);
    record->format = s->is_wav ? "wav" : "csv";
    record->rate = s->rate;
    record->t0 = s->t0;
    record->samples = s->samples;
    record->steps = count;
    free(f);
    if (status < 0)
        return -1;
    if (!run)
        return 0;
    if (run->steps > 0 && count < run->steps) {
        const double last = (double)(record->samples - 1);
        snprintf(err, err_size, "%s covers t = %.9g .. %.9g s (%.9g s: %llu samples at %g Hz); the run needs "
                 "t = %.9g .. %.9g s (t_end %.9g s, latency %.9g s)", path, record->t0,
                 record->t0 + last / record->rate, last / record->rate, (unsigned long long)record->samples,
                 record->rate, record->latency, (double)run->steps * run->dt + record->latency,
                 (double)run->steps * run->dt, record->latency);
        return -1;
    }
    if (count == 0) {
        snprintf(err, err_size, "%s: the record (%llu samples at %g Hz from t = %g s, latency %g s) covers no step "
                 "of dt = %g s from t = 0", path, (unsigned long long)record->samples, record->rate, record->t0,
                 record->latency, run->dt);
        return -1;
    }
    return 0;
}

/* ---- the run's pass */

int excitation_stream_open(excitation_stream *stream, const excitation_file *record, double dt, char *err,
                           size_t err_size)
{
    input_identity identity;
    memset(stream, 0, sizeof *stream);
    stream->record = record;
    if (source_open(&stream->source, record->path, &record->options, &identity, err, err_size) != 0)
        return -1;
    if (!input_file_unchanged(stream->source.file, &record->identity)) {
        snprintf(err, err_size, "%s has changed since it was checked: run again", record->path);
        source_close(&stream->source);
        return -1;
    }
    excitation_means_start(&stream->means, stream->source.rate, stream->source.t0, record->latency, dt, source_next,
                           &stream->source);
    return 0;
}

int excitation_stream_next(excitation_stream *stream, double *mean, char *err, size_t err_size)
{
    const int status = excitation_means_next(&stream->means, mean, err, err_size);
    if (status > 0)
        return 0;
    if (status == 0)
        snprintf(err, err_size, "%s: ended before step %llu, which it covered when it was checked (changed since?)",
                 stream->record->path, (unsigned long long)stream->means.step + 1);
    return -1;
}

int excitation_stream_sample(excitation_stream *stream, double *value, char *err, size_t err_size)
{
    return source_next(&stream->source, value, err, err_size);
}

void excitation_stream_close(excitation_stream *stream)
{
    source_close(&stream->source);
}
