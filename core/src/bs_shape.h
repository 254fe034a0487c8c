/* bs_shape.h - mode shapes phi_k(x) and their slopes from the scene's
 * piecewise polynomials. */
#ifndef BS_SHAPE_H
#define BS_SHAPE_H

#include "bs_sim_layout.h"

/* phi[k] = phi_k(x) [1/sqrt(kg)] and slope[k] = d phi_k / dx [1/(m sqrt(kg))]
 * for k < n_modes. Outside [0, L] the beam is inside a clamp, which moves
 * with the base: both are 0 there (docs/model.md 9.6: never extrapolated). */
void bs_shape_eval(const bs_scene *scene, bs_real x, bs_real *phi, bs_real *slope);

/* bs_shape_eval and the beam there: w = sum_k phi_k q_k [m], w_slope = w'. */
void bs_shape_deflection(const bs_scene *scene, bs_real x, const bs_real *q, bs_real *phi,
                         bs_real *slope, bs_real *w, bs_real *w_slope);

/* Fills bound for the scene's shapes, so that for x1, x2 in [0, L] less than
 * a piece apart the values bs_shape_eval returns obey
 *   |phi_k(x2) - phi_k(x1)| <= slope[k] |x2 - x1| + jump[k],   |phi_k'| <= slope[k]. */
void bs_shape_bounds(const bs_scene *scene, bs_shape_bound *bound);

#endif
