/* test_input_file.c - the one way files are opened for reading
 * (host/lib/io/input_file.c; docs/robustness.md, "Files a command reads"):
 * a FIFO without a writer is refused at once (not waited for), so are a
 * device and a folder; a file over its kind's bound is refused with its size
 * and the bound; a file that changes between two passes is told apart; lines
 * are bounded, NUL bytes refused, \n and \r\n ends both read.
 */
#define _POSIX_C_SOURCE 200809L /* mkfifo, ftruncate */

#include "support.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "input_file.h"

static char tmp_dir[64];
static char path[256];
static char err[1024];

static int make_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir(tmp_dir, sizeof tmp_dir, "test_input_file");
}

static int remove_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir_remove(tmp_dir);
}

static void write_text(const char *name, const char *text, size_t size)
{
    FILE *out;
    snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
    out = fopen(path, "wb");
    assert_non_null(out);
    assert_int_equal(fwrite(text, 1, size, out), size);
    assert_int_equal(fclose(out), 0);
}

/* The open of path as kind must fail with every one of wanted in err. */
static void open_fails(input_kind kind, const char *a, const char *b)
{
    FILE *file = (FILE *)1;
    assert_int_equal(input_file_open(path, kind, &file, NULL, err, sizeof err), -1);
    assert_null(file);
    if (!strstr(err, path) || !strstr(err, a) || (b && !strstr(err, b))) {
        print_error("message without '%s', '%s' or the path: %s\n", a, b ? b : "", err);
        fail();
    }
}

static void test_what_is_not_a_regular_file(void **state)
{
    (void)state;
    snprintf(path, sizeof path, "%s/fifo", tmp_dir);
    assert_int_equal(mkfifo(path, 0600), 0);
    open_fails(INPUT_MEASURED, "cannot read measured-signals file: a FIFO (named pipe), not a regular file",
               "give --measured -");
    open_fails(INPUT_RECORD, "cannot read excitation record: a FIFO", NULL);
    snprintf(path, sizeof path, "/dev/zero");
    open_fails(INPUT_MAP_RESULTS, "cannot read map result file: a character device, not a regular file", NULL);
    snprintf(path, sizeof path, "%s", tmp_dir);
    open_fails(INPUT_SCENE, "cannot read scene file: a folder, not a regular file", NULL);
    snprintf(path, sizeof path, "%s/none", tmp_dir);
    open_fails(INPUT_MAP_TABLE, "cannot open map table: No such file or directory", NULL);
}

/* A sparse file one byte over each bound: its size and the bound named. */
static void test_size_bound(void **state)
{
    static const input_kind kinds[] = { INPUT_SCENE, INPUT_MAP_IDENTITY, INPUT_MAP_RESULTS, INPUT_RECORD };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof kinds / sizeof kinds[0]; ++i) {
        const long long bound = input_kind_max_bytes(kinds[i]);
        char want[96];
        FILE *file;
        FILE *out;
        snprintf(path, sizeof path, "%s/big%lu", tmp_dir, (unsigned long)i);
        out = fopen(path, "w");
        assert_non_null(out);
        assert_int_equal(ftruncate(fileno(out), (off_t)bound), 0);
        assert_int_equal(fclose(out), 0);
        assert_int_equal(input_file_open(path, kinds[i], &file, NULL, err, sizeof err), 0); /* at the bound */
        fclose(file);
        assert_int_equal(truncate(path, (off_t)bound + 1), 0);
        snprintf(want, sizeof want, "%lld bytes, more than a %s may have (%lld, ", bound + 1, input_kind_name(kinds[i]),
                 bound);
        open_fails(kinds[i], want, NULL);
        unlink(path);
    }
}

/* The identity of an open file tells a changed file apart. */
static void test_identity(void **state)
{
    input_identity identity;
    FILE *file, *again;
    (void)state;
    write_text("same.csv", "1\n", 2);
    assert_int_equal(input_file_open(path, INPUT_RECORD, &file, &identity, err, sizeof err), 0);
    assert_int_equal(input_file_open(path, INPUT_RECORD, &again, NULL, err, sizeof err), 0);
    assert_true(input_file_unchanged(again, &identity));
    fclose(again);
    write_text("same.csv", "1\n2\n", 4);
    assert_int_equal(input_file_open(path, INPUT_RECORD, &again, NULL, err, sizeof err), 0);
    assert_false(input_file_unchanged(again, &identity));
    fclose(again);
    fclose(file);
}

static void test_lines(void **state)
{
    static const char text[] = "one\r\ntwo\n\nfour\r\n12345678\r\n123456789\nx\0y\n";
    input_lines in;
    char line[9], wide[32];
    FILE *file;
    (void)state;
    write_text("lines.txt", text, sizeof text - 1);
    assert_int_equal(input_file_open(path, INPUT_MEASURED, &file, NULL, err, sizeof err), 0);
    input_lines_start(&in, file, "lines.txt", input_kind_max_bytes(INPUT_MEASURED));
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), 1);
    assert_string_equal(line, "one");
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), 1);
    assert_string_equal(line, "two");
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), 1);
    assert_string_equal(line, "");
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), 1);
    assert_string_equal(line, "four");
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), 1); /* 8 and \r\n fit */
    assert_string_equal(line, "12345678");
    assert_int_equal(in.line, 5);
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), -1);
    assert_string_equal(err, "lines.txt:6: longer than 8 characters");
    fclose(file);
    assert_int_equal(input_file_open(path, INPUT_MEASURED, &file, NULL, err, sizeof err), 0);
    input_lines_start(&in, file, "lines.txt", 0);
    while (in.line < 6)
        assert_int_equal(input_lines_next(&in, wide, sizeof wide, err, sizeof err), 1);
    assert_string_equal(wide, "123456789");
    assert_int_equal(input_lines_next(&in, wide, sizeof wide, err, sizeof err), -1);
    assert_string_equal(err, "lines.txt:7: a NUL byte: not a text file");
    fclose(file);
    /* a bound below the file's size: the reader stops there (a file that grows) */
    assert_int_equal(input_file_open(path, INPUT_MEASURED, &file, NULL, err, sizeof err), 0);
    input_lines_start(&in, file, "lines.txt", 6);
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), 1);
    assert_int_equal(input_lines_next(&in, line, sizeof line, err, sizeof err), -1);
    assert_non_null(strstr(err, "lines.txt:2: the file grew past 6 bytes"));
    fclose(file);
}

/* The fields of a line: blanks, a trailing blank run, a number and its unit. */
static void test_fields(void **state)
{
    char text[] = "  1 \t ";
    double value = 0.0;
    (void)state;
    assert_string_equal(input_skip_blanks(" \t x "), "x ");
    input_trim_end(text);
    assert_string_equal(text, "  1");
    input_trim_end(text + 3); /* an empty text stays empty */
    assert_int_equal(input_number(" 1e3 Hz ", "Hz", &value), 0);
    assert_true(value == 1e3);
    assert_int_equal(input_number("2.5Hz", "Hz", &value), 0);
    assert_true(value == 2.5);
    assert_int_equal(input_number("-4", NULL, &value), 0);
    assert_true(value == -4.0);
    assert_int_equal(input_number("1 m/s^2", "m", &value), -1); /* "m" is not "m/s^2" */
    assert_int_equal(input_number("1 m/s^2", "m/s^2", &value), 0);
    assert_int_equal(input_number("1 Hzx", "Hz", &value), -1);
    assert_int_equal(input_number("1 Hz x", "Hz", &value), -1);
    assert_int_equal(input_number("1", "Hz", &value), -1);
    assert_int_equal(input_number("1 2", NULL, &value), -1);
    assert_int_equal(input_number("Hz", "Hz", &value), -1);
    assert_int_equal(input_number("", NULL, &value), -1);
    assert_int_equal(input_number("inf", NULL, &value), -1);
    assert_int_equal(input_number("nan", NULL, &value), -1);
    assert_int_equal(input_number("1e999", NULL, &value), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_what_is_not_a_regular_file),
        cmocka_unit_test(test_size_bound),
        cmocka_unit_test(test_identity),
        cmocka_unit_test(test_lines),
        cmocka_unit_test(test_fields),
    };
    return cmocka_run_group_tests(tests, make_tmp_dir, remove_tmp_dir);
}
