/* test_out.c - the writers of text that leaves the program in another
 * language (host/lib/io/out_c.c, out_gnuplot.c, out_json.c, out_text.c). Each is fed the texts that broke out of the
 * old ad-hoc quoting (a quote, a backslash, a backquote, an @, a comment's
 * end, a line break, every byte) and must give back, when the result is read
 * as its language reads it, the text as given and nothing else.
 * tests/check_outputs.sh runs the same texts through the commands (and the
 * real C compiler). */
#define _POSIX_C_SOURCE 200809L /* open_memstream */

#include "support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "out_c.h"
#include "out_gnuplot.h"
#include "out_json.h"
#include "out_text.h"

/* Texts an attacker would try, and every byte 1..255 in one. */
static const char *const hostile[] = {
    "x */ int injected = 42; /*",
    "m`touch PWNED`x",
    "@m macro $HOME \\n",
    "quote \" and ' and backslash \\",
    "line\nbreak\r and tab\t",
    "?\?/ trigraph ?\?= and ?\?? and ?",
    "ends with a backslash \\",
    "ends with a star *",
    "/ starts with a slash, */* and /*/ and **/",
    "",
};

static char every_byte[256];

static void fill_every_byte(void)
{
    int i;
    for (i = 1; i < 256; ++i)
        every_byte[i - 1] = (char)i;
    every_byte[255] = '\0';
}

/* What a writer wrote for text, malloc'd. */
static char *written(int (*writer)(FILE *, const char *), const char *text)
{
    char *data = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&data, &size);
    assert_non_null(out);
    assert_int_equal(writer(out, text), 0);
    assert_int_equal(fclose(out), 0);
    return data;
}

/* Reads backslash escapes as C does in a string literal: \ooo (1 to 3
 * octal digits) and \c for any other c; NULL if a lone quote or a line
 * break is inside (the literal would have ended). */
static char *read_escapes(const char *at, const char *end, int in_string)
{
    char *text = malloc((size_t)(end - at) + 1), *put = text;
    assert_non_null(text);
    while (at < end) {
        if ((in_string && *at == '"') || *at == '\n') {
            free(text);
            return NULL;
        }
        if (*at != '\\') {
            *put++ = *at++;
            continue;
        }
        ++at;
        if (*at >= '0' && *at <= '7') {
            int value = 0, digits = 0;
            while (digits < 3 && *at >= '0' && *at <= '7')
                value = value * 8 + (*at++ - '0'), ++digits;
            *put++ = (char)value;
        } else {
            *put++ = *at++;
        }
    }
    *put = '\0';
    return text;
}

static void check_string_literal(const char *text)
{
    char *literal = written(out_c_string, text), *back;
    const size_t n = strlen(literal);
    assert_true(n >= 2 && literal[0] == '"' && literal[n - 1] == '"');
    assert_null(strstr(literal, "??")); /* no trigraph */
    back = read_escapes(literal + 1, literal + n - 1, 1);
    if (!back || strcmp(back, text)) {
        print_error("literal %s does not read back as the text\n", literal);
        fail();
    }
    free(back);
    free(literal);
}

static void test_c_string_literals_read_back_as_given(void **state)
{
    size_t i;
    (void)state;
    fill_every_byte();
    for (i = 0; i < sizeof hostile / sizeof *hostile; ++i)
        check_string_literal(hostile[i]);
    check_string_literal(every_byte);
}

static void check_comment(const char *text)
{
    char *comment = written(out_c_comment_text, text), *back;
    const size_t n = strlen(comment);
    size_t i;
    for (i = 0; i < n; ++i)
        if (!(comment[i] >= 0x20 && comment[i] < 0x7f)) {
            print_error("comment text %s holds byte 0x%02x\n", comment, (unsigned)(unsigned char)comment[i]);
            fail();
        }
    if (strstr(comment, "*/") || strstr(comment, "/*") || strstr(comment, "??") || (n && comment[n - 1] == '\\')) {
        print_error("comment text %s could end, open or splice a comment\n", comment);
        fail();
    }
    back = read_escapes(comment, comment + n, 0);
    assert_non_null(back);
    if (strcmp(back, text)) {
        print_error("comment text %s does not read back as the text\n", comment);
        fail();
    }
    free(back);
    free(comment);
}

static void test_c_comment_text_cannot_leave_the_comment(void **state)
{
    size_t i;
    (void)state;
    fill_every_byte();
    for (i = 0; i < sizeof hostile / sizeof *hostile; ++i)
        check_comment(hostile[i]);
    check_comment(every_byte);
    /* a plain text is written as it is (the headers do not change) */
    {
        char *plain = written(out_c_comment_text, "fig6: signal deflection, noise 1e-07, N/sqrt(Hz)");
        assert_string_equal(plain, "fig6: signal deflection, noise 1e-07, N/sqrt(Hz)");
        free(plain);
    }
}

static void test_c_identifiers_are_checked(void **state)
{
    static const char *const good[] = { "bs_observer_gains_scene", "_x", "a1", "gains_fig6",
                                        "A23456789012345678901234567890123456789012345678901234567890123", NULL };
    static const char *const bad[][2] = {
        { "", "empty" },
        { "1abc", "character 1 ('1')" },
        { "x */ int injected = 42; /*", "character 2 (' ')" },
        { "a-b", "character 2 ('-')" },
        { "caf\xc3\xa9", "character 4 (byte 0xc3)" },
        { "int", "a keyword of C or C++" },
        { "class", "a keyword of C or C++" },
        { "_Bool", "reserved" },
        { "__x", "reserved" },
        { "A234567890123456789012345678901234567890123456789012345678901234", "too long" },
    };
    char err[512];
    size_t i;
    (void)state;
    for (i = 0; good[i]; ++i)
        if (out_c_identifier_check(good[i], "--name", err, sizeof err) != 0) {
            print_error("%s refused: %s\n", good[i], err);
            fail();
        }
    for (i = 0; i < sizeof bad / sizeof *bad; ++i) {
        assert_int_equal(out_c_identifier_check(bad[i][0], "--name", err, sizeof err), -1);
        if (!strstr(err, bad[i][1]) || strncmp(err, "--name", 6) || !strstr(err, "allowed: a C identifier")) {
            print_error("message \"%s\" lacks \"%s\", the option or the rule\n", err, bad[i][1]);
            fail();
        }
    }
}

static void test_c_macro_names_are_identifiers(void **state)
{
    char guard[57], err[512];
    (void)state;
    out_c_macro_name("BS_SCENE_", "fig6", guard, sizeof guard);
    assert_string_equal(guard, "BS_SCENE_FIG6");
    out_c_macro_name("BS_SCENE_", "x */ int injected = 42; /* `a` \n", guard, sizeof guard);
    assert_string_equal(guard, "BS_SCENE_X____INT_INJECTED___42______A___");
    assert_int_equal(out_c_identifier_check(guard, "guard", err, sizeof err), 0);
    fill_every_byte();
    out_c_macro_name("BS_SCENE_", every_byte, guard, sizeof guard);
    assert_int_equal(strlen(guard), 56); /* cut to fit */
    assert_int_equal(out_c_identifier_check(guard, "guard", err, sizeof err), 0);
}

static void test_c_reals_are_floating_literals(void **state)
{
    char text[OUT_C_REAL];
    (void)state;
    assert_int_equal(out_c_real(text, 124.0), 0);
    assert_string_equal(text, "BS_R(124.0)");
    assert_int_equal(out_c_real(text, 0.5), 0);
    assert_string_equal(text, "BS_R(0.5)");
    assert_int_equal(out_c_real(text, -1.7976931348623157e308), 0);
    assert_string_equal(text, "BS_R(-1.7976931348623157e+308)");
    assert_int_equal(out_c_real(text, (double)NAN), -1);
    assert_int_equal(out_c_real(text, (double)INFINITY), -1);
}

/* ---- gnuplot ---- */

/* A single-quoted gnuplot string read as gnuplot reads it ('' is a quote);
 * NULL if it is not one string. */
static char *read_single_quoted(const char *string)
{
    const size_t n = strlen(string);
    char *text = malloc(n + 1), *put = text;
    size_t i;
    assert_non_null(text);
    if (n < 2 || string[0] != '\'' || string[n - 1] != '\'') {
        free(text);
        return NULL;
    }
    for (i = 1; i + 1 < n; ++i) {
        if (string[i] == '\'') {
            if (string[i + 1] != '\'' || i + 2 >= n) { /* a lone quote ends the string early */
                free(text);
                return NULL;
            }
            ++i;
        }
        *put++ = string[i];
    }
    *put = '\0';
    return text;
}

static void test_gnuplot_strings_are_single_quoted_as_given(void **state)
{
    static const struct { const char *text, *shown; } cases[] = {
        { "m`touch PWNED`x", "m`touch PWNED`x" },
        { "@m $HOME \\n # ; \"q\"", "@m $HOME \\n # ; \"q\"" },
        { "it's '' ends with \\", "it's '' ends with \\" },
        { "line\nbreak\r\x7f", "line?break??" },
        { "caf\xc3\xa9 lat\xe9in", "caf\xc3\xa9 lat?in" },
        { "", "" },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof *cases; ++i) {
        char *string = written(out_gnuplot_string, cases[i].text), *back = read_single_quoted(string);
        if (!back || strcmp(back, cases[i].shown)) {
            print_error("case %zu: %s reads as %s\n", i, string, back ? back : "(not one string)");
            fail();
        }
        free(back);
        free(string);
    }
    fill_every_byte();
    {
        char *string = written(out_gnuplot_string, every_byte), *back = read_single_quoted(string);
        const char *c;
        assert_non_null(back);
        for (c = string; *c; c += out_text_utf8_length(c))
            assert_true(out_text_utf8_length(c) > 0 && (unsigned char)*c >= 0x20 && *c != 0x7f);
        free(back);
        free(string);
    }
}

static void test_gnuplot_paths_are_exact_or_refused(void **state)
{
    char *string, *back;
    (void)state;
    string = written(out_gnuplot_path, "/tmp/map \"'\xff`x`/plot.dat");
    back = read_single_quoted(string);
    assert_non_null(back);
    assert_string_equal(back, "/tmp/map \"'\xff`x`/plot.dat"); /* byte for byte: the file's name */
    free(back);
    free(string);
    assert_int_equal(out_gnuplot_path_ok("a\nb"), 0);
    assert_int_equal(out_gnuplot_path_ok("a\tb"), 0);
    assert_int_equal(out_gnuplot_path_ok("/tmp/ok'`"), 1);
    {
        char *data = NULL;
        size_t size = 0;
        FILE *out = open_memstream(&data, &size);
        assert_int_equal(out_gnuplot_path(out, "a\nb"), -1);
        fclose(out);
        assert_string_equal(data, ""); /* nothing written */
        free(data);
    }
}

static void test_gnuplot_comments_are_one_line(void **state)
{
    char *line;
    (void)state;
    line = written(out_gnuplot_comment, "dir\n!touch PWNED \\");
    assert_string_equal(line, "# dir?!touch PWNED ?\n"); /* no line break, no continuation */
    free(line);
    line = written(out_gnuplot_comment, "a \\ b");
    assert_string_equal(line, "# a \\ b\n");
    free(line);
}

/* ---- JSON ---- */

/* The line out_json_finish prints for j, malloc'd. */
static char *finished(out_json *j)
{
    char *data = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&data, &size);
    assert_non_null(out);
    assert_int_equal(out_json_finish(j, out), 0);
    assert_int_equal(fclose(out), 0);
    return data;
}

static void test_json_numbers_not_finite_are_null(void **state)
{
    out_json j;
    char *line;
    (void)state;
    out_json_start(&j);
    out_json_number(&j, "nan", "%.6g", (double)NAN);
    out_json_number(&j, "inf", "%.6f", (double)INFINITY);
    out_json_number(&j, "minus_inf", "%g", -(double)INFINITY);
    out_json_number(&j, "x", "%.6f", 0.5);
    out_json_number(&j, "huge", "%f", 1e300); /* 300 digits: cJSON's own text instead */
    out_json_number(&j, "hex", "%a", 0.5);    /* not JSON's grammar: cJSON's own text */
    out_json_int(&j, "n", -3);
    out_json_count(&j, "c", 18446744073709551615ull);
    out_json_bool(&j, "b", 1);
    out_json_open(&j, "set");
    out_json_number_text(&j, "a.b", "1e-05");
    out_json_number_text(&j, "c.d", "nan");
    out_json_close(&j);
    out_json_text(&j, "after", "root");
    line = finished(&j);
    assert_string_equal(line, "{\"nan\":null,\"inf\":null,\"minus_inf\":null,\"x\":0.500000,\"huge\":1e+300,"
                              "\"hex\":0.5,\"n\":-3,\"c\":18446744073709551615,\"b\":true,"
                              "\"set\":{\"a.b\":1e-05,\"c.d\":\"nan\"},\"after\":\"root\"}\n");
    free(line);
}

static void test_json_number_grammar(void **state)
{
    static const char *const good[] = { "0", "-0", "0.5", "-12.25", "1e+300", "1.0E-5", "4.9e-324", "120", NULL };
    static const char *const bad[] = { "", "nan", "-nan", "inf", "-inf", "01", "1.", ".5", "+1", "0x10", "1e",
                                       "1e+", "1,5", " 1", "1 ", "--1", NULL };
    int i;
    (void)state;
    for (i = 0; good[i]; ++i)
        if (!out_json_is_number(good[i])) {
            print_error("%s refused\n", good[i]);
            fail();
        }
    for (i = 0; bad[i]; ++i)
        if (out_json_is_number(bad[i])) {
            print_error("%s taken for a number\n", bad[i]);
            fail();
        }
}

/* Every text reads back as given (a parser's view), invalid UTF-8 bytes as U+FFFD. */
static void test_json_texts_read_back_as_given_and_utf8(void **state)
{
    static const char *const valid[] = { "q\"b\\c", "line\nbreak\ttab\x01\x7f", "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80",
                                         "m`touch PWNED`x @m $x '", NULL };
    out_json j;
    cJSON *parsed;
    char *line;
    size_t i;
    (void)state;
    for (i = 0; valid[i]; ++i) {
        out_json_start(&j);
        out_json_text(&j, "scene", valid[i]);
        line = finished(&j);
        parsed = cJSON_Parse(line);
        assert_non_null(parsed);
        assert_string_equal(cJSON_GetObjectItem(parsed, "scene")->valuestring, valid[i]);
        cJSON_Delete(parsed);
        free(line);
    }
    fill_every_byte();
    out_json_start(&j);
    out_json_text(&j, "scene", every_byte);
    line = finished(&j);
    for (i = 0; line[i]; i += out_text_utf8_length(line + i))
        if (out_text_utf8_length(line + i) == 0) {
            print_error("byte %zu (0x%02x) of the line is no UTF-8\n", i, (unsigned)(unsigned char)line[i]);
            fail();
        }
    parsed = cJSON_Parse(line);
    assert_non_null(parsed);
    {
        const char *text = cJSON_GetObjectItem(parsed, "scene")->valuestring;
        assert_int_equal(memcmp(text, every_byte, 127), 0); /* ASCII as it was */
        assert_int_equal(strlen(text), 127 + 128 * 3);      /* each byte 0x80..0xff alone: U+FFFD */
    }
    cJSON_Delete(parsed);
    free(line);
}

/* ---- line-based files and UTF-8 ---- */

static void test_utf8_characters_are_told_from_bytes(void **state)
{
    static const struct { const char *text; size_t length; } cases[] = {
        { "a", 1 }, { "\xc3\xa9", 2 }, { "\xe2\x82\xac", 3 }, { "\xf0\x9f\x98\x80", 4 },
        { "\x80", 0 }, { "\xc0\x80", 0 }, { "\xc1\xbf", 0 }, { "\xe0\x80\x80", 0 }, { "\xed\xa0\x80", 0 },
        { "\xf0\x80\x80\x80", 0 }, { "\xf4\x90\x80\x80", 0 }, { "\xf5\x80\x80\x80", 0 }, { "\xff", 0 },
        { "\xe2\x82", 0 }, { "\xc3", 0 }, { "\xc3" "a", 0 },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof *cases; ++i)
        if (out_text_utf8_length(cases[i].text) != cases[i].length) {
            print_error("case %zu: length %zu, expected %zu\n", i, out_text_utf8_length(cases[i].text),
                        cases[i].length);
            fail();
        }
}

static void test_one_line_texts_have_no_control_characters(void **state)
{
    char text[64];
    (void)state;
    snprintf(text, sizeof text, "two\n# sample_rate = 1 Hz\r\t\x7f caf\xc3\xa9");
    assert_string_equal(out_text_one_line(text), "two?# sample_rate = 1 Hz??? caf\xc3\xa9");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_c_string_literals_read_back_as_given),
        cmocka_unit_test(test_c_comment_text_cannot_leave_the_comment),
        cmocka_unit_test(test_c_identifiers_are_checked),
        cmocka_unit_test(test_c_macro_names_are_identifiers),
        cmocka_unit_test(test_c_reals_are_floating_literals),
        cmocka_unit_test(test_gnuplot_strings_are_single_quoted_as_given),
        cmocka_unit_test(test_gnuplot_paths_are_exact_or_refused),
        cmocka_unit_test(test_gnuplot_comments_are_one_line),
        cmocka_unit_test(test_json_numbers_not_finite_are_null),
        cmocka_unit_test(test_json_number_grammar),
        cmocka_unit_test(test_json_texts_read_back_as_given_and_utf8),
        cmocka_unit_test(test_utf8_characters_are_told_from_bytes),
        cmocka_unit_test(test_one_line_texts_have_no_control_characters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
