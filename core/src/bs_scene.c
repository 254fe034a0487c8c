/* bs_scene.c - validation of a scene before the core uses it.
 *
 * The host validates physical parameters with file and line
 * (host/lib/scene_ini.c); this is the core's own guard, for scenes that come
 * from anywhere (a generated header, a corrupted flash page, a caller's
 * struct). Every field has a rule in bs_scene_fields.h: the generic rules
 * (finite, positive, ...) are applied to every used element of every field
 * from that table; the fields whose validity depends on others (rule CROSS)
 * are checked by hand below. The first failure names its field.
 */
#include "beamslider.h"
#include "bs_beam.h"
#include "bs_piezo.h"
#include "bs_sim_internal.h"

/* NaN and infinity give x - x != 0; no libm needed. */
static int is_finite(bs_real x)
{
    return x - x == BS_R(0.0);
}

static int fail(const char **field, const char *name)
{
    if (field)
        *field = name;
    return 1;
}

enum rule { RULE_FINITE, RULE_POSITIVE, RULE_NONNEGATIVE, RULE_UNIT };

static int obeys(bs_real x, enum rule rule)
{
    switch (rule) {
    case RULE_POSITIVE: return is_finite(x) && x > BS_R(0.0);
    case RULE_NONNEGATIVE: return is_finite(x) && x >= BS_R(0.0);
    case RULE_UNIT: return x >= BS_R(0.0) && x <= BS_R(1.0);
    default: return is_finite(x);
    }
}

/* Every used element [i][j][k] (i < used1, ...) of an array declared with
 * sizes [.][size2][size3], seen as flat values. */
static int all_obey(const bs_real *values, int used1, int size2, int used2, int size3, int used3,
                    enum rule rule)
{
    int i, j, k;
    for (i = 0; i < used1; ++i)
        for (j = 0; j < used2; ++j)
            for (k = 0; k < used3; ++k)
                if (!obeys(values[(i * size2 + j) * size3 + k], rule))
                    return 0;
    return 1;
}

/* The generic rules, from the field table (REAL fields; CROSS is by hand). */
#define RULE_OF_FINITE RULE_FINITE
#define RULE_OF_POSITIVE RULE_POSITIVE
#define RULE_OF_NONNEGATIVE RULE_NONNEGATIVE
#define RULE_OF_UNIT RULE_UNIT
#define RULE_OF_CROSS RULE_FINITE /* not used: CHECKED_CROSS is 0 */
#define CHECKED_FINITE 1
#define CHECKED_POSITIVE 1
#define CHECKED_NONNEGATIVE 1
#define CHECKED_UNIT 1
#define CHECKED_CROSS 0
#define CHECK_REAL(name, d1, d2, d3, rule)                                                         \
    if (CHECKED_##rule                                                                             \
        && !all_obey((const bs_real *)&s->name, BS_USED_##d1(s), BS_SIZE_##d2, BS_USED_##d2(s),    \
                     BS_SIZE_##d3, BS_USED_##d3(s), RULE_OF_##rule))                                \
        return fail(field, #name);
#define CHECK_INT(name, d1, d2, d3, rule)
#define CHECK_U64(name, d1, d2, d3, rule)
#define CHECK_FIELD(kind, name, d1, d2, d3, rule, unit, meaning) CHECK_##kind(name, d1, d2, d3, rule)

static int check_fields(const bs_scene *s, const char **field)
{
    BS_SCENE_FIELDS(CHECK_FIELD)
    return 0;
}

/* The counts first: every other check loops over them. */
static int check_counts(const bs_scene *s, const char **field)
{
    if (s->n_modes < 0 || s->n_modes > BS_MAX_MODES)
        return fail(field, "n_modes");
    if (s->shape_pieces < 1 || s->shape_pieces > BS_SHAPE_MAX_PIECES)
        return fail(field, "shape_pieces");
    return 0;
}

static int check_cross(const bs_scene *s, const char **field)
{
    int i, j;

    for (i = 0; i < s->n_modes; ++i)
        for (j = 0; j < s->n_modes; ++j)
            if (!is_finite(s->stretch[i][j]) || s->stretch[i][j] != s->stretch[j][i])
                return fail(field, "stretch");
#ifdef BS_SCENE_STRETCH_USED
    /* a core compiled against a scene skips the zeros of its S and gamma
     * (core/src/bs_beam.h): another scene must have them there too */
    for (i = 0; i < s->n_modes && i < BS_SCENE_MODES; ++i) {
        if (s->gamma[i] != BS_R(0.0) && !BS_GAMMA_USED(i))
            return fail(field, "gamma");
        for (j = 0; j < s->n_modes && j < BS_SCENE_MODES; ++j)
            if (s->stretch[i][j] != BS_R(0.0) && !BS_STRETCH_USED(i, j))
                return fail(field, "stretch");
    }
#endif
    /* shape_scale must be shape_pieces / length (to rounding) */
    if (!is_finite(s->shape_scale)
        || !(s->shape_scale * s->length >= (bs_real)s->shape_pieces * (BS_R(1.0) - BS_R(1e-6))
             && s->shape_scale * s->length <= (bs_real)s->shape_pieces * (BS_R(1.0) + BS_R(1e-6))))
        return fail(field, "shape_scale");
    for (i = 0; i < BS_CORNERS; ++i)
        if (!is_finite(s->corner[i][0]) || !is_finite(s->corner[i][1]))
            return fail(field, "corner");
    /* the slot (P1 above P2, P4 above P3, left of P3/P4) must hold the beam;
     * R = h (no play) is allowed, to the rounding of the corner coordinates */
    if (!(s->corner[0][1] - s->corner[1][1] >= BS_R(2.0) * s->half_thickness * (BS_R(1.0) - BS_R(16.0) * BS_REAL_EPS))
        || !(s->corner[3][1] - s->corner[2][1] >= BS_R(2.0) * s->half_thickness * (BS_R(1.0) - BS_R(16.0) * BS_REAL_EPS))
        || !(s->corner[0][0] < s->corner[3][0]) || !(s->corner[1][0] < s->corner[2][0]))
        return fail(field, "corner");
    if (!(s->stop_min >= BS_R(0.0) && s->stop_min < s->stop_max && s->stop_max <= s->length))
        return fail(field, "stop_min/stop_max");
    /* at least two steps per excitation period: f_ex dt < 1/2; and the phase
     * step is f_ex dt / 2 (to the rounding of frequency and dt) */
    if (s->phase_step_half == 0 || s->phase_step_half >= ((uint64_t)1 << 62))
        return fail(field, "phase_step_half");
    {
        /* in 2^-64 turns: the step is an integer, rounded from f_ex dt / 2 */
        const double want = 0.5 * (double)s->frequency * (double)s->dt * 18446744073709551616.0;
        const double slack = 1.0 + 8.0 * (double)BS_REAL_EPS * want;
        if (!((double)s->phase_step_half - want <= slack && want - (double)s->phase_step_half <= slack))
            return fail(field, "frequency/phase_step_half (derived together with dt: for another frequency "
                               "call bs_sim_set_excitation on the sim, for another dt build the scene again)");
    }
    if (s->implicit != 0 && s->implicit != 1)
        return fail(field, "implicit");
    if (!(s->theta >= BS_R(0.5) && s->theta <= BS_R(1.0)) || (!s->implicit && s->theta != BS_R(0.5)))
        return fail(field, "theta");
    for (i = 0; i < s->n_modes; ++i)
        if (!(s->mode_gain[i] > BS_R(0.0) && s->mode_gain[i] <= BS_R(1.0))
            || (!s->implicit && s->mode_gain[i] != BS_R(1.0)))
            return fail(field, "mode_gain");
    if (s->load != BS_LOAD_NONE && s->load != BS_LOAD_RESISTOR && s->load != BS_LOAD_RECTIFIER)
        return fail(field, "load");
    if (s->load != BS_LOAD_NONE && !(s->piezo_capacitance_inv > BS_R(0.0) && is_finite(s->piezo_capacitance_inv)))
        return fail(field, "piezo_capacitance_inv");
    if (s->load == BS_LOAD_RECTIFIER && !(s->storage_capacitance_inv > BS_R(0.0)))
        return fail(field, "storage_capacitance_inv");
    return 0;
}

/* A build compiled for one scene must not be handed a scene that needs
 * what it left out. */
static int check_compiled_features(const bs_scene *s, const char **field)
{
#ifdef BS_SCENE_MODES
    if (s->n_modes != BS_SCENE_MODES)
        return fail(field, "n_modes");
#endif
    if (!BS_WITH_FRICTION && s->mu != BS_R(0.0))
        return fail(field, "mu");
    if (!BS_WITH_RESTITUTION && s->e_n != BS_R(0.0))
        return fail(field, "e_n");
    if (!BS_WITH_GRAVITY && (s->gravity[0] != BS_R(0.0) || s->gravity[1] != BS_R(0.0)))
        return fail(field, "gravity");
    if (!BS_WITH_ROTATION && s->inertia_inv != BS_R(0.0))
        return fail(field, "inertia_inv");
    if (!BS_WITH_PIEZO && s->load != BS_LOAD_NONE)
        return fail(field, "load");
    if (!BS_WITH_STRETCHING) {
        int i, j;
        for (i = 0; i < s->n_modes; ++i)
            for (j = 0; j < s->n_modes; ++j)
                if (s->stretch[i][j] != BS_R(0.0))
                    return fail(field, "stretch");
    }
    if (!BS_WITH_IMPLICIT && s->implicit)
        return fail(field, "implicit");
    (void)s;
    (void)field;
    return 0;
}

bs_status bs_scene_check_(uint32_t tag, size_t scene_size, const bs_scene *scene, const char **field)
{
    bs_real piezo = BS_R(0.0);
    int i;

    if (!scene)
        return BS_E_NULL;
    if (bs_build_matches(tag, sizeof(bs_sim), scene_size) != BS_OK)
        return BS_E_BUILD;
    if (check_counts(scene, field) || check_fields(scene, field) || check_cross(scene, field)
        || check_compiled_features(scene, field))
        return BS_E_SCENE;
#if BS_WITH_PIEZO
    piezo = bs_piezo_stiffness(scene);
#endif
    /* explicit stability limit of the smooth part: omega_max dt < 2, the
     * open patch's stiffness added to it as the step does (docs/design.md 10) */
    for (i = 0; i < scene->n_modes; ++i) {
        const bs_real beam = scene->implicit ? BS_R(0.0) : scene->omega_sq[i];
        if (!((beam + piezo) * scene->dt * scene->dt < BS_R(4.0))) {
            fail(field, piezo > BS_R(0.0) ? "piezo_theta" : "dt");
            return BS_E_UNSTABLE;
        }
    }
    return BS_OK;
}
