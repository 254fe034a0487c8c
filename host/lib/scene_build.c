/* scene_build.c - modal precomputation and scene assembly, in double.
 *
 * From the parameters of docs/model.md 8, in double (scene_data), then rounded to
 * bs_real (scene_data_round):
 *   omega_k, gamma_k, phi_k(4/7), I_ij          host/lib/modal.c
 *   mode-shape pieces                           host/lib/shape_fit.c
 *   S = sqrt(k_ax / 2L^2) I,  |S| by power iteration (S is positive semidefinite);
 *   S = 0 when the scene leaves stretching out
 *   1/J_C, or 0 when the scene locks the slider's rotation
 *   R = r_h h;  corners r_CP,i = P_i + (0, d): P1 (-B/2, R/2), P2 (-B/2, -R/2),
 *               P3 (B/2, -R/2), P4 (B/2, R/2)
 *   clamp stops x_C in [B/2, L - B/2] (the slot corners reach the clamp faces)
 *   gravity in the beam frame for a beam tilted by theta: g (-sin theta, -cos theta)
 *   phase step f_ex dt / 2 * 2^64, rounded once here
 */
#include "scene_build.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

double scene_fit_tolerance_for(int is_float)
{
    /* a few ulps of the working precision; double: far below every other error */
    return is_float ? 1e-7 : 1e-9;
}

double scene_fit_tolerance(void)
{
    return scene_fit_tolerance_for(BS_REAL_FLOAT);
}

static double largest_eigenvalue(const double s[BS_MAX_MODES][BS_MAX_MODES], int n)
{
    double v[BS_MAX_MODES];
    double value = 0.0;
    int i;
    int j;
    int iteration;

    for (i = 0; i < n; ++i)
        v[i] = 1.0 + 0.01 * i; /* not orthogonal to the dominant eigenvector */
    for (iteration = 0; iteration < 2000; ++iteration) {
        double next[BS_MAX_MODES];
        double norm = 0.0;
        for (i = 0; i < n; ++i) {
            next[i] = 0.0;
            for (j = 0; j < n; ++j)
                next[i] += s[i][j] * v[j];
            norm += next[i] * next[i];
        }
        norm = sqrt(norm);
        if (norm == 0.0)
            return 0.0;
        for (i = 0; i < n; ++i)
            v[i] = next[i] / norm;
        if (fabs(norm - value) <= 1e-15 * norm)
            return norm;
        value = norm;
    }
    return value;
}

static void compute_modes(const scene_params *p, const modal_set *modes, scene_data *d, double *stretch_norm)
{
    const double stretch_scale = p->stretching ? sqrt(modes->k_axial_total / (2.0 * p->beam.length * p->beam.length)) : 0.0;
    int i;
    int j;

    d->n_modes = modes->n;
    for (i = 0; i < modes->n; ++i) {
        double slope;
        d->omega_sq[i] = modes->omega[i] * modes->omega[i];
        d->damping[i] = 2.0 * p->damping_ratio * modes->omega[i];
        d->gamma[i] = modes->gamma[i];
        modal_shape(modes, i, 4.0 / 7.0, &d->phi_sensor[i], &slope);
        for (j = 0; j < modes->n; ++j)
            d->stretch[i][j] = stretch_scale * modes->slope_gram[i][j];
    }
    /* a hair above the true value: the stability check needs an upper bound */
    *stretch_norm = largest_eigenvalue(d->stretch, modes->n) * (1.0 + 1e-6);
}

static void compute_slider(const scene_params *p, scene_data *d)
{
    const double pi = 3.14159265358979323846;
    const double half_width = 0.5 * p->slot_width;
    const double half_slot = 0.5 * p->play_ratio * p->beam.thickness;
    const double tilt = p->tilt * pi / 180.0;
    const double corner[BS_CORNERS][2] = {
        { -half_width, half_slot }, { -half_width, -half_slot },
        { half_width, -half_slot }, { half_width, half_slot } };
    int i;

    d->length = p->beam.length;
    d->half_thickness = 0.5 * p->beam.thickness;
    for (i = 0; i < BS_CORNERS; ++i) {
        d->corner[i][0] = corner[i][0];
        d->corner[i][1] = corner[i][1] + p->com_offset;
    }
    d->com_offset = p->com_offset;
    d->stop_min = half_width;
    d->stop_max = p->beam.length - half_width;
    d->mass_inv = 1.0 / p->slider_mass;
    d->inertia_inv = p->rotation ? 1.0 / p->slider_inertia : 0.0; /* 0: locked */
    d->gravity[0] = -p->gravity * sin(tilt);
    d->gravity[1] = -p->gravity * cos(tilt);
    d->mu = p->mu;
    d->e_n = p->e_n;
}

static void compute_numerics(const scene_params *p, scene_data *d)
{
    const double omega = 2.0 * 3.14159265358979323846 * p->frequency;
    int k;
    d->base_accel = p->acceleration;
    d->base_velocity = p->acceleration / omega;
    d->base_displacement = p->acceleration / (omega * omega);
    d->phase_step_half = (uint64_t)llround(ldexp(0.5 * p->frequency * p->dt, 64));
    d->dt = p->dt;
    d->implicit = p->implicit;
    d->theta = p->implicit ? p->theta : 0.5;
    for (k = 0; k < d->n_modes; ++k) /* 1 / (1 + theta dt 2 D omega + theta^2 dt^2 omega^2) */
        d->mode_gain[k] = p->implicit ? 1.0 / (1.0 + d->theta * p->dt * d->damping[k]
                                               + d->theta * d->theta * p->dt * p->dt * d->omega_sq[k])
                                      : 1.0;
}

void scene_data_set_shapes(scene_data *data, const shape_fit *fit)
{
    data->shape_pieces = fit->pieces;
    data->shape_scale = fit->pieces / data->length;
    memcpy(data->shape_coef, fit->coef, sizeof data->shape_coef);
}

/* Every element of every field, whole arrays (the unused parts are zero). */
#define ROUND_REAL(name)                                                                          \
    for (i = 0; i < sizeof data->name / sizeof(double); ++i)                                        \
        ((bs_real *)&scene->name)[i] = (bs_real)((const double *)&data->name)[i];
#define ROUND_INT(name) scene->name = data->name;
#define ROUND_U64(name) scene->name = data->name;
#define ROUND_FIELD(kind, name, dim1, dim2, dim3, rule, unit, meaning) ROUND_##kind(name)

void scene_data_round(const scene_data *data, bs_scene *scene)
{
    size_t i;
    BS_SCENE_FIELDS(ROUND_FIELD)
}

/* Cross-field checks that need derived quantities. */
static int check_derived(const scene_file *file, const scene_model *model, char *err, size_t size)
{
    const scene_params *p = &file->params;
    const double omega_max = model->modes.omega[model->modes.n - 1];
    char where[SCENE_PATH + 16];
    char where2[SCENE_PATH + 16];

    if (!(p->slot_width < p->beam.length)) {
        snprintf(err, size, "%s: [slider] slot_width = %g m must be below [beam] length = %g m (%s)",
                 scene_where(file, "slider", "slot_width", where, sizeof where), p->slot_width,
                 p->beam.length, scene_where(file, "beam", "length", where2, sizeof where2));
        return -1;
    }
    if (!p->implicit && !(omega_max * p->dt < 2.0)) {
        snprintf(err, size,
                 "%s: [numerics] dt = %g s: omega_max dt = %.4g, above the explicit limit 2 "
                 "(mode %d, %.1f Hz); allowed: dt < %.4g s, or [numerics] integrator = implicit",
                 scene_where(file, "numerics", "dt", where, sizeof where), p->dt, omega_max * p->dt,
                 model->modes.n, omega_max / (2.0 * 3.14159265358979323846), 2.0 / omega_max);
        return -1;
    }
    if (!(p->frequency * p->dt < 0.5)) {
        snprintf(err, size, "%s: [numerics] dt = %g s: fewer than two steps per excitation period "
                 "(f_ex = %g Hz); allowed: dt < %g s",
                 scene_where(file, "numerics", "dt", where, sizeof where), p->dt, p->frequency,
                 0.5 / p->frequency);
        return -1;
    }
    /* steps are counted exactly in a double: t = n dt */
    if (!(p->t_end / p->dt <= 9007199254740992.0)) {
        snprintf(err, size, "%s: [run] t_end = %g s is more than 2^53 steps of dt = %g s",
                 scene_where(file, "run", "t_end", where, sizeof where), p->t_end, p->dt);
        return -1;
    }
    return 0;
}

/* The start position, checked as the core checks it: in bs_real, against the
 * rounded stops (in double the edge of the range can come out the other way). */
static int check_start(const scene_file *file, const bs_scene *scene, char *err, size_t size)
{
    const scene_params *p = &file->params;
    const bs_real x0 = (bs_real)p->s0 * scene->length;
    char where[SCENE_PATH + 16];

    if (p->model == BS_MODEL_FREE && !(x0 >= scene->stop_min && x0 <= scene->stop_max)) {
        snprintf(err, size, "%s: [run] s0 = %.17g: the slider would start inside a clamp; "
                 "allowed: [%.6g, %.6g] (slot corners between the clamps)",
                 scene_where(file, "run", "s0", where, sizeof where), p->s0,
                 (double)(scene->stop_min / scene->length), (double)(scene->stop_max / scene->length));
        return -1;
    }
    return 0;
}

/* The INI fields a core scene field is computed from, to point at them when
 * the core refuses a value the host's own checks let through (a product that
 * overflows bs_real, say). */
static const struct {
    const char *core_field;
    const char *inputs;
} origins[] = {
    { "length", "[beam] length" },
    { "stop_min/stop_max", "[beam] length, [slider] slot_width" },
    { "half_thickness", "[beam] thickness" },
    { "corner", "[beam] thickness, [slider] slot_width, play_ratio, com_offset" },
    { "com_offset", "[slider] com_offset" },
    { "com_offset/base_displacement", "[slider] com_offset, [excitation] acceleration, frequency" },
    { "base_accel", "[excitation] acceleration" },
    { "base_velocity", "[excitation] acceleration, frequency" },
    { "base_displacement", "[excitation] acceleration, frequency" },
    { "phase_step_half", "[excitation] frequency, [numerics] dt" },
    { "dt", "[numerics] dt" },
    { "mass_inv", "[slider] mass" },
    { "inertia_inv", "[slider] mass, inertia, com_offset" },
    { "gravity", "[environment] gravity, tilt" },
    { "mu", "[contact] friction" },
    { "theta", "[numerics] theta" },
    { NULL, "[beam] and [clamps] (the modal data)" },
};

static const char *core_field_inputs(const char *field)
{
    int i;
    for (i = 0; origins[i].core_field && strcmp(origins[i].core_field, field); ++i)
        ;
    return origins[i].inputs;
}

int scene_build(const scene_file *file, bs_scene *scene, scene_model *model, char *err, size_t size)
{
    const scene_params *p = &file->params;
    const char *field = "";
    bs_status status;

    memset(scene, 0, sizeof *scene);
    model->kappa = modal_kappa(&p->beam);
    model->width = modal_width(&p->beam);
    if (modal_compute(&p->beam, p->modes, &model->modes) != 0) {
        snprintf(err, size, "%s: modal analysis failed (no root of the frequency equation found)",
                 file->files[0]);
        return -1;
    }
    if (check_derived(file, model, err, size) != 0)
        return -1;
    if (shape_fit_modes(&model->modes, scene_fit_tolerance(), &model->fit) != 0) {
        snprintf(err, size, "%s: %d modes need more than %d shape pieces for a fit error of %g "
                 "(reached %.3g); lower [numerics] modes", file->files[0], p->modes,
                 BS_SHAPE_MAX_PIECES, scene_fit_tolerance(), model->fit.error_slope);
        return -1;
    }
    memset(&model->data, 0, sizeof model->data);
    compute_modes(p, &model->modes, &model->data, &model->stretch_norm);
    compute_slider(p, &model->data);
    compute_numerics(p, &model->data);
    scene_data_set_shapes(&model->data, &model->fit);
    scene_data_round(&model->data, scene);
    status = bs_scene_check(scene, &field);
    if (status != BS_OK) {
        snprintf(err, size, "%s: the core refuses the scene: %s (field %s, from %s): the values are "
                 "too extreme for %s", file->files[0], bs_status_text(status), field,
                 core_field_inputs(field), BS_REAL_FLOAT ? "float" : "double");
        return -1;
    }
    return check_start(file, scene, err, size);
}

bs_solver_options scene_solver(const scene_params *params)
{
    bs_solver_options options;
    options.max_sweeps = params->solver_max_sweeps;
    options.tol_rel = (bs_real)params->solver_tol_rel;
    options.tol_abs = (bs_real)params->solver_tol_abs;
    options.measure_residual = params->solver_residual;
    return options;
}

int scene_read(const char *path, scene_file *file, bs_scene *scene, scene_model *model, char *err,
               size_t size)
{
    if (scene_load(path, file, err, size) != 0)
        return -1;
    return scene_build(file, scene, model, err, size);
}
