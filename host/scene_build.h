/* scene_build.h - from physical parameters to the core's bs_scene. */
#ifndef SCENE_BUILD_H
#define SCENE_BUILD_H

#include <stddef.h>
#include "beamslider.h"
#include "modal.h"
#include "scene_ini.h"
#include "shape_fit.h"

/* What the host derived on the way (kept for reports and tests). */
typedef struct scene_model {
    modal_set modes;
    shape_fit fit;
    double kappa;     /* k_r L / EI */
    double width;     /* b [m] */
} scene_model;

/* Relative error the mode-shape fit must reach in this precision. */
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
