/* main.c - the beamslider Zephyr sample (port/zephyr/README.md): a twin-like
 * loop. The sim of the compiled scene (CONFIG_BEAMSLIDER_SCENE, prj.conf)
 * starts where the scene file says, with its solver settings, and runs in
 * blocks of 0.1 s of its own time; after each block the thread sleeps until
 * the uptime has caught up with the sim's time, so that on a fast enough
 * part the sim keeps to the plant's clock (a twin would step on each sensor
 * sample instead, port/cortex-m/twin). Each block prints one line:
 *
 *     t 0.3 s  s 0.299871  contacts 0  behind 0 ms
 *
 * s the slider's position [beam lengths], contacts those of the last step,
 * "behind" how far the sim lags the uptime at the end of the block (0 when it
 * keeps pace: docs/porting.md section 3 tells which parts do). After the
 * scene's t_end (or SAMPLE_TENTHS blocks, when set) it prints the state's
 * hash and stops.
 */
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>
#include "beamslider.h"

#ifndef BS_SCENE_CONFIG
#error "the sample runs a compiled scene: set CONFIG_BEAMSLIDER_SCENE (prj.conf)"
#endif
#include BS_SCENE_CONFIG /* bs_compiled_scene */

/* Blocks of 0.1 s to run; 0: the scene's whole run (BS_SCENE_STEPS). */
#ifndef SAMPLE_TENTHS
#define SAMPLE_TENTHS 0
#endif

static bs_sim sim;

/* s in millionths, for printk without floating-point formatting */
static long micro(bs_real x)
{
    return (long)(x * BS_R(1000000.0) + (x < BS_R(0.0) ? BS_R(-0.5) : BS_R(0.5)));
}

/* contacts that took part in the last step (slot corners and end stops) */
static unsigned contacts(unsigned active)
{
    unsigned n = 0;
    for (; active != 0u; active >>= 1)
        n += active & 1u;
    return n;
}

int main(void)
{
    const uint32_t block_steps = (uint32_t)(BS_R(0.1) / bs_compiled_scene.dt + BS_R(0.5));
    const uint32_t blocks = SAMPLE_TENTHS > 0 ? (uint32_t)SAMPLE_TENTHS : BS_SCENE_STEPS / block_steps;
    bs_solver_options solver = bs_solver_defaults();
    bs_step_report report;
    bs_status status;
    int64_t start_ms;
    uint32_t block, i;

    status = bs_sim_init(&sim, &bs_compiled_scene, BS_SCENE_MODEL, BS_SCENE_START);
    if (status == BS_OK) {
        solver.max_sweeps = BS_SCENE_SOLVER_MAX_SWEEPS;
        solver.tol_rel = BS_SCENE_SOLVER_TOL_REL;
        solver.tol_abs = BS_SCENE_SOLVER_TOL_ABS;
        solver.measure_residual = BS_SCENE_SOLVER_RESIDUAL;
        status = bs_sim_set_solver(&sim, &solver);
    }
    if (status != BS_OK) {
        /* BS_E_BUILD: this file and the library were built with other options */
        printk("beamslider: start refused: %s\n", bs_status_text(status));
        return 0;
    }
    printk("beamslider %s: scene %s, %s, %u blocks of %u steps\n", bs_version(), BS_SCENE_NAME, BS_REAL_NAME,
           (unsigned)blocks, (unsigned)block_steps);

    start_ms = k_uptime_get();
    for (block = 1; block <= blocks; ++block) {
        int64_t behind_ms;
        long s;
        for (i = 0; i < block_steps && status == BS_OK; ++i)
            status = bs_sim_step(&sim);
        if (status != BS_OK) {
            printk("beamslider: step %u: %s\n", (unsigned)bs_sim_steps(&sim), bs_status_text(status));
            return 0;
        }
        behind_ms = k_uptime_get() - start_ms - (int64_t)block * 100;
        if (behind_ms < 0) {
            k_msleep((int32_t)-behind_ms);
            behind_ms = 0;
        }
        (void)bs_sim_get_report(&sim, &report);
        s = micro(bs_sim_position(&sim));
        printk("t %u.%u s  s %ld.%06ld  contacts %u  behind %ld ms\n", (unsigned)(block / 10),
               (unsigned)(block % 10), s / 1000000, s % 1000000, contacts(report.active), (long)behind_ms);
    }
    printk("beamslider: done, %u steps, hash %08lx\n", (unsigned)bs_sim_steps(&sim),
           (unsigned long)bs_sim_hash(&sim));
    return 0;
}
