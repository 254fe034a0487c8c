/* twin_pack.c - host tool: the measured-signals CSV of `beamslider
 * twin-plant` (docs/twin.md, "Measured signals file") as the binary stream
 * the twin firmware reads (twin_stream.h).
 *
 *   twin_pack IN.csv OUT.stream
 *
 * Reads the header lines (sample_rate, a whole number of Hz; signal; noise
 * if given), the column line and every row; writes base_accel and signal of
 * each row as float32, rounded once from the decimal text as `beamslider
 * twin` rounds them in a float build. Any other column (t, s_true) is not
 * kept: the firmware gets what its sensors would give. A bad line stops the
 * tool with file and line, status 2, and no output file.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "twin_stream.h"

#define LINE 512

static int fail(const char *path, long line, const char *what)
{
    if (line > 0)
        fprintf(stderr, "twin_pack: %s:%ld: %s\n", path, line, what);
    else
        fprintf(stderr, "twin_pack: %s: %s\n", path, what);
    return 2;
}

/* The header lines up to the column line; 0, or -1 with *what set. */
static int read_header(FILE *in, long *line, twin_stream_header *h, int *columns, const char **what)
{
    char text[LINE], key[64], value[LINE];
    double rate = 0.0;
    int signal = -1;
    while (fgets(text, sizeof text, in)) {
        ++*line;
        if (*line == 1 && strncmp(text, "# beamslider measured signals", 29) != 0) {
            *what = "not a measured-signals file (line 1 is not \"# beamslider measured signals ...\")";
            return -1;
        }
        if (text[0] != '#') {
            text[strcspn(text, "\r\n")] = 0;
            if (!strcmp(text, "t,base_accel,signal") || !strcmp(text, "t,base_accel,signal,s_true")) {
                *columns = strcmp(text, "t,base_accel,signal") ? 4 : 3;
                break;
            }
            *what = "expected the column line t,base_accel,signal[,s_true]";
            return -1;
        }
        if (sscanf(text, "# %63[a-z_] = %511s", key, value) != 2)
            continue;
        if (!strcmp(key, "sample_rate"))
            rate = strtod(value, NULL);
        else if (!strcmp(key, "noise"))
            h->noise = (float)strtod(value, NULL);
        else if (!strcmp(key, "signal"))
            signal = !strcmp(value, "deflection") ? 0 : !strcmp(value, "voltage") ? 1 : -2;
    }
    if (*columns == 0) {
        *what = "no column line t,base_accel,signal[,s_true]";
        return -1;
    }
    if (!(rate >= 1.0 && rate < 4294967296.0 && rate == floor(rate))) {
        *what = "sample_rate must be a whole number of Hz (1/dt of the twin's scene)";
        return -1;
    }
    if (signal < 0) {
        *what = "signal must be deflection or voltage";
        return -1;
    }
    h->sample_rate = (uint32_t)rate;
    h->signal = (uint32_t)signal;
    return 0;
}

/* One row's base_accel and signal; 0, or -1 for a bad row. */
static int read_row(const char *text, int columns, twin_stream_sample *sample)
{
    double value[4];
    const char *p = text;
    char *end;
    int i;
    for (i = 0; i < columns; ++i) {
        errno = 0;
        value[i] = strtod(p, &end);
        if (end == p || errno || !isfinite(value[i]))
            return -1;
        if (i < columns - 1 ? *end != ',' : *end && *end != '\n' && *end != '\r')
            return -1;
        p = end + 1;
    }
    sample->base_accel = (float)value[1];
    sample->signal = (float)value[2];
    return 0;
}

int main(int argc, char **argv)
{
    twin_stream_header header;
    twin_stream_sample sample;
    char text[LINE];
    const char *what = NULL;
    long line = 0;
    int columns = 0, failed;
    FILE *in, *out;

    if (argc != 3) {
        fprintf(stderr, "usage: twin_pack IN.csv OUT.stream\n");
        return 2;
    }
    in = fopen(argv[1], "r");
    if (!in)
        return fail(argv[1], 0, strerror(errno));
    memset(&header, 0, sizeof header);
    memcpy(header.magic, TWIN_STREAM_MAGIC, 4);
    header.version = TWIN_STREAM_VERSION;
    if (read_header(in, &line, &header, &columns, &what) != 0) {
        fclose(in);
        return fail(argv[1], line, what);
    }
    out = fopen(argv[2], "wb");
    if (!out) {
        fclose(in);
        return fail(argv[2], 0, strerror(errno));
    }
    failed = fwrite(&header, sizeof header, 1, out) != 1; /* the count is written again at the end */
    while (!failed && fgets(text, sizeof text, in)) {
        ++line;
        if (read_row(text, columns, &sample) != 0) {
            fclose(in);
            fclose(out);
            remove(argv[2]);
            return fail(argv[1], line, "expected finite numbers separated by commas");
        }
        failed = fwrite(&sample, sizeof sample, 1, out) != 1;
        ++header.samples;
    }
    fclose(in);
    failed = failed || header.samples == 0 || fseek(out, 0, SEEK_SET) != 0
             || fwrite(&header, sizeof header, 1, out) != 1;
    if (fclose(out) != 0 || failed) {
        remove(argv[2]);
        return fail(argv[2], 0, header.samples == 0 ? "no samples" : "cannot write");
    }
    return 0;
}
