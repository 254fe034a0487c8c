/* fuzz_api.c - libFuzzer target: the public API as a caller drives it,
 * checkpoints and the twin's observer included.
 *
 * Base scenes, built once from FUZZ_CONFIGS: fig6 (the observer on the
 * deflection w(4L/7)), fig6 with a resistor load (the observer on the patch
 * voltage) and fig6 with a rectifier load (the deflection gains: a
 * transducer whose storage charges). The observer's constants are designed
 * once per signal (host/lib/twin/observer_design.c, short response maps: they
 * need to be valid, not accurate). Each input picks a base, a model and a
 * start, then plays a program of calls:
 *   op % 10: 0 steps, 1 measured steps (bs_sim_step_measured), 2
 *   bs_sim_set_excitation, 3 bs_sim_set_state, 4-5 bs_sim_restore of a
 *   checkpoint of the sim edited and re-sealed (below), 6
 *   bs_observer_init with edited gains and options, 7-8 bs_observer_step,
 *   9 bs_observer_predict, and a step of the observer on another sim.
 * The contract checked:
 *   - nothing crashes, hangs or reads out of bounds (ASan, UBSan);
 *   - every call returns a status it documents, and every refusal leaves
 *     the sim's hash (and for restore and the observer, every byte of the
 *     sim and of the observer) as it was;
 *   - a step that returns BS_OK leaves a finite state that bs_sim_set_state
 *     accepts (fuzz_check.h), for bs_observer_step as well: its correction
 *     never puts the slider outside the clamp stops' band;
 *   - bs_sim_restore: a checkpoint of the sim with 1-4 fields edited
 *     (header words, model, report counts, step, phase, phase step, any
 *     real: state, percussions, caches, transducer) and its FNV-1a checksum
 *     recomputed (re-sealed; 1 in 8 is not), restored into the sim or into
 *     a sim of another base. The harness decodes the fields itself and
 *     decides by each of restore's rules, in restore's order, which one
 *     refuses (the setters' rules through the setters on a scratch sim:
 *     bs_sim_set_state for the slider band, bs_sim_set_excitation for the
 *     excitation). Restore must refuse exactly when a rule does, with that
 *     rule's status; an accepted checkpoint must save back byte for byte,
 *     hold a state bs_sim_set_state accepts and step without UB (a step may
 *     refuse, with the state kept). How often each rule decided is printed
 *     at exit (docs/robustness.md lists which ones were reached).
 * FUZZ_VERBOSE in the environment prints what an input does.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, strnlen */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "beamslider.h"
#include "bs_excitation.h" /* the step amplitude of a phase step */
#include "bs_observer.h"
#include "fuzz_check.h"
#include "fuzz_files.h"
#include "fuzz_input.h"
#include "observer_design.h"
#include "scene_build.h"

#define MAX_STEPS 384     /* steps of all kinds an input may take */
#define MAX_SWEEPS 64     /* as in fuzz_step.c: a step costs up to the cap */
#define BASES 3

static const char *const base_texts[BASES] = {
    "[scene]\nbase = fig6.ini\n",
    "[scene]\nbase = fig6.ini\n[transducer]\nload = resistor\n",
    "[scene]\nbase = fig6.ini\n[transducer]\nload = rectifier\n",
};
static bs_scene bases[BASES];
static bs_observer_gains designed[2]; /* deflection (bases 0, 2), voltage (base 1) */
static int verbose;

static bs_sim sim, other, scratch, before_sim;
static bs_observer obs, before_obs;
static bs_observer_gains gains; /* what obs points to */
static int base;
static bs_model model;
static int steps;

/* ---- restore's rules, decided by the harness --------------------------- */

enum rule {
    RULE_SIZE_SHORT, RULE_MAGIC, RULE_BUILD, RULE_SIZE, RULE_CHECKSUM, RULE_SCENE_HASH, RULE_MODEL, RULE_STEP_MAX,
    RULE_REPORT, RULE_PERCUSSIONS, RULE_BEAM_FINITE, RULE_UNUSED_MODES, RULE_SLIDER, RULE_X_C_LOW, RULE_X_PCS,
    RULE_BASE_ACCEL, RULE_EXCITATION, RULE_LAWS, RULE_TRANSDUCER, RULE_ACCEPTED, RULES
};
static const char *const rule_names[RULES] = {
    "size below the header (BS_E_CHECKPOINT_SIZE)",
    "magic (BS_E_CHECKPOINT_DAMAGED)",
    "format, build tag or version (BS_E_CHECKPOINT_BUILD)",
    "recorded size or buffer size (BS_E_CHECKPOINT_SIZE)",
    "checksum (BS_E_CHECKPOINT_DAMAGED)",
    "scene hash (BS_E_CHECKPOINT_SCENE)",
    "model (BS_E_CHECKPOINT_SCENE)",
    "step count at its maximum (BS_E_CHECKPOINT_SCENE)",
    "step report: counts, residual (BS_E_CHECKPOINT_SCENE)",
    "percussions: finite, only at active contacts, none tangential at a stop (BS_E_CHECKPOINT_SCENE)",
    "q, u finite (BS_E_CHECKPOINT_SCENE)",
    "q, u of unused modes zero (BS_E_CHECKPOINT_SCENE)",
    "slider pose and velocity: bs_sim_set_state's rule, x_C in the stops band (BS_E_CHECKPOINT_SCENE)",
    "x_C remainder: finite, below eps |x_C| (BS_E_CHECKPOINT_SCENE)",
    "PCS position: finite, in [0, L] (BS_E_CHECKPOINT_SCENE)",
    "base acceleration finite (BS_E_CHECKPOINT_SCENE)",
    "excitation: bs_sim_set_excitation's rule, phase step and step amplitude (BS_E_CHECKPOINT_SCENE)",
    "contact laws: bs_sim_set_contact_laws's rule (BS_E_CHECKPOINT_SCENE)",
    "transducer: voltages, storage, power, energy (BS_E_CHECKPOINT_SCENE)",
    "accepted (BS_OK)",
};
static const bs_status rule_status[RULES] = {
    BS_E_CHECKPOINT_SIZE, BS_E_CHECKPOINT_DAMAGED, BS_E_CHECKPOINT_BUILD, BS_E_CHECKPOINT_SIZE,
    BS_E_CHECKPOINT_DAMAGED, BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE,
    BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE,
    BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE,
    BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE, BS_E_CHECKPOINT_SCENE, BS_OK,
};
static unsigned long rule_count[RULES];

/* The layout (core/src/bs_checkpoint.c): byte offsets and real indices. */
#define AT_MAGIC 0
#define AT_SIZE_WORD 20
#define AT_MODEL 24
#define AT_COUNTS 28
#define AT_STEP 44
#define AT_PHASE 52
#define AT_PHASE_STEP 60
#define AT_REALS 68
enum {
    R_X_PCS = 0, R_FREQUENCY, R_AMPLITUDE, R_STEP_ACCEL, R_BASE_ACCEL, R_LAWS,
    R_Q = R_LAWS + 2, /* the laws: mu, e_N */
    R_U = R_Q + BS_MAX_MODES,
    R_SLIDER = R_U + BS_MAX_MODES,
    R_VELOCITY = R_SLIDER + 3,
    R_X_C_LOW = R_VELOCITY + 3,
    R_PERCUSSION = R_X_C_LOW + 1,
    R_RESIDUAL = R_PERCUSSION + BS_MAX_CONTACTS * BS_ROWS,
    R_CACHES = R_RESIDUAL + 1,
    R_PIEZO = R_CACHES + 2 * (1 + BS_MAX_MODES * BS_SHAPE_TERMS),
    R_COUNT = R_PIEZO + 5 * BS_WITH_PIEZO
};
#define AT_CHECKSUM (BS_CHECKPOINT_SIZE - 4)

static uint32_t fnv(const unsigned char *bytes, size_t size)
{
    uint32_t hash = 2166136261u;
    size_t i;
    for (i = 0; i < size; ++i) {
        hash ^= bytes[i];
        hash *= 16777619u;
    }
    return hash;
}

static uint32_t word32(const unsigned char *b, size_t at)
{
    uint32_t w;
    memcpy(&w, b + at, 4);
    return w;
}

static uint64_t word64(const unsigned char *b, size_t at)
{
    uint64_t w;
    memcpy(&w, b + at, 8);
    return w;
}

static bs_real real_at(const unsigned char *b, int index)
{
    bs_real x;
    memcpy(&x, b + AT_REALS + (size_t)index * sizeof(bs_real), sizeof x);
    return x;
}

static int all_finite(const unsigned char *b, int from, int count)
{
    int k;
    for (k = 0; k < count; ++k)
        if (!fuzz_finite(real_at(b, from + k)))
            return 0;
    return 1;
}

/* The rule of restore that decides bytes (size given) restored into target,
 * whose own checkpoint is own (for the header words it must match). */
static int decide(const bs_sim *target, const unsigned char *b, size_t size, const unsigned char *own)
{
    const bs_scene *sc = target->scene;
    const int n = sc->n_modes;
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES], pose[3], velocity[3];
    int k, r;

    if (size < 24)
        return RULE_SIZE_SHORT;
    if (word32(b, AT_MAGIC) != word32(own, AT_MAGIC))
        return RULE_MAGIC;
    for (k = 1; k <= 3; ++k)
        if (word32(b, 4 * (size_t)k) != word32(own, 4 * (size_t)k))
            return RULE_BUILD;
    if (word32(b, AT_SIZE_WORD) != (uint32_t)BS_CHECKPOINT_SIZE || size < BS_CHECKPOINT_SIZE)
        return RULE_SIZE;
    if (fnv(b, AT_CHECKSUM) != word32(b, AT_CHECKSUM))
        return RULE_CHECKSUM;
    if (word32(b, 16) != bs_scene_hash(sc))
        return RULE_SCENE_HASH;
    if (word32(b, AT_MODEL) != (uint32_t)target->model)
        return RULE_MODEL;
    if (word64(b, AT_STEP) == UINT64_MAX)
        return RULE_STEP_MAX;
    { /* a residual >= 0 or -1, or, unconverged, +inf or NaN (a contact problem that overflowed) */
        const bs_real residual = real_at(b, R_RESIDUAL);
        const uint32_t converged = word32(b, AT_COUNTS + 12);
        if (!(word32(b, AT_COUNTS) < (1u << BS_MAX_CONTACTS) && word32(b, AT_COUNTS + 4) <= BS_SOLVER_MAX_SWEEPS
              && word32(b, AT_COUNTS + 8) <= BS_SOLVER_MAX_SWEEPS && converged <= 1u
              && (fuzz_finite(residual) ? residual >= BS_R(0.0) || residual == BS_R(-1.0)
                                        : converged == 0u && !(residual < BS_R(0.0)))))
            return RULE_REPORT;
    }
    if (!all_finite(b, R_PERCUSSION, BS_MAX_CONTACTS * BS_ROWS))
        return RULE_PERCUSSIONS;
    for (k = 0; k < BS_MAX_CONTACTS; ++k)
        for (r = 0; r < BS_ROWS; ++r)
            if (real_at(b, R_PERCUSSION + k * BS_ROWS + r) != BS_R(0.0)
                && (!(word32(b, AT_COUNTS) >> k & 1u) || (r > 0 && k >= BS_CORNERS)))
                return RULE_PERCUSSIONS;
    if (!all_finite(b, R_Q, BS_MAX_MODES) || !all_finite(b, R_U, BS_MAX_MODES))
        return RULE_BEAM_FINITE;
    for (k = n; k < BS_MAX_MODES; ++k)
        if (real_at(b, R_Q + k) != BS_R(0.0) || real_at(b, R_U + k) != BS_R(0.0))
            return RULE_UNUSED_MODES;
    /* the slider: bs_sim_set_state on a scratch copy decides */
    for (k = 0; k < n; ++k) {
        q[k] = real_at(b, R_Q + k);
        u[k] = real_at(b, R_U + k);
    }
    for (k = 0; k < 3; ++k) {
        pose[k] = real_at(b, R_SLIDER + k);
        velocity[k] = real_at(b, R_VELOCITY + k);
    }
    scratch = *target;
    if (bs_sim_set_state(&scratch, q, u, pose, velocity) != BS_OK)
        return RULE_SLIDER;
    {
        const bs_real low = real_at(b, R_X_C_LOW);
        const bs_real bound = BS_REAL_EPS * (pose[0] < BS_R(0.0) ? -pose[0] : pose[0]);
        if (!fuzz_finite(low) || !((low < BS_R(0.0) ? -low : low) <= bound))
            return RULE_X_C_LOW;
    }
    {
        const bs_real x_pcs = real_at(b, R_X_PCS);
        if (!fuzz_finite(x_pcs) || !(x_pcs >= BS_R(0.0) && x_pcs <= sc->length))
            return RULE_X_PCS;
    }
    if (!fuzz_finite(real_at(b, R_BASE_ACCEL)))
        return RULE_BASE_ACCEL;
    { /* the excitation: bs_sim_set_excitation on a scratch copy gives the phase step and step
       * amplitude of a frequency; the scene's own frequency with the scene's own phase step
       * is the scene's (in float the scene's phase step, made from the frequency in double,
       * is not the one of the frequency rounded to float), with its step amplitude */
        const bs_real f = real_at(b, R_FREQUENCY), a = real_at(b, R_AMPLITUDE), step_accel = real_at(b, R_STEP_ACCEL);
        const uint64_t half = word64(b, AT_PHASE_STEP);
        if (!fuzz_finite(f) || !fuzz_finite(a) || !fuzz_finite(step_accel))
            return RULE_EXCITATION;
        if (f == sc->frequency && half == sc->phase_step_half) {
            const bs_real scenes = (bs_real)((double)a * bs_excitation_step_factor(half));
            if (!(a >= BS_R(0.0)) || !(step_accel == scenes))
                return RULE_EXCITATION;
        } else {
            scratch = *target;
            if (bs_sim_set_excitation(&scratch, f, a) != BS_OK || half != scratch.phase_step_half
                || !(step_accel == scratch.step_accel))
                return RULE_EXCITATION;
        }
    }
    scratch = *target;
    if (bs_sim_set_contact_laws(&scratch, real_at(b, R_LAWS), real_at(b, R_LAWS + 1)) != BS_OK)
        return RULE_LAWS;
#if BS_WITH_PIEZO
    {
        bs_real p[5];
        for (k = 0; k < 5; ++k)
            p[k] = real_at(b, R_PIEZO + k);
        if (sc->load == BS_LOAD_NONE) {
            for (k = 0; k < 5; ++k)
                if (p[k] != BS_R(0.0))
                    return RULE_TRANSDUCER;
        } else if (!fuzz_finite(p[0]) || !fuzz_finite(p[1]) || !(p[2] >= BS_R(0.0)) || !(p[3] >= BS_R(0.0))
                   || (sc->load == BS_LOAD_RESISTOR ? p[1] != BS_R(0.0) : !(p[1] >= BS_R(0.0)))
                   || (fuzz_finite(p[3]) && !fuzz_finite(p[4]))) {
            return RULE_TRANSDUCER;
        }
    }
#endif
    return RULE_ACCEPTED;
}

static void print_rules(void)
{
    int r;
    fprintf(stderr, "fuzz_api: bs_sim_restore of edited checkpoints, the rule that decided (times):\n");
    for (r = 0; r < RULES; ++r)
        fprintf(stderr, "fuzz_api: restore rule %2d %-9lu %s\n", r, rule_count[r], rule_names[r]);
}

/* ---- the calls ----------------------------------------------------------- */

static void snapshot(void)
{
    memcpy(&before_sim, &sim, sizeof sim);
    memcpy(&before_obs, &obs, sizeof obs);
}

/* After a refused call: the observer as it was, byte for byte, and the sim
 * too, except that a failed step may leave its report and contact scratch
 * (not state: docs/robustness.md section 7); then its state hash. */
static void unchanged(const char *what, bs_status status)
{
    const int step_failed = status == BS_E_UNSTABLE || status == BS_E_NONFINITE || status == BS_E_ESCAPED;
    if (memcmp(&before_obs, &obs, sizeof obs) != 0) {
        fprintf(stderr, "%s: %s\n", what, bs_status_text(status));
        fuzz_fail("a refused call changed the observer");
    }
    if (step_failed ? bs_sim_hash(&before_sim) != bs_sim_hash(&sim) : memcmp(&before_sim, &sim, sizeof sim) != 0) {
        fprintf(stderr, "%s: %s\n", what, bs_status_text(status));
        fuzz_fail("a refused call changed the sim");
    }
}

/* After a call that returned BS_OK and advanced the sim. */
static void stepped_ok(void)
{
    if (!fuzz_state_finite(&sim))
        fuzz_fail("a step returned BS_OK with a non-finite state");
    fuzz_state_restorable(&sim); /* x_C in the stops band, everything finite */
}

static int is_step_status(bs_status s)
{
    return s == BS_E_UNSTABLE || s == BS_E_NONFINITE || s == BS_E_ESCAPED;
}

/* A base acceleration: near the sim's own harmonic one, or anything. */
static bs_real take_accel(input *in)
{
    const double own = (double)sim.excitation[1] * cos(6.283185307179586 * (double)bs_sim_phase(&sim));
    return take_value(in, (bs_real)own);
}

static void op_measured(input *in)
{
    const bs_real a = take_accel(in);
    const uint32_t hash = bs_sim_hash(&sim);
    const bs_status status = bs_sim_step_measured(&sim, a);
    ++steps;
    if (status == BS_OK) {
        if (!fuzz_finite(a))
            fuzz_fail("bs_sim_step_measured took a base acceleration that is not finite");
        stepped_ok();
        return;
    }
    if (status != BS_E_ARGUMENT && !is_step_status(status))
        fuzz_fail("bs_sim_step_measured returned a status it does not document");
    if (bs_sim_hash(&sim) != hash)
        fuzz_fail("a refused measured step changed the state");
}

static void op_excitation(input *in)
{
    const bs_real f = take_value(in, sim.excitation[0]), a = take_value(in, sim.excitation[1]);
    const uint32_t hash = bs_sim_hash(&sim);
    const bs_status status = bs_sim_set_excitation(&sim, f, a);
    const double fdt = (double)f * (double)sim.scene->dt;
    if (status == BS_OK && !(fdt > 0.0 && fdt < 0.5 && a >= BS_R(0.0) && fuzz_finite(a)))
        fuzz_fail("bs_sim_set_excitation accepted a frequency or amplitude out of range");
    if (status != BS_OK && (status != BS_E_ARGUMENT || bs_sim_hash(&sim) != hash))
        fuzz_fail("a refused bs_sim_set_excitation changed the state or gave an undocumented status");
}

static void op_set_state(input *in)
{
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES], pose[3], velocity[3];
    bs_real *const part[4] = { q, u, pose, velocity };
    const int length[4] = { sim.scene->n_modes, sim.scene->n_modes, 3, 3 };
    const int edits = (int)(take_byte(in) & 3) + 1;
    const uint32_t hash = bs_sim_hash(&sim);
    bs_status status;
    int e;
    bs_sim_get_state(&sim, q, u, pose, velocity);
    for (e = 0; e < edits; ++e) {
        const int p = (int)(take_byte(in) & 3);
        const int k = (int)(take_byte(in) % (unsigned)length[p]);
        part[p][k] = take_value(in, part[p][k]);
    }
    status = bs_sim_set_state(&sim, q, u, pose, velocity);
    if (status == BS_OK)
        stepped_ok();
    else if (status != BS_E_ARGUMENT || bs_sim_hash(&sim) != hash)
        fuzz_fail("a refused bs_sim_set_state changed the state or gave an undocumented status");
}

static uint32_t take_u32(input *in, uint32_t current)
{
    static const uint32_t specials[] = { 0, 1, 2, 0x3f, 0x40, 0xff, 1u << 31, 0xffffffffu, 0x7fffffffu,
                                         BS_SOLVER_MAX_SWEEPS, BS_SOLVER_MAX_SWEEPS + 1u };
    const unsigned how = take_byte(in);
    switch (how % 4) {
    case 0:
        return (uint32_t)take_bits(in, 4);
    case 1:
        return specials[take_byte(in) % (sizeof specials / sizeof specials[0])];
    case 2:
        return current + (uint32_t)(int8_t)take_byte(in);
    default:
        return current ^ (1u << (take_byte(in) & 31));
    }
}

static uint64_t take_u64(input *in, uint64_t current)
{
    static const uint64_t specials[] = { 0, 1, UINT64_MAX, UINT64_MAX - 1, (uint64_t)1 << 62, ((uint64_t)1 << 62) - 1,
                                         (uint64_t)1 << 63, (uint64_t)1 << 61 };
    const unsigned how = take_byte(in);
    switch (how % 4) {
    case 0:
        return take_bits(in, 8);
    case 1:
        return specials[take_byte(in) % (sizeof specials / sizeof specials[0])];
    case 2:
        return current + (uint64_t)(int64_t)(int8_t)take_byte(in);
    default:
        return current ^ ((uint64_t)1 << (take_byte(in) & 63));
    }
}

/* Edits one field of a checkpoint. */
static void edit_checkpoint(input *in, unsigned char *b)
{
    const unsigned kind = take_byte(in) % 10;
    switch (kind) {
    case 0: { /* a header word: magic, format, build tag, version, scene hash, size */
        const size_t at = 4 * (size_t)(take_byte(in) % 6);
        const uint32_t w = take_u32(in, word32(b, at));
        memcpy(b + at, &w, 4);
        break;
    }
    case 1: { /* the model, a report count */
        const size_t at = AT_MODEL + 4 * (size_t)(take_byte(in) % 5);
        const uint32_t w = take_u32(in, word32(b, at));
        memcpy(b + at, &w, 4);
        break;
    }
    case 2: { /* step, phase, phase step */
        const size_t at = AT_STEP + 8 * (size_t)(take_byte(in) % 3);
        const uint64_t w = take_u64(in, word64(b, at));
        memcpy(b + at, &w, 8);
        break;
    }
    case 3: { /* the checksum itself */
        const uint32_t w = take_u32(in, word32(b, AT_CHECKSUM));
        memcpy(b + AT_CHECKSUM, &w, 4);
        break;
    }
    case 4: { /* any real, the caches included */
        const int index = (int)(take_bits(in, 2) % R_COUNT);
        const bs_real x = take_value(in, real_at(b, index));
        memcpy(b + AT_REALS + (size_t)index * sizeof x, &x, sizeof x);
        break;
    }
    default: { /* a real of the state (before the caches), or of the transducer */
        int index = (int)(take_byte(in) % (R_CACHES + 5 * BS_WITH_PIEZO));
        bs_real x;
        if (index >= R_CACHES)
            index = R_PIEZO + (index - R_CACHES);
        x = take_value(in, real_at(b, index));
        memcpy(b + AT_REALS + (size_t)index * sizeof x, &x, sizeof x);
        break;
    }
    }
}

static void op_restore(input *in)
{
    static unsigned char own[BS_CHECKPOINT_SIZE + 16], bytes[BS_CHECKPOINT_SIZE + 16], again[BS_CHECKPOINT_SIZE];
    static const size_t short_sizes[] = { 0, 4, 23, 24, 25, BS_CHECKPOINT_SIZE - 1, BS_CHECKPOINT_SIZE + 16 };
    const unsigned flags = take_byte(in);
    const int edits = (int)(flags & 3) + 1;
    const int into_other = (flags & 0x1c) == 0x1c; /* 1 in 8: a sim of another base or model */
    const int sealed = (flags & 0xe0) != 0xe0;   /* 7 in 8: the checksum recomputed */
    size_t size = BS_CHECKPOINT_SIZE;
    bs_sim *target = into_other ? &other : &sim;
    int e, rule;
    bs_status status;

    if (bs_sim_save(&sim, bytes, sizeof bytes) != BS_OK)
        fuzz_fail("bs_sim_save refused a ready sim");
    if (bs_sim_save(target, own, sizeof own) != BS_OK)
        fuzz_fail("bs_sim_save refused a ready sim");
    for (e = 0; e < edits; ++e)
        edit_checkpoint(in, bytes);
    if (sealed) {
        const uint32_t checksum = fnv(bytes, AT_CHECKSUM);
        memcpy(bytes + AT_CHECKSUM, &checksum, 4);
    }
    if ((flags & 0x1c) == 0x18)
        size = short_sizes[take_byte(in) % (sizeof short_sizes / sizeof short_sizes[0])];
    rule = decide(target, bytes, size, own);
    ++rule_count[rule];

    memcpy(&before_sim, target, sizeof *target);
    memcpy(&before_obs, &obs, sizeof obs);
    status = bs_sim_restore(target, bytes, size);
    if (verbose)
        fprintf(stderr, "restore (%d edits, %s, into %s, size %zu): %s, the harness: %s\n", edits,
                sealed ? "sealed" : "not sealed", into_other ? "another sim" : "the sim", size,
                bs_status_text(status), rule_names[rule]);
    if (status != rule_status[rule]) {
        fprintf(stderr, "bs_sim_restore: %s; the harness's rule: %s\n", bs_status_text(status), rule_names[rule]);
        fuzz_fail("bs_sim_restore decided otherwise than its rules");
    }
    if (status != BS_OK) {
        if (memcmp(&before_sim, target, sizeof *target) != 0 || memcmp(&before_obs, &obs, sizeof obs) != 0)
            fuzz_fail("a refused bs_sim_restore changed the sim");
        return;
    }
    if (bs_sim_save(target, again, sizeof again) != BS_OK || memcmp(again, bytes, BS_CHECKPOINT_SIZE) != 0)
        fuzz_fail("a restored checkpoint does not save back byte for byte");
    if (!fuzz_state_finite(target))
        fuzz_fail("bs_sim_restore accepted a non-finite state");
    fuzz_state_restorable(target);
    for (e = 0; e < 4 && steps < MAX_STEPS; ++e, ++steps)
        if (fuzz_step_checked(target) != BS_OK)
            break;
}

/* Gains from the designed ones with a few fields edited. */
static void edit_gains(input *in)
{
    const int edits = (int)(take_byte(in) % 4);
    int e;
    gains = designed[base == 1];
    for (e = 0; e < edits; ++e) {
        const unsigned field = take_byte(in) % 17;
        const unsigned i = take_byte(in), k = take_byte(in);
        const int gi = (int)(i % BS_OBSERVER_GAINS), ti = (int)(i % BS_OBSERVER_TABLE), m = (int)(k % BS_OBSERVER_MAPS);
        switch (field) {
        case 0: gains.n_modes = take_int(in, gains.n_modes); break;
        case 1: gains.signal = take_int(in, gains.signal); break;
        case 2: gains.latency = take_int(in, gains.latency); break;
        case 3: gains.noise = take_value(in, gains.noise); break;
        case 4: gains.gain_count = take_int(in, gains.gain_count); break;
        case 5: gains.gain_s[gi] = take_value(in, gains.gain_s[gi]); break;
        case 6: gains.gain_q[gi][k % BS_MAX_MODES] = take_value(in, gains.gain_q[gi][k % BS_MAX_MODES]); break;
        case 7: gains.gain_u[gi][k % BS_MAX_MODES] = take_value(in, gains.gain_u[gi][k % BS_MAX_MODES]); break;
        case 8: gains.gain_v[gi] = take_value(in, gains.gain_v[gi]); break;
        case 9: gains.map_count = take_int(in, gains.map_count); break;
        case 10: gains.map_frequency[m] = take_value(in, gains.map_frequency[m]); break;
        case 11: gains.map_accel[m] = take_value(in, gains.map_accel[m]); break;
        case 12: gains.table_count = take_int(in, gains.table_count); break;
        case 13: gains.table_s[ti] = take_value(in, gains.table_s[ti]); break;
        case 14: gains.table_stiff[m][ti] = take_value(in, gains.table_stiff[m][ti]); break;
        case 15: gains.map_friction[m] = take_value(in, gains.map_friction[m]); break;
        default: gains.table_soft[m][ti] = take_value(in, gains.table_soft[m][ti]); break;
        }
    }
}

static void op_observer_init(input *in)
{
    bs_observer_options options = bs_observer_defaults();
    const unsigned how = take_byte(in);
    bs_status status;
    bs_observer_estimate estimate;
    edit_gains(in);
    if (how & 1) {
        const unsigned field = take_byte(in) % 11;
        switch (field) {
        case 0: options.correct_beam = take_int(in, options.correct_beam); break;
        case 1: options.correct_position = take_int(in, options.correct_position); break;
        case 2: options.lockin_time = take_value(in, options.lockin_time); break;
        case 3: options.position_gain = take_value(in, options.position_gain); break;
        case 4: options.position_rate = take_value(in, options.position_rate); break;
        case 5: options.position_deadband = take_value(in, options.position_deadband); break;
        case 6: options.sigma_hold = take_value(in, options.sigma_hold); break;
        case 7: options.excitation_tolerance = take_value(in, options.excitation_tolerance); break;
        case 8: options.settle_time = take_value(in, options.settle_time); break;
        case 9: options.jump_hold = take_value(in, options.jump_hold); break;
        default: options.outlier_gate = take_value(in, options.outlier_gate); break;
        }
    }
    if (how & 2) { /* quick corrections: the position moves within the steps an input has (any
                    * excitation taken as the map's, no settling, no deadband, fast and strong) */
        options.settle_time = BS_R(0.0);
        options.lockin_time = (bs_real)(32.0 * (double)sim.scene->dt);
        options.excitation_tolerance = BS_R(1e3);
        options.position_rate = BS_R(1e3);
        options.position_gain = BS_R(1e3);
        options.position_deadband = BS_R(0.0);
        options.sigma_hold = BS_R(2.0);
    }
    status = bs_observer_init(&obs, &sim, &gains, how & 4 ? &options : NULL);
    if (verbose)
        fprintf(stderr, "bs_observer_init: %s\n", bs_status_text(status));
    if (status != BS_OK && status != BS_E_ARGUMENT)
        fuzz_fail("bs_observer_init returned a status it does not document");
    if (status == BS_OK && (model != BS_MODEL_FREE || gains.n_modes != sim.scene->n_modes))
        fuzz_fail("bs_observer_init accepted a PCS sim or gains of another mode count");
    if (status != BS_OK && bs_observer_get(&obs, &estimate) != BS_E_UNINITIALISED)
        fuzz_fail("an observer whose init failed is not refused");
}

/* A measurement: near the twin's own signal, or anything. */
static bs_real take_measurement(input *in)
{
    bs_real own = bs_sim_sensor(&sim);
#if BS_WITH_PIEZO
    if (gains.signal == BS_SIGNAL_VOLTAGE)
        own = sim.voltage;
#endif
    return take_value(in, own);
}

static void op_observer_step(input *in, int predict)
{
    const int n = (int)(take_byte(in) & 15) + 1;
    int k;
    for (k = 0; k < n && steps < MAX_STEPS; ++k, ++steps) {
        const bs_real a = take_accel(in);
        const bs_real y = predict ? BS_R(0.0) : take_measurement(in);
        bs_observer_estimate estimate;
        bs_status status;
        snapshot();
        status = predict ? bs_observer_predict(&obs, &sim, a) : bs_observer_step(&obs, &sim, a, y);
        if (verbose)
            fprintf(stderr, "  observer %s (a %g, y %g): %s, x_C/L %g\n", predict ? "predict" : "step", (double)a,
                    (double)y, bs_status_text(status), (double)bs_sim_position(&sim));
        if (status == BS_OK) {
            if (!fuzz_finite(a) || (!predict && !fuzz_finite(y)))
                fuzz_fail("the observer took a base acceleration or measurement that is not finite");
            stepped_ok();
            if (bs_observer_get(&obs, &estimate) != BS_OK)
                fuzz_fail("bs_observer_get refused a ready observer");
            if (estimate.health != 0 && estimate.health != BS_OBSERVER_HEALTH_OUTLIERS)
                fuzz_fail("bs_observer_get gave health bits it does not document");
            continue;
        }
        if (status != BS_E_ARGUMENT && status != BS_E_UNINITIALISED && !is_step_status(status))
            fuzz_fail("the observer returned a status it does not document");
        unchanged(predict ? "bs_observer_predict" : "bs_observer_step", status);
        if (status != BS_E_ARGUMENT && status != BS_E_UNINITIALISED)
            break; /* the twin cannot step on: it would fail again */
    }
}

/* The observer given another sim than its own: refused, nothing changes. */
static void op_observer_other(input *in)
{
    const uint32_t hash = bs_sim_hash(&other);
    const bs_real a = take_accel(in);
    bs_status status;
    snapshot();
    status = take_byte(in) & 1 ? bs_observer_predict(&obs, &other, a) : bs_observer_step(&obs, &other, a, BS_R(0.0));
    if (status != BS_E_ARGUMENT && status != BS_E_UNINITIALISED)
        fuzz_fail("the observer took another sim than its own");
    unchanged("the observer on another sim", status);
    if (bs_sim_hash(&other) != hash)
        fuzz_fail("the observer changed another sim than its own");
    /* NULL arguments: BS_E_NULL, nothing changes */
    snapshot();
    if (bs_observer_init(NULL, &sim, &gains, NULL) != BS_E_NULL || bs_observer_step(NULL, &sim, a, a) != BS_E_NULL
        || bs_observer_predict(NULL, &sim, a) != BS_E_NULL || bs_observer_get(&obs, NULL) != BS_E_NULL
        || bs_observer_get(NULL, NULL) != BS_E_NULL)
        fuzz_fail("a NULL argument of the observer was not answered with BS_E_NULL");
    unchanged("the observer's NULL arguments", BS_E_NULL);
}

/* ---- set-up and the program --------------------------------------------- */

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static scene_file file;
    static scene_model scene_models[BASES];
    char err[1024];
    int b;

    (void)argc;
    (void)argv;
    verbose = getenv("FUZZ_VERBOSE") != NULL;
    if (R_COUNT != (int)BS_CHECKPOINT_REALS)
        fuzz_fail("the checkpoint layout of fuzz_api.c is not the core's");
    fuzz_copy_config("mssp2023.ini");
    fuzz_copy_config("fig6.ini");
    for (b = 0; b < BASES; ++b) {
        char name[16];
        const char *path;
        snprintf(name, sizeof name, "base%d.ini", b);
        path = fuzz_path(name);
        fuzz_write(path, (const uint8_t *)base_texts[b], strlen(base_texts[b]));
        if (scene_read(path, &file, &bases[b], &scene_models[b], err, sizeof err) != 0) {
            fprintf(stderr, "fuzz_api: %s\n", err);
            fuzz_fail("cannot build the base scenes");
        }
        if (b < 2) { /* the observer's constants, with short response maps */
            observer_design_options o = observer_design_defaults(b == 0 ? 7.5e-6 : 1e-3);
            o.signal = b == 0 ? BS_SIGNAL_DEFLECTION : BS_SIGNAL_VOLTAGE;
            o.map_hold = 0;
            o.map_record = 1;
            if (observer_design(&file, &scene_models[b], &bases[b], &o, &designed[b], err, sizeof err) != 0) {
                fprintf(stderr, "fuzz_api: %s\n", err);
                fuzz_fail("cannot design the observer's constants");
            }
        }
    }
    atexit(print_rules);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    input in = { data, size };
    const unsigned head = take_byte(&in);
    bs_solver_options solver;
    bs_real s0;
    bs_status status;

    base = (int)(head % BASES);
    model = (head >> 2 & 7) == 7 ? BS_MODEL_PCS : BS_MODEL_FREE;
    s0 = take_value(&in, BS_R(0.3));
    steps = 0;
    memset(&obs, 0, sizeof obs);
    status = bs_sim_init(&sim, &bases[base], model, s0);
    if (status != BS_OK) {
        if (status != BS_E_ARGUMENT)
            fuzz_fail("bs_sim_init refused a base scene for another reason than s0");
        return 0;
    }
    /* the other sim: another base (restore: the scene hash), or the same scene in the other model */
    if (bs_sim_init(&other, &bases[(base + 1 + (head >> 5 & 1)) % BASES], head & 0x80 ? BS_MODEL_PCS : BS_MODEL_FREE,
                    BS_R(0.3)) != BS_OK)
        fuzz_fail("bs_sim_init refused a base scene");
    bs_sim_get_solver(&sim, &solver);
    if (solver.max_sweeps > MAX_SWEEPS && !getenv("FUZZ_STRICT")) {
        solver.max_sweeps = MAX_SWEEPS;
        bs_sim_set_solver(&sim, &solver);
        bs_sim_set_solver(&other, &solver);
    }

    while (in.size > 0 && steps < MAX_STEPS) {
        const unsigned op = take_byte(&in);
        if (verbose)
            fprintf(stderr, "op %u (%u) after %d steps\n", op % 10, op, steps);
        switch (op % 10) {
        case 0: {
            int k;
            for (k = 0; k < (int)(op >> 4) + 1 && steps < MAX_STEPS; ++k, ++steps)
                if (fuzz_step_checked(&sim) != BS_OK)
                    break;
            break;
        }
        case 1:
            op_measured(&in);
            break;
        case 2:
            op_excitation(&in);
            break;
        case 3:
            op_set_state(&in);
            break;
        case 4:
        case 5:
            op_restore(&in);
            break;
        case 6:
            op_observer_init(&in);
            break;
        case 7:
        case 8:
            op_observer_step(&in, 0);
            break;
        default:
            if (op & 0x80)
                op_observer_other(&in);
            else
                op_observer_step(&in, 1);
            break;
        }
    }
    return 0;
}
