/* test_host_api.c - libbeamslider-host as a program takes it (host/include/
 * beamslider_host.h): errors as values with the CLI's text, scenes from
 * files and text with overrides, runs, sweeps, maps and the twin's design
 * and stream format; and no shared mutable state: four threads load and run
 * four scenes (and design four observers) at once and get the hashes (and
 * gains) of the serial runs, bit for bit.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "beamslider_host.h"

#define THREADS 4

static const char *const scene_paths[THREADS] = { "configs/fig6.ini", "configs/fig7.ini", "configs/fig8.ini",
                                                  "configs/fig9.ini" };
static const char *const short_run[] = { "run.t_end=0.5" };

static bs_host_scene *load(const char *path, const char *const *overrides, int count)
{
    bs_host_error error;
    bs_host_scene *scene = NULL;
    if (bs_host_scene_load(path, overrides, count, &scene, &error) != BS_HOST_OK) {
        print_error("%s: %s\n", path, error.text);
        fail();
    }
    return scene;
}

/* ---- errors as values --------------------------------------------------- */

static void test_errors_come_back_with_the_cli_text(void **state)
{
    static const char *const bad_override[] = { "numerics.dt=0" };
    static const char *const unknown[] = { "numerics.colour=red" };
    bs_host_error error;
    bs_host_scene *scene = (bs_host_scene *)&error; /* set to NULL on failure */
    char value[64];
    (void)state;
    assert_int_equal(bs_host_scene_load("configs/none.ini", NULL, 0, &scene, &error), BS_HOST_E_INPUT);
    assert_null(scene);
    assert_int_equal(error.status, BS_HOST_E_INPUT);
    assert_non_null(strstr(error.text, "configs/none.ini: cannot open scene file"));
    assert_int_equal(bs_host_scene_load("configs/fig6.ini", bad_override, 1, &scene, &error), BS_HOST_E_INPUT);
    assert_non_null(strstr(error.text, "--set numerics.dt=0: [numerics] dt = 0: out of range; allowed: "));
    assert_int_equal(bs_host_scene_load("configs/fig6.ini", unknown, 1, &scene, &error), BS_HOST_E_INPUT);
    assert_non_null(strstr(error.text, "unknown field [numerics] colour"));
    /* text with a line out of range: the name and line */
    assert_int_equal(bs_host_scene_parse("mine.ini", "[scene]\nbase = configs/fig6.ini\n[numerics]\ndt = -1\n", NULL,
                                         0, &scene, &error),
                     BS_HOST_E_INPUT);
    assert_non_null(strstr(error.text, "mine.ini:4: [numerics] dt = -1: out of range"));
    /* a program built against the other precision's headers */
    assert_int_equal(bs_host_scene_load_(BS_BUILD_TAG ^ 1u, sizeof(bs_sim), sizeof(bs_scene), "configs/fig6.ini",
                                         NULL, 0, &scene, &error),
                     BS_HOST_E_BUILD);
    assert_null(scene);
    assert_int_equal(bs_host_scene_load(NULL, NULL, 0, &scene, &error), BS_HOST_E_NULL);
    /* a good scene from text, and set: dt and the frequency change, the scene is built again */
    assert_int_equal(bs_host_scene_parse("configs/text.ini", "[scene]\nbase = fig6.ini\n[run]\nt_end = 0.1\n", NULL, 0,
                                         &scene, &error),
                     BS_HOST_OK);
    assert_string_equal(error.text, "");
    assert_int_equal(bs_host_scene_value(scene, "run.t_end", value, sizeof value, &error), BS_HOST_OK);
    assert_string_equal(value, "0.1");
    assert_int_equal(bs_host_scene_value(scene, "run.end", value, sizeof value, &error), BS_HOST_E_INPUT);
    assert_int_equal(bs_host_scene_set(scene, "numerics.dt=1e-05", &error), BS_HOST_OK);
    assert_true(bs_host_scene_core(scene)->dt == (bs_real)1e-5);
    assert_int_equal(bs_host_scene_set(scene, "numerics.dt=1", &error), BS_HOST_E_INPUT); /* unchanged */
    assert_true(bs_host_scene_core(scene)->dt == (bs_real)1e-5);
    assert_int_equal(bs_host_scene_set(scene, "excitation.frequency=110", &error), BS_HOST_OK);
    assert_true(bs_host_scene_core(scene)->frequency == BS_R(110.0));
    bs_host_scene_free(scene);
    assert_string_equal(bs_host_status_text(BS_HOST_E_INPUT), "bad input");
}

/* ---- the run is the core's loop ------------------------------------------- */

static void test_a_run_is_the_core_loop(void **state)
{
    static bs_sim sim;
    bs_host_scene *scene = load("configs/fig6.ini", short_run, 1);
    bs_host_run_options options;
    bs_host_run_result result;
    bs_host_setup setup;
    bs_host_modes modes;
    bs_host_error error;
    uint64_t k;
    (void)state;
    bs_host_scene_setup(scene, &setup);
    assert_string_equal(setup.name, "fig6");
    assert_int_equal(setup.steps, 25000);
    assert_int_equal(bs_sim_init(&sim, bs_host_scene_core(scene), setup.model, (bs_real)setup.s0), BS_OK);
    assert_int_equal(bs_sim_set_solver(&sim, &setup.solver), BS_OK);
    for (k = 0; k < setup.steps; ++k)
        assert_int_equal(bs_sim_step(&sim), BS_OK);
    bs_host_run_defaults(&options);
    assert_int_equal(bs_host_run(scene, &options, &result, &error), BS_HOST_OK);
    assert_int_equal(result.steps, setup.steps);
    assert_int_equal(result.hash, bs_sim_hash(&sim));
    assert_true(result.s_final == (double)bs_sim_position(&sim));
    bs_host_scene_modes(scene, &modes);
    assert_int_equal(modes.n, 5);
    assert_true(fabs(modes.frequency[0] - 260.28054) < 1e-3); /* beamslider modes configs/fig6.ini */
    assert_true(bs_host_attached_frequency(scene, 0.3) > 0.0);
    bs_host_scene_free(scene);
}

/* The summary of a run, and of a sweep, is the line `beamslider` prints: it
 * names the scene and carries the run's hash (the bridges read it). */
static void test_a_run_and_a_sweep_write_the_cli_summary(void **state)
{
    bs_host_scene *scene = load("configs/fig6.ini", short_run, 1);
    bs_host_run_options options;
    bs_host_run_result result;
    bs_host_sweep_options sweep;
    bs_host_error error;
    char line[4096], hash[32];
    FILE *out = tmpfile();
    (void)state;
    assert_non_null(out);
    bs_host_run_defaults(&options);
    options.summary = out;
    assert_int_equal(bs_host_run(scene, &options, &result, &error), BS_HOST_OK);
    rewind(out);
    assert_non_null(fgets(line, sizeof line, out));
    snprintf(hash, sizeof hash, "\"hash\":\"%08x\"", (unsigned)result.hash);
    assert_non_null(strstr(line, "{\"scene\":\"fig6\",\"model\":\"free\""));
    assert_non_null(strstr(line, hash));
    assert_non_null(strstr(line, "\"steps\":25000,"));
    assert_non_null(strstr(line, "\"set\":{\"run.t_end\":0.5}"));
    assert_true(strchr(line, '\n') != NULL);
    fclose(out);
    out = tmpfile();
    assert_non_null(out);
    bs_host_sweep_defaults(&sweep);
    sweep.from = 0.3;
    sweep.to = 0.31;
    sweep.step = 0.01;
    sweep.hold = 1;
    sweep.record = 1;
    sweep.summary = out;
    assert_int_equal(bs_host_sweep(scene, &sweep, NULL, &error), BS_HOST_OK);
    rewind(out);
    assert_non_null(fgets(line, sizeof line, out));
    assert_non_null(strstr(line, "\"command\":\"sweep\""));
    assert_non_null(strstr(line, "\"points\":2,"));
    fclose(out);
    bs_host_scene_free(scene);
}

/* on_step every N steps, and stopping a run from it */
static int count_steps(void *context, const bs_sim *sim, uint64_t step, double t)
{
    int *calls = context;
    (void)sim;
    (void)t;
    ++*calls;
    return step >= 1000;
}

static void test_on_step_sees_and_stops_the_run(void **state)
{
    bs_host_scene *scene = load("configs/fig6.ini", short_run, 1);
    bs_host_run_options options;
    bs_host_run_result result;
    bs_host_error error;
    int calls = 0;
    (void)state;
    bs_host_run_defaults(&options);
    options.every = 250;
    options.on_step = count_steps;
    options.on_step_context = &calls;
    assert_int_equal(bs_host_run(scene, &options, &result, &error), BS_HOST_E_FAILED);
    assert_true(result.stopped);
    assert_int_equal(result.steps, 1000);
    assert_int_equal(calls, 5); /* steps 0, 250, 500, 750, 1000 */
    assert_non_null(strstr(error.text, "stopped by on_step"));
    options.every = 0;
    assert_int_equal(bs_host_run(scene, &options, &result, &error), BS_HOST_E_INPUT);
    bs_host_scene_free(scene);
}

/* ---- threads ------------------------------------------------------------ */

typedef struct job {
    int index;
    uint32_t hash;
    bs_observer_gains gains;
    int failed;
} job;

static int design(const bs_host_scene *scene, bs_observer_gains *gains)
{
    bs_host_twin_options options;
    bs_host_error error;
    bs_host_twin_defaults(&options, 1e-6);
    options.map_count = 1;
    options.map_frequency[0] = 10000.0; /* five steps a period: a cheap map */
    return bs_host_twin_design(scene, &options, gains, &error) != BS_HOST_OK;
}

/* Loads, runs and designs for one scene, as a thread or in turn. */
static void *work(void *argument)
{
    job *j = argument;
    bs_host_scene *scene = NULL;
    bs_host_run_options options;
    bs_host_run_result result;
    bs_host_error error;
    j->failed = bs_host_scene_load(scene_paths[j->index], short_run, 1, &scene, &error) != BS_HOST_OK;
    if (j->failed)
        return NULL;
    bs_host_run_defaults(&options);
    j->failed = bs_host_run(scene, &options, &result, &error) != BS_HOST_OK || design(scene, &j->gains) != 0;
    j->hash = result.hash;
    bs_host_scene_free(scene);
    return NULL;
}

static void test_four_threads_compute_what_serial_runs_do(void **state)
{
    static job serial[THREADS], parallel[THREADS];
    pthread_t threads[THREADS];
    int i;
    (void)state;
    for (i = 0; i < THREADS; ++i) {
        serial[i].index = parallel[i].index = i;
        work(&serial[i]);
        assert_false(serial[i].failed);
    }
    for (i = 0; i < THREADS; ++i)
        assert_int_equal(pthread_create(&threads[i], NULL, work, &parallel[i]), 0);
    for (i = 0; i < THREADS; ++i)
        assert_int_equal(pthread_join(threads[i], NULL), 0);
    for (i = 0; i < THREADS; ++i) {
        assert_false(parallel[i].failed);
        if (parallel[i].hash != serial[i].hash)
            fail_msg("%s: hash %08x in a thread, %08x alone", scene_paths[i], (unsigned)parallel[i].hash,
                     (unsigned)serial[i].hash);
        assert_memory_equal(&parallel[i].gains, &serial[i].gains, sizeof serial[i].gains);
    }
    for (i = 1; i < THREADS; ++i) /* four different scenes: four different states */
        assert_true(serial[i].hash != serial[0].hash);
}

/* ---- sweeps and maps -------------------------------------------------------- */

static void test_a_sweep_fills_its_points(void **state)
{
    bs_host_scene *scene = load("configs/fig6.ini", NULL, 0);
    bs_host_sweep_options options;
    bs_host_sweep_point points[3];
    bs_host_error error;
    int done;
    (void)state;
    bs_host_sweep_defaults(&options);
    options.from = 0.3;
    options.to = 0.32;
    options.step = 0.01;
    options.hold = 2;
    options.record = 2;
    options.points = points;
    options.point_room = 2;
    assert_int_equal(bs_host_sweep_points(&options), 3);
    assert_int_equal(bs_host_sweep(scene, &options, &done, &error), BS_HOST_E_INPUT); /* room for 2 of 3 */
    options.point_room = 3;
    assert_int_equal(bs_host_sweep(scene, &options, &done, &error), BS_HOST_OK);
    assert_int_equal(done, 3);
    assert_true(points[2].s == 0.32 && points[0].amp_h > 0.0);
    bs_host_scene_free(scene);
}

static void test_a_map_runs_on_worker_threads(void **state)
{
    static const char *const vary[] = { "excitation.frequency=120,124" };
    static const char *const tiny[] = { "run.t_end=0.05" };
    bs_host_scene *scene = load("configs/fig6.ini", tiny, 1);
    bs_host_map_options options;
    bs_host_map_result result;
    bs_host_error error;
    char dir[64], path[128];
    FILE *table;
    (void)state;
    strcpy(dir, "/tmp/test_host_api.XXXXXX");
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/map", dir);
    bs_host_map_defaults(&options);
    options.dir = path;
    options.vary = vary;
    options.vary_count = 1;
    options.repeat = 2;
    options.jobs = 2;
    assert_int_equal(bs_host_map(scene, &options, &result, &error), BS_HOST_OK);
    assert_int_equal(result.cases, 4);
    assert_int_equal(result.run, 4);
    assert_true(result.complete);
    snprintf(path, sizeof path, "%s/map/map.csv", dir);
    table = fopen(path, "r");
    assert_non_null(table);
    fclose(table);
    snprintf(path, sizeof path, "%s/map", dir);
    assert_int_equal(bs_host_map(scene, &options, &result, &error), BS_HOST_OK); /* resumed: nothing left */
    assert_int_equal(result.skipped, 4);
    assert_int_equal(result.run, 0);
    options.repeat = 3; /* another map in the folder */
    assert_int_equal(bs_host_map(scene, &options, &result, &error), BS_HOST_E_INPUT);
    assert_non_null(strstr(error.text, "repeat"));
    bs_host_scene_free(scene);
    snprintf(path, sizeof path, "rm -rf '%s'", dir);
    assert_int_equal(system(path), 0);
}

/* ---- the measured-signals format ------------------------------------------- */

static void test_a_written_stream_reads_back(void **state)
{
    bs_host_measured_header header = { 50000.0, BS_HOST_DEFLECTION, 1e-6, 0.1, 0.0, 1 }, back;
    bs_host_measured_row row, got;
    bs_host_measured *reader;
    bs_host_error error;
    char path[] = "/tmp/test_host_api_stream.XXXXXX";
    FILE *out;
    int k, fd;
    (void)state;
    fd = mkstemp(path);
    assert_true(fd >= 0);
    out = fdopen(fd, "w");
    assert_non_null(out);
    assert_int_equal(bs_host_measured_write_header(out, &header, "a plant\nwith a line break"), BS_HOST_OK);
    for (k = 1; k <= 3; ++k) {
        row.t = k / header.rate;
        row.base_accel = 0.5 * k;
        row.signal = 1e-5 * k;
        row.s_true = 0.3;
        assert_int_equal(bs_host_measured_write_row(out, &row, 1), BS_HOST_OK);
    }
    assert_int_equal(fclose(out), 0);
    assert_int_equal(bs_host_measured_open(path, &reader, &back, &error), BS_HOST_OK);
    assert_true(back.rate == header.rate && back.noise == header.noise && back.has_truth);
    for (k = 1; k <= 3; ++k) {
        assert_int_equal(bs_host_measured_next(reader, &got, &error), 1);
        assert_true(got.base_accel == 0.5 * k && got.s_true == 0.3);
    }
    assert_int_equal(bs_host_measured_next(reader, &got, &error), 0);
    bs_host_measured_close(reader);
    unlink(path);
    assert_int_equal(bs_host_measured_open("/dev/null", &reader, &back, &error), BS_HOST_E_INPUT);
    assert_null(reader);
    assert_non_null(strstr(error.text, "/dev/null: cannot read measured-signals file"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_errors_come_back_with_the_cli_text),
        cmocka_unit_test(test_a_run_is_the_core_loop),
        cmocka_unit_test(test_a_run_and_a_sweep_write_the_cli_summary),
        cmocka_unit_test(test_on_step_sees_and_stops_the_run),
        cmocka_unit_test(test_four_threads_compute_what_serial_runs_do),
        cmocka_unit_test(test_a_sweep_fills_its_points),
        cmocka_unit_test(test_a_map_runs_on_worker_threads),
        cmocka_unit_test(test_a_written_stream_reads_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
