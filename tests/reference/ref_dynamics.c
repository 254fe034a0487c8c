/* ref_dynamics.c - smooth generalised forces (docs/model.md 3 and 5).
 *
 *   Beam, mode n:  h_n = -gamma_n ddw0(t) - omega_n^2 q_n - 2 D omega_n u_n - N_n(q)
 *   N_n(q) = k_ax / (2 L^2) sum_i sum_j sum_k I_ij I_kn q_i q_j q_k
 *            (from V = k_ax/2 dL^2, dL = 1/(2L) q^T I q; I_ij = int phi_i' phi_j' dxi)
 *   Slider:        h = (m g_x, m g_z, 0), (g_x, g_z) = g (-sin tilt, -cos tilt). */
#include "ref_dynamics.h"

void ref_dynamics_stretching(const ref_scene *scene, const double *q_b, double *n_out)
{
    const int n = scene->n_modes;
    const double (*gram)[REF_MAX_MODES] = scene->modes.slope_gram;
    int i, j, k, m;

    for (m = 0; m < n; ++m) {
        double sum = 0.0;
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j)
                for (k = 0; k < n; ++k)
                    sum += gram[i][j] * gram[k][m] * q_b[i] * q_b[j] * q_b[k];
        n_out[m] = scene->stretch_factor * sum;
    }
}

void ref_dynamics_force(const ref_scene *scene, const ref_excitation *ex, const double *q, const double *u,
                        double *h)
{
    double stretch[REF_MAX_MODES];
    int k;

    ref_dynamics_stretching(scene, q, stretch);
    for (k = 0; k < scene->n_modes; ++k) {
        const double omega = scene->modes.omega[k];
        h[k] = -scene->modes.gamma[k] * ex->w0_ddot - omega * omega * q[k]
               - 2.0 * scene->damping * omega * u[k] - stretch[k];
    }
    h[scene->i_x] = scene->slider_mass * scene->gravity[0];
    h[scene->i_z] = scene->slider_mass * scene->gravity[1];
    h[scene->i_beta] = 0.0;
}
