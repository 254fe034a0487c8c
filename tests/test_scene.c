/* test_scene.c - the INI scene reader: scene_load, scene_set, scene_build.
 *
 * Every refusal is checked for what the user needs to fix it: the file and
 * line (or the option) where the value was set, the [section] key and the
 * allowed range as field_range_text() writes it. Scene files are written into
 * a mkdtemp folder under /tmp; the ones that need the full parameter set name
 * a copy of configs/mssp2023.ini there as their base. Run from the repository
 * root (the shipped scenes are read as configs/NAME.ini).
 */
#define _POSIX_C_SOURCE 200809L

#include "support.h"
#include "scene_limits.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* static: large */
static scene_file read_scene;
static bs_scene core_scene;
static scene_model scene_derived;
static char message[1024];

static char tmp_dir[64];
static char field_path[SCENE_PATH]; /* the scene written by write_field_scene */

#define FIELD_LINE 4 /* the line write_field_scene puts the field under test on */

/* ---- helpers ---------------------------------------------------------- */

static void tmp_path(char *out, size_t size, const char *name)
{
    const int length = snprintf(out, size, "%s/%s", tmp_dir, name);
    assert_true(length > 0 && (size_t)length < size);
}

static void write_file(const char *name, const char *text)
{
    char path[SCENE_PATH];
    FILE *out;

    tmp_path(path, sizeof path, name);
    out = fopen(path, "w");
    assert_non_null(out);
    assert_true(fputs(text, out) >= 0);
    assert_int_equal(fclose(out), 0);
}

static void copy_file(const char *from, const char *name)
{
    char text[8192];
    FILE *in = fopen(from, "r");
    size_t length;

    assert_non_null(in);
    length = fread(text, 1, sizeof text - 1, in);
    assert_true(feof(in)); /* the whole file fitted */
    assert_int_equal(fclose(in), 0);
    text[length] = '\0';
    write_file(name, text);
}

/* scene_load of tmp_dir/name into read_scene; the path goes to path. */
static int load_tmp(const char *name, char *path, size_t size)
{
    tmp_path(path, size, name);
    message[0] = '\0';
    return scene_load(path, &read_scene, message, sizeof message);
}

/* 1-based number of the first line of path starting with prefix; fails if none. */
static int line_of(const char *path, const char *prefix)
{
    char text[512];
    FILE *in = fopen(path, "r");
    int line = 0;

    assert_non_null(in);
    while (fgets(text, sizeof text, in)) {
        ++line;
        if (!strncmp(text, prefix, strlen(prefix))) {
            fclose(in);
            return line;
        }
    }
    fclose(in);
    print_error("%s has no line starting with \"%s\"\n", path, prefix);
    fail();
    return -1;
}

static const field_spec *field_of(const char *section, const char *key)
{
    int i;
    for (i = 0; scene_fields[i].key; ++i)
        if (!strcmp(scene_fields[i].section, section) && !strcmp(scene_fields[i].key, key))
            return &scene_fields[i];
    print_error("no field [%s] %s in scene_fields\n", section, key);
    fail();
    return NULL;
}

static void range_text(const char *section, const char *key, char *out, size_t size)
{
    field_range_text(field_of(section, key), out, size);
}

/* Fails unless message contains every string given (a NULL ends the list). */
#define assert_message_has(...) check_message_has(__FILE__, __LINE__, __VA_ARGS__, (const char *)NULL)
static void check_message_has(const char *source, int source_line, const char *first, ...)
{
    va_list args;
    const char *needle;
    const char *missing = NULL;

    va_start(args, first);
    for (needle = first; needle && !missing; needle = va_arg(args, const char *))
        if (!strstr(message, needle))
            missing = needle;
    va_end(args);
    if (missing) {
        print_error("error message \"%s\"\n  does not contain \"%s\"\n", message, missing);
        _fail(source, source_line);
    }
}

/* "path:line:" into out. */
static void place(char *out, size_t size, const char *path, int line)
{
    snprintf(out, size, "%s:%d:", path, line);
}

/* A complete scene (base mssp2023.ini) with [section] key = value on line
 * FIELD_LINE, written as field.ini. The excitation and run lines it adds
 * leave out the field under test, so a valid value loads. */
static void write_field_scene(const char *section, const char *key, const char *value)
{
    static const struct { const char *section, *key, *value; } extra[] = {
        { "excitation", "frequency", "124" },
        { "excitation", "acceleration", "14" },
        { "run", "s0", "0.3" },
        { "run", "t_end", "1" },
    };
    char text[2048];
    size_t used;
    size_t i;

    used = (size_t)snprintf(text, sizeof text, "[scene]\nbase = mssp2023.ini\n[%s]\n%s = %s\n", section,
                            key, value);
    for (i = 0; i < sizeof extra / sizeof extra[0]; ++i) {
        if (!strcmp(extra[i].section, section) && !strcmp(extra[i].key, key))
            continue;
        used += (size_t)snprintf(text + used, sizeof text - used, "[%s]\n%s = %s\n", extra[i].section,
                                 extra[i].key, extra[i].value);
    }
    assert_true(used < sizeof text);
    write_file("field.ini", text);
    tmp_path(field_path, sizeof field_path, "field.ini");
}

static int load_field(const char *section, const char *key, const char *value)
{
    write_field_scene(section, key, value);
    message[0] = '\0';
    return scene_load(field_path, &read_scene, message, sizeof message);
}

/* The value must be refused by scene_load with file:line, [section] key and
 * the allowed range in the message. */
#define assert_field_refused(section, key, value) \
    check_field_refused(section, key, value, __FILE__, __LINE__)
static void check_field_refused(const char *section, const char *key, const char *value,
                                const char *source, int source_line)
{
    char where[SCENE_PATH + 16];
    char field[96];
    char range[96];
    const int status = load_field(section, key, value);

    if (status != -1) {
        print_error("[%s] %s = \"%s\": scene_load returned %d, expected -1\n", section, key, value, status);
        _fail(source, source_line);
    }
    place(where, sizeof where, field_path, FIELD_LINE);
    snprintf(field, sizeof field, "[%s] %s", section, key);
    range_text(section, key, range, sizeof range);
    check_message_has(source, source_line, where, field, range, (const char *)NULL);
}

#define assert_field_accepted(section, key, value) \
    check_field_accepted(section, key, value, __FILE__, __LINE__)
static void check_field_accepted(const char *section, const char *key, const char *value,
                                 const char *source, int source_line)
{
    if (load_field(section, key, value) != 0) {
        print_error("[%s] %s = \"%s\" refused: %s\n", section, key, value, message);
        _fail(source, source_line);
    }
}

/* ---- fixture ---------------------------------------------------------- */

static int make_tmp_dir(void **state)
{
    (void)state;
    if (support_tmp_dir(tmp_dir, sizeof tmp_dir, "test_scene") != 0) {
        perror("support_tmp_dir");
        return -1;
    }
    copy_file("configs/mssp2023.ini", "mssp2023.ini");
    return 0;
}

static int remove_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir_remove(tmp_dir);
}

/* ---- shipped scenes --------------------------------------------------- */

static void test_shipped_scenes_load_and_build(void **state)
{
    static const char *const names[] = { "fig6", "fig7", "fig8", "fig9", "fig12a", "fig12b",
                                         "fig6_1mode" };
    size_t i;

    (void)state;
    for (i = 0; i < sizeof names / sizeof names[0]; ++i) {
        char path[64];
        snprintf(path, sizeof path, "configs/%s.ini", names[i]);
        support_load(path, &read_scene, &core_scene, &scene_derived);
        assert_string_equal(read_scene.params.name, names[i]);
        assert_int_equal(core_scene.n_modes, read_scene.params.modes);
        assert_int_equal(scene_derived.modes.n, read_scene.params.modes);
    }
}

static void test_fig6_has_the_section8_values(void **state)
{
    const scene_params *p = &read_scene.params;
    char where[SCENE_PATH + 16];

    (void)state;
    support_load("configs/fig6.ini", &read_scene, &core_scene, &scene_derived);
    assert_close("frequency", p->frequency, 124.0, 0.0, 1e-15);
    assert_close("acceleration", p->acceleration, 14.0, 0.0, 1e-15);
    assert_close("s0", p->s0, 0.3, 0.0, 1e-15);
    assert_close("t_end", p->t_end, 60.0, 0.0, 1e-15);
    assert_int_equal(p->modes, 5);
    assert_int_equal(p->model, BS_MODEL_FREE);
    assert_close("dt (from the base)", p->dt, 2e-5, 0.0, 1e-15);
    assert_close("beam length (from the base)", p->beam.length, 0.140, 0.0, 1e-15);
    assert_close("core dt", core_scene.dt, 2e-5, 0.0, 2.0 * SUPPORT_EPS);
    /* where each value came from: the file itself, or its base */
    assert_non_null(strstr(scene_where(&read_scene, "excitation", "frequency", where, sizeof where),
                           "configs/fig6.ini:"));
    assert_non_null(strstr(scene_where(&read_scene, "numerics", "dt", where, sizeof where),
                           "configs/mssp2023.ini:"));
}

static void test_fig6_1mode_has_one_mode_and_fig6_values(void **state)
{
    const scene_params *p = &read_scene.params;
    char where[SCENE_PATH + 16];

    (void)state;
    support_load("configs/fig6_1mode.ini", &read_scene, &core_scene, &scene_derived);
    assert_int_equal(p->modes, 1);
    assert_int_equal(core_scene.n_modes, 1);
    assert_close("frequency (base fig6)", p->frequency, 124.0, 0.0, 1e-15);
    assert_close("acceleration (base fig6)", p->acceleration, 14.0, 0.0, 1e-15);
    assert_close("t_end (base fig6)", p->t_end, 60.0, 0.0, 1e-15);
    assert_string_equal(p->name, "fig6_1mode");
    assert_non_null(strstr(scene_where(&read_scene, "numerics", "modes", where, sizeof where),
                           "configs/fig6_1mode.ini:"));
    assert_non_null(strstr(scene_where(&read_scene, "excitation", "frequency", where, sizeof where),
                           "configs/fig6.ini:"));
}

static void test_name_defaults_to_file_name_without_ini(void **state)
{
    char path[SCENE_PATH];

    (void)state;
    write_field_scene("numerics", "modes", "5");
    copy_file(field_path, "plain.ini");
    assert_int_equal(load_tmp("plain.ini", path, sizeof path), 0);
    assert_string_equal(read_scene.params.name, "plain");
    /* only the .ini goes, not everything after the first dot */
    copy_file(field_path, "v1.5.ini");
    assert_int_equal(load_tmp("v1.5.ini", path, sizeof path), 0);
    assert_string_equal(read_scene.params.name, "v1.5");
    /* a name in the file wins */
    assert_int_equal(load_field("scene", "name", "my scene"), 0);
    assert_string_equal(read_scene.params.name, "my scene");
}

/* Names go into the JSON summary, which is UTF-8; and a name is never cut
 * short unseen. */
static void test_names_must_be_utf8_and_whole(void **state)
{
    char path[SCENE_PATH];
    char name[SCENE_TEXT + 16];
    char text[512];
    (void)state;
    assert_field_refused("scene", "name", "caf\xe9");          /* Latin-1 */
    assert_message_has("not UTF-8");
    assert_field_refused("scene", "name", "\xc0\xaf");          /* overlong "/" */
    assert_field_refused("scene", "name", "\xed\xa0\x80");      /* a surrogate */
    assert_field_refused("scene", "name", "\xe2\x82");          /* cut short */
    assert_field_accepted("scene", "name", "caf\xc3\xa9 \xf0\x9f\x8e\xb8");
    assert_string_equal(read_scene.params.name, "caf\xc3\xa9 \xf0\x9f\x8e\xb8");

    /* the file name stands in for a missing [scene] name only when it can */
    write_field_scene("numerics", "modes", "5");
    copy_file(field_path, "caf\xe9.ini");
    assert_int_equal(load_tmp("caf\xe9.ini", path, sizeof path), -1);
    assert_message_has(path, "set [scene] name");
    memset(name, 'n', SCENE_TEXT);
    strcpy(name + SCENE_TEXT, ".ini");
    copy_file(field_path, name);
    assert_int_equal(load_tmp(name, path, sizeof path), -1);
    assert_message_has("longer than 127 characters", "set [scene] name");
    snprintf(text, sizeof text, "[scene]\nbase = mssp2023.ini\nname = named\n[excitation]\nfrequency = 124\n"
                                "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n");
    write_file(name, text);
    assert_int_equal(load_tmp(name, path, sizeof path), 0);
    assert_string_equal(read_scene.params.name, "named");
}

/* ---- unknown, duplicate and overridden keys --------------------------- */

/* refused at its section line: a section without keys would pass unseen */
static void test_unknown_section_is_refused(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    assert_int_equal(load_field("beams", "length", "0.14"), -1);
    place(where, sizeof where, field_path, FIELD_LINE - 1);
    assert_message_has(where, "unknown section [beams]", "allowed: scene, beam, clamps");
    write_file("emptysection.ini", "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\n"
                                   "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n[exitation]\n");
    assert_int_equal(load_tmp("emptysection.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 9);
    assert_message_has(where, "unknown section [exitation]");
}

static void test_unknown_key_is_refused(void **state)
{
    char where[SCENE_PATH + 16];
    (void)state;
    assert_int_equal(load_field("beam", "lenght", "0.14"), -1);
    place(where, sizeof where, field_path, FIELD_LINE);
    assert_message_has(where, "unknown", "[beam] lenght");
}

static void test_key_outside_a_section_is_refused(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("nosection.ini", "dt = 1e-5\n[scene]\nbase = mssp2023.ini\n");
    assert_int_equal(load_tmp("nosection.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 1);
    assert_message_has(where, "dt = 1e-5", "before any [section]");
}

static void test_key_without_a_name_is_refused(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("nokey.ini", "[scene]\nbase = mssp2023.ini\n[run]\n= 0.3\n");
    assert_int_equal(load_tmp("nokey.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 4);
    assert_message_has(where, "no key", "= 0.3");
}

static void test_key_set_twice_names_both_lines(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("twice.ini", "[scene]\n"               /* 1 */
                            "base = mssp2023.ini\n"   /* 2 */
                            "[excitation]\n"          /* 3 */
                            "frequency = 124\n"       /* 4 */
                            "acceleration = 14\n"     /* 5 */
                            "[run]\n"                 /* 6 */
                            "s0 = 0.3\n"              /* 7 */
                            "t_end = 1\n"             /* 8 */
                            "[excitation]\n"          /* 9 */
                            "frequency = 125\n");     /* 10 */
    assert_int_equal(load_tmp("twice.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 10);
    assert_message_has(where, "[excitation] frequency", "twice", "line 4");
}

static void test_base_set_twice_names_both_lines(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    copy_file("configs/fig6.ini", "fig6.ini");
    write_file("twobases.ini", "[scene]\n"               /* 1 */
                               "base = fig6.ini\n"       /* 2 */
                               "base = mssp2023.ini\n"   /* 3 */
                               "[run]\n"                 /* 4 */
                               "s0 = 0.3\n"              /* 5 */
                               "t_end = 1\n"             /* 6 */
                               "[excitation]\n"          /* 7 */
                               "frequency = 124\n"       /* 8 */
                               "acceleration = 14\n");   /* 9 */
    assert_int_equal(load_tmp("twobases.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 3);
    assert_message_has(where, "[scene] base", "twice", "line 2");
}

static void test_file_value_overrides_its_base(void **state)
{
    char base_path[SCENE_PATH];
    char expected[SCENE_PATH + 16];
    char where[SCENE_PATH + 16];

    (void)state;
    assert_int_equal(load_field("beam", "length", "0.15"), 0);
    assert_close("overridden length", read_scene.params.beam.length, 0.15, 0.0, 1e-15);
    snprintf(expected, sizeof expected, "%s:%d", field_path, FIELD_LINE);
    assert_string_equal(scene_where(&read_scene, "beam", "length", where, sizeof where), expected);
    /* the rest of [beam] still comes from the base */
    tmp_path(base_path, sizeof base_path, "mssp2023.ini");
    assert_close("density from the base", read_scene.params.beam.density, 7683.0, 0.0, 1e-15);
    snprintf(expected, sizeof expected, "%s:%d", base_path, line_of(base_path, "density"));
    assert_string_equal(scene_where(&read_scene, "beam", "density", where, sizeof where), expected);
}

/* ---- values ----------------------------------------------------------- */

static void test_real_field_refuses_non_numbers(void **state)
{
    (void)state;
    assert_field_refused("beam", "length", "abc");
    assert_field_refused("beam", "length", "1.0x");
    assert_field_refused("beam", "length", "");
    assert_field_refused("contact", "friction", ""); /* not read as 0, which is allowed */
    assert_field_refused("beam", "length", "0.14 m");
    assert_field_refused("numerics", "dt", "1e-5s");
}

static void test_real_field_refuses_non_finite(void **state)
{
    (void)state;
    assert_field_refused("beam", "length", "nan");
    assert_field_refused("beam", "length", "inf");
    assert_field_refused("beam", "length", "-inf");
    assert_field_refused("beam", "length", "1e999"); /* overflows to inf */
    assert_field_refused("slider", "com_offset", "inf"); /* range (-inf, inf) still wants finite */
    assert_message_has("not finite");
}

static void test_integer_field_refuses_non_integers(void **state)
{
    (void)state;
    assert_field_refused("numerics", "modes", "2.5");
    assert_field_refused("numerics", "modes", "abc");
    assert_field_refused("numerics", "modes", "");
    assert_field_refused("numerics", "modes", "5x");
}

static void test_out_of_range_values_are_refused(void **state)
{
    char too_many[16];

    (void)state;
    snprintf(too_many, sizeof too_many, "%d", BS_MAX_MODES + 1);
    assert_field_refused("beam", "length", "0");
    assert_field_refused("beam", "length", "-1");
    assert_field_refused("slider", "mass", "0");
    assert_field_refused("slider", "play_ratio", "0.99");
    assert_field_refused("contact", "friction", "-0.1");
    assert_field_refused("contact", "restitution", "1.5");
    assert_field_refused("contact", "restitution", "-0.1");
    assert_field_refused("numerics", "modes", "0");
    assert_field_refused("numerics", "modes", too_many);
    assert_field_refused("numerics", "dt", "0");
    assert_field_refused("numerics", "dt", "-1e-5");
    assert_field_refused("beam", "damping_ratio", "1");
    assert_field_refused("run", "s0", "1.5");
    assert_field_refused("run", "model", "fixed");
    assert_message_has("one of: free, pcs");
}

/* The other side of each range edge above: these must load. */
static void test_values_on_the_range_edges_are_accepted(void **state)
{
    const scene_params *p = &read_scene.params;
    char most[16];

    (void)state;
    snprintf(most, sizeof most, "%d", BS_MAX_MODES);
    assert_field_accepted("slider", "play_ratio", "1");
    assert_close("play_ratio", p->play_ratio, 1.0, 0.0, 0.0);
    assert_field_accepted("contact", "friction", "0");
    assert_close("friction", p->mu, 0.0, 0.0, 0.0);
    assert_field_accepted("contact", "restitution", "0");
    assert_field_accepted("contact", "restitution", "1");
    assert_close("restitution", p->e_n, 1.0, 0.0, 0.0);
    assert_field_accepted("numerics", "modes", "1");
    assert_field_accepted("numerics", "modes", most);
    assert_int_equal(p->modes, BS_MAX_MODES);
    assert_field_accepted("beam", "damping_ratio", "0");
    assert_field_accepted("beam", "damping_ratio", "0.999");
    assert_field_accepted("run", "s0", "0");
    assert_field_accepted("run", "s0", "1");
    assert_close("s0", p->s0, 1.0, 0.0, 0.0);
    assert_field_accepted("slider", "com_offset", "-4e-3");
    assert_close("com_offset", p->com_offset, -4e-3, 0.0, 1e-15);
    assert_field_accepted("run", "model", "pcs");
    assert_int_equal(p->model, BS_MODEL_PCS);
    assert_field_accepted("numerics", "dt", "1e-5 ; an inline comment");
    assert_close("dt", p->dt, 1e-5, 0.0, 1e-15);
}

/* ---- missing things --------------------------------------------------- */

static void test_missing_required_field_is_named(void **state)
{
    char path[SCENE_PATH];
    char range[96];

    (void)state;
    write_file("no_t_end.ini", "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\n"
                               "acceleration = 14\n[run]\ns0 = 0.3\n");
    assert_int_equal(load_tmp("no_t_end.ini", path, sizeof path), -1);
    range_text("run", "t_end", range, sizeof range);
    assert_message_has(path, "missing", "[run] t_end", range);
}

static void test_missing_base_file_is_named(void **state)
{
    char path[SCENE_PATH];
    char base_path[SCENE_PATH];
    char where[SCENE_PATH + 16];

    (void)state;
    write_file("nobase.ini", "[scene]\nbase = nope.ini\n[excitation]\nfrequency = 124\n"
                             "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n");
    assert_int_equal(load_tmp("nobase.ini", path, sizeof path), -1);
    tmp_path(base_path, sizeof base_path, "nope.ini");
    place(where, sizeof where, path, 2); /* the line that names the base */
    assert_message_has(base_path, where, "[scene] base");
}

static void test_file_that_does_not_exist_is_named(void **state)
{
    char path[SCENE_PATH];
    (void)state;
    assert_int_equal(load_tmp("absent.ini", path, sizeof path), -1);
    assert_message_has(path);
}

static void test_base_cycle_is_refused(void **state)
{
    char path[SCENE_PATH];
    (void)state;
    write_file("loop.ini", "[scene]\nbase = loop.ini\n");
    assert_int_equal(load_tmp("loop.ini", path, sizeof path), -1);
    assert_message_has(path, "base");
    write_file("ping.ini", "[scene]\nbase = pong.ini\n");
    write_file("pong.ini", "[scene]\nbase = ping.ini\n");
    assert_int_equal(load_tmp("ping.ini", path, sizeof path), -1);
    assert_message_has(tmp_dir, "base");
}

static void test_error_in_the_base_names_the_base(void **state)
{
    char path[SCENE_PATH];
    char base_path[SCENE_PATH];
    char where[SCENE_PATH + 16];

    (void)state;
    write_file("badbase.ini", "[beam]\nlength = -0.14\n");
    write_file("onbadbase.ini", "[scene]\nbase = badbase.ini\n");
    assert_int_equal(load_tmp("onbadbase.ini", path, sizeof path), -1);
    tmp_path(base_path, sizeof base_path, "badbase.ini");
    place(where, sizeof where, base_path, 2);
    assert_message_has(where, "[beam] length");
}

/* ---- what is read: regular files, at most SCENE_MAX_BYTES ------------- */

/* /dev/zero never ends and a FIFO waits for a writer: both used to hang */
static void test_base_that_is_not_a_regular_file_is_refused(void **state)
{
    char path[SCENE_PATH];
    char fifo[SCENE_PATH];
    char where[SCENE_PATH + 16];

    (void)state;
    alarm(60); /* a hang ends the program (SIGALRM) instead of the test run */
    write_file("zero.ini", "[scene]\nbase = /dev/zero\n");
    assert_int_equal(load_tmp("zero.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 2);
    assert_message_has(where, "/dev/zero", "a character device, not a regular file");

    tmp_path(fifo, sizeof fifo, "fifo.ini");
    assert_int_equal(mkfifo(fifo, 0600), 0);
    write_file("onfifo.ini", "[scene]\nbase = fifo.ini\n");
    assert_int_equal(load_tmp("onfifo.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 2);
    assert_message_has(where, fifo, "FIFO", "not a regular file");
    assert_int_equal(load_tmp("fifo.ini", path, sizeof path), -1);
    assert_message_has(fifo, "cannot read scene file", "not a regular file");
    alarm(0);
}

static void test_folder_as_scene_is_refused(void **state)
{
    (void)state;
    message[0] = '\0';
    assert_int_equal(scene_load(tmp_dir, &read_scene, message, sizeof message), -1);
    assert_message_has(tmp_dir, "cannot read scene file", "a folder, not a regular file");
}

/* A valid scene padded with comment lines to size bytes, as big.ini. */
static void write_padded_scene(long size)
{
    static const char head[] = "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\n"
                               "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n";
    char path[SCENE_PATH];
    long used = (long)sizeof head - 1;
    FILE *out;

    tmp_path(path, sizeof path, "big.ini");
    out = fopen(path, "w");
    assert_non_null(out);
    assert_true(fputs(head, out) >= 0);
    for (; used + 100 <= size; used += 100)
        assert_true(fprintf(out, ";%98s\n", "padding") == 100);
    for (; used < size; ++used)
        assert_true(fputc('\n', out) == '\n');
    assert_int_equal(fclose(out), 0);
}

static void test_scene_file_over_the_size_limit_is_refused(void **state)
{
    char path[SCENE_PATH];

    (void)state;
    write_padded_scene(SCENE_MAX_BYTES);
    if (load_tmp("big.ini", path, sizeof path) != 0) {
        print_error("a scene of exactly SCENE_MAX_BYTES: %s\n", message);
        fail();
    }
    write_padded_scene(SCENE_MAX_BYTES + 1);
    assert_int_equal(load_tmp("big.ini", path, sizeof path), -1);
    assert_message_has(path, "1048577 bytes", "more than a scene file may have (1048576, 1 MiB)");
}

/* ---- syntax ----------------------------------------------------------- */

static void test_unclosed_section_is_a_syntax_error(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("section.ini", "[scene]\nbase = mssp2023.ini\n[clamps\nrotational_stiffness = 125\n");
    assert_int_equal(load_tmp("section.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 3);
    assert_message_has(where, "syntax");
}

static void test_text_without_equals_is_a_syntax_error(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("text.ini", "[scene]\nbase = mssp2023.ini\n\n; a comment\njusttext\n[run]\ns0 = 0.3\n");
    assert_int_equal(load_tmp("text.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 5);
    assert_message_has(where, "syntax");
}

/* libinih ignores what follows the ] of a section line: a key written there
 * would be lost and the base value would run. */
static void test_text_after_a_section_line_is_refused(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("after.ini", "[scene]\nbase = mssp2023.ini\n"
                            "[excitation] frequency = 200\n"  /* 3 */
                            "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n");
    assert_int_equal(load_tmp("after.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 3);
    assert_message_has(where, "text after [excitation]", "frequency = 200");
    write_file("afterx.ini", "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\n"
                             "acceleration = 14\n[run]x\ns0 = 0.3\nt_end = 1\n");
    assert_int_equal(load_tmp("afterx.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 6);
    assert_message_has(where, "text after [run]", "\"x\"");
}

/* a ; comment may follow, as after a value */
static void test_comment_after_a_section_line_is_accepted(void **state)
{
    char path[SCENE_PATH];
    (void)state;
    write_file("sectioncomment.ini", "[scene]   ; what it is\nbase = mssp2023.ini\n[excitation];x\n"
                                     "frequency = 124\nacceleration = 14\n[run]\t\ns0 = 0.3\nt_end = 1\n");
    if (load_tmp("sectioncomment.ini", path, sizeof path) != 0) {
        print_error("%s\n", message);
        fail();
    }
}

/* [ run ] would be a section named " run ", [] no section at all */
static void test_section_name_must_be_a_plain_name(void **state)
{
    static const char *const bad[] = { "[ run ]", "[run ]", "[]", "[run.x]", "[r\xc3\xbcn]" };
    char text[256];
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    size_t i;

    (void)state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        snprintf(text, sizeof text, "[scene]\nbase = mssp2023.ini\n%s\ns0 = 0.3\n", bad[i]);
        write_file("badsection.ini", text);
        assert_int_equal(load_tmp("badsection.ini", path, sizeof path), -1);
        place(where, sizeof where, path, 3);
        assert_message_has(where, "section");
    }
}

/* A file saved with classic Mac line ends is one line to a reader that
 * splits at LF: libinih would read "[scene]" and drop the rest. */
static void test_cr_only_line_ends_are_refused(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("mac.ini", "[scene]\rbase = mssp2023.ini\r[excitation]\rfrequency = 124\r"
                          "acceleration = 14\r[run]\rs0 = 0.3\rt_end = 1\r");
    assert_int_equal(load_tmp("mac.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 1);
    assert_message_has(where, "carriage return without a line feed");
    /* one stray CR inside a line */
    write_file("straycr.ini", "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\r200\n");
    assert_int_equal(load_tmp("straycr.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 4);
    assert_message_has(where, "carriage return");
}

static void test_crlf_line_ends_and_bom_are_accepted(void **state)
{
    char path[SCENE_PATH];
    (void)state;
    write_file("crlf.ini", "\xEF\xBB\xBF[scene]\r\nbase = mssp2023.ini\r\n[excitation]\r\nfrequency = 124\r\n"
                           "acceleration = 14\r\n[run]\r\ns0 = 0.3\r\nt_end = 1\r\n");
    if (load_tmp("crlf.ini", path, sizeof path) != 0) {
        print_error("%s\n", message);
        fail();
    }
    assert_close("frequency", read_scene.params.frequency, 124.0, 0.0, 0.0);
    assert_close("t_end", read_scene.params.t_end, 1.0, 0.0, 0.0);
}

static void test_control_character_is_refused(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    (void)state;
    write_file("control.ini", "[scene]\nbase = mssp2023.ini\nname = a\x1b[2Jb\n");
    assert_int_equal(load_tmp("control.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 3);
    assert_message_has(where, "control character 0x1b");
}

/* inih reads lines of at most ini_max_line - 3 characters; a longer one
 * must be refused, not cut into two lines. */
static void test_over_long_line_is_refused_not_split(void **state)
{
    char text[1024];
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    size_t used;

    (void)state;
    /* a valid number padded with zeros: the first part alone would parse */
    used = (size_t)snprintf(text, sizeof text, "[scene]\nbase = mssp2023.ini\n[beam]\nlength = 0.14");
    memset(text + used, '0', 240);
    used += 240;
    snprintf(text + used, sizeof text - used, "\n[excitation]\nfrequency = 124\nacceleration = 14\n"
                                              "[run]\ns0 = 0.3\nt_end = 1\n");
    write_file("long.ini", text);
    assert_int_equal(load_tmp("long.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 4);
    assert_message_has(where, "longer");

    /* a comment whose cut-off tail would read as "dt = 1" */
    used = (size_t)snprintf(text, sizeof text, "[scene]\nbase = mssp2023.ini\n[numerics]\n;");
    memset(text + used, 'x', 250);
    used += 250;
    snprintf(text + used, sizeof text - used, "dt = 1\n[excitation]\nfrequency = 124\n"
                                              "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n");
    write_file("longcomment.ini", text);
    assert_int_equal(load_tmp("longcomment.ini", path, sizeof path), -1);
    place(where, sizeof where, path, 4);
    assert_message_has(where, "longer");
}

static void test_line_at_the_length_limit_is_accepted(void **state)
{
    char text[1024];
    char path[SCENE_PATH];
    size_t used;

    (void)state;
    used = (size_t)snprintf(text, sizeof text, "[scene]\nbase = mssp2023.ini\n;");
    memset(text + used, 'x', 196); /* 197 characters with the ';' */
    used += 196;
    snprintf(text + used, sizeof text - used, "\n[excitation]\nfrequency = 124\nacceleration = 14\n"
                                              "[run]\ns0 = 0.3\nt_end = 1\n");
    write_file("limit.ini", text);
    if (load_tmp("limit.ini", path, sizeof path) != 0) {
        print_error("%s\n", message);
        fail();
    }
}

/* ---- scene_build: checks across fields -------------------------------- */

static void test_dt_above_explicit_limit_is_refused(void **state)
{
    char where[SCENE_PATH + 16];
    char allowed[64];
    char limit[40];

    (void)state;
    assert_int_equal(load_field("numerics", "dt", "1e-4"), 0);
    assert_int_equal(read_scene.params.modes, 5);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    assert_int_equal(scene_derived.modes.n, 5);
    /* omega_5 = 2 pi 3500 Hz: 2 / omega_5 = 9.09e-5 s */
    bound_text(2.0 / scene_derived.modes.omega[4], 1, limit, sizeof limit);
    snprintf(allowed, sizeof allowed, "dt < %s s", limit);
    assert_true(strtod(limit, NULL) <= 2.0 / scene_derived.modes.omega[4]);
    assert_close("2 / omega_max", 2.0 / scene_derived.modes.omega[4], 9.094e-5, 0.0, 1e-3);
    snprintf(where, sizeof where, "%s:%d", field_path, FIELD_LINE);
    assert_message_has(where, "[numerics] dt", "explicit limit", allowed);
}

static void test_dt_below_explicit_limit_builds(void **state)
{
    (void)state;
    assert_int_equal(load_field("numerics", "dt", "9e-5"), 0);
    support_build(&read_scene, &core_scene, &scene_derived);
    assert_close("core dt", core_scene.dt, 9e-5, 0.0, 2.0 * SUPPORT_EPS);
}

/* "allowed: [LOW, HIGH]" of message into low, high; fails if absent. */
static void allowed_range(double *low, double *high)
{
    const char *range = strstr(message, "allowed: [");
    char *end;

    assert_non_null(range);
    *low = strtod(range + strlen("allowed: ["), &end);
    assert_true(end[0] == ',' && end[1] == ' ');
    *high = strtod(end + 2, &end);
    assert_true(*end == ']');
}

/* s0 = text (as the user would type it) must build. */
static void assert_start_accepted(const char *text)
{
    assert_int_equal(scene_set(&read_scene, "run", "s0", text, "--s0", message, sizeof message), 0);
    message[0] = '\0';
    if (scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message) != 0) {
        print_error("s0 = %s, an end of the printed range, refused: %s\n", text, message);
        fail();
    }
}

static void test_free_start_inside_a_clamp_is_refused(void **state)
{
    char where[SCENE_PATH + 16];
    const double low = 0.5 * 10e-3 / 0.140; /* B/2 / L of mssp2023 */
    double printed_low, printed_high;
    char text[40];

    (void)state;
    assert_int_equal(load_field("run", "s0", "0.01"), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    snprintf(where, sizeof where, "%s:%d", field_path, FIELD_LINE);
    assert_message_has(where, "[run] s0", "clamp", "allowed: [0.0357143, 0.9642857]");
    allowed_range(&printed_low, &printed_high);
    assert_close("low end", printed_low, low, 0.0, 1e-6);
    assert_close("high end", printed_high, 1.0 - low, 0.0, 1e-6);
    /* each printed end, typed back, starts (%g printed 0.964286, outside) */
    snprintf(text, sizeof text, "%.17g", printed_low);
    assert_start_accepted(text);
    snprintf(text, sizeof text, "%.17g", printed_high);
    assert_start_accepted(text);
}

/* A slot a hair narrower than the beam: the ends of the start range differ
 * in the 7th digit, where %.6g printed "[0.5, 0.5]". */
static void test_start_range_ends_are_told_apart(void **state)
{
    double printed_low, printed_high;
    char low_text[40], high_text[40];

    (void)state;
    assert_int_equal(load_field("slider", "slot_width", "0.13999994"), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    assert_message_has("[run] s0", "clamp");
    allowed_range(&printed_low, &printed_high);
    assert_true(printed_low < printed_high);
    assert_true(printed_low > 0.4999 && printed_high < 0.5001);
    snprintf(low_text, sizeof low_text, "%.17g", printed_low);
    snprintf(high_text, sizeof high_text, "%.17g", printed_high);
    assert_start_accepted(low_text);
    assert_start_accepted(high_text);
}

/* The largest count of significant digits of a number in message. */
static int most_digits_in_message(void)
{
    const char *c = message;
    int most = 0;

    while (*c) {
        int digits = 0;
        int leading = 1;
        if (!isdigit((unsigned char)*c)) {
            ++c;
            continue;
        }
        for (; isdigit((unsigned char)*c) || *c == '.'; ++c) {
            if (*c == '.' || (leading && *c == '0'))
                continue;
            leading = 0;
            ++digits;
        }
        if (digits > most)
            most = digits;
    }
    return most;
}

/* Adversarial values used to print ranges and limits with %f (150 digits
 * for the frequency of a thick beam) or %g (ends that read alike). */
static void test_range_texts_have_at_most_17_digits(void **state)
{
    static const struct { const char *section, *key, *value; } cases[] = {
        { "beam", "youngs_modulus", "1e200" },
        { "beam", "youngs_modulus", "1e30" },
        { "beam", "thickness", "1e100" },
        { "beam", "density", "1e-200" },
        { "excitation", "frequency", "1e300" },
        { "excitation", "frequency", "1.7e308" },
        { "numerics", "dt", "1e300" },
        { "slider", "slot_width", "0.13999999999999" },
        { "slider", "slot_width", "0.14000000000001" },
    };
    size_t i;

    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        int status = load_field(cases[i].section, cases[i].key, cases[i].value);
        if (status == 0) {
            message[0] = '\0';
            status = scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message);
        }
        if (status == 0 || most_digits_in_message() > 17) {
            print_error("[%s] %s = %s: %s\n", cases[i].section, cases[i].key, cases[i].value,
                        status == 0 ? "accepted" : message);
            fail();
        }
    }
}

static void test_bound_texts_stay_on_their_side(void **state)
{
    static const double values[] = { 0.9642857142857143, 0.03571428571428571, 1.0 / 3.0, 2.0 / 3.0,
                                     9.094372e-05, 1e-300, 1.7976931348623157e308, 4.9e-324, 0.5, 100000 };
    char low[40], high[40], text[40];
    size_t i;

    (void)state;
    for (i = 0; i < sizeof values / sizeof values[0]; ++i) {
        bound_text(values[i], -1, text, sizeof text);
        assert_true(strtod(text, NULL) >= values[i]);
        bound_text(values[i], 1, text, sizeof text);
        assert_true(strtod(text, NULL) <= values[i]);
        assert_true(strlen(text) <= 24);
    }
    bound_text(0.5, 1, text, sizeof text);
    assert_string_equal(text, "0.5");
    range_ends_text(0.49999999, 0.50000001, low, high, sizeof low);
    assert_string_not_equal(low, high);
    assert_true(strtod(low, NULL) >= 0.49999999 && strtod(high, NULL) <= 0.50000001);
    range_ends_text(0.0, HUGE_VAL, low, high, sizeof low);
    assert_string_equal(low, "0");
    assert_string_equal(high, "inf");
    range_ends_text(1.0, nextafter(1.0, 2.0), low, high, sizeof low);
    assert_string_not_equal(low, high);
    values_text(0.14, 0.13999999999999, low, high, sizeof low);
    assert_string_not_equal(low, high);
}

static void test_pcs_start_inside_a_clamp_builds(void **state)
{
    (void)state;
    assert_int_equal(load_field("run", "s0", "0.01"), 0);
    assert_int_equal(scene_set(&read_scene, "run", "model", "pcs", "--model", message, sizeof message), 0);
    support_build(&read_scene, &core_scene, &scene_derived);
}

static void test_slot_as_wide_as_the_beam_is_refused(void **state)
{
    char where[SCENE_PATH + 16];

    (void)state;
    assert_int_equal(load_field("slider", "slot_width", "0.140"), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    snprintf(where, sizeof where, "%s:%d", field_path, FIELD_LINE);
    assert_message_has(where, "[slider] slot_width", "[beam] length");
}

/* ---- extreme values: derived quantities out of their number range ----- */

/* Each value is in its field's range, but a quantity derived from it
 * overflows or underflows (found with a script trying tiny and huge values
 * of every field, docs/robustness.md). The refusal must name the field where
 * it was set, with a range, and not blame another field: a denormal
 * thickness used to give NaN frequencies and a message about dt. */
static void test_extreme_values_are_blamed_on_their_field(void **state)
{
    static const struct { const char *section, *key, *value; } cases[] = {
        { "beam", "thickness", "1e-320" },      /* the denormal of the report: NaN modes */
        { "beam", "thickness", "1.7e308" },
        { "beam", "length", "1e-320" },
        { "beam", "length", "1e300" },
        { "beam", "density", "1e-320" },
        { "beam", "youngs_modulus", "1e-320" },
        { "beam", "mass", "1e-320" },
        { "beam", "mass", "1.7e308" },
        { "clamps", "rotational_stiffness", "1.7e308" },
        { "slider", "mass", "1e-320" },
        { "slider", "inertia", "1e-320" },
        { "slider", "slot_width", "1e-320" },
        { "slider", "com_offset", "1.7e308" },
        { "excitation", "frequency", "1e-320" },
        { "excitation", "acceleration", "1.7e308" },
        { "numerics", "dt", "1e-320" },
    };
    char where[SCENE_PATH + 16];
    char field[96];
    size_t i;

    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        int status = load_field(cases[i].section, cases[i].key, cases[i].value);
        if (status == 0) {
            message[0] = '\0';
            status = scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message);
        }
        snprintf(where, sizeof where, "%s:%d: ", field_path, FIELD_LINE);
        snprintf(field, sizeof field, "[%s] %s = ", cases[i].section, cases[i].key);
        if (status == 0 || strncmp(message, where, strlen(where)) || !strstr(message, field)
            || !strstr(message, "allowed") || strstr(message, "nan") || strstr(message, "inf Hz")
            || strstr(message, "explicit limit")) {
            print_error("[%s] %s = %s: %s\n", cases[i].section, cases[i].key, cases[i].value,
                        status == 0 ? "accepted" : message);
            fail();
        }
    }
}

/* The range a message gives for a field: a value at either end passes the
 * checks of extreme values (the other fields as set). */
static void test_range_of_an_extreme_field_is_one_that_passes(void **state)
{
    double low, high;
    char text[40];

    (void)state;
    assert_int_equal(load_field("beam", "thickness", "1e-320"), 0);
    assert_int_equal(scene_limits_range(&read_scene, "beam", "thickness", &low, &high), 0);
    assert_true(low > 1e-320 && low < 1e-3 && high > 1e-3);
    message[0] = '\0';
    assert_int_equal(scene_limits_check(&read_scene, message, sizeof message), -1);
    bound_text(low, -1, text, sizeof text);
    assert_message_has("[beam] thickness = ", text);
    assert_int_equal(scene_set(&read_scene, "beam", "thickness", text, "--h", message, sizeof message), 0);
    if (scene_limits_check(&read_scene, message, sizeof message) != 0) {
        print_error("thickness = %s, the low end of its range: %s\n", text, message);
        fail();
    }
    bound_text(high, 1, text, sizeof text);
    assert_int_equal(scene_set(&read_scene, "beam", "thickness", text, "--h", message, sizeof message), 0);
    if (scene_limits_check(&read_scene, message, sizeof message) != 0) {
        print_error("thickness = %s, the high end of its range: %s\n", text, message);
        fail();
    }
}

/* Two inputs each within its own range can still make a derived number
 * overflow: E and h together in omega_k^2 = lambda_k^4 E h^2 / (12 rho L^4),
 * which the core holds in bs_real. The message names the quantity and, for
 * each input, its range with the others as set; E at the end of its range is
 * then accepted (the implicit step, so that the stiff beam is not refused for
 * its explicit limit). */
static void test_inputs_overflowing_together_are_each_named_with_a_range(void **state)
{
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    const char *modulus;
    char text[40];
    const char *const scene = BS_REAL_FLOAT
        ? "[scene]\nbase = mssp2023.ini\n[beam]\nyoungs_modulus = 1e300\nthickness = 0.01\n[numerics]\n"
          "integrator = implicit\n[excitation]\nfrequency = 124\nacceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n"
        : "[scene]\nbase = mssp2023.ini\n[beam]\nyoungs_modulus = 1e308\nthickness = 0.1\n[numerics]\n"
          "integrator = implicit\n[excitation]\nfrequency = 124\nacceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n";
    const char *const given = BS_REAL_FLOAT ? "[beam] youngs_modulus = 1e+300 Pa (" : "[beam] youngs_modulus = 1e+308 Pa (";

    (void)state;
    write_file("together.ini", scene); /* youngs_modulus on line 4, thickness on line 5 */
    assert_int_equal(load_tmp("together.ini", path, sizeof path), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    place(where, sizeof where, path, 4);
    assert_message_has(where, "omega_k^2", given, "[beam] thickness = ");
    snprintf(where, sizeof where, "%s:4): [", path);
    assert_message_has(where);
    modulus = strstr(message, given);
    modulus = strstr(modulus, "): [");
    assert_non_null(modulus);
    modulus = strchr(modulus, ',');
    assert_non_null(modulus);
    snprintf(text, sizeof text, "%.*s", (int)strcspn(modulus + 2, "]"), modulus + 2);
    assert_int_equal(scene_set(&read_scene, "beam", "youngs_modulus", text, "--E", message, sizeof message), 0);
    message[0] = '\0';
    if (scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message) != 0) {
        print_error("youngs_modulus = %s, the end of its range: %s\n", text, message);
        fail();
    }
}

/* A large offset d next to a small play: rounded to bs_real, the corners
 * R/2 + d and -R/2 + d lose the play (the core refused it as "corner"). */
static void test_offset_that_rounds_the_play_away_is_refused_with_a_range(void **state)
{
    char where[SCENE_PATH + 16];
    const char *range;
    double low, high;
    char text[40];

    (void)state;
    assert_int_equal(load_field("slider", "com_offset", "1e13"), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    snprintf(where, sizeof where, "%s:%d:", field_path, FIELD_LINE);
    assert_message_has(where, "[slider] com_offset", "play", "allowed: [");
    range = strstr(message, "allowed: [") + strlen("allowed: [");
    low = strtod(range, (char **)&range);
    assert_true(range[0] == ',');
    high = strtod(range + 2, NULL);
    assert_true(low == -high && high > 0.14);
    snprintf(text, sizeof text, "%.17g", high);
    assert_int_equal(scene_set(&read_scene, "slider", "com_offset", text, "--d", message, sizeof message), 0);
    message[0] = '\0';
    if (scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message) != 0) {
        print_error("com_offset = %s, the end of its range: %s\n", text, message);
        fail();
    }
}

/* A slot a hair narrower than the beam passes the check in double; in float
 * the clamp stops B/2 and L - B/2 round together (the core refused it as
 * "stop_min/stop_max", naming no line). */
static void test_slot_that_rounds_to_the_beam_length_is_refused(void **state)
{
    char where[SCENE_PATH + 16];

    (void)state;
    if (!BS_REAL_FLOAT) {
        skip();
        return;
    }
    assert_int_equal(load_field("slider", "slot_width", "0.1399999995"), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    snprintf(where, sizeof where, "%s:%d:", field_path, FIELD_LINE);
    assert_message_has(where, "[slider] slot_width", "[beam] length", "allowed: slot_width < 0.13999998");
}

/* ---- scene_set: command-line overrides -------------------------------- */

static void test_override_applies_a_valid_value(void **state)
{
    char where[SCENE_PATH + 16];
    int files;

    (void)state;
    support_load("configs/fig6.ini", &read_scene, &core_scene, &scene_derived);
    assert_int_equal(scene_set(&read_scene, "numerics", "dt", "1e-5", "--dt", message, sizeof message), 0);
    assert_close("dt", read_scene.params.dt, 1e-5, 0.0, 1e-15);
    assert_string_equal(scene_where(&read_scene, "numerics", "dt", where, sizeof where), "--dt");
    files = read_scene.file_count;
    /* the same option again replaces the value */
    assert_int_equal(scene_set(&read_scene, "numerics", "dt", "1.5e-5", "--dt", message, sizeof message), 0);
    assert_close("dt", read_scene.params.dt, 1.5e-5, 0.0, 1e-15);
    assert_int_equal(read_scene.file_count, files);
    support_build(&read_scene, &core_scene, &scene_derived);
    assert_close("core dt", core_scene.dt, 1.5e-5, 0.0, 2.0 * SUPPORT_EPS);
}

/* Options used to be recorded as extra "files": a long enough command line
 * (or one option spelt several ways) failed with "too many nested base
 * files". Options and the base chain now have separate limits. */
static void test_options_leave_the_base_file_slots_alone(void **state)
{
    static const char *const spellings[] = { "--dt", "--time-step", "-dt", "--DT", "--dt=", "--step",
                                              "--h", "--delta-t", "--dt2", "--dt3", "--dt4", "--dt5" };
    char name[32];
    char text[160];
    char path[SCENE_PATH];
    char where[SCENE_PATH + 16];
    int i;

    (void)state;
    /* a chain of SCENE_MAX_FILES files: chain1.ini .. chainN.ini, the last on mssp2023.ini */
    for (i = 1; i < SCENE_MAX_FILES; ++i) {
        snprintf(name, sizeof name, "chain%d.ini", i);
        if (i + 1 < SCENE_MAX_FILES)
            snprintf(text, sizeof text, "[scene]\nbase = chain%d.ini\n", i + 1);
        else
            snprintf(text, sizeof text, "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\n"
                                        "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 1\n");
        write_file(name, text);
    }
    if (load_tmp("chain1.ini", path, sizeof path) != 0) {
        print_error("%s\n", message);
        fail();
    }
    assert_int_equal(read_scene.file_count, SCENE_MAX_FILES);
    for (i = 0; i < (int)(sizeof spellings / sizeof spellings[0]); ++i) {
        snprintf(text, sizeof text, "%d.5e-5", 1 + i % 3);
        if (scene_set(&read_scene, "numerics", "dt", text, spellings[i], message, sizeof message) != 0) {
            print_error("option %d (%s): %s\n", i + 1, spellings[i], message);
            fail();
        }
        assert_string_equal(scene_where(&read_scene, "numerics", "dt", where, sizeof where), spellings[i]);
    }
    assert_int_equal(scene_set(&read_scene, "run", "t_end", "0.5", "--t-end", message, sizeof message), 0);
    assert_int_equal(read_scene.file_count, SCENE_MAX_FILES);
    /* the files keep their places in messages */
    tmp_path(path, sizeof path, "mssp2023.ini");
    assert_non_null(strstr(scene_where(&read_scene, "beam", "length", where, sizeof where), path));
    support_build(&read_scene, &core_scene, &scene_derived);
    /* the chain limit itself is unchanged: one file more is refused */
    write_file("chain0.ini", "[scene]\nbase = chain1.ini\n");
    assert_int_equal(load_tmp("chain0.ini", path, sizeof path), -1);
    assert_message_has("too many nested base files");
}

static void test_override_refuses_a_bad_value_naming_the_option(void **state)
{
    char range[96];

    (void)state;
    support_load("configs/fig6.ini", &read_scene, &core_scene, &scene_derived);
    range_text("numerics", "dt", range, sizeof range);
    message[0] = '\0';
    assert_int_equal(scene_set(&read_scene, "numerics", "dt", "abc", "--dt", message, sizeof message), -1);
    assert_message_has("--dt", "abc", range);
    message[0] = '\0';
    assert_int_equal(scene_set(&read_scene, "numerics", "dt", "0", "--dt", message, sizeof message), -1);
    assert_message_has("--dt", range);
    assert_close("dt unchanged", read_scene.params.dt, 2e-5, 0.0, 1e-15);
    range_text("run", "t_end", range, sizeof range);
    message[0] = '\0';
    assert_int_equal(scene_set(&read_scene, "run", "t_end", "-1", "--t-end", message, sizeof message), -1);
    assert_message_has("--t-end", range);
    assert_close("t_end unchanged", read_scene.params.t_end, 60.0, 0.0, 1e-15);
    message[0] = '\0';
    assert_int_equal(scene_set(&read_scene, "run", "model", "fixed", "--model", message, sizeof message), -1);
    assert_message_has("--model", "one of: free, pcs");
}

static void test_override_beyond_explicit_limit_names_the_option(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &read_scene, &core_scene, &scene_derived);
    assert_int_equal(scene_set(&read_scene, "numerics", "dt", "1e-4", "--dt", message, sizeof message), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    assert_message_has("--dt", "[numerics] dt", "explicit limit");
}

/* --set section.key=value: the file's checks, the file's message with the
 * option in place of file:line, and the option as the field's place. */
static void test_set_assignment_is_checked_like_a_file_line(void **state)
{
    char where[SCENE_PATH + 16];
    char range[96];
    char section[SCENE_NAME], key[SCENE_NAME];

    (void)state;
    support_load("configs/fig6.ini", &read_scene, &core_scene, &scene_derived);
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "numerics.dt=1e-5", message, sizeof message), 0);
    assert_close("dt", read_scene.params.dt, 1e-5, 0.0, 1e-15);
    assert_string_equal(scene_where(&read_scene, "numerics", "dt", where, sizeof where), "--set numerics.dt=1e-5");
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "run.model=pcs", message, sizeof message), 0);
    assert_int_equal(read_scene.params.model, BS_MODEL_PCS);
    range_text("numerics", "dt", range, sizeof range);
    message[0] = '\0';
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "numerics.dt=abc", message, sizeof message), -1);
    assert_message_has("--set numerics.dt=abc: [numerics] dt = abc: not a number; allowed: ", range);
    assert_close("dt unchanged", read_scene.params.dt, 1e-5, 0.0, 1e-15);
    message[0] = '\0';
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "numerics.dt=-1", message, sizeof message), -1);
    assert_message_has("--set numerics.dt=-1: [numerics] dt = -1: out of range");
    message[0] = '\0';
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "numerics.step=1", message, sizeof message), -1);
    assert_message_has("--set numerics.step=1: unknown field [numerics] step", "beamslider fields");
    message[0] = '\0';
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "dt=1e-5", message, sizeof message), -1);
    assert_message_has("expected section.key=value");
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "numerics.dt", message, sizeof message), -1);
    assert_int_equal(scene_set_assignment(&read_scene, "--set", ".dt=1", message, sizeof message), -1);
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "numerics.=1", message, sizeof message), -1);
    /* [scene] base is the file's business, not a field */
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "scene.base=x.ini", message, sizeof message), -1);
    /* a derived check names the option as the field's place */
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "run.model=free", message, sizeof message), 0);
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "numerics.dt=1e-4", message, sizeof message), 0);
    message[0] = '\0';
    assert_int_equal(scene_build(&read_scene, &core_scene, &scene_derived, message, sizeof message), -1);
    assert_message_has("--set numerics.dt=1e-4", "[numerics] dt", "explicit limit");
    /* field names */
    assert_true(scene_field_named("excitation.frequency=3", 20, section, key) >= 0);
    assert_string_equal(section, "excitation");
    assert_string_equal(key, "frequency");
    assert_int_equal(scene_field_named("excitation.frequency", 19, NULL, NULL), -1);
    assert_int_equal(scene_field_named("excitation", 10, NULL, NULL), -1);
}

/* The table of derived quantities (scene_origins.h): every factor names a
 * field of the scene file, every core field the core can refuse comes from
 * inputs of its own, and the core's text for a changed copy's frequency
 * finds frequency and dt. */
static void test_every_core_field_has_its_origin(void **state)
{
    static const char *const core_fields[] = {
#define CORE_FIELD_NAME(kind, name, dim1, dim2, dim3, rule, unit, meaning) #name,
        BS_SCENE_FIELDS(CORE_FIELD_NAME)
#undef CORE_FIELD_NAME
        "stop_min/stop_max", "frequency/phase_step_half (derived together with dt: ...)"
    };
    scene_input inputs[32];
    size_t c;
    int i, j, k, count;
    (void)state;
    for (i = 0; i < scene_origin_count; ++i)
        for (j = 0; j < SCENE_ORIGIN_FACTORS && scene_origins[i].factors[j].section; ++j) {
            for (k = 0; scene_fields[k].key; ++k)
                if (!strcmp(scene_fields[k].section, scene_origins[i].factors[j].section)
                    && !strcmp(scene_fields[k].key, scene_origins[i].factors[j].key))
                    break;
            if (!scene_fields[k].key)
                fail_msg("row %d (%s): [%s] %s is no field of the scene file", i, scene_origins[i].what,
                         scene_origins[i].factors[j].section, scene_origins[i].factors[j].key);
        }
    for (c = 0; c < sizeof core_fields / sizeof core_fields[0]; ++c) {
        const size_t n = strcspn(core_fields[c], " ");
        int named = 0;
        for (i = 0; i < scene_origin_count && !named; ++i) { /* a row names it, not only the fallback */
            const char *at = scene_origins[i].core_fields;
            while (*at && !named) {
                const size_t m = strcspn(at, " ");
                named = m == n && !strncmp(at, core_fields[c], n);
                at += m + strspn(at + m, " ");
            }
        }
        count = scene_origin_inputs(core_fields[c], inputs, 32);
        if (!named || count < 1)
            fail_msg("core field %s: no row of scene_origins names it", core_fields[c]);
    }
    count = scene_origin_inputs(core_fields[c - 1], inputs, 32);
    assert_int_equal(count, 2);
    assert_string_equal(inputs[0].key, "frequency");
    assert_string_equal(inputs[1].key, "dt");
    count = scene_origin_inputs("corner", inputs, 32);
    assert_int_equal(count, 4); /* slot_width, play_ratio, thickness, com_offset: each once */
    count = scene_origin_inputs("modal", inputs, 32); /* the modal analysis: the beam, the clamps */
    assert_int_equal(count, 7);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shipped_scenes_load_and_build),
        cmocka_unit_test(test_fig6_has_the_section8_values),
        cmocka_unit_test(test_fig6_1mode_has_one_mode_and_fig6_values),
        cmocka_unit_test(test_name_defaults_to_file_name_without_ini),
        cmocka_unit_test(test_names_must_be_utf8_and_whole),
        cmocka_unit_test(test_unknown_section_is_refused),
        cmocka_unit_test(test_unknown_key_is_refused),
        cmocka_unit_test(test_key_outside_a_section_is_refused),
        cmocka_unit_test(test_key_without_a_name_is_refused),
        cmocka_unit_test(test_key_set_twice_names_both_lines),
        cmocka_unit_test(test_base_set_twice_names_both_lines),
        cmocka_unit_test(test_file_value_overrides_its_base),
        cmocka_unit_test(test_real_field_refuses_non_numbers),
        cmocka_unit_test(test_real_field_refuses_non_finite),
        cmocka_unit_test(test_integer_field_refuses_non_integers),
        cmocka_unit_test(test_out_of_range_values_are_refused),
        cmocka_unit_test(test_values_on_the_range_edges_are_accepted),
        cmocka_unit_test(test_missing_required_field_is_named),
        cmocka_unit_test(test_missing_base_file_is_named),
        cmocka_unit_test(test_file_that_does_not_exist_is_named),
        cmocka_unit_test(test_base_cycle_is_refused),
        cmocka_unit_test(test_error_in_the_base_names_the_base),
        cmocka_unit_test(test_base_that_is_not_a_regular_file_is_refused),
        cmocka_unit_test(test_folder_as_scene_is_refused),
        cmocka_unit_test(test_scene_file_over_the_size_limit_is_refused),
        cmocka_unit_test(test_unclosed_section_is_a_syntax_error),
        cmocka_unit_test(test_text_without_equals_is_a_syntax_error),
        cmocka_unit_test(test_text_after_a_section_line_is_refused),
        cmocka_unit_test(test_comment_after_a_section_line_is_accepted),
        cmocka_unit_test(test_section_name_must_be_a_plain_name),
        cmocka_unit_test(test_cr_only_line_ends_are_refused),
        cmocka_unit_test(test_crlf_line_ends_and_bom_are_accepted),
        cmocka_unit_test(test_control_character_is_refused),
        cmocka_unit_test(test_over_long_line_is_refused_not_split),
        cmocka_unit_test(test_line_at_the_length_limit_is_accepted),
        cmocka_unit_test(test_dt_above_explicit_limit_is_refused),
        cmocka_unit_test(test_dt_below_explicit_limit_builds),
        cmocka_unit_test(test_free_start_inside_a_clamp_is_refused),
        cmocka_unit_test(test_start_range_ends_are_told_apart),
        cmocka_unit_test(test_range_texts_have_at_most_17_digits),
        cmocka_unit_test(test_bound_texts_stay_on_their_side),
        cmocka_unit_test(test_pcs_start_inside_a_clamp_builds),
        cmocka_unit_test(test_slot_as_wide_as_the_beam_is_refused),
        cmocka_unit_test(test_extreme_values_are_blamed_on_their_field),
        cmocka_unit_test(test_range_of_an_extreme_field_is_one_that_passes),
        cmocka_unit_test(test_inputs_overflowing_together_are_each_named_with_a_range),
        cmocka_unit_test(test_offset_that_rounds_the_play_away_is_refused_with_a_range),
        cmocka_unit_test(test_slot_that_rounds_to_the_beam_length_is_refused),
        cmocka_unit_test(test_override_applies_a_valid_value),
        cmocka_unit_test(test_options_leave_the_base_file_slots_alone),
        cmocka_unit_test(test_override_refuses_a_bad_value_naming_the_option),
        cmocka_unit_test(test_override_beyond_explicit_limit_names_the_option),
        cmocka_unit_test(test_set_assignment_is_checked_like_a_file_line),
        cmocka_unit_test(test_every_core_field_has_its_origin),
    };
    return cmocka_run_group_tests(tests, make_tmp_dir, remove_tmp_dir);
}
