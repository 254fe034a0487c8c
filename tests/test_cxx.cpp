/* test_cxx.cpp - the public headers (beamslider.h, bs_monitor.h) and a scene
 * header written by `beamslider gen` are valid C++11, and a C++ program runs
 * the C core through them.
 *
 * Built with g++ -std=c++11 -Wall -Wextra -Werror -pedantic (Makefile):
 * `make test-one` links it with the core compiled for configs/fig6_1mode.h in
 * REAL (the scene header is then read twice: by the build configuration for
 * the sizes, here for bs_compiled_scene); tests/check_consumer.sh links it
 * with the installed run-time-scene library, where this one inclusion gives
 * the data only. Exit status 0 when every check passes.
 */
#include <cmath>
#include <cstdio>
#include "beamslider.h"
#include "bs_monitor.h"
#include "configs/fig6_1mode.h"

#ifdef BS_SCENE_CONFIG
#define CORE_KIND "core compiled for " BS_SCENE_NAME
#else
#define CORE_KIND "run-time-scene core, scene " BS_SCENE_NAME
#endif

namespace {

bs_sim sim;
bs_sim never_initialised;
bs_monitor monitor;
int failures = 0;

void check(bool passed, const char *what)
{
    if (!passed) {
        ++failures;
        std::printf("test_cxx: FAIL: %s\n", what);
    }
}

bool is_finite(bs_real value)
{
    return std::isfinite(static_cast<double>(value));
}

} // namespace

int main()
{
    // 1000 steps of 20 us: two complete periods of the 124 Hz excitation.
    const uint64_t steps = 1000;
    check(bs_build_check() == BS_OK, "bs_build_check: this program and the library are built alike");
    check(bs_sim_init(&sim, &bs_compiled_scene, BS_SCENE_MODEL, BS_SCENE_START) == BS_OK, "bs_sim_init");

    bs_solver_options solver = bs_solver_defaults();
    solver.max_sweeps = BS_SCENE_SOLVER_MAX_SWEEPS;
    solver.tol_rel = BS_SCENE_SOLVER_TOL_REL;
    solver.tol_abs = BS_SCENE_SOLVER_TOL_ABS;
    solver.measure_residual = BS_SCENE_SOLVER_RESIDUAL;
    check(bs_sim_set_solver(&sim, &solver) == BS_OK, "bs_sim_set_solver: the scene's settings");
    check(bs_monitor_init(&monitor, &sim) == BS_OK, "bs_monitor_init");

    bs_status status = BS_OK;
    for (uint64_t i = 0; i < steps && status == BS_OK; ++i) {
        status = bs_sim_step(&sim);
        if (status == BS_OK)
            check(bs_monitor_update(&monitor, &sim) >= 0, "bs_monitor_update");
    }
    check(status == BS_OK, bs_status_text(status));
    check(bs_sim_steps(&sim) == steps, "bs_sim_steps counts every step");

    const bs_real s = bs_sim_position(&sim);
    check(is_finite(s) && std::fabs(static_cast<double>(s - BS_SCENE_START)) < 0.01,
          "the slider is still near its start s0 after 20 ms");
    bs_real w = BS_R(0.0), slope = BS_R(0.0);
    check(bs_sim_beam_at(&sim, BS_R(0.5) * bs_compiled_scene.length, &w, &slope) == BS_OK && is_finite(w)
              && is_finite(slope),
          "bs_sim_beam_at mid-span");
    bs_step_report report;
    check(bs_sim_get_report(&sim, &report) == BS_OK && report.sweeps >= 0, "bs_sim_get_report");
    check(monitor.periods >= 1 && is_finite(monitor.amplitude) && monitor.amplitude > BS_R(0.0),
          "the monitor completed a period with a positive amplitude");

    check(std::isnan(static_cast<double>(bs_sim_position(&never_initialised))),
          "a never-initialised sim reads NaN");
    check(bs_sim_step(&never_initialised) == BS_E_UNINITIALISED, "a never-initialised sim refuses to step");

    std::printf("test_cxx (C++11, %s, %s): %llu steps, s = %.6f, %u periods, amplitude %.3g m, hash %08lx: %s\n",
                BS_REAL_NAME, CORE_KIND, static_cast<unsigned long long>(bs_sim_steps(&sim)),
                static_cast<double>(s), static_cast<unsigned>(monitor.periods),
                static_cast<double>(monitor.amplitude), static_cast<unsigned long>(bs_sim_hash(&sim)),
                failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
