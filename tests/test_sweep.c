/* test_sweep.c - the quasi-static PCS sweep (host/lib/run/sweep.c): the grid, the
 * per-point numbers against a plain bs_sim loop written from docs/model.md 6,
 * continuation from rest, the sign of v_mean, determinism and bad options. */
#include "support.h"

#include <math.h>
#include <string.h>
#include "bs_monitor.h"
#include "sweep.h"

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_sim sim;

static void load_fig6(void)
{
    support_load("configs/fig6.ini", &file, &scene, &model);
}

static sweep_options small_sweep(double from, double to, double step, int down)
{
    sweep_options options;
    memset(&options, 0, sizeof options);
    options.from = from;
    options.to = to;
    options.step = step;
    options.down = down;
    options.hold = 3;
    options.record = 2;
    options.dt = file.params.dt;
    options.solver = scene_solver(&file.params);
    return options;
}

static void test_grid(void **state)
{
    sweep_options options;
    (void)state;
    load_fig6();
    assert_int_equal(sweep_grid_size(0.0, 0.5, 0.005), 101);
    assert_int_equal(sweep_grid_size(0.2, 0.3, 0.05), 3);
    assert_int_equal(sweep_grid_size(0.0, 0.5, 0.003), -1);  /* does not divide */
    assert_int_equal(sweep_grid_size(0.3, 0.2, 0.05), -1);   /* from above to */
    assert_int_equal(sweep_grid_size(0.0, 1.5, 0.5), -1);    /* beyond the beam */
    assert_int_equal(sweep_grid_size(0.0, 0.5, 0.0), -1);
    assert_int_equal(sweep_grid_size(0.0, 0.5, 1e-9), -1);   /* too many points */
    options = small_sweep(0.0, 0.5, 0.005, 0);
    assert_true(sweep_grid_s(&options, 60) == 0.0 + 60 * 0.005);
    assert_true(sweep_grid_s(&options, 100) == 0.5); /* the last point is `to` itself */
    assert_int_equal(sweep_grid_index(&options, 0.3), 60);
    assert_int_equal(sweep_grid_index(&options, 0.5), 100);
    assert_int_equal(sweep_grid_index(&options, 0.3001), -1);
    assert_int_equal(sweep_grid_index(&options, 0.6), -1);
}

/* docs/model.md 6 as a plain loop: one PCS sim from rest at grid[0]; per point
 * move s~, hold, record; periods counted by the monitor's phase wraps. */
static void reference_sweep(const double *grid, int n, int hold, int record, sweep_point *out)
{
    const double h = 2.0 * (double)scene.half_thickness;
    bs_monitor monitor;
    int i;
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_PCS, (bs_real)grid[0]), BS_OK);
    bs_monitor_init(&monitor, &sim);
    for (i = 0; i < n; ++i) {
        double amp = 0.0, transport = 0.0;
        int periods = 0;
        uint64_t steps = 0;
        assert_int_equal(bs_sim_set_pcs_position(&sim, (bs_real)grid[i]), BS_OK);
        while (periods < hold + record) {
            assert_int_equal(bs_sim_step(&sim), BS_OK);
            ++steps;
            if (bs_monitor_update(&monitor, &sim) && ++periods > hold) {
                amp += (double)monitor.amplitude;
                transport += (double)monitor.transport;
            }
        }
        out[i].s = grid[i];
        out[i].amp_h = amp / (record * h);
        out[i].v_mean = (grid[i] <= 0.5 ? 1.0 : -1.0) * transport / record; /* + toward the centre */
        out[i].steps = steps;
    }
}

static void assert_points_equal(const sweep_point *got, const sweep_point *want, int n)
{
    int i;
    for (i = 0; i < n; ++i) {
        assert_true(got[i].s == want[i].s);
        assert_close("amp_h", got[i].amp_h, want[i].amp_h, 0.0, 1e-15);
        assert_close("v_mean", got[i].v_mean, want[i].v_mean, 0.0, 1e-15);
        assert_true(got[i].steps == want[i].steps);
    }
}

/* Up across the centre (s~ = 0.4, 0.5, 0.6: v_mean changes its sign
 * convention at 0.5) and down: each point as the plain loop computes it. */
static void test_points_match_the_plain_loop(void **state)
{
    const double up[3] = { 0.4, 0.5, 0.6 }, down[3] = { 0.6, 0.5, 0.4 };
    sweep_point got[3], want[3];
    sweep_options options;
    sweep_result result;
    int i;
    (void)state;
    load_fig6();
    options = small_sweep(0.4, 0.6, 0.1, 0);
    options.points = got;
    assert_int_equal(sweep_run(&scene, &options, &result), 0);
    assert_int_equal(result.status, BS_OK);
    assert_int_equal(result.points_done, 3);
    reference_sweep(up, 3, options.hold, options.record, want);
    assert_points_equal(got, want, 3);
    /* an exact number of periods per point: 5 periods of 403.2 steps */
    for (i = 0; i < 3; ++i) {
        assert_true(got[i].steps == 2016 || got[i].steps == 2017);
        assert_true(got[i].amp_h > 0.0);
    }
    assert_true(result.steps == got[0].steps + got[1].steps + got[2].steps);

    options.down = 1;
    assert_int_equal(sweep_run(&scene, &options, &result), 0);
    reference_sweep(down, 3, options.hold, options.record, want);
    assert_points_equal(got, want, 3);
}

/* Each sweep starts from rest at its first point; the next points carry the
 * state (a different history gives a different point). */
static void test_continuation_from_rest(void **state)
{
    const double grid[1] = { 0.3 };
    sweep_point up[2], down[2], want[1];
    sweep_options options;
    sweep_result result;
    (void)state;
    load_fig6();
    options = small_sweep(0.25, 0.3, 0.05, 0);
    options.points = up;
    assert_int_equal(sweep_run(&scene, &options, &result), 0);
    options.down = 1;
    options.points = down;
    assert_int_equal(sweep_run(&scene, &options, &result), 0);
    /* down[0] is s~ = 0.3 from rest, up[1] is 0.3 after 0.25 */
    assert_true(down[0].s == up[1].s);
    assert_true(down[0].amp_h != up[1].amp_h);
    reference_sweep(grid, 1, options.hold, options.record, want);
    assert_points_equal(down, want, 1);
}

static void test_deterministic(void **state)
{
    sweep_point first[3], second[3];
    sweep_options options;
    sweep_result result;
    (void)state;
    load_fig6();
    memset(first, 0, sizeof first); /* padding compared too */
    memset(second, 0, sizeof second);
    options = small_sweep(0.2, 0.3, 0.05, 0);
    options.points = first;
    assert_int_equal(sweep_run(&scene, &options, &result), 0);
    options.points = second;
    assert_int_equal(sweep_run(&scene, &options, &result), 0);
    assert_memory_equal(first, second, sizeof first);
}

static void test_refuses_bad_options(void **state)
{
    sweep_options options;
    sweep_result result;
    (void)state;
    load_fig6();
    options = small_sweep(0.3, 0.2, 0.05, 0);
    assert_int_equal(sweep_run(&scene, &options, &result), -1);
    assert_int_equal(result.status, BS_E_ARGUMENT);
    options = small_sweep(0.2, 0.3, 0.05, 0);
    options.record = 0;
    assert_int_equal(sweep_run(&scene, &options, &result), -1);
    assert_int_equal(result.status, BS_E_ARGUMENT);
    options = small_sweep(0.2, 0.3, 0.05, 0);
    options.hold = -1;
    assert_int_equal(sweep_run(&scene, &options, &result), -1);
    assert_int_equal(result.status, BS_E_ARGUMENT);
    assert_int_equal(result.points_done, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grid),
        cmocka_unit_test(test_points_match_the_plain_loop),
        cmocka_unit_test(test_continuation_from_rest),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_refuses_bad_options),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
