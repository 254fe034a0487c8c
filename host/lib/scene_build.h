/* scene_build.h - from physical parameters to the core's bs_scene. */
#ifndef SCENE_BUILD_H
#define SCENE_BUILD_H

#include <stddef.h>
#include "beamslider.h"
#include "modal.h"
#include "scene_ini.h"
#include "shape_fit.h"

/* A bs_scene's values in double, before they are rounded to bs_real (the
 * mode-shape table lives in a shape_fit). */
typedef struct scene_data {
    int n_modes;
    double omega_sq[BS_MAX_MODES], damping[BS_MAX_MODES], gamma[BS_MAX_MODES];
    double stretch[BS_MAX_MODES][BS_MAX_MODES], stretch_norm, phi_sensor[BS_MAX_MODES];
    double length, half_thickness, corner[BS_CORNERS][2], com_offset, stop_min, stop_max;
    double mass_inv, inertia_inv, gravity[2], mu, e_n;
    double base_accel, base_velocity, base_displacement;
    uint64_t phase_step_half;
    double dt;
    int implicit;
    double theta, mode_gain[BS_MAX_MODES];
    int pgs_max_sweeps;
    double pgs_tol_rel, pgs_tol_abs;
} scene_data;

/* What the host derived on the way (kept for reports, tests and `gen`). */
typedef struct scene_model {
    modal_set modes;
    shape_fit fit;    /* at scene_fit_tolerance() */
    scene_data data;
    double kappa;     /* k_r L / EI */
    double width;     /* b [m] */
} scene_model;

/* Relative error the mode-shape fit must reach in float (is_float = 1) or
 * double; scene_fit_tolerance() is the one of this build's bs_real. */
double scene_fit_tolerance_for(int is_float);
double scene_fit_tolerance(void);

/* Fills scene (and model) from file->params: modal analysis, shape fit,
 * geometry, excitation. Checks what single fields cannot: the explicit limit
 * omega_max dt < 2, f_ex dt < 1/2, slot narrower than the beam, s0 within the
 * clamp stops (free model). Returns 0, or -1 with a message naming the
 * field(s), where they were set and the allowed range. */
int scene_build(const scene_file *file, bs_scene *scene, scene_model *model, char *err, size_t size);

/* Convenience: scene_load then scene_build. */
int scene_read(const char *path, scene_file *file, bs_scene *scene, scene_model *model, char *err,
               size_t size);

#endif
