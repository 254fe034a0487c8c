/* test_measured.c - the one reader of the measured-signals format
 * (host/lib/twin/measured_signals.c; docs/twin.md, "Measured signals file"): the
 * header's fields with their units, the rows and a second pass, and the
 * strictness the former readers lacked: a field given twice, a unit misread
 * (kHz as Hz), an unknown key, a free comment holding '=', a gap between
 * rows. tests/check_inputs.sh feeds the same malformed streams to
 * `beamslider twin` and to twin_pack.
 */

#include "support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measured_signals.h"

static char tmp_dir[64];
static char path[256];
static char err[1024];

static int make_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir(tmp_dir, sizeof tmp_dir, "test_measured");
}

static int remove_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir_remove(tmp_dir);
}

static void write_text(const char *name, const char *text)
{
    FILE *out;
    snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
    out = fopen(path, "w");
    assert_non_null(out);
    assert_int_equal(fputs(text, out) >= 0, 1);
    assert_int_equal(fclose(out), 0);
}

#define TITLE "# beamslider measured signals (a test)\n"
#define HEAD TITLE "# sample_rate = 1000 Hz\n# signal = deflection\n"

/* path must be refused (at open, or at a row) with wanted in err. */
static void refused(const char *text, const char *wanted)
{
    measured_reader m;
    measured_row row;
    int status;
    write_text("bad.csv", text);
    if (measured_open(&m, path, err, sizeof err) == 0) {
        while ((status = measured_next(&m, &row, err, sizeof err)) > 0)
            ;
        measured_close(&m);
        assert_int_equal(status, -1);
    }
    if (!strstr(err, wanted) || !strstr(err, path)) {
        print_error("expected '%s' (and the path) in: %s\n", wanted, err);
        fail();
    }
}

static void test_header_and_rows(void **state)
{
    measured_reader m;
    measured_row row;
    int pass;
    (void)state;
    write_text("good.csv", TITLE "# plant = a = b, free text\n# a free comment\n# sample_rate = 1000 Hz\n"
                               "# signal = voltage\n# signal_unit = V\n# base_accel_unit = m/s^2\n"
                               "# latency = 0.002 s\n# noise = 1.5e-3 V\n# accel_noise = 0 m/s^2\n"
                               "t,base_accel,signal,s_true\n0.001, 1.5,-2e-3 ,0.3\r\n0.002,2,3,0.31\n");
    assert_int_equal(measured_open(&m, path, err, sizeof err), 0);
    assert_true(m.header.rate == 1000.0 && m.header.signal == MEASURED_VOLTAGE && m.header.has_truth);
    assert_true(m.header.noise == 1.5e-3 && m.header.accel_noise == 0.0 && m.header.latency == 0.002);
    for (pass = 0; pass < 2; ++pass) { /* the second pass reads the same rows */
        assert_int_equal(measured_next(&m, &row, err, sizeof err), 1);
        assert_true(row.t == 0.001 && row.base_accel == 1.5 && row.signal == -2e-3 && row.s_true == 0.3);
        assert_int_equal(m.lines.line, 12);
        assert_int_equal(measured_next(&m, &row, err, sizeof err), 1);
        assert_true(row.s_true == 0.31);
        assert_int_equal(measured_next(&m, &row, err, sizeof err), 0);
        assert_int_equal(measured_rewind(&m, err, sizeof err), 0);
    }
    measured_close(&m);
    write_text("plain.csv", HEAD "t,base_accel,signal\n0.001,1,2\n");
    assert_int_equal(measured_open(&m, path, err, sizeof err), 0);
    assert_true(isnan(m.header.noise) && isnan(m.header.accel_noise) && !m.header.has_truth);
    assert_int_equal(measured_next(&m, &row, err, sizeof err), 1);
    assert_true(isnan(row.s_true));
    measured_close(&m);
}

static void test_strict_header(void **state)
{
    (void)state;
    refused("# beamslider measured signalsX\n", ":1: not a measured-signals file");
    refused(HEAD "# sample_rate = 1000 Hz\nt,base_accel,signal\n", ":4: sample_rate given twice (first at line 2)");
    refused(TITLE "# sample_rate = 1 kHz\n", ":2: sample_rate must be a finite number followed by Hz, not '1 kHz'");
    refused(TITLE "# sample_rate = 1000\n", ":2: sample_rate must be a finite number followed by Hz, not '1000'");
    refused(TITLE "# sample_rate = 4.9e-324 Hz\n", ":2: sample_rate 4.94066e-324 Hz is out of range");
    refused(HEAD "# samplerate = 1000 Hz\n", ":4: unknown header field 'samplerate' (known: sample_rate, signal");
    refused(HEAD "# the rate = 1000 Hz\n", ":4: a header line with '=' is a field");
    refused(HEAD "# noise = 1e-6\n", ":4: noise must be a finite number > 0 followed by the signal's unit");
    refused(HEAD "# noise = 1e-6 V\nt,base_accel,signal\n", ":4: noise is given in V, but signal = deflection is in m");
    refused(HEAD "# signal_unit = V\nt,base_accel,signal\n", ":4: signal_unit = V, but signal = deflection is in m");
    refused(HEAD "# base_accel_unit = g\n", ":4: base_accel_unit must be m/s^2, not 'g'");
    refused(HEAD "# latency = -1 s\n", ":4: latency must be a finite number >= 0 followed by s");
    refused(TITLE "# sample_rate = 1000 Hz\nt,base_accel,signal\n0.001,1,2\n",
            "has no line '# signal = deflection (or voltage)'");
    refused(HEAD "\nt,base_accel,signal\n", ":4: expected the column line t,base_accel,signal[,s_true], got '' "
                                            "(an empty line)");
    refused(HEAD, "no column line");
}

static void test_strict_rows(void **state)
{
    (void)state;
    refused(HEAD "t,base_accel,signal\n", "no rows after the column line (line 4)");
    refused(HEAD "t,base_accel,signal\n0.001,1,2\n0.003,1,2\n",
            ":6: t = 0.003 s, expected 0.002 s (row 2 at sample_rate = 1000 Hz): a gap");
    refused(HEAD "t,base_accel,signal\n0.001,1,2\n0.001,1,2\n", ":6: t = 0.001 s, expected 0.002 s");
    refused(HEAD "t,base_accel,signal\n0.00102,1,2\n", ":5: t = 0.00102 s, expected 0.001 s");
    refused(HEAD "t,base_accel,signal\n0.001,inf,2\n", ":5: base_accel 'inf' is not a finite number");
    refused(HEAD "t,base_accel,signal\n0.001,1\n", ":5: 2 values: the column line names 3");
    refused(HEAD "t,base_accel,signal\n0.001,1,2,3\n", ":5: more than 3 values");
    refused(HEAD "t,base_accel,signal\n0.001,,2\n", ":5: empty value in column base_accel");
    refused(HEAD "t,base_accel,signal\n# late\n", ":5: a comment after the column line");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_header_and_rows),
        cmocka_unit_test(test_strict_header),
        cmocka_unit_test(test_strict_rows),
    };
    return cmocka_run_group_tests(tests, make_tmp_dir, remove_tmp_dir);
}
