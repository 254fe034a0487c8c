/* ref_dynamics.h - smooth forces of the reference model (docs/model.md 3, 5, 10). */
#ifndef REF_DYNAMICS_H
#define REF_DYNAMICS_H

#include "ref_scene.h"

/* N_n(q_b) = k_ax/(2 L^2) sum_i sum_j sum_k I_ij I_kn q_i q_j q_k, n = 1..N
 * (the literal triple sum) [sqrt(kg) m/s^2]; zero when stretching is off. */
void ref_dynamics_stretching(const ref_scene *scene, const double *q_b, double *n_out);

/* Stretching energy k_ax/2 dL^2, dL = 1/(2L) q_b^T I q_b [J]. */
double ref_dynamics_stretching_energy(const ref_scene *scene, const double *q_b);

/* h(q, u) in the base frame for base acceleration base_accel [m/s^2]:
 * (-gamma ddw0 - omega^2 q_b - 2 D omega u_b - N(q_b); m g_x; m g_z - m ddw0; 0).
 * The patch's force -theta v is the step's (ref_step.c), not part of h. */
void ref_dynamics_force(const ref_scene *scene, double base_accel, const double *q, const double *u, double *h);

#endif
