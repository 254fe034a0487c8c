/* scene_build.h - from physical parameters to the core's bs_scene. */
#ifndef SCENE_BUILD_H
#define SCENE_BUILD_H

#include <stddef.h>
#include "beamslider.h"
#include "modal.h"
#include "scene_ini.h"
#include "shape_fit.h"

/* A bs_scene's values in double, before they are rounded to bs_real: the
 * same fields (core/include/bs_scene_fields.h), in double. */
#define SCENE_DATA_TYPE_REAL double
#define SCENE_DATA_TYPE_INT int
#define SCENE_DATA_TYPE_U64 uint64_t
#define SCENE_DATA_MEMBER(kind, name, dim1, dim2, dim3, rule, unit, meaning) \
    SCENE_DATA_TYPE_##kind name BS_DIM_##dim1 BS_DIM_##dim2 BS_DIM_##dim3;
typedef struct scene_data {
    BS_SCENE_FIELDS(SCENE_DATA_MEMBER)
} scene_data;

/* What the host derived on the way (kept for reports, tests and `gen`). */
typedef struct scene_model {
    modal_set modes;
    shape_fit fit;    /* at scene_fit_tolerance() */
    scene_data data;  /* its shape fields from fit */
    double stretch_norm; /* an upper bound of |S| (0: no stretching) */
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

/* Puts fit's mode-shape table into data (shape_pieces, shape_scale, shape_coef). */
void scene_data_set_shapes(scene_data *data, const shape_fit *fit);

/* Rounds data into the core's bs_real scene. */
void scene_data_round(const scene_data *data, bs_scene *scene);

/* The contact-solve settings of the scene file's [solver] section. */
bs_solver_options scene_solver(const scene_params *params);

/* Convenience: scene_load then scene_build. */
int scene_read(const char *path, scene_file *file, bs_scene *scene, scene_model *model, char *err,
               size_t size);

#endif
