/* twin_pack.c - host tool: the measured-signals CSV of `beamslider
 * twin-plant` (docs/twin.md, "Measured signals file") as the binary stream
 * the twin firmware reads (twin_stream.h).
 *
 *   twin_pack IN.csv OUT.stream
 *
 * The CSV is read by the one reader of its format, host/lib/twin/measured_signals.c,
 * the one `beamslider twin` reads it with: the same file is accepted or
 * refused by both, with the same line and reason (tests/check_inputs.sh).
 * What the firmware needs beyond the format: a whole number of Hz (the
 * stream holds it as an integer) and fewer than 2^32 rows. Each row's
 * base_accel and signal are written as float32, rounded once from the
 * decimal text as `beamslider twin` rounds them in a float build; t and
 * s_true are not kept: the firmware gets what its sensors would give. A bad
 * line stops the tool with file and line, status 2, and no output file.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "measured_signals.h"
#include "twin_stream.h"

static int fail(const char *message)
{
    fprintf(stderr, "twin_pack: %s\n", message);
    return 2;
}

int main(int argc, char **argv)
{
    twin_stream_header header;
    twin_stream_sample sample;
    measured_reader in;
    measured_row row;
    char err[1024];
    int status = 0, failed = 0;
    FILE *out;

    if (argc != 3) {
        fprintf(stderr, "usage: twin_pack IN.csv OUT.stream\n");
        return 2;
    }
    if (measured_open(&in, argv[1], err, sizeof err) != 0)
        return fail(err);
    if (!(in.header.rate >= 1.0 && in.header.rate < 4294967296.0 && in.header.rate == floor(in.header.rate))) {
        snprintf(err, sizeof err, "%s: sample_rate = %g Hz: the firmware's stream needs a whole number of Hz, "
                 "1 .. 4294967295 (1/dt of the twin's scene)", in.path, in.header.rate);
        measured_close(&in);
        return fail(err);
    }
    memset(&header, 0, sizeof header);
    memcpy(header.magic, TWIN_STREAM_MAGIC, 4);
    header.version = TWIN_STREAM_VERSION;
    header.sample_rate = (uint32_t)in.header.rate;
    header.signal = (uint32_t)in.header.signal;
    header.noise = isnan(in.header.noise) ? 0.0f : (float)in.header.noise;
    out = fopen(argv[2], "wb");
    if (!out) {
        snprintf(err, sizeof err, "%s: cannot create", argv[2]);
        measured_close(&in);
        return fail(err);
    }
    failed = fwrite(&header, sizeof header, 1, out) != 1; /* the count is written again at the end */
    while (!failed && (status = measured_next(&in, &row, err, sizeof err)) > 0) {
        if (header.samples == UINT32_MAX) {
            snprintf(err, sizeof err, "%s:%ld: more than %lu rows: the stream counts them in 32 bits", in.path,
                     in.lines.line, (unsigned long)UINT32_MAX);
            status = -1;
            break;
        }
        sample.base_accel = (float)row.base_accel;
        sample.signal = (float)row.signal;
        failed = fwrite(&sample, sizeof sample, 1, out) != 1;
        ++header.samples;
    }
    measured_close(&in);
    if (!failed && status < 0) {
        fclose(out);
        remove(argv[2]);
        return fail(err);
    }
    failed = failed || fseek(out, 0, SEEK_SET) != 0 || fwrite(&header, sizeof header, 1, out) != 1;
    if (fclose(out) != 0 || failed) {
        remove(argv[2]);
        snprintf(err, sizeof err, "%s: cannot write", argv[2]);
        fprintf(stderr, "twin_pack: %s\n", err);
        return 1;
    }
    return 0;
}
