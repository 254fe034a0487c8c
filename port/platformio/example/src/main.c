/* main.c - the PlatformIO example (port/platformio/README.md): the compiled
 * scene (build_flags: BS_SCENE_CONFIG) from its start, with its solver
 * settings, s printed after every 0.1 s of the sim's time, the state's hash at
 * the end. On a board, call run() from your main (or Arduino's setup()) and
 * send the lines where you like. */
#include <stdio.h>
#include "beamslider.h"

#ifndef BS_SCENE_CONFIG
#error "the example runs a compiled scene: add -D BS_SCENE_CONFIG='\"configs/NAME.h\"' to build_flags"
#endif
#include BS_SCENE_CONFIG /* bs_compiled_scene */

/* Blocks of 0.1 s to run. */
#ifndef EXAMPLE_TENTHS
#define EXAMPLE_TENTHS 10
#endif

static bs_sim sim;

static int run(void)
{
    const unsigned block_steps = (unsigned)(BS_R(0.1) / bs_compiled_scene.dt + BS_R(0.5));
    bs_solver_options solver = bs_solver_defaults();
    bs_status status;
    unsigned block, i;

    status = bs_sim_init(&sim, &bs_compiled_scene, BS_SCENE_MODEL, BS_SCENE_START);
    if (status == BS_OK) {
        solver.max_sweeps = BS_SCENE_SOLVER_MAX_SWEEPS;
        solver.tol_rel = BS_SCENE_SOLVER_TOL_REL;
        solver.tol_abs = BS_SCENE_SOLVER_TOL_ABS;
        solver.measure_residual = BS_SCENE_SOLVER_RESIDUAL;
        status = bs_sim_set_solver(&sim, &solver);
    }
    if (status != BS_OK) {
        /* BS_E_BUILD: this file and the library were built with other flags */
        printf("beamslider: start refused: %s\n", bs_status_text(status));
        return 1;
    }
    printf("beamslider %s: scene %s, %s\n", bs_version(), BS_SCENE_NAME, BS_REAL_NAME);
    for (block = 1; block <= EXAMPLE_TENTHS; ++block) {
        for (i = 0; i < block_steps && status == BS_OK; ++i)
            status = bs_sim_step(&sim);
        if (status != BS_OK) {
            printf("beamslider: step %lu: %s\n", (unsigned long)bs_sim_steps(&sim), bs_status_text(status));
            return 1;
        }
        printf("t %u.%u s  s %.6f\n", block / 10, block % 10, (double)bs_sim_position(&sim));
    }
    printf("beamslider: done, %lu steps, hash %08lx\n", (unsigned long)bs_sim_steps(&sim),
           (unsigned long)bs_sim_hash(&sim));
    return 0;
}

int main(void)
{
    return run();
}
