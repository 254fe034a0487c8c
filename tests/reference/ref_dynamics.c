/* ref_dynamics.c - smooth generalised forces (docs/model.md 3, 5 and 10).
 *
 *   Base frame (docs/model.md 10): q = (q_b, x_C, z_r, beta), z_r = z_C - w0.
 *   Beam, mode n:  h_n = -gamma_n ddw0 - omega_n^2 q_n - 2 D omega_n u_n - N_n(q)
 *   N_n(q) = k_ax / (2 L^2) sum_i sum_j sum_k I_ij I_kn q_i q_j q_k
 *            (from V = k_ax/2 dL^2, dL = 1/(2L) q^T I q; I_ij = int phi_i' phi_j' dxi)
 *   Slider:        h = (m g_x, m g_z - m ddw0, 0), (g_x, g_z) = g (-sin tilt, -cos tilt);
 *                  -m ddw0 is the inertial force of the frame riding with the base. */
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

double ref_dynamics_stretching_energy(const ref_scene *scene, const double *q_b)
{
    double quad = 0.0;
    int i, j;
    for (i = 0; i < scene->n_modes; ++i)
        for (j = 0; j < scene->n_modes; ++j)
            quad += scene->modes.slope_gram[i][j] * q_b[i] * q_b[j];
    /* k_ax/2 (quad / 2L)^2 = (k_ax / 2L^2) quad^2 / 4 */
    return 0.25 * scene->stretch_factor * quad * quad;
}

void ref_dynamics_force(const ref_scene *scene, double base_accel, const double *q, const double *u, double *h)
{
    double stretch[REF_MAX_MODES];
    int k;

    ref_dynamics_stretching(scene, q, stretch);
    for (k = 0; k < scene->n_modes; ++k) {
        const double omega = scene->modes.omega[k];
        h[k] = -scene->modes.gamma[k] * base_accel - omega * omega * q[k] - 2.0 * scene->damping * omega * u[k]
               - stretch[k];
    }
    h[scene->i_x] = scene->slider_mass * scene->gravity[0];
    h[scene->i_z] = scene->slider_mass * (scene->gravity[1] - base_accel);
    h[scene->i_beta] = 0.0;
}
