/* fuzz_excitation.c - libFuzzer target: a recorded base acceleration, CSV or
 * WAV (host/lib/run/excitation_file.c), as `run --excitation` reads it.
 *
 * Input: 8 bytes of options, then the file's bytes (written to a file in a
 * private temporary folder: the reader opens it through input_file.c).
 *   [0] bits 0-1 --channel (0: not given), bit 2 --scale given, bits 3-4
 *       the run: 0 every whole step the record covers, 1 a given number of
 *       steps, 2 a given number at a dt of the table below, 3 no run (the
 *       file alone)
 *   [1] --scale, [2] the latency, [6] the largest step mean: from tables
 *   [3..4] K: the run's dt is the record's span / K (so that a run is at
 *       most a few thousand steps); [5] the given number of steps - 1
 *   [7] the dt of run 2
 * The contract checked:
 *   - nothing crashes, hangs, leaks or reads out of bounds (ASan, UBSan:
 *     no out-of-range conversion of a count derived from the file);
 *   - excitation_file_read answers 0 or -1 with a message;
 *   - an accepted record states a rate in [EXCITATION_RATE_MIN,
 *     EXCITATION_RATE_MAX], |t0| <= EXCITATION_T0_MAX, at least one sample,
 *     and, for a run, at least one step (the given number, if given);
 *   - the run's pass (excitation_stream) opens it again and gives every one
 *     of those steps a finite mean within the largest mean allowed, and
 *     refuses the step after the last one the record covers;
 *   - those means equal, bit for bit, the means of the same samples taken
 *     from memory (excitation_stream_sample, then excitation_means over an
 *     array): the streaming reader reads what the samples are.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, strnlen */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "excitation_file.h"
#include "fuzz_check.h"
#include "fuzz_files.h"

#define HEAD 8
#define MAX_MEANS 70000 /* K <= 65536 plus slack */

static const double scales[] = { 1.0, 9.80665, 100.0, 1e-300, 1e300, 1.7976931348623157e308, 3.4e38, 0.0, -1.0,
                                 (double)NAN, (double)INFINITY, 4.9406564584124654e-324, 1e-3, 1e6, 2.0, 0.5 };
static const double latencies[] = { 0.0, 0.0, 0.0, 1e-3, 0.01, 0.5, 1.0, 10.0, 1e9, 1e300,
                                    -1.0, (double)NAN, (double)INFINITY, 4.9406564584124654e-324, 1e-9, 2.5e-4 };
static const double max_means[] = { (double)INFINITY, 1.7976931348623157e308, 1e300, 1e10, 1e6, 1e3,
                                    100.0, 10.0, 1.0, 1e-3, 1e-300, 0.0, -1.0, (double)NAN, 3.4e38, 50.0 };
static const double dts[] = { 1e-5, 2e-5, 1e-4, 1e-3, 0.01, 0.1, 1.0, 10.0,
                              1e3, 1e9, 1e-9, 1e-300, 1e300, 0.0, -1e-5, (double)NAN };

#define PICK(table, byte) table[(byte) % (sizeof table / sizeof table[0])]

static double samples[(1 << 16) + 8];
static double stream_means[MAX_MEANS];

typedef struct memory_source {
    const double *x;
    uint64_t count, at;
} memory_source;

static int memory_next(void *source, double *value, char *err, size_t err_size)
{
    memory_source *m = source;
    (void)err;
    (void)err_size;
    if (m->at == m->count)
        return 0;
    *value = m->x[m->at++];
    return 1;
}

static void check_stream(const excitation_file *record, double dt, double max_mean)
{
    static excitation_stream stream; /* static: large */
    excitation_means means;
    memory_source memory;
    char err[1024];
    uint64_t k, n = 0;
    double value;
    int status;

    /* the run's pass: every step the first pass accepted */
    if (excitation_stream_open(&stream, record, dt, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        fuzz_fail("excitation_stream_open refused a record excitation_file_read accepted");
    }
    for (k = 0; k < record->steps; ++k) {
        double mean;
        if (excitation_stream_next(&stream, &mean, err, sizeof err) != 0) {
            fprintf(stderr, "step %llu: %s\n", (unsigned long long)k + 1, err);
            fuzz_fail("excitation_stream_next refused a step the first pass accepted");
        }
        if (!(fabs(mean) <= max_mean))
            fuzz_fail("excitation_stream_next gave a mean beyond the largest allowed");
        stream_means[k] = mean;
    }
    excitation_stream_close(&stream);

    /* the samples themselves, then the same means from memory */
    if (excitation_stream_open(&stream, record, dt, err, sizeof err) != 0)
        fuzz_fail("excitation_stream_open refused a record the second time");
    while ((status = excitation_stream_sample(&stream, &value, err, sizeof err)) > 0) {
        if (!isfinite(value))
            fuzz_fail("excitation_stream_sample gave a sample that is not finite");
        if (n < sizeof samples / sizeof samples[0])
            samples[n] = value;
        ++n;
    }
    excitation_stream_close(&stream);
    if (status < 0) {
        fprintf(stderr, "%s\n", err);
        fuzz_fail("excitation_stream_sample refused a sample the first pass accepted");
    }
    if (n != record->samples)
        fuzz_fail("excitation_stream_sample gave another number of samples than the first pass counted");
    if (n > sizeof samples / sizeof samples[0])
        return; /* an input longer than -max_len 4096 can hold */
    memory.x = samples;
    memory.count = n;
    memory.at = 0;
    excitation_means_start(&means, record->rate, record->t0, record->latency, dt, memory_next, &memory);
    for (k = 0; k < record->steps; ++k) {
        double mean;
        if (excitation_means_next(&means, &mean, err, sizeof err) != 1)
            fuzz_fail("the means of the samples in memory end before the stream's");
        if (memcmp(&mean, &stream_means[k], sizeof mean) != 0) {
            fprintf(stderr, "step %llu: stream %.17g, memory %.17g\n", (unsigned long long)k + 1, stream_means[k],
                    mean);
            fuzz_fail("the streamed step mean differs from the mean of the same samples in memory");
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static excitation_file record, alone;
    uint8_t head[HEAD] = { 0 };
    const char *path = fuzz_path("record");
    excitation_file_options options;
    excitation_run run;
    char err[1024];
    int mode, status;
    unsigned k_steps;
    double span;

    memcpy(head, data, size < HEAD ? size : HEAD);
    fuzz_write(path, data + (size < HEAD ? size : HEAD), size < HEAD ? 0 : size - HEAD);
    memset(&options, 0, sizeof options);
    options.channel = head[0] & 3;
    options.has_scale = head[0] >> 2 & 1;
    options.scale = PICK(scales, head[1]);
    options.latency = PICK(latencies, head[2]);
    mode = head[0] >> 3 & 3;

    /* the file alone */
    err[0] = '\0';
    status = excitation_file_read(path, &options, NULL, &alone, err, sizeof err);
    fuzz_check_message(status, err, sizeof err);
    if (status != 0)
        return 0;
    if (!(alone.rate >= EXCITATION_RATE_MIN && alone.rate <= EXCITATION_RATE_MAX)
        || !(fabs(alone.t0) <= EXCITATION_T0_MAX) || alone.samples < 1 || alone.steps != 0)
        fuzz_fail("excitation_file_read accepted a record outside its documented ranges");
    if (mode == 3)
        return 0;

    /* a run over it */
    k_steps = (unsigned)(head[3] | head[4] << 8) + 1;
    span = alone.samples > 1 ? (double)(alone.samples - 1) / alone.rate : 1.0 / alone.rate;
    run.dt = mode == 2 ? PICK(dts, head[7]) : span / k_steps;
    run.steps = mode == 0 ? 0 : (uint64_t)head[5] + 1;
    run.max_mean = PICK(max_means, head[6]);
    if (!(run.dt > 0.0) || !isfinite(run.dt))
        run.dt = 1e-5; /* the reader's caller checks dt (a scene's); refusing it is "internal" */
    if (!(run.max_mean > 0.0))
        run.max_mean = (double)INFINITY;
    err[0] = '\0';
    status = excitation_file_read(path, &options, &run, &record, err, sizeof err);
    fuzz_check_message(status, err, sizeof err);
    if (status != 0)
        return 0;
    if (record.samples != alone.samples || memcmp(&record.rate, &alone.rate, sizeof record.rate) != 0
        || memcmp(&record.t0, &alone.t0, sizeof record.t0) != 0)
        fuzz_fail("excitation_file_read read another record with a run than without");
    if (record.steps < 1 || (run.steps > 0 && record.steps != run.steps) || record.steps > MAX_MEANS)
        fuzz_fail("excitation_file_read accepted a run of a step count it does not document");
    check_stream(&record, run.dt, run.max_mean);
    if (run.steps == 0) { /* every covered step was given: the next is not covered */
        static excitation_stream stream;
        double mean;
        uint64_t k;
        if (excitation_stream_open(&stream, &record, run.dt, err, sizeof err) != 0)
            fuzz_fail("excitation_stream_open refused a record the third time");
        for (k = 0; k < record.steps; ++k)
            if (excitation_stream_next(&stream, &mean, err, sizeof err) != 0)
                fuzz_fail("excitation_stream_next refused a step the third time");
        err[0] = '\0';
        if (excitation_stream_next(&stream, &mean, err, sizeof err) == 0)
            fuzz_fail("excitation_stream_next gave a step the first pass did not count as covered");
        fuzz_check_message(-1, err, sizeof err);
        excitation_stream_close(&stream);
    }
    return 0;
}
