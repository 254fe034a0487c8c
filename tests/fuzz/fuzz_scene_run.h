/* fuzz_scene_run.h - what the host accepts, the core must accept and run:
 * shared by the scene targets (fuzz_scene.c, fuzz_scene_set.c). */
#ifndef FUZZ_SCENE_RUN_H
#define FUZZ_SCENE_RUN_H

#include <stdio.h>
#include <stdlib.h>
#include "beamslider.h"
#include "fuzz_check.h"
#include "scene_build.h"

#define FUZZ_SCENE_STEPS 16
#define FUZZ_SCENE_MAX_SWEEPS 64 /* as in fuzz_step.c: a step costs up to the cap, by design */

/* Starts the scene the host built from file (bs_sim_init with the file's
 * model and s0, its solver options with the sweeps capped) and steps it
 * FUZZ_SCENE_STEPS times or until a step refuses (fuzz_step_checked). */
static inline void fuzz_scene_runs(const scene_file *file, const bs_scene *scene)
{
    static bs_sim sim;
    bs_status status = bs_sim_init(&sim, scene, (bs_model)file->params.model, (bs_real)file->params.s0);
    int n;
    if (status == BS_OK) {
        bs_solver_options solver = scene_solver(&file->params);
        if (solver.max_sweeps > FUZZ_SCENE_MAX_SWEEPS && !getenv("FUZZ_STRICT"))
            solver.max_sweeps = FUZZ_SCENE_MAX_SWEEPS;
        status = bs_sim_set_solver(&sim, &solver);
    }
    if (status != BS_OK) {
        fprintf(stderr, "bs_sim_init: %s\n", bs_status_text(status));
        fuzz_fail("the host accepted a scene the core refuses");
    }
    if (!fuzz_state_finite(&sim))
        fuzz_fail("bs_sim_init returned BS_OK with a non-finite state");
    for (n = 0; n < FUZZ_SCENE_STEPS && fuzz_step_checked(&sim) == BS_OK; ++n)
        ;
}

#endif
