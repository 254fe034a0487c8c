/* bs_scene.c - validation of a scene before the core uses it.
 *
 * The host validates physical parameters with file and line (host/lib/scene_ini.c);
 * this is the core's own guard, for scenes that come from anywhere (a
 * generated header, a corrupted flash page, a caller's struct).
 */
#include "beamslider.h"

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

static int check_modes(const bs_scene *s, const char **field)
{
    int i;
    int j;
    int c;

    if (s->n_modes < 0 || s->n_modes > BS_MAX_MODES)
        return fail(field, "n_modes");
    if (s->shape_pieces < 1 || s->shape_pieces > BS_SHAPE_MAX_PIECES)
        return fail(field, "shape_pieces");
    for (i = 0; i < s->n_modes; ++i) {
        if (!is_finite(s->omega_sq[i]) || !(s->omega_sq[i] > BS_R(0.0)))
            return fail(field, "omega_sq");
        if (!is_finite(s->damping[i]) || !(s->damping[i] >= BS_R(0.0)))
            return fail(field, "damping");
        if (!is_finite(s->gamma[i]))
            return fail(field, "gamma");
        if (!is_finite(s->phi_sensor[i]))
            return fail(field, "phi_sensor");
        for (j = 0; j < s->n_modes; ++j)
            if (!is_finite(s->stretch[i][j]) || s->stretch[i][j] != s->stretch[j][i])
                return fail(field, "stretch");
        for (j = 0; j < s->shape_pieces; ++j)
            for (c = 0; c < BS_SHAPE_COEFS; ++c)
                if (!is_finite(s->shape_coef[j][i][c]))
                    return fail(field, "shape_coef");
    }
    return 0;
}

static int check_geometry(const bs_scene *s, const char **field)
{
    int i;

    if (!is_finite(s->length) || !(s->length > BS_R(0.0)))
        return fail(field, "length");
    /* shape_scale must be shape_pieces / length (to rounding) */
    if (!is_finite(s->shape_scale)
        || !(s->shape_scale * s->length >= (bs_real)s->shape_pieces * (BS_R(1.0) - BS_R(1e-6))
             && s->shape_scale * s->length <= (bs_real)s->shape_pieces * (BS_R(1.0) + BS_R(1e-6))))
        return fail(field, "shape_scale");
    if (!is_finite(s->half_thickness) || !(s->half_thickness > BS_R(0.0)))
        return fail(field, "half_thickness");
    for (i = 0; i < BS_CORNERS; ++i)
        if (!is_finite(s->corner[i][0]) || !is_finite(s->corner[i][1]))
            return fail(field, "corner");
    /* the slot (P1 above P2, P4 above P3, left of P3/P4) must hold the beam;
     * R = h (no play) is allowed, to the rounding of the corner coordinates */
    if (!(s->corner[0][1] - s->corner[1][1] >= BS_R(2.0) * s->half_thickness * (BS_R(1.0) - BS_R(16.0) * BS_REAL_EPS))
        || !(s->corner[3][1] - s->corner[2][1] >= BS_R(2.0) * s->half_thickness * (BS_R(1.0) - BS_R(16.0) * BS_REAL_EPS))
        || !(s->corner[0][0] < s->corner[3][0]) || !(s->corner[1][0] < s->corner[2][0]))
        return fail(field, "corner");
    if (!is_finite(s->com_offset))
        return fail(field, "com_offset");
    if (!(s->stop_min >= BS_R(0.0) && s->stop_min < s->stop_max && s->stop_max <= s->length))
        return fail(field, "stop_min/stop_max");
    return 0;
}

static int check_slider_contact(const bs_scene *s, const char **field)
{
    if (!is_finite(s->mass_inv) || !(s->mass_inv > BS_R(0.0)))
        return fail(field, "mass_inv");
    if (!is_finite(s->inertia_inv) || !(s->inertia_inv >= BS_R(0.0)))
        return fail(field, "inertia_inv");
    if (!is_finite(s->gravity[0]) || !is_finite(s->gravity[1]))
        return fail(field, "gravity");
    if (!is_finite(s->mu) || !(s->mu >= BS_R(0.0)))
        return fail(field, "mu");
    if (!(s->e_n >= BS_R(0.0) && s->e_n <= BS_R(1.0)))
        return fail(field, "e_n");
    return 0;
}

static int check_numerics(const bs_scene *s, const char **field)
{
    if (!is_finite(s->base_accel) || !is_finite(s->base_velocity)
        || !is_finite(s->base_displacement))
        return fail(field, "base_accel/base_velocity/base_displacement");
    /* bs_sim_init starts the slider at z_C = base_displacement - com_offset:
     * each finite is not enough, their sum must be too */
    if (!is_finite(s->base_displacement - s->com_offset))
        return fail(field, "com_offset/base_displacement");
    /* at least two steps per excitation period: f_ex dt < 1/2 */
    if (s->phase_step_half == 0 || s->phase_step_half >= ((uint64_t)1 << 62))
        return fail(field, "phase_step_half");
    if (!is_finite(s->dt) || !(s->dt > BS_R(0.0)))
        return fail(field, "dt");
    if (s->implicit != 0 && s->implicit != 1)
        return fail(field, "implicit");
    if (!(s->theta >= BS_R(0.5) && s->theta <= BS_R(1.0)) || (!s->implicit && s->theta != BS_R(0.5)))
        return fail(field, "theta");
    {
        int k;
        for (k = 0; k < s->n_modes; ++k)
            if (!(s->mode_gain[k] > BS_R(0.0) && s->mode_gain[k] <= BS_R(1.0))
                || (!s->implicit && s->mode_gain[k] != BS_R(1.0)))
                return fail(field, "mode_gain");
    }
    if (s->pgs_max_sweeps < 1)
        return fail(field, "pgs_max_sweeps");
    if (!is_finite(s->pgs_tol_rel) || !(s->pgs_tol_rel >= BS_R(0.0)))
        return fail(field, "pgs_tol_rel");
    if (!is_finite(s->pgs_tol_abs) || !(s->pgs_tol_abs >= BS_R(0.0)))
        return fail(field, "pgs_tol_abs");
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

bs_status bs_scene_check(const bs_scene *scene, const char **field)
{
    int i;

    if (!scene)
        return BS_E_NULL;
    if (check_modes(scene, field) || check_geometry(scene, field)
        || check_slider_contact(scene, field) || check_numerics(scene, field)
        || check_compiled_features(scene, field))
        return BS_E_SCENE;
    /* explicit stability limit of the smooth part: omega_max dt < 2 */
    for (i = 0; i < scene->n_modes && !scene->implicit; ++i)
        if (!(scene->omega_sq[i] * scene->dt * scene->dt < BS_R(4.0))) {
            fail(field, "dt");
            return BS_E_UNSTABLE;
        }
    return BS_OK;
}
