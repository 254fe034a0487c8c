/* test_excitation_file.c - a recorded base acceleration (host/lib/excitation_file.c;
 * docs/twin.md, "Recorded base acceleration"): the CSV format with and
 * without a time column, WAV of every sample type read to its exact full
 * scale, the step means of the polyline (exact for constants and ramps, the
 * stated error bound for a sine above, at and below the step rate), the
 * latency, and every class of bad input, each refused with a message that
 * names the file and the line or sample.
 *
 * Files are written into a temporary folder. The numbers are doubles on the
 * host side in either REAL, so the tolerances are those of double.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include "support.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "excitation_file.h"

#define PI 3.14159265358979323846

static char tmp_dir[64];
static char path[256];
static char err[1024];

static int make_tmp_dir(void **state)
{
    (void)state;
    strcpy(tmp_dir, "/tmp/test_excitation_file.XXXXXX");
    return mkdtemp(tmp_dir) ? 0 : -1;
}

static int remove_tmp_dir(void **state)
{
    DIR *dir = opendir(tmp_dir);
    struct dirent *entry;
    char name[512];

    (void)state;
    if (!dir)
        return -1;
    while ((entry = readdir(dir)) != NULL) {
        if (strcmp(entry->d_name, ".") && strcmp(entry->d_name, "..")) {
            snprintf(name, sizeof name, "%s/%s", tmp_dir, entry->d_name);
            unlink(name);
        }
    }
    closedir(dir);
    return rmdir(tmp_dir);
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

static void read_ok(const excitation_file_options *options, excitation_file *record)
{
    if (excitation_file_read(path, options, record, err, sizeof err) != 0) {
        print_error("%s\n", err);
        fail();
    }
}

/* The read must fail with a message holding the path and every one of
 * wanted (NULL-terminated). */
static void read_fails(const excitation_file_options *options, const char *const *wanted)
{
    excitation_file record;
    assert_int_equal(excitation_file_read(path, options, &record, err, sizeof err), -1);
    assert_null(record.accel);
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

#define FAILS_WITH(options, ...)                                     \
    do {                                                             \
        static const char *const wanted_[] = { __VA_ARGS__, NULL };  \
        read_fails(options, wanted_);                                \
    } while (0)

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
    assert_true(r.accel[0] == 1.5 && r.accel[1] == -2e-3 && r.accel[2] == 7.0);
    excitation_file_free(&r);
}

static void test_csv_unit_g_is_standard_gravity(void **state)
{
    const excitation_file_options options = no_options();
    excitation_file r;
    (void)state;
    write_text("g.csv", "# beamslider base acceleration\n# unit = g\n# sample_rate = 100 Hz\n1\n-0.5\n");
    read_ok(&options, &r);
    assert_true(r.t0 == 0.0);
    assert_true(r.accel[0] == 9.80665 && r.accel[1] == -0.5 * 9.80665);
    excitation_file_free(&r);
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
    assert_true(r.accel[0] == 1.0 && r.accel[3] == 4.0);
    excitation_file_free(&r);
    /* with a header t0 the first time must agree with it */
    write_text("timed_t0.csv", "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n"
                               "# t0 = 0.5 s\n0.5,1\n0.501,2\n");
    read_ok(&options, &r);
    assert_true(r.t0 == 0.5 && r.samples == 2);
    excitation_file_free(&r);
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
    assert_true(r.accel[0] == -20.0);
    assert_true(r.accel[1] == 20.0 * ((double)top / full));
    assert_true(r.accel[2] == 0.0);
    assert_true(r.accel[3] == -20.0 / full);
    excitation_file_free(&r);
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
    assert_true(r.accel[0] == 9.80665 && r.accel[1] == -0.5 * 9.80665 && r.accel[2] == 0.25 * 9.80665);
    excitation_file_free(&r);
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
    assert_true(r.accel[0] == -200.0 && r.accel[1] == -400.0 && r.accel[2] == -600.0);
    excitation_file_free(&r);
}

/* ---- step means */

/* A record in memory: samples x(t0 + j / fs), j = 0 .. n - 1. */
static excitation_file record_of(double (*signal)(double), double rate, double t0, size_t n)
{
    excitation_file r;
    size_t j;
    memset(&r, 0, sizeof r);
    r.path = "memory";
    r.format = "csv";
    r.rate = rate;
    r.t0 = t0;
    r.samples = n;
    r.accel = malloc(n * sizeof *r.accel);
    assert_non_null(r.accel);
    for (j = 0; j < n; ++j)
        r.accel[j] = signal(t0 + (double)j / rate);
    return r;
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
        excitation_file c = record_of(constant, rates[i], t0, n);
        excitation_file r = record_of(ramp, rates[i], t0, n);
        assert_int_equal(excitation_file_means(&c, DT, STEPS, means, err, sizeof err), 0);
        for (k = 0; k < STEPS; ++k)
            assert_close("constant", means[k], -3.7, 0.0, 1e-15);
        assert_int_equal(excitation_file_means(&r, DT, STEPS, means, err, sizeof err), 0);
        for (k = 0; k < STEPS; ++k)
            assert_close("ramp", means[k], ramp(((double)k + 0.5) * DT), 0.0, 1e-12);
        excitation_file_free(&c);
        excitation_file_free(&r);
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
        excitation_file r = record_of(sine, rate, 0.0, (size_t)(STEPS * per_step[i]) + 1);
        double worst = 0.0;
        assert_int_equal(excitation_file_means(&r, DT, STEPS, means, err, sizeof err), 0);
        for (k = 0; k < STEPS; ++k)
            worst = fmax(worst, fabs(means[k] - sine_mean((double)k * DT, (double)(k + 1) * DT)));
        print_message("fs = %g / dt: worst |mean - sine's mean| = %.3e m/s^2, bound %.3e\n", per_step[i],
                      worst, bound);
        assert_true(worst <= bound * (1.0 + 1e-6) + 1e-12);
        if (per_step[i] == 1.0)
            assert_true(worst >= 0.5 * bound);
        excitation_file_free(&r);
    }
}

/* With latency L the step [t_B, t_E] reads the record over [t_B + L, t_E + L]:
 * a ramp's mean moves by its slope times L, and a latency of whole steps
 * shifts the means by as many steps. */
static void test_latency_reads_later(void **state)
{
    excitation_file r = record_of(ramp, 3.0 / DT, 0.0, 3 * STEPS + 100);
    static double shifted[STEPS];
    uint64_t k;
    (void)state;
    r.latency = 7.3e-6;
    assert_int_equal(excitation_file_means(&r, DT, STEPS, means, err, sizeof err), 0);
    for (k = 0; k < STEPS; ++k)
        assert_close("ramp, latency", means[k], ramp(((double)k + 0.5) * DT + 7.3e-6), 0.0, 1e-12);
    free(r.accel);
    r = record_of(sine, 3.0 / DT, 0.0, 3 * STEPS + 100);
    assert_int_equal(excitation_file_means(&r, DT, STEPS, means, err, sizeof err), 0);
    r.latency = 4 * DT;
    assert_int_equal(excitation_file_means(&r, DT, STEPS - 4, shifted, err, sizeof err), 0);
    for (k = 0; k + 4 < STEPS; ++k)
        assert_close("sine, 4 steps late", shifted[k], means[k + 4], 1e-12, 1e-9);
    excitation_file_free(&r);
}

/* The run needs [L, t_end + L]: steps counts the whole steps a record holds;
 * a record that starts after L or ends early is refused with both spans. */
static void test_record_too_short(void **state)
{
    excitation_file r = record_of(constant, 1.0 / DT, 0.0, 101); /* 100 intervals: 100 steps */
    (void)state;
    assert_int_equal(excitation_file_steps(&r, DT), 100);
    assert_int_equal(excitation_file_means(&r, DT, 100, means, err, sizeof err), 0);
    assert_int_equal(excitation_file_means(&r, DT, 101, means, err, sizeof err), -1);
    assert_non_null(strstr(err, "memory covers t = 0 .. 0.002 s"));
    assert_non_null(strstr(err, "the run needs t = 0 .. 0.00202 s"));
    r.latency = 2.5 * DT;
    assert_int_equal(excitation_file_steps(&r, DT), 97);
    assert_int_equal(excitation_file_means(&r, DT, 98, means, err, sizeof err), -1);
    assert_non_null(strstr(err, "latency"));
    r.latency = 0.0;
    r.t0 = 1e-6; /* begins after t = 0 */
    assert_int_equal(excitation_file_steps(&r, DT), 0);
    assert_int_equal(excitation_file_means(&r, DT, 1, means, err, sizeof err), -1);
    r.t0 = -0.5 * DT; /* half a step early: the last step ends half a step sooner */
    assert_int_equal(excitation_file_steps(&r, DT), 99);
    excitation_file_free(&r);
}

/* ---- bad input */

#define HEAD "# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n"

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
        cmocka_unit_test(test_record_too_short),
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
