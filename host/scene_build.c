/* scene_build.c - modal precomputation and scene assembly, in double.
 *
 * From the parameters of MODEL.md 8:
 *   omega_k, gamma_k, phi_k(4/7), I_ij          host/modal.c
 *   mode-shape pieces                           host/shape_fit.c
 *   S = sqrt(k_ax / 2L^2) I,  |S| by power iteration (S is positive semidefinite)
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

double scene_fit_tolerance(void)
{
    /* a few ulps of the working precision; double: far below every other error */
    return BS_REAL_FLOAT ? 1e-7 : 1e-9;
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

static void fill_modes(const scene_params *p, const scene_model *model, bs_scene *scene)
{
    const modal_set *modes = &model->modes;
    const double stretch_scale = sqrt(modes->k_axial_total / (2.0 * p->beam.length * p->beam.length));
    double stretch[BS_MAX_MODES][BS_MAX_MODES];
    int i;
    int j;
    int c;

    scene->n_modes = modes->n;
    for (i = 0; i < modes->n; ++i) {
        double phi, slope;
        scene->omega_sq[i] = (bs_real)(modes->omega[i] * modes->omega[i]);
        scene->damping[i] = (bs_real)(2.0 * p->damping_ratio * modes->omega[i]);
        scene->gamma[i] = (bs_real)modes->gamma[i];
        modal_shape(modes, i, 4.0 / 7.0, &phi, &slope);
        scene->phi_sensor[i] = (bs_real)phi;
        for (j = 0; j < modes->n; ++j) {
            stretch[i][j] = stretch_scale * modes->slope_gram[i][j];
            scene->stretch[i][j] = (bs_real)stretch[i][j];
        }
    }
    /* a hair above the true value: the stability check needs an upper bound */
    scene->stretch_norm = (bs_real)(largest_eigenvalue(stretch, modes->n) * (1.0 + 1e-6));
    scene->shape_pieces = model->fit.pieces;
    scene->shape_scale = (bs_real)(model->fit.pieces / p->beam.length);
    for (j = 0; j < model->fit.pieces; ++j)
        for (i = 0; i < modes->n; ++i)
            for (c = 0; c < BS_SHAPE_COEFS; ++c)
                scene->shape_coef[j][i][c] = (bs_real)model->fit.coef[j][i][c];
}

static void fill_slider(const scene_params *p, bs_scene *scene)
{
    const double pi = 3.14159265358979323846;
    const double half_width = 0.5 * p->slot_width;
    const double half_slot = 0.5 * p->play_ratio * p->beam.thickness;
    const double tilt = p->tilt * pi / 180.0;
    const double corner[BS_CORNERS][2] = {
        { -half_width, half_slot }, { -half_width, -half_slot },
        { half_width, -half_slot }, { half_width, half_slot } };
    int i;

    scene->length = (bs_real)p->beam.length;
    scene->half_thickness = (bs_real)(0.5 * p->beam.thickness);
    for (i = 0; i < BS_CORNERS; ++i) {
        scene->corner[i][0] = (bs_real)corner[i][0];
        scene->corner[i][1] = (bs_real)(corner[i][1] + p->com_offset);
    }
    scene->com_offset = (bs_real)p->com_offset;
    scene->stop_min = (bs_real)half_width;
    scene->stop_max = (bs_real)(p->beam.length - half_width);
    scene->mass_inv = (bs_real)(1.0 / p->slider_mass);
    scene->inertia_inv = (bs_real)(1.0 / p->slider_inertia);
    scene->gravity[0] = (bs_real)(-p->gravity * sin(tilt));
    scene->gravity[1] = (bs_real)(-p->gravity * cos(tilt));
    scene->mu = (bs_real)p->mu;
    scene->e_n = (bs_real)p->e_n;
}

static void fill_numerics(const scene_params *p, bs_scene *scene)
{
    const double omega = 2.0 * 3.14159265358979323846 * p->frequency;
    scene->base_accel = (bs_real)p->acceleration;
    scene->base_velocity = (bs_real)(p->acceleration / omega);
    scene->base_displacement = (bs_real)(p->acceleration / (omega * omega));
    scene->phase_step_half = (uint64_t)llround(ldexp(0.5 * p->frequency * p->dt, 64));
    scene->dt = (bs_real)p->dt;
    scene->pgs_max_sweeps = p->pgs_max_sweeps;
    scene->pgs_tol_rel = (bs_real)p->pgs_tol_rel;
    scene->pgs_tol_abs = (bs_real)p->pgs_tol_abs;
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
    if (!(omega_max * p->dt < 2.0)) {
        snprintf(err, size,
                 "%s: [numerics] dt = %g s: omega_max dt = %.4g, above the explicit limit 2 "
                 "(mode %d, %.1f Hz); allowed: dt < %.4g s",
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
    if (p->model == BS_MODEL_FREE) {
        const double low = 0.5 * p->slot_width / p->beam.length;
        if (!(p->s0 >= low && p->s0 <= 1.0 - low)) {
            snprintf(err, size, "%s: [run] s0 = %g: the slider would start inside a clamp; "
                     "allowed: [%.6g, %.6g] (slot corners between the clamps)",
                     scene_where(file, "run", "s0", where, sizeof where), p->s0, low, 1.0 - low);
            return -1;
        }
    }
    return 0;
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
    fill_modes(p, model, scene);
    fill_slider(p, scene);
    fill_numerics(p, scene);
    status = bs_scene_check(scene, &field);
    if (status != BS_OK) { /* the host checks above should make this unreachable */
        snprintf(err, size, "%s: core refused the scene: %s (field %s)", file->files[0],
                 bs_status_text(status), field);
        return -1;
    }
    return 0;
}

int scene_read(const char *path, scene_file *file, bs_scene *scene, scene_model *model, char *err,
               size_t size)
{
    if (scene_load(path, file, err, size) != 0)
        return -1;
    return scene_build(file, scene, model, err, size);
}
