/* consumer.c - a program that takes beamslider as a library, built the ways
 * its users build (tests/check_consumer.sh): against the installed library
 * with pkg-config, with CMake's add_subdirectory(port/cmake) and with
 * find_package(beamslider).
 *
 * Its scene is configs/fig6_1mode.h, written by `beamslider gen`; the
 * repository root is on its include path. Linked with a run-time-scene build
 * (the installed libraries), this one inclusion gives the scene as data,
 * which the library checks like any other (bs_scene_check); linked with a
 * build compiled for fig6_1mode, the build configuration has read the header
 * once already for the sizes and this inclusion gives the same data.
 *
 * Runs 1000 steps from the scene's start with its solver settings and prints
 * one line, "consumer: beamslider VERSION, REAL, KIND: N steps, s = S, hash H"
 * (equal hashes: bit-identical states). Exit status 0 on success; 3 when
 * bs_sim_init refuses the library as built otherwise than this program's
 * headers (BS_E_BUILD); 1 on any other failure.
 */
#include <math.h>
#include <stdio.h>
#include "beamslider.h"
#include "configs/fig6_1mode.h"

#ifdef BS_SCENE_CONFIG
#define CORE_KIND "compiled scene " BS_SCENE_NAME
#else
#define CORE_KIND "run-time scenes"
#endif

static bs_sim sim;

int main(void)
{
    const uint64_t steps = 1000;
    const char *field = NULL;
    bs_solver_options solver;
    bs_status status;
    bs_real s;
    uint64_t i;

    status = bs_sim_init(&sim, &bs_compiled_scene, BS_SCENE_MODEL, BS_SCENE_START);
    if (status == BS_E_BUILD) {
        printf("consumer: bs_sim_init refused with BS_E_BUILD (%s): this program was compiled "
               "against the %s headers of beamslider %s, the library it links was built otherwise\n",
               bs_status_text(status), BS_REAL_NAME, BS_VERSION_STRING);
        return 3;
    }
    if (status != BS_OK) {
        const bs_status check = bs_scene_check(&bs_compiled_scene, &field);
        printf("consumer: FAIL: bs_sim_init: %s (bs_scene_check: %s, field %s)\n", bs_status_text(status),
               bs_status_text(check), field ? field : "-");
        return 1;
    }
    solver = bs_solver_defaults();
    solver.max_sweeps = BS_SCENE_SOLVER_MAX_SWEEPS;
    solver.tol_rel = BS_SCENE_SOLVER_TOL_REL;
    solver.tol_abs = BS_SCENE_SOLVER_TOL_ABS;
    solver.measure_residual = BS_SCENE_SOLVER_RESIDUAL;
    status = bs_sim_set_solver(&sim, &solver);
    for (i = 0; i < steps && status == BS_OK; ++i)
        status = bs_sim_step(&sim);
    if (status != BS_OK) {
        printf("consumer: FAIL: step %llu: %s\n", (unsigned long long)bs_sim_steps(&sim), bs_status_text(status));
        return 1;
    }
    s = bs_sim_position(&sim);
    if (bs_sim_steps(&sim) != steps || !(fabs((double)(s - BS_SCENE_START)) < 0.01)) {
        printf("consumer: FAIL: %llu steps (expected %llu), s = %g (expected near s0)\n",
               (unsigned long long)bs_sim_steps(&sim), (unsigned long long)steps, (double)s);
        return 1;
    }
    printf("consumer: beamslider %s, %s, %s: %llu steps, s = %.9g, hash %08lx\n", bs_version(), BS_REAL_NAME,
           CORE_KIND, (unsigned long long)bs_sim_steps(&sim), (double)s, (unsigned long)bs_sim_hash(&sim));
    return 0;
}
