/* bs_checkpoint.c - a sim's complete state in the caller's bytes, and back
 * (docs/twin.md, "Checkpoints").
 *
 * Layout, every value in the machine's byte order, no padding:
 *   u32 magic "BSCP", u32 format, u32 BS_BUILD_TAG, u32 BS_VERSION_NUMBER,
 *   u32 bs_scene_hash, u32 BS_CHECKPOINT_SIZE,
 *   u32 model, u32 report.active, sweeps, systems, converged,
 *   u64 step, phase, phase_step_half,
 *   bs_real x_pcs, excitation[2], step_accel, base_accel, contact laws mu and
 *     e_N (bs_sim_set_contact_laws), q_beam[BS_MAX_MODES],
 *     u_beam[BS_MAX_MODES], slider[3], slider_velocity[3], x_c_low,
 *     percussion[BS_MAX_CONTACTS][BS_ROWS], report.residual,
 *     2 x (shape cache centre, coef[BS_MAX_MODES][BS_SHAPE_TERMS]),
 *     with the transducer: voltage, storage_voltage, power, energy, energy_low,
 *   u32 FNV-1a checksum of every byte before it.
 * The mode-shape caches are saved as they are, not expanded again, because a
 * new expansion about another centre rounds differently and would break the
 * bit-for-bit continuation. What bs_sim_init derives from the scene alone
 * (shape reach, stretching rows, the patch's stiffness bound) is not saved.
 */
#include "beamslider.h"
#include "bs_scene_fields.h"
#include "bs_port.h"
#include "bs_shape.h"
#include "bs_sim_internal.h"

#define CHECKPOINT_MAGIC 0x50435342u /* "BSCP" read as a little-endian u32 */
#define CHECKPOINT_FORMAT 2u /* 2: the contact laws (0.8.0) */
#define FNV_OFFSET 2166136261u
#define FNV_PRIME 16777619u

static uint32_t fnv(uint32_t hash, const void *data, size_t size)
{
    const unsigned char *byte = (const unsigned char *)data;
    size_t i;
    for (i = 0; i < size; ++i) {
        hash ^= byte[i];
        hash *= FNV_PRIME;
    }
    return hash;
}

/* --- scene hash: every used element, through the field table ------------- */

#define HASH_REAL(s, e) hash = fnv(hash, &(e), sizeof(bs_real))
#define HASH_INT(s, e) hash = fnv(hash, &(e), sizeof(int))
#define HASH_U64(s, e) hash = fnv(hash, &(e), sizeof(uint64_t))
#define HASH_FIELD(kind, name, d1, d2, d3, rule, unit, meaning)                                   \
    for (i = 0; i < BS_USED_##d1(scene); ++i)                                                     \
        for (j = 0; j < BS_USED_##d2(scene); ++j)                                                 \
            for (k = 0; k < BS_USED_##d3(scene); ++k)                                             \
                HASH_##kind(scene, *(&scene->name BS_INDEX_##d1(i) BS_INDEX_##d2(j) BS_INDEX_##d3(k)));

#define BS_INDEX_ONE(i)
#define BS_INDEX_MODES(i) [i]
#define BS_INDEX_PIECES(i) [i]
#define BS_INDEX_COEFS(i) [i]
#define BS_INDEX_CORNERS(i) [i]
#define BS_INDEX_XZ(i) [i]

uint32_t bs_scene_hash(const bs_scene *scene)
{
    uint32_t hash = FNV_OFFSET;
    int i, j, k;
    if (!scene)
        return 0;
    BS_SCENE_FIELDS(HASH_FIELD)
    return hash;
}

/* --- byte cursor ----------------------------------------------------------- */

typedef struct cursor {
    unsigned char *out;      /* writing: the buffer; reading: NULL */
    const unsigned char *in; /* reading: the buffer */
    size_t at;
} cursor;

static void copy_bytes(unsigned char *to, const unsigned char *from, size_t size)
{
    size_t i;
    for (i = 0; i < size; ++i)
        to[i] = from[i];
}

/* Writes or reads size bytes at the cursor, as the cursor's direction says. */
static void field(cursor *c, void *value, size_t size)
{
    if (c->out)
        copy_bytes(c->out + c->at, (const unsigned char *)value, size);
    else
        copy_bytes((unsigned char *)value, c->in + c->at, size);
    c->at += size;
}

static void reals(cursor *c, bs_real *values, int count)
{
    field(c, values, (size_t)count * sizeof(bs_real));
}

static void u32(cursor *c, uint32_t *value)
{
    field(c, value, sizeof *value);
}

/* What a checkpoint holds beyond its header (small: restore decodes into it
 * on the stack, not into a copy of the whole sim with its solver scratch). */
typedef struct saved_state {
    uint32_t model, counts[4]; /* report.active, sweeps, systems, converged */
    uint64_t step, phase, phase_step_half;
    bs_real x_pcs, excitation[2], step_accel, base_accel, laws[2]; /* laws: mu, e_N */
    bs_real q_beam[BS_MAX_MODES], u_beam[BS_MAX_MODES];
    bs_real slider[3], slider_velocity[3], x_c_low;
    bs_real percussion[BS_MAX_CONTACTS][BS_ROWS];
    bs_real residual;
    bs_shape_cache side[2];
#if BS_WITH_PIEZO
    bs_real piezo[5]; /* voltage, storage_voltage, power, energy, energy_low */
#endif
} saved_state;

/* The state part, in the layout above, between a saved_state and the cursor. */
static void state(cursor *c, saved_state *s)
{
    int side;
    u32(c, &s->model);
    field(c, s->counts, sizeof s->counts);
    field(c, &s->step, sizeof s->step);
    field(c, &s->phase, sizeof s->phase);
    field(c, &s->phase_step_half, sizeof s->phase_step_half);
    reals(c, &s->x_pcs, 1);
    reals(c, s->excitation, 2);
    reals(c, &s->step_accel, 1);
    reals(c, &s->base_accel, 1);
    reals(c, s->laws, 2);
    reals(c, s->q_beam, BS_MAX_MODES);
    reals(c, s->u_beam, BS_MAX_MODES);
    reals(c, s->slider, 3);
    reals(c, s->slider_velocity, 3);
    reals(c, &s->x_c_low, 1);
    reals(c, &s->percussion[0][0], BS_MAX_CONTACTS * BS_ROWS);
    reals(c, &s->residual, 1);
    for (side = 0; side < 2; ++side) {
        reals(c, &s->side[side].centre, 1);
        reals(c, &s->side[side].coef[0][0], BS_MAX_MODES * BS_SHAPE_TERMS);
    }
#if BS_WITH_PIEZO
    reals(c, s->piezo, 5);
#endif
}

static void copy_reals(bs_real *to, const bs_real *from, int count)
{
    int k;
    for (k = 0; k < count; ++k)
        to[k] = from[k];
}

/* Element by element: a struct assignment may become a call of memcpy,
 * which the freestanding core does not have (tests/check_core_symbols.sh). */
static void copy_cache(bs_shape_cache *to, const bs_shape_cache *from)
{
    to->centre = from->centre;
    copy_reals(&to->coef[0][0], &from->coef[0][0], BS_MAX_MODES * BS_SHAPE_TERMS);
}

static void save_state(const bs_sim *sim, saved_state *s)
{
    s->model = (uint32_t)sim->model;
    s->counts[0] = sim->report.active;
    s->counts[1] = (uint32_t)sim->report.sweeps; /* ints pass as u32: int's size does not matter */
    s->counts[2] = (uint32_t)sim->report.systems;
    s->counts[3] = (uint32_t)sim->report.converged;
    s->step = sim->step;
    s->phase = sim->phase;
    s->phase_step_half = sim->phase_step_half;
    s->x_pcs = sim->x_pcs;
    copy_reals(s->excitation, sim->excitation, 2);
    s->step_accel = sim->step_accel;
    s->base_accel = sim->base_accel;
    s->laws[0] = sim->k.mu;
    s->laws[1] = sim->k.e_n;
    copy_reals(s->q_beam, sim->q_beam, BS_MAX_MODES);
    copy_reals(s->u_beam, sim->u_beam, BS_MAX_MODES);
    copy_reals(s->slider, sim->slider, 3);
    copy_reals(s->slider_velocity, sim->slider_velocity, 3);
    s->x_c_low = sim->x_c_low;
    copy_reals(&s->percussion[0][0], &sim->percussion[0][0], BS_MAX_CONTACTS * BS_ROWS);
    s->residual = sim->report.residual;
    copy_cache(&s->side[0], &sim->side[0]);
    copy_cache(&s->side[1], &sim->side[1]);
#if BS_WITH_PIEZO
    s->piezo[0] = sim->voltage;
    s->piezo[1] = sim->storage_voltage;
    s->piezo[2] = sim->power;
    s->piezo[3] = sim->energy;
    s->piezo[4] = sim->energy_low;
#endif
}

static void load_state(bs_sim *sim, const saved_state *s)
{
    sim->report.active = s->counts[0];
    sim->report.sweeps = (int)s->counts[1];
    sim->report.systems = (int)s->counts[2];
    sim->report.converged = (int)s->counts[3];
    sim->report.residual = s->residual;
    sim->step = s->step;
    sim->phase = s->phase;
    sim->phase_step_half = s->phase_step_half;
    sim->x_pcs = s->x_pcs;
    copy_reals(sim->excitation, s->excitation, 2);
    sim->step_accel = s->step_accel;
    sim->base_accel = s->base_accel;
    sim->k.mu = s->laws[0];
    sim->k.e_n = s->laws[1];
    copy_reals(sim->q_beam, s->q_beam, BS_MAX_MODES);
    copy_reals(sim->u_beam, s->u_beam, BS_MAX_MODES);
    copy_reals(sim->slider, s->slider, 3);
    copy_reals(sim->slider_velocity, s->slider_velocity, 3);
    sim->x_c_low = s->x_c_low;
    copy_reals(&sim->percussion[0][0], &s->percussion[0][0], BS_MAX_CONTACTS * BS_ROWS);
    copy_cache(&sim->side[0], &s->side[0]);
    copy_cache(&sim->side[1], &s->side[1]);
    sim->side[0].on_beam = bs_shape_on_beam(sim->scene, sim->side[0].centre); /* not in the file: its centre's */
    sim->side[1].on_beam = bs_shape_on_beam(sim->scene, sim->side[1].centre);
#if BS_WITH_PIEZO
    sim->voltage = s->piezo[0];
    sim->storage_voltage = s->piezo[1];
    sim->power = s->piezo[2];
    sim->energy = s->piezo[3];
    sim->energy_low = s->piezo[4];
#endif
    sim->contacts.count = 0; /* scratch of a step under way: none between steps */
}

static void header(cursor *c, uint32_t words[6])
{
    field(c, words, 6 * sizeof words[0]);
}

bs_status bs_sim_save(const bs_sim *sim, void *buffer, size_t size)
{
    const bs_status status = bs_sim_status(sim);
    uint32_t words[6], checksum;
    saved_state s;
    cursor c;

    if (status != BS_OK)
        return status;
    if (!buffer)
        return BS_E_NULL;
    if (size < BS_CHECKPOINT_SIZE)
        return BS_E_CHECKPOINT_SIZE;
    words[0] = CHECKPOINT_MAGIC;
    words[1] = CHECKPOINT_FORMAT;
    words[2] = BS_BUILD_TAG;
    words[3] = BS_VERSION_NUMBER;
    words[4] = bs_scene_hash(sim->scene);
    words[5] = (uint32_t)BS_CHECKPOINT_SIZE;
    save_state(sim, &s);
    c.out = (unsigned char *)buffer;
    c.in = 0;
    c.at = 0;
    header(&c, words);
    state(&c, &s);
    checksum = fnv(FNV_OFFSET, buffer, c.at);
    u32(&c, &checksum);
    return BS_OK;
}

static int finite(const bs_real *values, int count)
{
    int k;
    for (k = 0; k < count; ++k)
        if (values[k] - values[k] != BS_R(0.0))
            return 0;
    return 1;
}

/* 1 if values[from .. count - 1] are all 0 (the unused modes: nothing
 * writes them after bs_sim_init). */
static int zero_beyond(const bs_real *values, int from, int count)
{
    int k;
    for (k = from; k < count; ++k)
        if (values[k] != BS_R(0.0))
            return 0;
    return 1;
}

/* The step's report: counts within what a solve can take, a residual >= 0
 * or -1 (not measured), or, unconverged, +inf or not a number (a contact
 * problem that overflows, e.g. an infinite Delassus diagonal: the step keeps
 * a finite state and reports the solve as it went; tests/test_checkpoint.c). */
static int acceptable_report(const saved_state *s)
{
    return s->counts[0] < (1u << BS_MAX_CONTACTS) && s->counts[1] <= (uint32_t)BS_SOLVER_MAX_SWEEPS
           && s->counts[2] <= (uint32_t)BS_SOLVER_MAX_SWEEPS && s->counts[3] <= 1u
           && (finite(&s->residual, 1) ? s->residual >= BS_R(0.0) || s->residual == BS_R(-1.0)
                                        : s->counts[3] == 0u && !(s->residual < BS_R(0.0)));
}

/* Percussions: finite, 0 for every contact the last step did not have
 * (the step clears them), and no tangential percussion at a clamp stop
 * (frictionless). */
static int acceptable_percussions(const saved_state *s)
{
    int k, r;
    if (!finite(&s->percussion[0][0], BS_MAX_CONTACTS * BS_ROWS))
        return 0;
    for (k = 0; k < BS_MAX_CONTACTS; ++k)
        for (r = 0; r < BS_ROWS; ++r)
            if (s->percussion[k][r] != BS_R(0.0)
                && (!(s->counts[0] >> k & 1u) || (r > 0 && k >= BS_CORNERS)))
                return 0;
    return 1;
}

#if BS_WITH_PIEZO
/* The transducer: nothing without one; else finite voltages, a storage
 * charged only one way, power and energy >= 0 (they may overflow to
 * infinity in a run far beyond any harvester, and then the energy's
 * compensation term is NaN). */
static int acceptable_transducer(const bs_scene *scene, const bs_real *piezo)
{
    if (scene->load == BS_LOAD_NONE)
        return zero_beyond(piezo, 0, 5);
    if (!finite(piezo, 2) || !(piezo[2] >= BS_R(0.0)) || !(piezo[3] >= BS_R(0.0)))
        return 0;
    if (scene->load == BS_LOAD_RESISTOR ? piezo[1] != BS_R(0.0) : !(piezo[1] >= BS_R(0.0)))
        return 0;
    return finite(&piezo[3], 1) ? finite(&piezo[4], 1) : 1;
}
#endif

/* A decoded state the sim can take, by the rules the setters apply
 * (bs_sim_set_state, bs_sim_set_excitation, bs_sim_set_pcs_position,
 * bs_sim_set_contact_laws) and the
 * invariants the step keeps: the model the sim was initialised with; the
 * beam and slider state finite, x_C in the stops band; the excitation one
 * the setter accepts with the phase step and step amplitude it derives; a
 * step count short of its maximum; x_C's compensation term below its half
 * ulp; the report, percussions and transducer as a step leaves them.
 * The shape caches are not checked: they are derived (an expansion about
 * x = L has its centre a rounding above L, an extreme scene's coefficients
 * may overflow), any value of theirs can only make a step fail with a
 * status, and the checksum vouches for them. */
static int acceptable(const bs_sim *sim, const saved_state *s)
{
    const bs_scene *scene = sim->scene;
    const int n = scene->n_modes;
    if (s->model != (uint32_t)sim->model || s->step == UINT64_MAX || !acceptable_report(s)
        || !acceptable_percussions(s))
        return 0;
    if (!finite(s->q_beam, BS_MAX_MODES) || !finite(s->u_beam, BS_MAX_MODES) || !zero_beyond(s->q_beam, n, BS_MAX_MODES)
        || !zero_beyond(s->u_beam, n, BS_MAX_MODES)
        || !bs_state_acceptable(sim, s->q_beam, s->u_beam, s->slider, s->slider_velocity))
        return 0;
    if (!finite(&s->x_c_low, 1) || !(bs_fabs(s->x_c_low) <= BS_REAL_EPS * bs_fabs(s->slider[0])))
        return 0;
    if (!finite(&s->x_pcs, 1) || !(s->x_pcs >= BS_R(0.0) && s->x_pcs <= scene->length) || !finite(&s->base_accel, 1)
        || !finite(s->excitation, 2) || !finite(&s->step_accel, 1)
        || !bs_excitation_acceptable(sim, s->excitation[0], s->excitation[1], s->phase_step_half, s->step_accel)
        || !bs_contact_laws_acceptable(s->laws[0], s->laws[1]))
        return 0;
#if BS_WITH_PIEZO
    return acceptable_transducer(scene, s->piezo);
#else
    return 1;
#endif
}

bs_status bs_sim_restore(bs_sim *sim, const void *buffer, size_t size)
{
    const bs_status status = bs_sim_status(sim);
    const size_t body = BS_CHECKPOINT_SIZE - sizeof(uint32_t);
    uint32_t words[6], checksum;
    saved_state s;
    cursor c;

    if (status != BS_OK)
        return status;
    if (!buffer)
        return BS_E_NULL;
    if (size < sizeof words)
        return BS_E_CHECKPOINT_SIZE;
    c.out = 0;
    c.in = (const unsigned char *)buffer;
    c.at = 0;
    header(&c, words);
    if (words[0] != CHECKPOINT_MAGIC)
        return BS_E_CHECKPOINT_DAMAGED; /* not a checkpoint, or another byte order */
    if (words[1] != CHECKPOINT_FORMAT || words[2] != BS_BUILD_TAG || words[3] != BS_VERSION_NUMBER)
        return BS_E_CHECKPOINT_BUILD;
    if (words[5] != (uint32_t)BS_CHECKPOINT_SIZE || size < BS_CHECKPOINT_SIZE)
        return BS_E_CHECKPOINT_SIZE;
    c.at = body;
    u32(&c, &checksum);
    if (fnv(FNV_OFFSET, buffer, body) != checksum)
        return BS_E_CHECKPOINT_DAMAGED;
    if (words[4] != bs_scene_hash(sim->scene))
        return BS_E_CHECKPOINT_SCENE;
    c.at = sizeof words;
    state(&c, &s);
    if (!acceptable(sim, &s))
        return BS_E_CHECKPOINT_SCENE;
    load_state(sim, &s);
    return BS_OK;
}
