/* test_out.c - the writers of text that leaves the program in another
 * language (host/lib/out_c.c). Each is fed the texts that broke out of the
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_c_string_literals_read_back_as_given),
        cmocka_unit_test(test_c_comment_text_cannot_leave_the_comment),
        cmocka_unit_test(test_c_identifiers_are_checked),
        cmocka_unit_test(test_c_macro_names_are_identifiers),
        cmocka_unit_test(test_c_reals_are_floating_literals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
