/* scene_run.c - the firmware of the embedded tests and cost reports: runs the
 * compiled scene (BS_SCENE_CONFIG) from its start and prints its state, so
 * that a target under QEMU and the host can be compared line by line.
 *
 * Build with -DBS_SCENE_CONFIG='"configs/NAME.h"' -DBS_RUN_STEPS=N and, for
 * the cost report, -DBS_RUN_COST=1: then every step is bracketed by
 * bs_board_mark() (the instruction counter attributes the instructions between
 * two marks to one step), a second phase runs the same code on a copy of the
 * scene with no play (R = h) started against the left clamp stop, so that all
 * four corners and the stop take part at once, and the stack used by a step
 * is measured by painting.
 *
 * Output (check mode): "step N hash H s S" every BS_RUN_EVERY steps, then
 * "end status N hash H"; values are bit patterns in hex, so equal lines mean
 * bit-identical states.
 */
#include <stdio.h>
#include <string.h>
#include "beamslider.h"
#include BS_SCENE_CONFIG
#include "bs_board.h"

#ifndef BS_RUN_STEPS
#define BS_RUN_STEPS 20000
#endif
#ifndef BS_RUN_EVERY
#define BS_RUN_EVERY 1000
#endif
#ifndef BS_RUN_COST
#define BS_RUN_COST 0
#endif

static bs_sim sim;

static unsigned long bits(bs_real value)
{
#if BS_REAL_FLOAT
    uint32_t pattern;
    memcpy(&pattern, &value, sizeof pattern);
    return (unsigned long)pattern;
#else
    uint64_t pattern;
    memcpy(&pattern, &value, sizeof pattern);
    return (unsigned long)(pattern >> 32) ^ (unsigned long)(uint32_t)pattern;
#endif
}

/* A step through a volatile pointer, so that the compiler cannot move work
 * across the marks around it. */
static bs_status (*volatile step_function)(bs_sim *) = bs_sim_step;

/* Runs steps steps of the sim as it is; prints as the header says. */
static int run(long steps, const char *phase)
{
    long n;
    unsigned most = 0;
    for (n = 1; n <= steps; ++n) {
        bs_status status;
        unsigned active, count = 0;
        bs_board_mark();
        status = step_function(&sim);
        bs_board_mark();
        if (status != BS_OK) {
            printf("%s: end status %d at step %ld hash %08lx\n", phase, (int)status, n,
                   (unsigned long)bs_sim_hash(&sim));
            return 1;
        }
        for (active = bs_sim_report(&sim)->active; active; active >>= 1)
            count += active & 1u;
        if (count > most)
            most = count;
        if (n % BS_RUN_EVERY == 0)
            printf("%s: step %ld hash %08lx s %08lx\n", phase, n, (unsigned long)bs_sim_hash(&sim),
                   bits(bs_sim_position(&sim)));
    }
    printf("%s: end status 0 steps %ld hash %08lx most-contacts %u\n", phase, steps,
           (unsigned long)bs_sim_hash(&sim), most);
    return 0;
}

#if BS_RUN_COST
/* A copy of the scene in RAM whose slot is pushed 2 um into the beam after
 * init (bs_scene_check refuses an interference fit, rightly, for a real
 * scene): a preloaded slider at the left clamp stop, so that all four corners
 * and the stop are in contact at once - the contact solve's worst case. */
static bs_scene tight;

static int run_tight(void)
{
    const bs_real interference = BS_R(2e-6);
    bs_real pose[3];
    bs_real squeeze;
    memcpy(&tight, &bs_compiled_scene, sizeof tight);
    if (bs_sim_init(&sim, &tight, BS_SCENE_MODEL, BS_R(0.5)) != BS_OK)
        return 1;
    bs_sim_get_state(&sim, 0, 0, pose, 0);
    pose[0] = tight.stop_min;
    if (bs_sim_set_state(&sim, 0, 0, pose, 0) != BS_OK)
        return 1;
    squeeze = BS_R(0.5) * ((tight.corner[0][1] - tight.corner[1][1]) - BS_R(2.0) * tight.half_thickness)
              + interference;
    tight.corner[0][1] -= squeeze; /* top corners down, bottom corners up */
    tight.corner[3][1] -= squeeze;
    tight.corner[1][1] += squeeze;
    tight.corner[2][1] += squeeze;
    return run(BS_RUN_STEPS / 4, "tight");
}
#endif

int main(void)
{
    int failed;
    printf("scene %s real %s steps %ld\n", BS_SCENE_NAME, BS_REAL_NAME, (long)BS_RUN_STEPS);
#if BS_RUN_COST
    bs_board_stack_paint();
#endif
    if (bs_sim_init(&sim, &bs_compiled_scene, BS_SCENE_MODEL, BS_SCENE_START) != BS_OK) {
        printf("scene: init refused\n");
        return 1;
    }
    failed = run(BS_RUN_STEPS, "scene");
#if BS_RUN_COST
    printf("stack: %u bytes\n", bs_board_stack_used());
    failed |= run_tight();
#endif
    return failed;
}
