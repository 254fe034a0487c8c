/* ref_scene.c - reference scene constants (docs/model.md 2-6).
 *
 *   M = diag(1, ..., 1, m, m, J_C) (mass-normalised modes), dense here and
 *   inverted by elimination; a locked slider rotation is a coordinate with no
 *   mobility (row/column beta of M^-1 = 0).
 *   Corners relative to G: P1 (-B/2, +R/2), P2 (-B/2, -R/2), P3 (+B/2, -R/2),
 *   P4 (+B/2, +R/2); r_GC = (0, -d) so r_CP,i = P_i + (0, d); zeta = +1 for P1, P4.
 *   Gravity in the beam frame: g (-sin tilt, -cos tilt).
 *   Excitation: w0 = (a/Omega^2) cos Omega t, dw0 = -(a/Omega) sin Omega t,
 *   ddw0 = -a cos Omega t, Omega t = 2 pi frac(f_ex t), t = j dt_sub / 2 in long double. */
#include "ref_scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "ref_linalg.h"

int ref_scene_init(ref_scene *scene, const scene_params *p, int substeps, char *err, size_t err_size)
{
    ref_beam beam;
    long double tilt;
    long double a[REF_MAX_Q * REF_MAX_Q], col[REF_MAX_Q];
    int free_index[REF_MAX_Q];
    int n_free = 0, i, j, k;

    memset(scene, 0, sizeof *scene);
    if (p->modes < 0 || p->modes > REF_MAX_MODES) {
        snprintf(err, err_size, "modes = %d: the reference supports 0..%d", p->modes, REF_MAX_MODES);
        return -1;
    }
    if (p->implicit) {
        snprintf(err, err_size, "integrator = implicit: the reference implements docs/model.md 5's explicit midpoint step only");
        return -1;
    }
    if (substeps < 1) {
        snprintf(err, err_size, "substeps = %d: must be >= 1", substeps);
        return -1;
    }
    beam.length = p->beam.length;
    beam.thickness = p->beam.thickness;
    beam.density = p->beam.density;
    beam.youngs_modulus = p->beam.youngs_modulus;
    beam.mass = p->beam.mass;
    beam.k_rot = p->beam.k_rot;
    beam.k_axial = p->beam.k_axial;
    if (ref_modes_compute(&beam, p->modes, &scene->modes) != 0) {
        snprintf(err, err_size, "the beam's modes could not be computed");
        return -1;
    }
    scene->n_modes = p->modes;
    scene->n_q = p->modes + 3;
    scene->i_x = p->modes;
    scene->i_z = p->modes + 1;
    scene->i_beta = p->modes + 2;
    scene->length = p->beam.length;
    scene->half_thickness = 0.5 * p->beam.thickness;
    scene->damping = p->damping_ratio;
    scene->stretch_factor = p->stretching
        ? (double)(scene->modes.k_ax / (2.0L * (long double)p->beam.length * (long double)p->beam.length))
        : 0.0;
    scene->slider_mass = p->slider_mass;
    scene->slider_inertia = p->slider_inertia;
    scene->rotation = p->rotation;
    scene->slot_width = p->slot_width;
    scene->com_offset = p->com_offset;
    scene->slot_height = p->play_ratio * p->beam.thickness;
    for (i = 0; i < REF_CORNERS; ++i) {
        const double x = i < 2 ? -0.5 * p->slot_width : 0.5 * p->slot_width;
        const double z = (i == 0 || i == 3) ? 0.5 * scene->slot_height : -0.5 * scene->slot_height;
        scene->corner[i][0] = x;
        scene->corner[i][1] = z + p->com_offset;
        scene->zeta[i] = (i == 0 || i == 3) ? 1.0 : -1.0;
    }
    scene->mu = p->mu;
    scene->e_n = p->e_n;
    tilt = (long double)p->tilt * REF_PI / 180.0L;
    scene->gravity[0] = (double)(-(long double)p->gravity * sinl(tilt));
    scene->gravity[1] = (double)(-(long double)p->gravity * cosl(tilt));
    scene->frequency = p->frequency;
    scene->acceleration = p->acceleration;
    scene->omega_ex = (double)(2.0L * REF_PI * (long double)p->frequency);
    scene->dt = p->dt;
    scene->substeps = substeps;
    scene->dt_sub = (double)((long double)p->dt / (long double)substeps);
    scene->model = p->model == 1 ? REF_MODEL_PCS : REF_MODEL_FREE;
    scene->s_pcs = p->s0;
    scene->s0 = p->s0;
    scene->end_stops = scene->model == REF_MODEL_FREE;

    for (i = 0; i < scene->n_q; ++i)
        for (j = 0; j < scene->n_q; ++j)
            scene->mass[i][j] = scene->mass_inv[i][j] = 0.0;
    for (k = 0; k < scene->n_modes; ++k)
        scene->mass[k][k] = 1.0;
    scene->mass[scene->i_x][scene->i_x] = p->slider_mass;
    scene->mass[scene->i_z][scene->i_z] = p->slider_mass;
    scene->mass[scene->i_beta][scene->i_beta] = p->slider_inertia;
    for (i = 0; i < scene->n_q; ++i)
        if (i != scene->i_beta || scene->rotation)
            free_index[n_free++] = i;
    for (j = 0; j < n_free; ++j) {
        for (i = 0; i < n_free; ++i) {
            for (k = 0; k < n_free; ++k)
                a[i * n_free + k] = scene->mass[free_index[i]][free_index[k]];
            col[i] = i == j ? 1.0L : 0.0L;
        }
        if (ref_linalg_solve(n_free, a, col, 1e-300L) != 0) {
            snprintf(err, err_size, "the mass matrix is singular");
            return -1;
        }
        for (i = 0; i < n_free; ++i)
            scene->mass_inv[free_index[i]][free_index[j]] = (double)col[i];
    }
    for (k = 0; k < scene->n_modes; ++k) {
        long double v[3];
        ref_modes_shape(&scene->modes, k, 4.0L / 7.0L, v);
        scene->sensor_phi[k] = (double)v[0];
    }
    return 0;
}

long double ref_scene_time(const ref_scene *scene, uint64_t half_steps)
{
    return (long double)half_steps * ((long double)scene->dt / (long double)scene->substeps) / 2.0L;
}

void ref_scene_excitation(const ref_scene *scene, long double t, ref_excitation *ex)
{
    const long double cycles = t * (long double)scene->frequency;
    const long double phase = 2.0L * REF_PI * (cycles - floorl(cycles));
    const long double omega = 2.0L * REF_PI * (long double)scene->frequency;
    const long double a = scene->acceleration;

    ex->w0 = (double)(a / (omega * omega) * cosl(phase));
    ex->w0_dot = (double)(-a / omega * sinl(phase));
    ex->w0_ddot = (double)(-a * cosl(phase));
}

void ref_scene_beam(const ref_scene *scene, const double *q_b, double x, double *w, double *w_x,
                    double *phi, double *phi_x)
{
    double phi_local[REF_MAX_MODES], phi_xi[REF_MAX_MODES];
    double *ph = phi ? phi : phi_local;
    double value = 0.0, slope = 0.0;
    int k;

    ref_modes_eval(&scene->modes, x / scene->length, ph, phi_xi);
    for (k = 0; k < scene->n_modes; ++k) {
        const double d = phi_xi[k] / scene->length;
        value += ph[k] * q_b[k];
        slope += d * q_b[k];
        if (phi_x)
            phi_x[k] = d;
    }
    *w = value;
    *w_x = slope;
}

double ref_scene_sensor(const ref_scene *scene, const double *q)
{
    double w = 0.0;
    int k;
    for (k = 0; k < scene->n_modes; ++k)
        w += scene->sensor_phi[k] * q[k];
    return w;
}
