/* bs_shape.h - mode shapes phi_k(x) and their slopes from the scene's
 * piecewise polynomials. */
#ifndef BS_SHAPE_H
#define BS_SHAPE_H

#include "bs_scene.h"

/* phi[k] = phi_k(x) [1/sqrt(kg)] and slope[k] = d phi_k / dx [1/(m sqrt(kg))]
 * for k < n_modes. Outside [0, L] the beam is inside a clamp, which moves
 * with the base: both are 0 there (MODEL.md 9.6: never extrapolated). */
void bs_shape_eval(const bs_scene *scene, bs_real x, bs_real *phi, bs_real *slope);

#endif
