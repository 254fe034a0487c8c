/* test_summary.c - the JSON summaries of run and sweep (host/lib/run/run_summary.c).
 *
 * The summaries used to be printf'd, the scene name unescaped: a name with a
 * quote, a backslash or a control character (the file name gives the name
 * when [scene] name is not set, and a file name may hold all of those) made
 * the line invalid JSON. Each summary here is parsed back with cJSON; the
 * number formats are compared with the line README.md shows. Run from the
 * repository root (the scenes name a copy of configs/mssp2023.ini).
 */
#define _POSIX_C_SOURCE 200809L

#include "support.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run.h"
#include "scene_values.h"
#include "source_revision.h"
#include "run_summary.h"
#include "sweep.h"

/* static: large */
static scene_file read_scene;
static bs_scene core_scene;
static scene_model scene_derived;
static char tmp_dir[64];
static char line[4096]; /* the summary as printed */

static const char good_scene[] = "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\n"
                                 "acceleration = 14\n[run]\ns0 = 0.3\nt_end = 0.002\n";

/* The keys of each summary, in their order. */
static const char *const run_keys[] = {
    "scene", "model", "precision", "modes", "dt", "excitation", "status", "t_end", "steps", "s0", "s_final",
    "s_min", "t_s_min", "amp_final_h", "amp_periods", "wall_s", "steps_per_s", "max_pgs_iters",
    "unconverged_steps", "contact_steps", "mean_pgs_iters", "max_systems", "mean_systems", "hash", "set", "scene_hash",
    "fields_hash", "version", "revision", NULL };
static const char *const sweep_keys[] = {
    "scene", "command", "dir", "precision", "modes", "dt", "status", "from", "to", "step", "hold", "record",
    "points", "steps", "wall_s", "steps_per_s", "max_pgs_iters", "unconverged_steps", "contact_steps",
    "mean_pgs_iters", "max_systems", "mean_systems", "set", "scene_hash", "fields_hash", "version", "revision",
    NULL };

static void write_file(const char *path, const char *text)
{
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    assert_true(fputs(text, out) >= 0);
    assert_int_equal(fclose(out), 0);
}

static int make_tmp_dir(void **state)
{
    char from[SCENE_PATH];
    char text[4096];
    size_t length;
    FILE *in;

    (void)state;
    if (support_tmp_dir(tmp_dir, sizeof tmp_dir, "test_summary") != 0)
        return -1;
    in = fopen("configs/mssp2023.ini", "r");
    if (!in)
        return -1;
    length = fread(text, 1, sizeof text - 1, in);
    fclose(in);
    text[length] = '\0';
    snprintf(from, sizeof from, "%s/mssp2023.ini", tmp_dir);
    write_file(from, text);
    return 0;
}

static int remove_tmp_dir(void **state)
{
    (void)state;
    return support_tmp_dir_remove(tmp_dir);
}

/* What print wrote to a temporary file, into line. */
#define capture(call)                                                   \
    do {                                                                \
        FILE *out_ = tmpfile();                                         \
        size_t length_;                                                 \
        assert_non_null(out_);                                          \
        assert_int_equal(call, 0);                                      \
        rewind(out_);                                                   \
        length_ = fread(line, 1, sizeof line - 1, out_);                \
        line[length_] = '\0';                                           \
        fclose(out_);                                                   \
    } while (0)

/* line must be one line of JSON, an object with exactly keys, in order;
 * returns the parsed object (cJSON_Delete it). */
static cJSON *parse_summary(const char *const *keys)
{
    const size_t length = strlen(line);
    cJSON *root;
    const cJSON *item;
    int i = 0;

    assert_true(length > 2 && line[length - 1] == '\n');
    assert_null(memchr(line, '\n', length - 1)); /* one line */
    root = cJSON_Parse(line);
    if (!root) {
        print_error("not JSON: %s", line);
        fail();
    }
    assert_true(cJSON_IsObject(root));
    cJSON_ArrayForEach(item, root) {
        assert_non_null(keys[i]);
        assert_string_equal(item->string, keys[i]);
        ++i;
    }
    assert_null(keys[i]);
    return root;
}

/* Runs the scene read from path for its t_end (a few steps) and prints the
 * summary into line. */
/* Runs the scene read into read_scene and core_scene with model and
 * captures its JSON summary. */
static void summarise_loaded(bs_model model)
{
    run_options options;
    run_result result;

    memset(&options, 0, sizeof options);
    options.model = model;
    options.s0 = read_scene.params.s0;
    options.t_end = read_scene.params.t_end;
    options.dt = read_scene.params.dt;
    options.solver = scene_solver(&read_scene.params);
    options.every = 1;
    assert_int_equal(run_scene(&core_scene, &options, &result), 0);
    capture(summary_print_run(out_, &read_scene, &core_scene, NULL, &result));
}

static void run_and_summarise(const char *path)
{
    support_load(path, &read_scene, &core_scene, &scene_derived);
    summarise_loaded((bs_model)read_scene.params.model);
}

/* The name comes from the file name: quote, backslash, newline, tab and a
 * control character, all of which a file name may hold. */
static void test_run_summary_of_a_hostile_file_name_is_json(void **state)
{
    static const char name[] = "q\"b\\c\n\t\x01x";
    char path[SCENE_PATH];
    cJSON *root;

    (void)state;
    snprintf(path, sizeof path, "%s/%s.ini", tmp_dir, name);
    write_file(path, good_scene);
    run_and_summarise(path);
    assert_non_null(strstr(line, "\"scene\":\"q\\\"b\\\\c\\n\\t\\u0001x\""));
    root = parse_summary(run_keys);
    assert_string_equal(cJSON_GetObjectItemCaseSensitive(root, "scene")->valuestring, name);
    assert_string_equal(cJSON_GetObjectItemCaseSensitive(root, "status")->valuestring, "ok");
    assert_true(cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(root, "steps")));
    assert_int_equal(cJSON_GetObjectItemCaseSensitive(root, "steps")->valueint, 100);
    cJSON_Delete(root);
}

static void test_run_summary_of_a_hostile_scene_name_is_json(void **state)
{
    static const char name[] = "a\"b\\c {\"x\":1} \xc3\xbc";
    char path[SCENE_PATH];
    char text[512];
    cJSON *root;

    (void)state;
    snprintf(path, sizeof path, "%s/named.ini", tmp_dir);
    snprintf(text, sizeof text, "%s[scene]\nname = %s\n", good_scene, name);
    write_file(path, text);
    run_and_summarise(path);
    root = parse_summary(run_keys);
    assert_string_equal(cJSON_GetObjectItemCaseSensitive(root, "scene")->valuestring, name);
    cJSON_Delete(root);
}

/* The formats of README.md's example line, digit for digit. */
static void test_run_summary_keeps_the_number_formats(void **state)
{
    static scene_file file; /* static: large */
    static bs_scene scene;
    scene_params params;
    run_result r;
    char expected[1024];
    char hashes[128];
    cJSON *root;

    (void)state;
    memset(&params, 0, sizeof params);
    memset(&scene, 0, sizeof scene);
    memset(&r, 0, sizeof r);
    strcpy(params.name, "fig6");
    params.model = BS_MODEL_FREE;
    params.dt = 2e-5;
    params.s0 = 0.3;
    scene.n_modes = 5;
    r.status = BS_OK;
    r.t = 60.0;
    r.steps = 3000000;
    r.s_final = 0.3312941449;
    r.s_min = 0.2585022091;
    r.t_s_min = 9.29016;
    r.amp_final_h = 1.235241;
    r.amp_periods = 25;
    r.wall_s = 2.359;
    r.solve.max_sweeps = 2;
    r.solve.unconverged_steps = 13;
    r.solve.contact_steps = 2713455;
    r.solve.sweeps = 2721596;
    r.solve.max_systems = 8;
    r.solve.systems = 436006;
    r.hash = 0xa75df610u;
    memset(&file, 0, sizeof file);
    file.params = params;
    capture(summary_print_run(out_, &file, &scene, NULL, &r));
    snprintf(hashes, sizeof hashes, "\"set\":{},\"scene_hash\":\"%08x\",\"fields_hash\":\"%016llx\"",
             (unsigned)bs_scene_hash(&scene), (unsigned long long)scene_values_hash(&params, NULL));
    snprintf(expected, sizeof expected,
             "{\"scene\":\"fig6\",\"model\":\"free\",\"precision\":\"%s\",\"modes\":5,\"dt\":2e-05,"
             "\"excitation\":\"harmonic\",\"status\":\"ok\",\"t_end\":60,\"steps\":3000000,\"s0\":0.3,"
             "\"s_final\":0.331294145,\"s_min\":0.258502209,\"t_s_min\":9.290160,\"amp_final_h\":1.23524,"
             "\"amp_periods\":25,\"wall_s\":2.359,\"steps_per_s\":1.272e+06,\"max_pgs_iters\":2,"
             "\"unconverged_steps\":13,\"contact_steps\":2713455,\"mean_pgs_iters\":1.003,\"max_systems\":8,"
             "\"mean_systems\":0.1607,\"hash\":\"a75df610\",%s,\"version\":\"%s\","
             "\"revision\":\"%s\"}\n", BS_REAL_NAME, hashes, BS_VERSION_STRING, source_revision());
    assert_string_equal(line, expected);
    root = parse_summary(run_keys);
    cJSON_Delete(root);
}

/* JSON has no NaN: a number that is not finite is null, the line stays JSON. */
static void test_non_finite_numbers_are_null(void **state)
{
    static scene_file file; /* static: large */
    static bs_scene scene;
    scene_params params;
    run_result r;
    cJSON *root;

    (void)state;
    memset(&params, 0, sizeof params);
    memset(&scene, 0, sizeof scene);
    memset(&r, 0, sizeof r);
    strcpy(params.name, "nf");
    params.dt = 2e-5;
    r.status = BS_E_NONFINITE;
    r.s_final = (double)NAN;
    r.amp_final_h = HUGE_VAL;
    r.t_s_min = 1e300; /* %.6f: 301 digits, still a number */
    memset(&file, 0, sizeof file);
    file.params = params;
    capture(summary_print_run(out_, &file, &scene, NULL, &r));
    root = parse_summary(run_keys);
    assert_true(cJSON_IsNull(cJSON_GetObjectItemCaseSensitive(root, "s_final")));
    assert_true(cJSON_IsNull(cJSON_GetObjectItemCaseSensitive(root, "amp_final_h")));
    assert_close("t_s_min", cJSON_GetObjectItemCaseSensitive(root, "t_s_min")->valuedouble, 1e300, 0.0, 1e-15);
    cJSON_Delete(root);
}

static void test_sweep_summary_is_json_with_its_formats(void **state)
{
    static const char name[] = "sw\"eep\\\x1f";
    static scene_file file; /* static: large */
    static bs_scene scene;
    scene_params params;
    char hashes[128];
    sweep_options o;
    sweep_result r;
    char expected[1024];
    cJSON *root;

    (void)state;
    memset(&params, 0, sizeof params);
    memset(&scene, 0, sizeof scene);
    memset(&o, 0, sizeof o);
    memset(&r, 0, sizeof r);
    strcpy(params.name, name);
    params.dt = 2e-5;
    scene.n_modes = 5;
    o.from = 0.0;
    o.to = 0.5;
    o.step = 0.005;
    o.hold = 100;
    o.record = 25;
    r.status = BS_OK;
    r.points_done = 101;
    r.steps = 5000000;
    r.wall_s = 3.25;
    r.solve.max_sweeps = 2;
    r.solve.contact_steps = 4;
    r.solve.sweeps = 5;
    r.solve.max_systems = 3;
    r.solve.systems = 3;
    memset(&file, 0, sizeof file);
    file.params = params;
    capture(summary_print_sweep(out_, &file, &scene, &o, &r));
    snprintf(hashes, sizeof hashes, "\"set\":{},\"scene_hash\":\"%08x\",\"fields_hash\":\"%016llx\"",
             (unsigned)bs_scene_hash(&scene), (unsigned long long)scene_values_hash(&params, NULL));
    snprintf(expected, sizeof expected,
             "{\"scene\":\"sw\\\"eep\\\\\\u001f\",\"command\":\"sweep\",\"dir\":\"up\",\"precision\":\"%s\","
             "\"modes\":5,\"dt\":2e-05,\"status\":\"ok\",\"from\":0,\"to\":0.5,\"step\":0.005,\"hold\":100,"
             "\"record\":25,\"points\":101,\"steps\":5000000,\"wall_s\":3.25,\"steps_per_s\":1.538e+06,"
             "\"max_pgs_iters\":2,\"unconverged_steps\":0,\"contact_steps\":4,\"mean_pgs_iters\":1.25,"
             "\"max_systems\":3,\"mean_systems\":0.75,%s,"
             "\"version\":\"%s\",\"revision\":\"%s\"}\n",
             BS_REAL_NAME, hashes, BS_VERSION_STRING, source_revision());
    assert_string_equal(line, expected);
    root = parse_summary(sweep_keys);
    assert_string_equal(cJSON_GetObjectItemCaseSensitive(root, "scene")->valuestring, name);
    cJSON_Delete(root);
}

/* The summary says what it is about: every field the command line set,
 * with its resolved value (numbers as numbers), and hashes that change with
 * any field but the scene's name and description. */
static void test_run_summary_echoes_overrides_and_hashes(void **state)
{
    static scene_file renamed; /* static: large */
    char path[SCENE_PATH];
    char err[1024];
    cJSON *root, *set;

    (void)state;
    snprintf(path, sizeof path, "%s/echo.ini", tmp_dir);
    write_file(path, good_scene);
    support_load(path, &read_scene, &core_scene, &scene_derived);
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "excitation.frequency=1.1e2", err, sizeof err), 0);
    assert_int_equal(scene_set_assignment(&read_scene, "--set", "run.model=free", err, sizeof err), 0);
    assert_int_equal(scene_set(&read_scene, "run", "t_end", "0.001", "--t-end", err, sizeof err), 0);
    support_build(&read_scene, &core_scene, &scene_derived);
    summarise_loaded(BS_MODEL_FREE);
    root = parse_summary(run_keys);
    set = cJSON_GetObjectItemCaseSensitive(root, "set");
    assert_int_equal(cJSON_GetArraySize(set), 3);
    assert_true(cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(set, "excitation.frequency")));
    assert_true(cJSON_GetObjectItemCaseSensitive(set, "excitation.frequency")->valuedouble == 110.0);
    assert_string_equal(cJSON_GetObjectItemCaseSensitive(set, "run.model")->valuestring, "free");
    assert_true(cJSON_GetObjectItemCaseSensitive(set, "run.t_end")->valuedouble == 0.001);
    assert_non_null(strstr(line, "\"set\":{\"excitation.frequency\":110,"));
    assert_int_equal(strlen(cJSON_GetObjectItemCaseSensitive(root, "fields_hash")->valuestring), 16);
    cJSON_Delete(root);
    /* another name and description: the same hash; another value: another */
    renamed = read_scene;
    strcpy(renamed.params.name, "another");
    strcpy(renamed.params.description, "described");
    assert_true(scene_values_hash(&renamed.params, NULL) == scene_values_hash(&read_scene.params, NULL));
    renamed.params.acceleration = nextafter(renamed.params.acceleration, 0.0);
    assert_true(scene_values_hash(&renamed.params, NULL) != scene_values_hash(&read_scene.params, NULL));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_run_summary_of_a_hostile_file_name_is_json),
        cmocka_unit_test(test_run_summary_of_a_hostile_scene_name_is_json),
        cmocka_unit_test(test_run_summary_keeps_the_number_formats),
        cmocka_unit_test(test_non_finite_numbers_are_null),
        cmocka_unit_test(test_sweep_summary_is_json_with_its_formats),
        cmocka_unit_test(test_run_summary_echoes_overrides_and_hashes),
    };
    return cmocka_run_group_tests(tests, make_tmp_dir, remove_tmp_dir);
}
