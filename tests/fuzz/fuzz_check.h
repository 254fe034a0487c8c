/* fuzz_check.h - invariants of the core shared by the fuzz targets. */
#ifndef FUZZ_CHECK_H
#define FUZZ_CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include "beamslider.h"

/* Prints what broke and aborts (libFuzzer saves the input as a crash). */
static inline void fuzz_fail(const char *what)
{
    fprintf(stderr, "fuzz invariant broken: %s\n", what);
    abort();
}

static inline int fuzz_finite(bs_real x)
{
    return x - x == BS_R(0.0);
}

/* The whole dynamic state of a sim is finite: q, u, slider pose and
 * velocities, the compensated-sum remainder and the warm-start percussions
 * (members are private; a test may look). */
static inline int fuzz_state_finite(const bs_sim *sim)
{
    int k, r;
    for (k = 0; k < sim->scene->n_modes; ++k)
        if (!fuzz_finite(sim->q_beam[k]) || !fuzz_finite(sim->u_beam[k]))
            return 0;
    for (k = 0; k < 3; ++k)
        if (!fuzz_finite(sim->slider[k]) || !fuzz_finite(sim->slider_velocity[k]))
            return 0;
    if (!fuzz_finite(sim->x_c_low))
        return 0;
    for (k = 0; k < BS_MAX_CONTACTS; ++k)
        for (r = 0; r < BS_ROWS; ++r)
            if (!fuzz_finite(sim->percussion[k][r]))
                return 0;
    return 1;
}

/* The state a successful step leaves, handed back through bs_sim_set_state
 * (on a copy), must be accepted: what the step produces, set_state takes. */
static inline void fuzz_state_restorable(const bs_sim *sim)
{
    static bs_sim copy;
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES], pose[3], velocity[3];
    copy = *sim;
    if (bs_sim_get_state(&copy, q, u, pose, velocity) != BS_OK
        || bs_sim_set_state(&copy, q, u, pose, velocity) != BS_OK)
        fuzz_fail("bs_sim_set_state refused a state bs_sim_step produced");
}

/* One bs_sim_step with its contract checked: BS_OK with a finite state that
 * bs_sim_set_state accepts, or BS_E_UNSTABLE / BS_E_NONFINITE / BS_E_ESCAPED
 * with the state (hash) as it was, also when the failing step is tried
 * again. Returns the status. */
static inline bs_status fuzz_step_checked(bs_sim *sim)
{
    const uint32_t before = bs_sim_hash(sim);
    const bs_status status = bs_sim_step(sim);
    bs_step_report report;
    bs_solver_options solver;

    if (status == BS_OK) {
        if (!fuzz_state_finite(sim))
            fuzz_fail("bs_sim_step returned BS_OK with a non-finite state");
        if (bs_sim_get_report(sim, &report) != BS_OK || bs_sim_get_solver(sim, &solver) != BS_OK)
            fuzz_fail("bs_sim_get_report or bs_sim_get_solver refused a ready sim");
        if (report.sweeps < 0 || report.sweeps > solver.max_sweeps)
            fuzz_fail("bs_sim_step reported sweeps outside [0, max_sweeps]");
        if (report.converged != 0 && report.converged != 1)
            fuzz_fail("bs_sim_step reported convergence other than 0 or 1");
        if (report.residual < BS_R(0.0) && !(report.residual == BS_R(-1.0) && !solver.measure_residual))
            fuzz_fail("bs_sim_step reported a negative residual other than -1 (not measured)");
        if (!fuzz_finite(report.residual) && report.converged)
            fuzz_fail("bs_sim_step reported a converged solve whose residual is not finite");
        fuzz_state_restorable(sim);
        return status;
    }
    if (status != BS_E_UNSTABLE && status != BS_E_NONFINITE && status != BS_E_ESCAPED)
        fuzz_fail("bs_sim_step returned a status it does not document");
    if (bs_sim_hash(sim) != before)
        fuzz_fail("bs_sim_step failed and changed the state");
    if (bs_sim_step(sim) != status || bs_sim_hash(sim) != before)
        fuzz_fail("bs_sim_step failed differently when tried again");
    return status;
}

#endif
