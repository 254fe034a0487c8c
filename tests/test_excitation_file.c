/* test_excitation_file.c - a recorded base acceleration (host/lib/run/excitation_file.c;
 * docs/twin.md, "Recorded base acceleration"): the CSV format with and
 * without a time column, WAV of every sample type read to its exact full
 * scale, the step means of the polyline (exact for constants and ramps, the
 * stated error bound for a sine above, at and below the step rate), the
 * latency, and every class of bad input, each refused with a message that
 * names the file and the line or sample. The means are computed streaming
 * (two samples held): on random records they equal, bit for bit, those of
 * the straightforward computation over the whole record in memory (the
 * reference below, the reader's former code), and a file's second pass gives
 * the means its first pass checked. Counts derived from a record (its rate,
 * t0, the steps it covers) and step means the core cannot take are refused
 * before anything is allocated or run.
 *
 * Files are written into a temporary folder. The numbers are doubles on the
 * host side in either REAL, so the tolerances are those of double.
 */

#include "support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "excitation_file.h"

#define PI 3.14159265358979323846

static char tmp_dir[64];
static char path[256];
static char err[1024];

static int make_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir(tmp_dir, sizeof tmp_dir, "test_excitation_file");
}

static int remove_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir_remove(tmp_dir);
}

/* Writes size bytes to tmp_dir/name and leaves its path in path. */
static void write_bytes(const char *name, const void *bytes, size_t size)
{
    FILE *out;
    snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
    out = fopen(path, "wb");
    assert_non_null(out);
    assert_int_equal(fwrite(bytes, 1, size, out), size);
    assert_int_equal(fclose(out), 0);
}

static void write_text(const char *name, const char *text)
{
    write_bytes(name, text, strlen(text));
}

static excitation_file_options no_options(void)
{
    excitation_file_options options;
    memset(&options, 0, sizeof options);
    return options;
}

static excitation_file_options wav_options(double scale, int channel)
{
    excitation_file_options options = no_options();
    options.has_scale = 1;
    options.scale = scale;
    options.channel = channel;
    return options;
}

#define MAX_SAMPLES 64
static double sample[MAX_SAMPLES];

/* Reads the file at path (for run, NULL: the file alone) and its samples
 * into sample[] (at most MAX_SAMPLES of them). */
static void read_plan_ok(const excitation_file_options *options, const excitation_run *run, excitation_file *record)
{
    excitation_stream stream;
    uint64_t j;
    if (excitation_file_read(path, options, run, record, err, sizeof err) != 0) {
        print_error("%s\n", err);
        fail();
    }
    assert_int_equal(excitation_stream_open(&stream, record, run ? run->dt : 1.0, err, sizeof err), 0);
    for (j = 0; j < record->samples && j < MAX_SAMPLES; ++j)
        assert_int_equal(excitation_stream_sample(&stream, &sample[j], err, sizeof err), 1);
    excitation_stream_close(&stream);
}

static void read_ok(const excitation_file_options *options, excitation_file *record)
{
    read_plan_ok(options, NULL, record);
}

/* The read for run (NULL: of the file alone) must fail with a message
 * holding the path and every one of wanted (NULL-terminated). */
static void read_plan_fails(const excitation_file_options *options, const excitation_run *run,
                            const char *const *wanted)
{
    excitation_file record;
    assert_int_equal(excitation_file_read(path, options, run, &record, err, sizeof err), -1);
    if (!strstr(err, path)) {
        print_error("message without the file name: %s\n", err);
        fail();
    }
    for (; *wanted; ++wanted) {
        if (!strstr(err, *wanted)) {
            print_error("message without '%s': %s\n", *wanted, err);
            fail();
        }
    }
}

#define PLAN_FAILS_WITH(options, run, ...)                           \
    do {                                                             \
        static const char *const wanted_[] = { __VA_ARGS__, NULL };  \
        read_plan_fails(options, run, wanted_);                      \
    } while (0)
#define FAILS_WITH(options, ...) PLAN_FAILS_WITH(options, NULL, __VA_ARGS__)

/* ---- CSV */

static void test_csv_without_time_column(void **state)
{
    const excitation_file_options options = no_options();
    excitation_file r;
    (void)state;
    write_text("plain.csv", "# beamslider base acceleration\r\n"
                            "# recorded on the shaker, free text is a comment\r\n"
                            "# sample_rate = 2000 Hz\r\n"
                            "#unit=m/s^2\r\n"
                            "# t0 = -0.25 s\r\n"
                            "1.5\r\n-2e-3\r\n  7 \r\n");
    read_ok(&options, &r);
    assert_string_equal(r.format, "csv");
    assert_true(r.rate == 2000.0 && r.t0 == -0.25 && r.latency == 0.0);
    assert_int_equal(r.samples, 3);
    assert_true(sample[0] == 1.5 && sample[1] == -2e-3 && sample[2] == 7.0);
}

static void test_csv_unit_g_is_standard_gravity(void **state)
{
    const excitation_file_options options = no_options();
    excitation_file r;
    (void)state;
    write_text("g.csv", "# beamslider base acceleration\n# unit = g\n# sample_rate = 100 Hz\n1\n-0.5\n");
    read_ok(&options, &r);
    assert_true(r.t0 == 0.0);
    assert_true(sample[0] == 9.80665 && sample[1] == -0.5 * 9.80665);
}

/* t0 comes from the first time; every time is t0 + k / fs to 1 % of a period. */
static void test_csv_with_time_column(void **state)
{
    const excitation_file_options options = no_options();
    excitation_file r;
    (void)state;
    write_text("timed.csv", "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n"
                            "0.5, 1\n0.501, 2\n0.50200001,3\n0.503,4\n");
    read_ok(&options, &r);
    assert_true(r.t0 == 0.5);
    assert_int_equal(r.samples, 4);
    assert_true(sample[0] == 1.0 && sample[3] == 4.0);
    /* with a header t0 the first time must agree with it */
    write_text("timed_t0.csv", "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n"
                               "# t0 = 0.5 s\n0.5,1\n0.501,2\n");
    read_ok(&options, &r);
    assert_true(r.t0 == 0.5 && r.samples == 2);
}

/* ---- WAV */

static void put_le(unsigned char *at, unsigned long value, int bytes)
{
    int i;
    for (i = 0; i < bytes; ++i)
        at[i] = (unsigned char)(value >> (8 * i));
}

/* A WAV image into out: RIFF header, an unknown chunk of odd size (to be
 * skipped with its pad byte), 'fmt ' (extensible: 40 bytes with the format
 * in its sub-format), 'data'. Returns its size. */
static size_t wav_image(unsigned char *out, unsigned tag, int extensible, unsigned channels, unsigned long rate,
                        unsigned bits, const unsigned char *data, size_t data_size)
{
    const unsigned fmt_size = extensible ? 40 : 16;
    size_t n = 12;
    memcpy(out, "RIFF", 4);
    memcpy(out + 8, "WAVE", 4);
    memcpy(out + n, "LIST", 4);
    put_le(out + n + 4, 3, 4);
    memcpy(out + n + 8, "abc", 4); /* 3 bytes and the pad */
    n += 12;
    memcpy(out + n, "fmt ", 4);
    put_le(out + n + 4, fmt_size, 4);
    memset(out + n + 8, 0, fmt_size);
    put_le(out + n + 8, extensible ? 0xFFFEu : tag, 2);
    put_le(out + n + 10, channels, 2);
    put_le(out + n + 12, rate, 4);
    put_le(out + n + 16, rate * channels * (bits / 8), 4);
    put_le(out + n + 20, channels * (bits / 8), 2);
    put_le(out + n + 22, bits, 2);
    if (extensible)
        put_le(out + n + 8 + 24, tag, 2);
    n += 8 + fmt_size;
    memcpy(out + n, "data", 4);
    put_le(out + n + 4, (unsigned long)data_size, 4);
    memcpy(out + n + 8, data, data_size);
    n += 8 + data_size;
    put_le(out + 4, (unsigned long)(n - 8), 4);
    return n;
}

/* Integer codes of bits each (two's complement) into data; its size. */
static size_t int_samples(unsigned char *data, const long *codes, size_t count, unsigned bits)
{
    size_t i;
    for (i = 0; i < count; ++i)
        put_le(data + i * (bits / 8), (unsigned long)codes[i], (int)(bits / 8));
    return count * (bits / 8);
}

/* Full scale is 2^(bits-1): the most negative code reads -scale exactly,
 * the most positive one scale (1 - 2^(1-bits)). */
static void check_int_wav(unsigned bits, int extensible)
{
    const long top = (1L << (bits - 1)) - 1;
    const long codes[4] = { -top - 1, top, 0, -1 };
    const double full = ldexp(1.0, (int)bits - 1);
    const excitation_file_options options = wav_options(20.0, 0);
    unsigned char data[16], image[256];
    char name[32];
    excitation_file r;

    snprintf(name, sizeof name, "int%u%s.wav", bits, extensible ? "x" : "");
    write_bytes(name, image,
                wav_image(image, 1, extensible, 1, 48000, bits, data, int_samples(data, codes, 4, bits)));
    read_ok(&options, &r);
    assert_string_equal(r.format, "wav");
    assert_true(r.rate == 48000.0 && r.t0 == 0.0);
    assert_int_equal(r.samples, 4);
    assert_true(sample[0] == -20.0);
    assert_true(sample[1] == 20.0 * ((double)top / full));
    assert_true(sample[2] == 0.0);
    assert_true(sample[3] == -20.0 / full);
}

static void test_wav_16_bit(void **state)
{
    (void)state;
    check_int_wav(16, 0);
}

static void test_wav_24_bit_extensible(void **state)
{
    (void)state;
    check_int_wav(24, 1);
}

static void test_wav_32_bit(void **state)
{
    (void)state;
    check_int_wav(32, 0);
}

/* Floats are read as stored, 1.0 being full scale. */
static void test_wav_float(void **state)
{
    const float values[3] = { 1.0f, -0.5f, 0.25f };
    const excitation_file_options options = wav_options(9.80665, 0);
    unsigned char data[12], image[256];
    excitation_file r;
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        unsigned long word;
        uint32_t bits;
        memcpy(&bits, &values[i], 4);
        word = bits;
        put_le(data + 4 * i, word, 4);
    }
    write_bytes("float.wav", image, wav_image(image, 3, 0, 1, 10000, 32, data, sizeof data));
    read_ok(&options, &r);
    assert_true(r.rate == 10000.0 && r.samples == 3);
    assert_true(sample[0] == 9.80665 && sample[1] == -0.5 * 9.80665 && sample[2] == 0.25 * 9.80665);
}

/* --channel picks one channel of an interleaved file. */
static void test_wav_channel(void **state)
{
    const long codes[6] = { 100, -200, 300, -400, 500, -600 }; /* left, right per frame */
    const excitation_file_options options = wav_options(32768.0, 2);
    unsigned char data[12], image[256];
    excitation_file r;
    (void)state;
    write_bytes("stereo.wav", image,
                wav_image(image, 1, 0, 2, 8000, 16, data, int_samples(data, codes, 6, 16)));
    read_ok(&options, &r);
    assert_int_equal(r.samples, 3);
    assert_true(sample[0] == -200.0 && sample[1] == -400.0 && sample[2] == -600.0);
}

#define HEAD "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n"

/* ---- step means */

/* A record in memory: samples x(t0 + j / fs), j = 0 .. n - 1. */
typedef struct memory_record {
    double rate, t0, latency;
    size_t samples, next;
    double *accel;
} memory_record;

static memory_record record_of(double (*signal)(double), double rate, double t0, size_t n)
{
    memory_record r;
    size_t j;
    memset(&r, 0, sizeof r);
    r.rate = rate;
    r.t0 = t0;
    r.samples = n;
    r.accel = malloc(n * sizeof *r.accel);
    assert_non_null(r.accel);
    for (j = 0; j < n; ++j)
        r.accel[j] = signal(t0 + (double)j / rate);
    return r;
}

/* excitation_sample_fn of a memory record. */
static int memory_next(void *source, double *value, char *message, size_t size)
{
    memory_record *r = source;
    (void)message;
    (void)size;
    if (r->next == r->samples)
        return 0;
    *value = r->accel[r->next++];
    return 1;
}

/* The streaming means of up to steps steps into out; how many the record covers. */
static uint64_t stream_means(memory_record *r, double dt, uint64_t steps, double *out)
{
    excitation_means m;
    uint64_t k;
    r->next = 0;
    excitation_means_start(&m, r->rate, r->t0, r->latency, dt, memory_next, r);
    for (k = 0; k < steps; ++k) {
        const int status = excitation_means_next(&m, &out[k], err, sizeof err);
        assert_true(status >= 0);
        if (status == 0)
            break;
    }
    return k;
}

/* Every step mean of up to steps, which the record must cover. */
static void means_of(memory_record *r, double dt, uint64_t steps, double *out)
{
    assert_int_equal(stream_means(r, dt, steps, out), steps);
}

/* ---- the reference: the whole record in memory, each step on its own */

static void reference_span(const memory_record *r, double dt, uint64_t k, double *a, double *b)
{
    const double shift = r->latency - r->t0;
    *a = ((double)(k - 1) * dt + shift) * r->rate;
    *b = ((double)k * dt + shift) * r->rate;
}

static int reference_covers(const memory_record *r, double dt, uint64_t steps)
{
    double a, b;
    reference_span(r, dt, 1, &a, &b);
    if (a < -1e-6)
        return 0;
    reference_span(r, dt, steps, &a, &b);
    return b <= (double)(r->samples - 1) + 1e-6;
}

/* The largest step count the record covers. */
static uint64_t reference_steps(const memory_record *r, double dt)
{
    uint64_t steps = 0;
    while (reference_covers(r, dt, steps + 1))
        ++steps;
    return steps;
}

static double reference_integral(const double *x, size_t samples, double lo, double hi)
{
    size_t j = (size_t)lo;
    double sum = 0.0, p = lo;
    if (j > samples - 2)
        j = samples - 2;
    for (; p < hi; ++j) {
        const double q = fmin(hi, (double)(j + 1));
        sum += (q - p) * (x[j] + (x[j + 1] - x[j]) * (0.5 * (p + q) - (double)j));
        p = q;
    }
    return sum;
}

static void reference_means(const memory_record *r, double dt, uint64_t steps, double *out)
{
    const double last = (double)(r->samples - 1);
    uint64_t k;
    for (k = 1; k <= steps; ++k) {
        double a, b, lo, hi;
        reference_span(r, dt, k, &a, &b);
        lo = fmax(a, 0.0);
        hi = fmin(b, last);
        out[k - 1] = reference_integral(r->accel, r->samples, lo, hi) / (hi - lo);
    }
}

static double constant(double t)
{
    (void)t;
    return -3.7;
}

static double ramp(double t)
{
    return 2.0 + 50.0 * t;
}

#define SINE_A 14.0
#define SINE_F 124.0
static double sine(double t)
{
    return SINE_A * sin(2.0 * PI * SINE_F * t + 0.3);
}

/* The sine's own mean over [a, b]. */
static double sine_mean(double a, double b)
{
    const double omega = 2.0 * PI * SINE_F;
    return -SINE_A * (cos(omega * b + 0.3) - cos(omega * a + 0.3)) / (omega * (b - a));
}

#define DT 2e-5
#define STEPS 2000

static double means[STEPS];
static double expected[STEPS];

/* A constant's mean is the constant, and a ramp's the ramp at the step's
 * midpoint, whatever the rate (commensurate with 1/dt or not) and t0. */
static void test_means_of_constant_and_ramp_are_exact(void **state)
{
    static const double rates[] = { 5.0 / DT, 1.0 / DT, 0.5 / DT, 3.7 / DT, 0.37 / DT };
    size_t i;
    uint64_t k;
    (void)state;
    for (i = 0; i < sizeof rates / sizeof rates[0]; ++i) {
        const double t0 = -0.3 / rates[i];
        const size_t n = (size_t)(STEPS * DT * rates[i]) + 3;
        memory_record c = record_of(constant, rates[i], t0, n);
        memory_record r = record_of(ramp, rates[i], t0, n);
        means_of(&c, DT, STEPS, means);
        for (k = 0; k < STEPS; ++k)
            assert_close("constant", means[k], -3.7, 0.0, 1e-15);
        means_of(&r, DT, STEPS, means);
        for (k = 0; k < STEPS; ++k)
            assert_close("ramp", means[k], ramp(((double)k + 0.5) * DT), 0.0, 1e-12);
        free(c.accel);
        free(r.accel);
    }
}

/* A sine: the polyline's mean misses the sine's by at most
 * a omega^2 / (8 fs^2), the bound of docs/twin.md, at 5, 1 and 0.5 samples
 * per step; at fs = 1/dt (the trapezoid rule) the error is near
 * a omega^2 / (12 fs^2), so the bound is not loose by much. */
static void test_means_of_a_sine_within_the_bound(void **state)
{
    static const double per_step[] = { 5.0, 1.0, 0.5 };
    const double omega = 2.0 * PI * SINE_F;
    size_t i;
    uint64_t k;
    (void)state;
    for (i = 0; i < sizeof per_step / sizeof per_step[0]; ++i) {
        const double rate = per_step[i] / DT;
        const double bound = SINE_A * omega * omega / (8.0 * rate * rate);
        memory_record r = record_of(sine, rate, 0.0, (size_t)(STEPS * per_step[i]) + 1);
        double worst = 0.0;
        means_of(&r, DT, STEPS, means);
        for (k = 0; k < STEPS; ++k)
            worst = fmax(worst, fabs(means[k] - sine_mean((double)k * DT, (double)(k + 1) * DT)));
        print_message("fs = %g / dt: worst |mean - sine's mean| = %.3e m/s^2, bound %.3e\n", per_step[i],
                      worst, bound);
        assert_true(worst <= bound * (1.0 + 1e-6) + 1e-12);
        if (per_step[i] == 1.0)
            assert_true(worst >= 0.5 * bound);
        free(r.accel);
    }
}

/* With latency L the step [t_B, t_E] reads the record over [t_B + L, t_E + L]:
 * a ramp's mean moves by its slope times L, and a latency of whole steps
 * shifts the means by as many steps. */
static void test_latency_reads_later(void **state)
{
    memory_record r = record_of(ramp, 3.0 / DT, 0.0, 3 * STEPS + 100);
    static double shifted[STEPS];
    uint64_t k;
    (void)state;
    r.latency = 7.3e-6;
    means_of(&r, DT, STEPS, means);
    for (k = 0; k < STEPS; ++k)
        assert_close("ramp, latency", means[k], ramp(((double)k + 0.5) * DT + 7.3e-6), 0.0, 1e-12);
    free(r.accel);
    r = record_of(sine, 3.0 / DT, 0.0, 3 * STEPS + 100);
    means_of(&r, DT, STEPS, means);
    r.latency = 4 * DT;
    means_of(&r, DT, STEPS - 4, shifted);
    for (k = 0; k + 4 < STEPS; ++k)
        assert_close("sine, 4 steps late", shifted[k], means[k + 4], 1e-12, 1e-9);
    free(r.accel);
}

/* The steps a record covers: whole steps of [L, t_end + L] within it. */
static void test_steps_covered(void **state)
{
    memory_record r = record_of(constant, 1.0 / DT, 0.0, 101); /* 100 intervals: 100 steps */
    (void)state;
    assert_int_equal(stream_means(&r, DT, STEPS, means), 100);
    r.latency = 2.5 * DT;
    assert_int_equal(stream_means(&r, DT, STEPS, means), 97);
    r.latency = 0.0;
    r.t0 = 1e-6; /* begins after t = 0 */
    assert_int_equal(stream_means(&r, DT, STEPS, means), 0);
    r.t0 = -0.5 * DT; /* half a step early: the last step ends half a step sooner */
    assert_int_equal(stream_means(&r, DT, STEPS, means), 99);
    free(r.accel);
}

static uint64_t rng = 0x2545f4914f6cdd1dull;

/* xorshift64*: a uniform number in [0, 1). */
static double uniform(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return (double)((rng * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

/* The streaming means equal the whole-record reference bit for bit, and
 * cover as many steps, on random records: 2 to 3000 samples of noise at 0.05
 * to 50 samples per step, t0 from before to after t = 0, latencies from 0
 * to a few steps. */
static void test_streaming_means_equal_reference(void **state)
{
    int trial;
    (void)state;
    for (trial = 0; trial < 300; ++trial) {
        const size_t n = 2 + (size_t)(uniform() * 3000.0);
        const double rate = pow(10.0, uniform() * 3.0 - 1.3) / DT;
        memory_record r;
        uint64_t steps, k;
        size_t j;
        memset(&r, 0, sizeof r);
        r.samples = n;
        r.rate = rate;
        r.t0 = (uniform() - 0.8) * 0.3 * (double)n / rate;
        r.latency = uniform() < 0.3 ? 0.0 : uniform() * 5.0 * DT;
        r.accel = malloc(n * sizeof *r.accel);
        assert_non_null(r.accel);
        for (j = 0; j < n; ++j)
            r.accel[j] = (uniform() - 0.5) * pow(10.0, uniform() * 6.0 - 3.0);
        steps = reference_steps(&r, DT);
        if (steps > STEPS)
            steps = STEPS;
        assert_int_equal(stream_means(&r, DT, STEPS, means), steps);
        reference_means(&r, DT, steps, expected);
        for (k = 0; k < steps; ++k)
            if (memcmp(&means[k], &expected[k], sizeof means[k]) != 0) {
                print_error("trial %d (n %lu, rate %.17g, t0 %.17g, latency %.17g): step %lu: %.17g, reference "
                            "%.17g\n", trial, (unsigned long)n, rate, r.t0, r.latency, (unsigned long)k + 1, means[k],
                            expected[k]);
                fail();
            }
        free(r.accel);
    }
}

/* A file's two passes: the run's stream gives, bit for bit, the means the
 * reference computes from the file's samples, for the steps the first pass
 * counted (every whole step) or was given. */
static void test_file_stream_gives_the_checked_means(void **state)
{
    const excitation_file_options options = no_options();
    excitation_run run;
    excitation_file record;
    excitation_stream stream;
    memory_record r;
    char text[64];
    FILE *out;
    size_t j;
    uint64_t k;
    (void)state;
    snprintf(path, sizeof path, "%s/noise.csv", tmp_dir);
    out = fopen(path, "w");
    assert_non_null(out);
    memset(&r, 0, sizeof r);
    r.samples = 1000;
    r.rate = 3.3 / DT;
    r.t0 = -0.1 / r.rate;
    r.accel = malloc(r.samples * sizeof *r.accel);
    assert_non_null(r.accel);
    fprintf(out, "# beamslider base acceleration\n# sample_rate = %.17g Hz\n# unit = m/s^2\n# t0 = %.17g s\n",
            r.rate, r.t0);
    for (j = 0; j < r.samples; ++j) {
        snprintf(text, sizeof text, "%.17g", (uniform() - 0.5) * 30.0);
        r.accel[j] = strtod(text, NULL);
        fprintf(out, "%s\n", text);
    }
    assert_int_equal(fclose(out), 0);
    run.dt = DT;
    run.steps = 0;
    run.max_mean = HUGE_VAL;
    read_plan_ok(&options, &run, &record);
    assert_int_equal(record.steps, reference_steps(&r, DT));
    reference_means(&r, DT, record.steps, expected);
    assert_int_equal(excitation_stream_open(&stream, &record, DT, err, sizeof err), 0);
    for (k = 0; k < record.steps; ++k) {
        assert_int_equal(excitation_stream_next(&stream, &means[k], err, sizeof err), 0);
        assert_memory_equal(&means[k], &expected[k], sizeof means[k]);
    }
    excitation_stream_close(&stream);
    run.steps = 100; /* --t-end: only those steps */
    read_plan_ok(&options, &run, &record);
    assert_int_equal(record.steps, 100);
    free(r.accel);
}

/* The run needs [L, t_end + L]: a record that starts after L or ends early
 * is refused with both spans; one that covers no step says so. */
static void test_record_too_short(void **state)
{
    const excitation_file_options options = no_options();
    excitation_run run;
    excitation_file record;
    char text[4096];
    int j;
    (void)state;
    strcpy(text, "# beamslider base acceleration\n# sample_rate = 50000 Hz\n# unit = m/s^2\n");
    for (j = 0; j <= 100; ++j) /* 100 intervals: 100 steps */
        strcat(text, "1\n");
    write_text("short.csv", text);
    run.dt = DT;
    run.max_mean = HUGE_VAL;
    run.steps = 100;
    read_plan_ok(&options, &run, &record);
    run.steps = 0;
    read_plan_ok(&options, &run, &record);
    assert_int_equal(record.steps, 100);
    run.steps = 101;
    PLAN_FAILS_WITH(&options, &run, "short.csv covers t = 0 .. 0.002 s", "the run needs t = 0 .. 0.00202 s");
    {
        excitation_file_options late = no_options();
        late.latency = 2.5 * DT;
        run.steps = 0;
        read_plan_ok(&late, &run, &record);
        assert_int_equal(record.steps, 97);
        run.steps = 98;
        PLAN_FAILS_WITH(&late, &run, "latency");
    }
    write_text("after.csv", "# beamslider base acceleration\n# sample_rate = 50000 Hz\n# unit = m/s^2\n# t0 = 1e-6 s\n"
                            "1\n2\n3\n");
    run.steps = 0;
    PLAN_FAILS_WITH(&options, &run, "covers no step of dt = 2e-05 s from t = 0");
}

/* Counts derived from a record are checked in double before anything
 * becomes an integer: a rate or t0 outside the stated range, a record
 * reaching past 2^53 steps (refused at its second sample, not after 2^53
 * means). */
static void test_counts_out_of_range(void **state)
{
    const excitation_file_options options = no_options();
    excitation_run run;
    (void)state;
    write_text("wrap.csv", "# beamslider base acceleration\n# sample_rate = 1.0842027145865592e-14 Hz\n"
                           "# unit = m/s^2\n1\n2\n3\n");
    FAILS_WITH(&options, ":2:", "sample_rate 1.0842e-14 Hz is out of range; allowed: 0.001 .. 1e+10 Hz");
    write_text("denormal.csv", "# beamslider base acceleration\n# sample_rate = 4.9e-324 Hz\n# unit = m/s^2\n1\n");
    FAILS_WITH(&options, ":2:", "sample_rate 4.94066e-324 Hz is out of range");
    write_text("fast.csv", "# beamslider base acceleration\n# sample_rate = 2e10 Hz\n# unit = m/s^2\n1\n");
    FAILS_WITH(&options, ":2:", "out of range; allowed: 0.001 .. 1e+10 Hz");
    write_text("t0.csv", "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# t0 = -1e300 s\n# unit = m/s^2\n1\n");
    FAILS_WITH(&options, ":3:", "t0 -1e+300 s is out of range; allowed: -1e+09 .. 1e+09 s");
    write_text("time0.csv", "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n"
                            "-1e300,1\n");
    FAILS_WITH(&options, ":4:", "the first time (t0) -1e+300 s is out of range");
    write_text("long.csv", "# beamslider base acceleration\n# sample_rate = 0.001 Hz\n# unit = m/s^2\n1\n2\n3\n");
    run.dt = 1e-13;
    run.steps = 0;
    run.max_mean = HUGE_VAL;
    PLAN_FAILS_WITH(&options, &run, "reaches t = 1000 s", "more than 2^53 steps of dt = 1e-13 s", "give --t-end");
    run.steps = 10; /* with the steps given, only those are taken */
    {
        excitation_file record;
        read_plan_ok(&options, &run, &record);
        assert_int_equal(record.steps, 10);
    }
}

/* Finite values whose step means the core cannot take: a unit that
 * overflows, differences that overflow, means beyond the range. Refused
 * with the step, its time and the lines it reads. */
static void test_means_out_of_range(void **state)
{
    const excitation_file_options options = no_options();
    excitation_run run;
    (void)state;
    run.dt = 1e-3;
    run.steps = 0;
    run.max_mean = 4.5e307;
    write_text("g.csv", "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = g\n1\n1e308\n");
    FAILS_WITH(&options, ":5:", "1e+308 g is inf m/s^2: beyond the range of double");
    write_text("alternating.csv", HEAD "1e308\n-1e308\n1e308\n-1e308\n");
    PLAN_FAILS_WITH(&options, &run, "step 1 (t = 0 .. 0.001 s) reads lines 4 .. 5", "not a finite number",
                    "allowed: a finite mean within +-4.5e+307 m/s^2");
    write_text("large.csv", HEAD "1\n2\n1e300\n1e300\n");
    run.max_mean = 1e299;
    PLAN_FAILS_WITH(&options, &run, "step 2 (t = 0.001 .. 0.002 s) reads lines 5 .. 6",
                    "mean base acceleration is 5e+299 m/s^2: beyond the core's range");
}

/* ---- bad input */


static void test_csv_bad_values(void **state)
{
    const excitation_file_options options = no_options();
    (void)state;
    write_text("nan.csv", HEAD "1\n2\nnan\n");
    FAILS_WITH(&options, ":6:", "'nan' is not a finite number");
    write_text("inf.csv", HEAD "1\n-inf\n");
    FAILS_WITH(&options, ":5:", "not a finite number");
    write_text("empty.csv", HEAD "1\n\n3\n");
    FAILS_WITH(&options, ":5:", "empty value");
    write_text("empty_time.csv", HEAD "0,1\n,2\n");
    FAILS_WITH(&options, ":5:", "empty value");
    write_text("text.csv", HEAD "1\n2 m/s^2\n");
    FAILS_WITH(&options, ":5:", "not a finite number");
    write_text("three.csv", HEAD "0,1,2\n");
    FAILS_WITH(&options, ":4:", "more than 2 values");
    write_text("mixed.csv", HEAD "0,1\n2\n");
    FAILS_WITH(&options, ":5:", "the lines before hold 2");
    write_text("late_comment.csv", HEAD "1\n# sample_rate = 10 Hz\n");
    FAILS_WITH(&options, ":5:", "comment after the first value");
    write_text("none.csv", HEAD);
    FAILS_WITH(&options, "no samples");
}

static void test_csv_bad_times(void **state)
{
    const excitation_file_options options = no_options();
    (void)state;
    write_text("gap.csv", HEAD "0,1\n0.001,2\n0.003,3\n");
    FAILS_WITH(&options, ":6:", "a gap: t = 0.003 s follows t = 0.001 s");
    write_text("spacing.csv", HEAD "0,1\n0.001,2\n0.00205,3\n");
    FAILS_WITH(&options, ":6:", "expected 0.002 s", "1 % of that");
    write_text("backwards.csv", HEAD "0,1\n0.001,2\n0.001,3\n");
    FAILS_WITH(&options, ":6:", "expected 0.002 s");
    write_text("t0.csv", HEAD "# t0 = 1 s\n1.5,1\n");
    FAILS_WITH(&options, ":5:", "the first time is 1.5 s, the header's t0 1 s");
}

static void test_csv_bad_header(void **state)
{
    const excitation_file_options options = no_options();
    (void)state;
    write_text("untitled.csv", "# sample_rate = 1000 Hz\n# unit = m/s^2\n1\n");
    FAILS_WITH(&options, ":1:", "# beamslider base acceleration");
    write_text("no_rate.csv", "# beamslider base acceleration\n# unit = m/s^2\n1\n");
    FAILS_WITH(&options, "no line '# sample_rate = ... Hz'");
    write_text("no_unit.csv", "# beamslider base acceleration\n# sample_rate = 1000 Hz\n");
    FAILS_WITH(&options, "no line '# unit = m/s^2 (or g)'");
    write_text("zero_rate.csv", "# beamslider base acceleration\n# sample_rate = 0 Hz\n");
    FAILS_WITH(&options, ":2:", "sample_rate must be a finite number > 0");
    write_text("negative_rate.csv", "# beamslider base acceleration\n# sample_rate = -100 Hz\n");
    FAILS_WITH(&options, ":2:", "sample_rate must be a finite number > 0");
    write_text("kHz.csv", "# beamslider base acceleration\n# sample_rate = 10 kHz\n");
    FAILS_WITH(&options, ":2:", "followed by Hz, not '10 kHz'");
    write_text("unit.csv", "# beamslider base acceleration\n# unit = mm/s^2\n");
    FAILS_WITH(&options, ":2:", "unit must be m/s^2 or g");
    write_text("typo.csv", "# beamslider base acceleration\n# samplerate = 1000 Hz\n");
    FAILS_WITH(&options, ":2:", "unknown header field 'samplerate'");
    write_text("twice.csv", HEAD "# unit = g\n");
    FAILS_WITH(&options, ":4:", "unit given twice");
}

static void test_csv_refuses_wav_options(void **state)
{
    excitation_file_options options = wav_options(10.0, 0);
    (void)state;
    write_text("scaled.csv", HEAD "1\n");
    FAILS_WITH(&options, "--scale is for WAV files");
    options = no_options();
    options.channel = 1;
    FAILS_WITH(&options, "--channel is for WAV files");
}

static void test_wav_bad_files(void **state)
{
    const long codes[4] = { 1, 2, 3, 4 };
    const excitation_file_options options = wav_options(1.0, 0);
    const excitation_file_options unscaled = no_options();
    unsigned char data[16], image[256];
    size_t n;
    (void)state;

    n = wav_image(image, 1, 0, 1, 1000, 16, data, int_samples(data, codes, 4, 16));
    write_bytes("unscaled.wav", image, n);
    FAILS_WITH(&unscaled, "give --scale S");
    put_le(image + 4, (unsigned long)(n - 3 - 8), 4); /* the data chunk declares more than follows */
    write_bytes("truncated.wav", image, n - 3);
    FAILS_WITH(&options, "truncated: chunk 'data'", "declares 8 bytes, 5 follow");
    put_le(image + 4, (unsigned long)(n - 8), 4);
    write_bytes("riff_short.wav", image, n - 3); /* the RIFF size says more than the file holds */
    FAILS_WITH(&options, "truncated: the RIFF header declares");

    n = wav_image(image, 1, 0, 1, 1000, 16, data, 7); /* 3.5 frames */
    write_bytes("partial.wav", image, n);
    FAILS_WITH(&options, "not whole 2-byte frames");

    n = wav_image(image, 1, 0, 2, 1000, 16, data, int_samples(data, codes, 4, 16));
    write_bytes("stereo.wav", image, n);
    FAILS_WITH(&options, "has 2 channels: choose one with --channel N (1 to 2)");
    {
        const excitation_file_options third = wav_options(1.0, 3);
        FAILS_WITH(&third, "--channel 3", "2 channel(s)");
    }

    n = wav_image(image, 1, 0, 1, 0, 16, data, int_samples(data, codes, 4, 16));
    write_bytes("zero_rate.wav", image, n);
    FAILS_WITH(&options, "sample rate 0");
    n = wav_image(image, 1, 0, 1, 1000, 8, data, 4);
    write_bytes("8bit.wav", image, n);
    FAILS_WITH(&options, "8-bit integer samples");
    n = wav_image(image, 2, 0, 1, 1000, 16, data, 8); /* ADPCM */
    write_bytes("adpcm.wav", image, n);
    FAILS_WITH(&options, "sample format 0x0002");
    n = wav_image(image, 1, 0, 1, 1000, 16, data, 0);
    write_bytes("empty.wav", image, n);
    FAILS_WITH(&options, "no samples");
    memcpy(image + 48, "junk", 4); /* the 'data' chunk renamed: skipped as unknown */
    write_bytes("no_data.wav", image, n);
    FAILS_WITH(&options, "no 'data' chunk");
    write_bytes("not_wave.wav", "RIFF\4\0\0\0AVI ", 12);
    FAILS_WITH(&options, "not WAVE");
}

static void test_wav_non_finite_sample(void **state)
{
    const excitation_file_options options = wav_options(1.0, 0);
    unsigned char data[12], image[256];
    (void)state;
    put_le(data, 0x3f800000ul, 4);  /* 1.0f */
    put_le(data + 4, 0x3f800000ul, 4);
    put_le(data + 8, 0x7fc00000ul, 4); /* NaN */
    write_bytes("nan.wav", image, wav_image(image, 3, 0, 1, 1000, 32, data, 12));
    FAILS_WITH(&options, "sample 2 (from 0; channel 1) is not a finite number");
    {
        const excitation_file_options huge = wav_options(1e300, 0);
        put_le(data + 8, 0x7f7fffffUL, 4); /* FLT_MAX: finite, times 1e300 not */
        write_bytes("scaled.wav", image, wav_image(image, 3, 0, 1, 1000, 32, data, 12));
        FAILS_WITH(&huge, "sample 2 (from 0; channel 1) times --scale 1e+300 is beyond the range of double");
    }
}

static void test_missing_file(void **state)
{
    const excitation_file_options options = no_options();
    (void)state;
    snprintf(path, sizeof path, "%s/no_such.csv", tmp_dir);
    FAILS_WITH(&options, "cannot open");
    snprintf(path, sizeof path, "%s", tmp_dir);
    FAILS_WITH(&options, "not a regular file");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_csv_without_time_column),
        cmocka_unit_test(test_csv_unit_g_is_standard_gravity),
        cmocka_unit_test(test_csv_with_time_column),
        cmocka_unit_test(test_wav_16_bit),
        cmocka_unit_test(test_wav_24_bit_extensible),
        cmocka_unit_test(test_wav_32_bit),
        cmocka_unit_test(test_wav_float),
        cmocka_unit_test(test_wav_channel),
        cmocka_unit_test(test_means_of_constant_and_ramp_are_exact),
        cmocka_unit_test(test_means_of_a_sine_within_the_bound),
        cmocka_unit_test(test_latency_reads_later),
        cmocka_unit_test(test_steps_covered),
        cmocka_unit_test(test_streaming_means_equal_reference),
        cmocka_unit_test(test_file_stream_gives_the_checked_means),
        cmocka_unit_test(test_record_too_short),
        cmocka_unit_test(test_counts_out_of_range),
        cmocka_unit_test(test_means_out_of_range),
        cmocka_unit_test(test_csv_bad_values),
        cmocka_unit_test(test_csv_bad_times),
        cmocka_unit_test(test_csv_bad_header),
        cmocka_unit_test(test_csv_refuses_wav_options),
        cmocka_unit_test(test_wav_bad_files),
        cmocka_unit_test(test_wav_non_finite_sample),
        cmocka_unit_test(test_missing_file),
    };
    return cmocka_run_group_tests(tests, make_tmp_dir, remove_tmp_dir);
}
