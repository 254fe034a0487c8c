/* bs_beam.h - smooth modal forces of the beam. */
#ifndef BS_BEAM_H
#define BS_BEAM_H

#include "bs_scene.h"

/* force[k] = h_k of MODEL.md 5 per unit modal mass at (q, u) for base
 * acceleration base_accel. Returns the stiffness added by the cubic term,
 * an upper bound of the largest eigenvalue of dN/dq [1/s^2], for the
 * explicit stability check. */
bs_real bs_beam_force(const bs_scene *scene, const bs_real *q, const bs_real *u,
                      bs_real base_accel, bs_real *force);

#endif
