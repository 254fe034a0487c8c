/* fuzz_step.c - libFuzzer target: the core's API driven by arbitrary scene
 * fields, start positions, states and step sequences.
 *
 * Base scenes are built once from configs/fig6.ini, fig6_1mode.ini and
 * fig6_frictionless.ini (FUZZ_CONFIGS); compiled with
 * -DBS_SCENE_CONFIG='"configs/NAME.h"' (an embedded build: constant mode
 * count, features left out) the base is that header's bs_compiled_scene and
 * no host code is linked. Each input picks one, perturbs scene
 * fields (NaN, infinities, huge, tiny and denormal values, negative lengths,
 * sign flips, values a few ulps either side of where they were, raw bit
 * patterns, bad counts), starts a run and then plays a little program of
 * steps, state overwrites, PCS moves and restarts. The contract checked:
 *   - nothing crashes, hangs or reads out of bounds (ASan, UBSan);
 *   - bs_scene_check answers BS_OK, BS_E_SCENE or BS_E_UNSTABLE, names the
 *     field on error, and bs_sim_init refuses every scene it refuses;
 *   - bs_sim_init, bs_sim_set_state and bs_sim_step never return BS_OK with
 *     a non-finite state (fuzz_check.h);
 *   - after an error status the state hash is unchanged, and stays so when
 *     the failing step is tried again;
 *   - bs_sim_set_state refuses non-finite values (and, free model, x_C off
 *     the clamp stops) and otherwise stores exactly what it was given;
 *   - NULL arguments give BS_E_NULL, a model that does not exist BS_E_ARGUMENT.
 *
 * Input layout (bytes; a short input reads as zeros):
 *   [0] base scene (low 2 bits), model (bit 2), count of scene edits (>> 3)
 *   scene edits: target byte, index (2 bytes), value (see take_value)
 *   s0: value edit of 0.3
 *   then opcodes until the input ends (at most FUZZ_MAX_STEPS steps in all),
 *   op % 12: 0-2 run (op >> 3) * 2 + 1 steps, 3-4 bs_sim_set_state, 5 PCS
 *   move, 6 queries and NULL arguments, 7 restart with another s0, 8 new
 *   contact-solve settings (bs_sim_set_solver), 9 a step on a measured base
 *   acceleration, 10 new excitation (bs_sim_set_excitation), 11 checkpoint
 *   round trip (save, restore into another sim, both step alike; a damaged
 *   copy is refused).
 * FUZZ_VERBOSE in the environment prints what an input does.
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "beamslider.h"
#include "fuzz_check.h"
#include "fuzz_input.h"
#ifdef BS_SCENE_CONFIG
#include BS_SCENE_CONFIG /* again, after beamslider.h: bs_compiled_scene */
#else
#include "scene_build.h"
#endif

#ifndef FUZZ_CONFIGS
#define FUZZ_CONFIGS "configs"
#endif

#define FUZZ_MAX_STEPS 1024
/* A step costs up to max_sweeps sweeps, by design (docs/design.md 6): the
 * solve stops early only when a sweep does not lower the residual, and in a
 * near-singular contact problem it creeps down for 5e5 sweeps and more
 * (docs/robustness.md). Larger caps are lowered to this, so that an input
 * cannot spend minutes in one step (unless FUZZ_STRICT is set). */
#define FUZZ_MAX_SWEEPS 64
#ifdef BS_SCENE_CONFIG
#define FUZZ_BASES 1
#else
#define FUZZ_BASES 3
static const char *const base_names[FUZZ_BASES] = { "fig6.ini", "fig6_1mode.ini", "fig6_frictionless.ini" };
#endif
static bs_scene bases[FUZZ_BASES];
static bs_scene scene;
static bs_sim sim;

/* ---- scene edits ------------------------------------------------------ */

typedef enum kind { REAL_FIELD, INT_FIELD, PHASE_FIELD, STRETCH_SYMMETRIC, IMPLICIT_ON } kind;

typedef struct target {
    kind kind;
    size_t offset;
    int count; /* elements of bs_real / int */
} target;

/* Every field of the scene (core/include/bs_scene_fields.h), then two edits
 * that keep a scene consistent so that the checks look further. */
#define TARGET_REAL(name) { REAL_FIELD, offsetof(bs_scene, name), (int)(sizeof scene.name / sizeof(bs_real)) },
#define TARGET_INT(name) { INT_FIELD, offsetof(bs_scene, name), 1 },
#define TARGET_U64(name) { PHASE_FIELD, offsetof(bs_scene, name), 1 },
#define TARGET(kind, name, dim1, dim2, dim3, rule, unit, meaning) TARGET_##kind(name)
static const target targets[] = {
    BS_SCENE_FIELDS(TARGET)
    { STRETCH_SYMMETRIC, offsetof(bs_scene, stretch), BS_MAX_MODES * BS_MAX_MODES },
    { IMPLICIT_ON, offsetof(bs_scene, implicit), 1 },
};
#define TARGETS ((int)(sizeof targets / sizeof targets[0]))

static int verbose; /* FUZZ_VERBOSE set: print what an input does (to read a reproducer) */

static void edit_scene(input *in)
{
    const int which = (int)(take_byte(in) % TARGETS);
    const target *t = &targets[which];
    const int index = (int)(take_bits(in, 2) % (uint64_t)t->count);
    char *field = (char *)&scene + t->offset;

    if (verbose)
        fprintf(stderr, "edit: target %d (offset %zu) element %d\n", which, t->offset, index);

    switch (t->kind) {
    case REAL_FIELD: {
        bs_real *value = (bs_real *)field + index;
        *value = take_value(in, *value);
        break;
    }
    case STRETCH_SYMMETRIC: { /* keeps S symmetric, so the check looks further */
        const int i = index / BS_MAX_MODES, j = index % BS_MAX_MODES;
        scene.stretch[i][j] = scene.stretch[j][i] = take_value(in, scene.stretch[i][j]);
        break;
    }
    case INT_FIELD: {
        int *value = (int *)field;
        *value = take_int(in, *value);
        break;
    }
    case PHASE_FIELD: {
        static const uint64_t specials[] = { 0, 1, (uint64_t)1 << 61, ((uint64_t)1 << 62) - 1, (uint64_t)1 << 62,
                                             UINT64_MAX };
        const unsigned how = take_byte(in);
        scene.phase_step_half = how & 1 ? take_bits(in, 8) : specials[(how >> 1) % 6];
        break;
    }
    case IMPLICIT_ON:
#if BS_WITH_IMPLICIT
    { /* a consistent implicit scene: the gains as the host computes them */
        int k;
        scene.implicit = 1;
        scene.theta = take_value(in, BS_R(0.5) + (bs_real)(take_byte(in) & 7) * BS_R(0.0625));
        for (k = 0; k < BS_MAX_MODES; ++k)
            scene.mode_gain[k] = BS_R(1.0) / (BS_R(1.0) + scene.theta * scene.dt * scene.damping[k]
                                               + scene.theta * scene.theta * scene.dt * scene.dt * scene.omega_sq[k]);
    }
#endif
        break;
    }
}

/* ---- the program -------------------------------------------------------- */

static void check_init(bs_status check, bs_status init)
{
    if (init != BS_OK && init != BS_E_SCENE && init != BS_E_UNSTABLE && init != BS_E_ARGUMENT)
        fuzz_fail("bs_sim_init returned a status it does not document");
    if (check != BS_OK && init != check)
        fuzz_fail("bs_sim_init did not refuse a scene bs_scene_check refuses, with the same status");
    if (check == BS_OK && init != BS_OK && init != BS_E_ARGUMENT)
        fuzz_fail("bs_sim_init refused a checked scene for a reason other than s0");
    if (init == BS_OK && !fuzz_state_finite(&sim))
        fuzz_fail("bs_sim_init returned BS_OK with a non-finite state");
}

/* Equal values (x_C is read back as x_C + its remainder, which turns -0 into +0). */
static int same(bs_real a, bs_real b)
{
    return !(a < b) && !(a > b);
}

/* Overwrites parts of the state with fuzzed values through bs_sim_set_state. */
static void set_state(input *in)
{
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES], pose[3], velocity[3], got[4][BS_MAX_MODES > 3 ? BS_MAX_MODES : 3];
    bs_real *const part[4] = { q, u, pose, velocity };
    const int length[4] = { scene.n_modes, scene.n_modes, 3, 3 };
    const unsigned parts = take_byte(in); /* bit p: pass part p */
    const int edits = (int)(take_byte(in) & 7);
    const uint32_t before = bs_sim_hash(&sim);
    int finite = 1;
    int e, p, k;
    bs_status status;

    bs_sim_get_state(&sim, q, u, pose, velocity);
    for (e = 0; e < edits; ++e) {
        p = (int)(take_byte(in) & 3);
        if (length[p] > 0) {
            k = (int)(take_byte(in) % (unsigned)length[p]);
            part[p][k] = take_value(in, part[p][k]);
        }
    }
    for (p = 0; p < 4; ++p)
        for (k = 0; parts >> p & 1 && k < length[p]; ++k)
            finite &= fuzz_finite(part[p][k]);
    status = bs_sim_set_state(&sim, parts & 1 ? q : NULL, parts & 2 ? u : NULL, parts & 4 ? pose : NULL,
                              parts & 8 ? velocity : NULL);
    if (status != BS_OK) {
        if (status != BS_E_ARGUMENT)
            fuzz_fail("bs_sim_set_state returned a status it does not document");
        if (finite && !(parts & 4))
            fuzz_fail("bs_sim_set_state refused finite values");
        if (bs_sim_hash(&sim) != before)
            fuzz_fail("bs_sim_set_state failed and changed the state");
        return;
    }
    if (!finite)
        fuzz_fail("bs_sim_set_state accepted a non-finite value");
    if (!fuzz_state_finite(&sim))
        fuzz_fail("bs_sim_set_state returned BS_OK with a non-finite state");
    bs_sim_get_state(&sim, got[0], got[1], got[2], got[3]);
    for (p = 0; p < 4; ++p)
        for (k = 0; parts >> p & 1 && k < length[p]; ++k)
            if (!same(got[p][k], part[p][k])) {
                fprintf(stderr, "part %d [%d]: set %.9g, read back %.9g\n", p, k, (double)part[p][k],
                        (double)got[p][k]);
                fuzz_fail("bs_sim_set_state did not store what it was given");
            }
}

/* New contact-solve settings from the input: accepted exactly when valid,
 * and nothing changes when refused. */
static void set_solver(input *in)
{
    bs_solver_options options, got;
    const uint32_t before = bs_sim_hash(&sim);
    int valid;
    bs_status status;

    bs_sim_get_solver(&sim, &options);
    options.max_sweeps = take_int(in, options.max_sweeps);
    if (options.max_sweeps > FUZZ_MAX_SWEEPS && options.max_sweeps <= BS_SOLVER_MAX_SWEEPS && !getenv("FUZZ_STRICT"))
        options.max_sweeps = FUZZ_MAX_SWEEPS;
    options.tol_rel = take_value(in, options.tol_rel);
    options.tol_abs = take_value(in, options.tol_abs);
    options.measure_residual = (int)(take_byte(in) % 3) - (take_byte(in) & 1); /* -1 .. 2 */
    valid = options.max_sweeps >= 1 && options.max_sweeps <= BS_SOLVER_MAX_SWEEPS
            && fuzz_finite(options.tol_rel) && options.tol_rel >= BS_R(0.0) && fuzz_finite(options.tol_abs)
            && options.tol_abs >= BS_R(0.0) && (options.measure_residual == 0 || options.measure_residual == 1);
    status = bs_sim_set_solver(&sim, &options);
    if (status != (valid ? BS_OK : BS_E_ARGUMENT))
        fuzz_fail("bs_sim_set_solver: wrong status");
    bs_sim_get_solver(&sim, &got);
    if (valid && (got.max_sweeps != options.max_sweeps || !same(got.tol_rel, options.tol_rel)
                  || !same(got.tol_abs, options.tol_abs) || got.measure_residual != options.measure_residual))
        fuzz_fail("bs_sim_set_solver did not store the options");
    if (bs_sim_hash(&sim) != before)
        fuzz_fail("bs_sim_set_solver changed the state");
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
#ifndef BS_SCENE_CONFIG
    static scene_file file;
    static scene_model model;
    char path[SCENE_PATH];
    char err[1024];
    int i;
#endif

    (void)argc;
    (void)argv;
    verbose = getenv("FUZZ_VERBOSE") != NULL;
#ifdef BS_SCENE_CONFIG
    bases[0] = bs_compiled_scene;
#else
    for (i = 0; i < FUZZ_BASES; ++i) {
        snprintf(path, sizeof path, "%s/%s", FUZZ_CONFIGS, base_names[i]);
        if (scene_read(path, &file, &bases[i], &model, err, sizeof err) != 0) {
            fprintf(stderr, "fuzz_step: %s\n", err);
            fuzz_fail("cannot build the base scenes");
        }
    }
#endif
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    input in = { data, size };
    const unsigned head = take_byte(&in);
    const bs_model model = head & 4 ? BS_MODEL_PCS : BS_MODEL_FREE;
    const char *field = NULL;
    bs_status check, status;
    bs_real s0;
    int steps = 0;
    int i;

    scene = bases[(head & 3) % FUZZ_BASES];
    for (i = 0; i < (int)(head >> 3); ++i)
        edit_scene(&in);

    check = bs_scene_check(&scene, &field);
    if (check != BS_OK && check != BS_E_SCENE && check != BS_E_UNSTABLE)
        fuzz_fail("bs_scene_check returned a status it does not document");
    if (check != BS_OK && (!field || !*field))
        fuzz_fail("bs_scene_check refused a scene without naming the field");
    s0 = take_value(&in, BS_R(0.3));
    status = bs_sim_init(&sim, &scene, model, s0);
    if (verbose)
        fprintf(stderr, "base %u, model %d, bs_scene_check: %s (%s), s0 %.17g, bs_sim_init: %s\n", (head & 3) % FUZZ_BASES,
                (int)model, bs_status_text(check), field ? field : "-", (double)s0, bs_status_text(status));
    check_init(check, status);
    if (status != BS_OK)
        return 0;

    while (in.size > 0 && steps < FUZZ_MAX_STEPS) {
        const unsigned op = take_byte(&in);
        if (verbose)
            fprintf(stderr, "op %u (%u) after %d steps\n", op % 12, op, steps);
        switch (op % 12) {
        case 0:
        case 1:
        case 2: { /* run up to 64 steps, or until the step refuses */
            int n;
            for (n = 0; n < (int)(op >> 3) * 2 + 1 && steps < FUZZ_MAX_STEPS; ++n, ++steps) {
                bs_step_report report;
                status = fuzz_step_checked(&sim);
                bs_sim_get_report(&sim, &report);
                if (verbose)
                    fprintf(stderr, "  step %d: %s, contacts 0x%x, sweeps %d, residual %g\n", steps + 1,
                            bs_status_text(status), report.active, report.sweeps, (double)report.residual);
                if (status != BS_OK)
                    break;
            }
            break;
        }
        case 3:
        case 4:
            set_state(&in);
            break;
        case 5: { /* PCS: move the prescribed position */
            const uint32_t before = bs_sim_hash(&sim);
            const bs_real s = take_value(&in, BS_R(0.5));
            status = bs_sim_set_pcs_position(&sim, s);
            if (status != (model == BS_MODEL_PCS && s >= BS_R(0.0) && s <= BS_R(1.0) ? BS_OK : BS_E_ARGUMENT))
                fuzz_fail("bs_sim_set_pcs_position: wrong status");
            if (bs_sim_hash(&sim) != before)
                fuzz_fail("bs_sim_set_pcs_position changed the state");
            break;
        }
        case 6: { /* the read-only queries */
            const bs_real phase = bs_sim_phase(&sim);
            bs_real pose[3];
            if (!(phase >= BS_R(0.0) && phase < BS_R(1.0)))
                fuzz_fail("bs_sim_phase outside [0, 1)");
            bs_sim_get_state(&sim, NULL, NULL, pose, NULL);
            (void)bs_sim_sensor(&sim);
            (void)bs_sim_position(&sim);
            (void)bs_status_text((bs_status)((int)(op >> 3) - 16));
            { /* NULL pointers and a model that does not exist; the sim is untouched */
                static bs_sim scratch;
                const uint32_t before = bs_sim_hash(&sim);
                static bs_sim never; /* zeroed, never initialised */
                if (bs_scene_check(NULL, NULL) != BS_E_NULL
                    || bs_sim_init(NULL, &scene, model, s0) != BS_E_NULL || bs_sim_init(&scratch, NULL, model, s0) != BS_E_NULL
                    || bs_sim_step(NULL) != BS_E_NULL || bs_sim_set_state(NULL, NULL, NULL, NULL, NULL) != BS_E_NULL
                    || bs_sim_set_pcs_position(NULL, BS_R(0.5)) != BS_E_NULL || bs_sim_set_solver(&sim, NULL) != BS_E_NULL
                    || bs_sim_get_report(&sim, NULL) != BS_E_NULL)
                    fuzz_fail("a NULL argument was not answered with BS_E_NULL");
                if (bs_sim_step(&never) != BS_E_UNINITIALISED || bs_sim_hash(&never) != 0
                    || !(bs_sim_position(&never) != bs_sim_position(&never)))
                    fuzz_fail("a never-initialised sim was not refused");
                if (bs_sim_init(&scratch, &scene, (bs_model)(int)(op >> 3), s0) == BS_OK && (op >> 3) > 1)
                    fuzz_fail("bs_sim_init accepted a model that does not exist");
                if (bs_sim_hash(&sim) != before)
                    fuzz_fail("a call on another sim changed the state");
            }
            break;
        }
        case 8:
            set_solver(&in);
            break;
        case 9: { /* a measured input: refused without a trace unless finite */
            const uint32_t before = bs_sim_hash(&sim);
            const bs_real a = take_value(&in, BS_R(3.0));
            status = bs_sim_step_measured(&sim, a);
            ++steps;
            if (!(a - a == BS_R(0.0)) && (status != BS_E_ARGUMENT || bs_sim_hash(&sim) != before))
                fuzz_fail("bs_sim_step_measured took a base acceleration that is not finite");
            if (status != BS_OK && bs_sim_hash(&sim) != before)
                fuzz_fail("a refused measured step changed the state");
            break;
        }
        case 10: { /* new frequency and amplitude: documented range or nothing changes */
            const uint32_t before = bs_sim_hash(&sim);
            const bs_real f = take_value(&in, BS_R(124.0)), a = take_value(&in, BS_R(14.0));
            const double fdt = (double)f * (double)scene.dt;
            const int valid = fdt > 0.0 && fdt < 0.5 && a >= BS_R(0.0) && a - a == BS_R(0.0);
            status = bs_sim_set_excitation(&sim, f, a);
            if (valid && status != BS_OK && status != BS_E_ARGUMENT)
                fuzz_fail("bs_sim_set_excitation: undocumented status");
            if (!valid && status != BS_E_ARGUMENT)
                fuzz_fail("bs_sim_set_excitation accepted a frequency or amplitude out of range");
            if (status != BS_OK && bs_sim_hash(&sim) != before)
                fuzz_fail("a refused bs_sim_set_excitation changed the state");
            break;
        }
        case 11: { /* checkpoint round trip */
            static unsigned char bytes[BS_CHECKPOINT_SIZE];
            static bs_sim restored;
            bs_status a, b;
            if (bs_sim_save(&sim, bytes, sizeof bytes) != BS_OK)
                fuzz_fail("bs_sim_save refused a ready sim");
            if (bs_sim_init(&restored, &scene, model, s0) != BS_OK)
                fuzz_fail("bs_sim_init refused what it accepted before");
            { /* the solver options are the caller's setting, not state: carried over by hand */
                bs_solver_options options;
                if (bs_sim_get_solver(&sim, &options) != BS_OK || bs_sim_set_solver(&restored, &options) != BS_OK)
                    fuzz_fail("the solver options of one sim do not go to another");
            }
            bytes[(op >> 3) % (BS_CHECKPOINT_SIZE - 40) + 36] ^= 0x01u; /* a bit of the state part */
            if (bs_sim_restore(&restored, bytes, sizeof bytes) != BS_E_CHECKPOINT_DAMAGED)
                fuzz_fail("bs_sim_restore took a damaged checkpoint");
            bytes[(op >> 3) % (BS_CHECKPOINT_SIZE - 40) + 36] ^= 0x01u;
            status = bs_sim_restore(&restored, bytes, sizeof bytes);
            if (status != BS_OK) {
                fprintf(stderr, "bs_sim_restore: %s\n", bs_status_text(status)); /* which refusal */
                fuzz_fail("bs_sim_restore refused a checkpoint of a state the step produced");
            }
            if (bs_sim_hash(&restored) != bs_sim_hash(&sim))
                fuzz_fail("a restored sim differs from the one saved");
            a = bs_sim_step(&sim);
            b = bs_sim_step(&restored);
            ++steps;
            if (a != b || bs_sim_hash(&restored) != bs_sim_hash(&sim))
                fuzz_fail("a restored sim steps differently from the one saved");
            break;
        }
        default: /* restart with another s0 */
            s0 = take_value(&in, s0);
            status = bs_sim_init(&sim, &scene, model, s0);
            check_init(check, status);
            if (status != BS_OK)
                return 0;
            break;
        }
    }
    return 0;
}
