/* bs_beam.h - smooth modal forces of the beam. */
#ifndef BS_BEAM_H
#define BS_BEAM_H

#include "bs_scene.h"

/* force[k] = h_k of docs/model.md 5 per unit modal mass for base acceleration
 * base_accel: the cubic term at q, the linear stiffness at q_stiff (q itself
 * for the explicit step; docs/design.md 4), damping at u. Returns an upper
 * bound [1/s^2] of the largest eigenvalue of the explicitly integrated
 * stiffness: dN/dq, plus diag(omega_k^2) when linear_explicit (stretch_rows:
 * bs_beam_stretch_rows). */
bs_real bs_beam_force(const bs_scene *scene, const bs_real *stretch_rows, const bs_real *q, const bs_real *q_stiff,
                      const bs_real *u, bs_real base_accel, int linear_explicit, bs_real *force);

/* rows[i] = sum_j |S_ij| (0 past the scene's modes), the constant part of the
 * stability bound above; once per run. */
void bs_beam_stretch_rows(const bs_scene *scene, bs_real *rows);

#endif
