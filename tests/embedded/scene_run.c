/* scene_run.c - the firmware of the embedded tests and cost reports: runs the
 * compiled scene (BS_SCENE_CONFIG) from its start and prints its state, so
 * that a target under QEMU and the host can be compared line by line.
 *
 * Build against a build configuration naming the scene (BS_SCENE_CONFIG,
 * tests/embedded/embedded.mk) with -DBS_RUN_STEPS=N.
 *
 * Check mode (default): "scene: step N hash H s S = X" every BS_RUN_EVERY
 * steps, then "scene: end status 0 steps N hash H most-contacts C"; H is the
 * state's hash and S the bit pattern of s, so equal lines mean bit-identical
 * states; X is s as a number a reader can take in (9 decimals, formatted
 * with integers: the same digits on every C library).
 *
 * Cost mode (-DBS_RUN_COST=1): every step is bracketed by bs_board_mark(), so
 * that the instruction counter (tests/qemu/count.sh) prints one count per
 * step; nothing is printed while a phase runs. Phase "scene" runs the scene
 * from its start (impacts included); phase "tight" runs the same code on a copy
 * of the scene whose slot is pushed 2 um into the beam, started at the left
 * clamp stop, so that all four corners and the stop are in contact at once
 * (the contact solve's worst case; bs_scene_check rightly refuses such an
 * interference fit for a real scene, so the copy is changed after init and
 * the sim's prepared constants made again from it); it
 * runs BS_RUN_TIGHT_STEPS steps, a quarter of BS_RUN_STEPS unless set (0
 * leaves it out: -DBS_RUN_STEPS=BS_SCENE_STEPS -DBS_RUN_TIGHT_STEPS=0 counts
 * the scene's whole run and nothing else). The stack is painted before and
 * measured after each phase.
 *
 * With -DBS_RUN_SKIP=N the cost mode first runs N steps unmarked, so that a
 * stretch from the middle of a run is counted.
 *
 * Scene in RAM (-DBS_RUN_SCENE_IN_RAM=1, either mode): the constant scene
 * bs_compiled_scene (modal data, shape table), which a firmware keeps in
 * flash, is copied once into a static bs_scene (RAM, or CCM with a linker
 * script that puts .bss there) and both phases run from that copy, so that
 * no step reads scene data from flash (docs/embedded.md: flash wait states
 * on data reads). The copy is bit for bit the constant, so the printed
 * hashes are those of the default build.
 */
#include <math.h>
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
#ifndef BS_RUN_TIGHT_STEPS
#define BS_RUN_TIGHT_STEPS (BS_RUN_STEPS / 4)
#endif
#ifndef BS_RUN_SCENE_IN_RAM
#define BS_RUN_SCENE_IN_RAM 0
#endif
#ifndef BS_RUN_SKIP
#define BS_RUN_SKIP 0 /* cost mode: steps run unmarked before the counted ones */
#endif
#if BS_RUN_COST
#include "bs_prepare.h" /* a core-internal header: the tight phase changes its scene after init */
#endif

static bs_sim sim;
#if BS_RUN_SCENE_IN_RAM
static bs_scene scene_in_ram; /* bs_compiled_scene copied (see the header) */
#endif

/* bs_sim_init and the scene file's solver settings. */
static bs_status start(const bs_scene *scene, bs_real s0)
{
    bs_solver_options solver;
    const bs_status status = bs_sim_init(&sim, scene, BS_SCENE_MODEL, s0);
    if (status != BS_OK)
        return status;
    solver.max_sweeps = BS_SCENE_SOLVER_MAX_SWEEPS;
    solver.tol_rel = BS_SCENE_SOLVER_TOL_REL;
    solver.tol_abs = BS_SCENE_SOLVER_TOL_ABS;
    solver.measure_residual = BS_SCENE_SOLVER_RESIDUAL;
    return bs_sim_set_solver(&sim, &solver);
}

typedef struct phase_result {
    bs_status status;
    long steps;        /* steps done */
    unsigned most;     /* largest number of contacts active at once */
} phase_result;

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

/* s as "0.299981234": its 9 decimals rounded and printed as integers, so
 * that newlib on the target and glibc on the host print the same digits
 * (the product and floor are exact IEEE operations on both). */
static void print_number(bs_real value)
{
    const double x = (double)value;
    const double scaled = floor((x < 0.0 ? -x : x) * 1e9 + 0.5);
    const unsigned long whole = (unsigned long)(scaled / 1e9);
    const unsigned long decimals = (unsigned long)(scaled - (double)whole * 1e9);
    printf("%s%lu.%09lu", x < 0.0 ? "-" : "", whole, decimals);
}

/* A step through a volatile pointer, so that the compiler cannot move work
 * across the marks around it. */
static bs_status (*volatile step_function)(bs_sim *) = bs_sim_step;

static phase_result run(long steps, const char *phase)
{
    phase_result result = { BS_OK, 0, 0 };
    while (result.steps < steps) {
        bs_step_report report;
        unsigned active, count = 0;
        bs_board_mark();
        result.status = step_function(&sim);
        bs_board_mark();
        if (result.status != BS_OK)
            break;
        ++result.steps;
        result.status = bs_sim_get_report(&sim, &report);
        if (result.status != BS_OK)
            break;
        for (active = report.active; active; active >>= 1)
            count += active & 1u;
        if (count > result.most)
            result.most = count;
        if (!BS_RUN_COST && result.steps % BS_RUN_EVERY == 0) {
            printf("%s: step %ld hash %08lx s %08lx = ", phase, result.steps, (unsigned long)bs_sim_hash(&sim),
                   bits(bs_sim_position(&sim)));
            print_number(bs_sim_position(&sim));
            printf("\n");
        }
    }
    return result;
}

static int report(const char *phase, phase_result result, unsigned stack)
{
    printf("%s: end status %d steps %ld hash %08lx most-contacts %u", phase, (int)result.status,
           result.steps, (unsigned long)bs_sim_hash(&sim), result.most);
    if (BS_RUN_COST)
        printf(" stack %u", stack);
    printf("\n");
    return result.status != BS_OK;
}

#if BS_RUN_COST
static bs_scene tight;

/* The tight phase's scene: a copy of SCENE (the one the scene phase ran), changed. */
static int prepare_tight(const bs_scene *scene)
{
    const bs_real interference = BS_R(2e-6);
    bs_real pose[3];
    bs_real squeeze;
    memcpy(&tight, scene, sizeof tight);
    if (start(&tight, BS_R(0.5)) != BS_OK)
        return -1;
    bs_sim_get_state(&sim, 0, 0, pose, 0);
    pose[0] = tight.stop_min;
    if (bs_sim_set_state(&sim, 0, 0, pose, 0) != BS_OK)
        return -1;
    squeeze = BS_R(0.5) * ((tight.corner[0][1] - tight.corner[1][1]) - BS_R(2.0) * tight.half_thickness)
              + interference;
    tight.corner[0][1] -= squeeze; /* top corners down, bottom corners up */
    tight.corner[3][1] -= squeeze;
    tight.corner[1][1] += squeeze;
    tight.corner[2][1] += squeeze;
    bs_prepare(&sim); /* the step reads its constants from the sim (core/src/bs_prepare.c) */
    return 0;
}
#endif

int main(void)
{
    phase_result result;
    unsigned stack = 0;
    int failed;
    const bs_scene *scene = &bs_compiled_scene;

    printf("scene %s real %s steps %ld\n", BS_SCENE_NAME, BS_REAL_NAME, (long)BS_RUN_STEPS);
    if (bs_build_check() != BS_OK) {
        printf("scene: this program and the core were built differently\n");
        return 1;
    }
#if BS_RUN_SCENE_IN_RAM
    memcpy(&scene_in_ram, &bs_compiled_scene, sizeof scene_in_ram);
    scene = &scene_in_ram;
#endif
    if (start(scene, BS_SCENE_START) != BS_OK) {
        printf("scene: init refused\n");
        return 1;
    }
    if (BS_RUN_COST) {
        long skipped;
        for (skipped = 0; skipped < BS_RUN_SKIP; ++skipped)
            if (bs_sim_step(&sim) != BS_OK) {
                printf("scene: failed while skipping\n");
                return 1;
            }
        bs_board_stack_paint();
    }
    result = run(BS_RUN_STEPS, "scene");
    if (BS_RUN_COST)
        stack = bs_board_stack_used();
    failed = report("scene", result, stack);
#if BS_RUN_COST
    if (BS_RUN_TIGHT_STEPS == 0)
        return failed;
    if (prepare_tight(scene) != 0) {
        printf("tight: init refused\n");
        return 1;
    }
    bs_board_stack_paint();
    result = run(BS_RUN_TIGHT_STEPS, "tight");
    stack = bs_board_stack_used();
    failed |= report("tight", result, stack);
#endif
    return failed;
}
