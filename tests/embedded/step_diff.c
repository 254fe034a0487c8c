/* step_diff.c - the step of a compiled scene against the step of a run-time
 * scene: one source, built twice on the host (tests/embedded/embedded.mk,
 * step-diff-test):
 *   - against the core compiled for the scene (BS_SCENE_CONFIG: constant mode
 *     count, features left out, the zero masks of S and gamma), as a firmware
 *     builds it;
 *   - against the run-time core of the host build (the CLI's and the
 *     library's), taking the same scene header as data (DIFF_SCENE_HEADER).
 * Both print the status and state hash after one step from each of many
 * states (random ones around the scene's start, and ones a run reaches), and
 * the hash every 1000 steps of a run from the start, and after each state's
 * hash its values (q, u, the slider's pose and velocity). The two paths are
 * one implementation of the step, so the stated tolerance is none: the
 * outputs must be equal byte for byte (docs/design.md, "Determinism") -
 * except where the compiled scene leaves friction out and the run-time core
 * solves the same contacts with tangential rows of mu = 0: another sequence
 * of operations, compared value by value to a tolerance
 * (tests/embedded/check_step_diff.sh).
 */
#include <stdio.h>
#include "beamslider.h"
#ifdef BS_SCENE_CONFIG
#include BS_SCENE_CONFIG /* again, now that bs_scene exists: the scene's data */
#else
#include DIFF_SCENE_HEADER
#endif

#define RANDOM_STATES 3000
#define RUN_STEPS 20000

static bs_sim sim;

static unsigned report_active(const bs_sim *s)
{
    bs_step_report report;
    return bs_sim_get_report(s, &report) == BS_OK ? report.active : 0xffu;
}

/* xorshift64*: uniform in [-1, 1). */
static uint64_t rng = 0x9e3779b97f4a7c15u;
static double uniform(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return (double)((rng * UINT64_C(2685821657736338717)) >> 11) / 4503599627370496.0 - 1.0;
}

static int start(void)
{
    bs_solver_options solver;
    if (bs_sim_init(&sim, &bs_compiled_scene, BS_SCENE_MODEL, BS_SCENE_START) != BS_OK)
        return -1;
    solver.max_sweeps = BS_SCENE_SOLVER_MAX_SWEEPS;
    solver.tol_rel = BS_SCENE_SOLVER_TOL_REL;
    solver.tol_abs = BS_SCENE_SOLVER_TOL_ABS;
    solver.measure_residual = BS_SCENE_SOLVER_RESIDUAL;
    return bs_sim_set_solver(&sim, &solver) == BS_OK ? 0 : -1;
}

int main(void)
{
    const bs_scene *scene = &bs_compiled_scene;
    const int n = scene->n_modes;
    bs_real q[20], u[20], pose[3], velocity[3];
    long k;
    int i;

    if (bs_build_check() != BS_OK || start() != 0) {
        printf("step_diff: init failed\n");
        return 1;
    }
    /* a run from the start */
    for (k = 1; k <= RUN_STEPS; ++k) {
        const bs_status status = bs_sim_step(&sim);
        if (status != BS_OK || k % 1000 == 0)
            printf("run %ld status %d hash %08lx\n", k, (int)status, (unsigned long)bs_sim_hash(&sim));
        if (status != BS_OK)
            break;
    }
    /* one step from each of many states: random ones near the scene's start
     * (beam deflections up to a few play widths, the slot anywhere within
     * its play and beyond, velocities of a vibrating beam), half of them
     * started from where the run above ended */
    for (k = 0; k < RANDOM_STATES; ++k) {
        const double play = (double)(scene->corner[0][1] - scene->corner[1][1]) - 2.0 * (double)scene->half_thickness;
        bs_status status;
        if (k % 2 == 0 && start() != 0)
            return 1;
        if (bs_sim_get_state(&sim, q, u, pose, velocity) != BS_OK)
            return 1;
        for (i = 0; i < n && i < 20; ++i) {
            q[i] = (bs_real)((double)q[i] + 1e-4 * uniform() / (double)(i + 1));
            u[i] = (bs_real)((double)u[i] + 0.3 * uniform() / (double)(i + 1));
        }
        pose[0] = (bs_real)((double)pose[0] + 1e-3 * uniform());
        if (k % 7 == 3) /* at the left clamp stop: a third contact */
            pose[0] = (bs_real)((double)scene->stop_min + 1e-6 * uniform());
        pose[1] = (bs_real)((double)pose[1] + 2.0 * play * uniform());
        pose[2] = (bs_real)((double)pose[2] + 0.005 * uniform());
        velocity[0] = (bs_real)((double)velocity[0] + 0.01 * uniform());
        velocity[1] = (bs_real)((double)velocity[1] + 0.5 * uniform());
        velocity[2] = (bs_real)((double)velocity[2] + 50.0 * uniform());
        if (bs_sim_set_state(&sim, q, u, pose, velocity) != BS_OK) {
            printf("state %ld refused\n", k);
            continue;
        }
        status = bs_sim_step(&sim);
        printf("state %ld status %d active %02x hash %08lx", k, (int)status, report_active(&sim),
               (unsigned long)bs_sim_hash(&sim));
        if (bs_sim_get_state(&sim, q, u, pose, velocity) != BS_OK)
            return 1;
        for (i = 0; i < n && i < 20; ++i)
            printf(" %.17g %.17g", (double)q[i], (double)u[i]);
        for (i = 0; i < 3; ++i)
            printf(" %.17g %.17g", (double)pose[i], (double)velocity[i]);
        printf("\n");
    }
    return 0;
}
