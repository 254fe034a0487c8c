/* ref_dynamics.h - smooth forces of the reference model (docs/model.md 3, 5). */
#ifndef REF_DYNAMICS_H
#define REF_DYNAMICS_H

#include "ref_scene.h"

/* N_n(q_b) = k_ax/(2 L^2) sum_i sum_j sum_k I_ij I_kn q_i q_j q_k, n = 1..N
 * (the literal triple sum) [sqrt(kg) m/s^2]; zero when stretching is off. */
void ref_dynamics_stretching(const ref_scene *scene, const double *q_b, double *n_out);

/* h(t, q, u) = (-gamma ddw0 - omega^2 q_b - 2 D omega u_b - N(q_b); m g_x; m g_z; 0). */
void ref_dynamics_force(const ref_scene *scene, const ref_excitation *ex, const double *q, const double *u,
                        double *h);

#endif
