/* bs_beam.c - modal equations of the beam without contact.
 *
 *   q_k'' = h_k = -gamma_k w0'' - omega_k^2 q_k - 2 D omega_k q_k' - N_k(q)
 *
 * Bending-stretching (MODEL.md 3): the stretching energy k_ax/(8 L^2) (q^T I q)^2
 * gives N(q) = (k_ax / 2L^2) (q^T I q) I q. With S = sqrt(k_ax / 2L^2) I held
 * by the scene that is N = (q^T S q) S q: N^2 + N multiply-adds instead of the
 * N^4 of the written triple sum.
 *
 * Its Jacobian dN/dq = 2 (Sq)(Sq)^T + (q^T S q) S has largest eigenvalue at
 * most 2 |Sq|^2 + (q^T S q) |S|, which the step adds to omega_max^2 to check
 * the explicit limit while the beam hardens at large amplitude.
 */
#include "bs_beam.h"

bs_real bs_beam_force(const bs_scene *scene, const bs_real *q, const bs_real *u,
                      bs_real base_accel, bs_real *force)
{
    const int n = BS_NMODES(scene);
    int i;
#if BS_WITH_STRETCHING
    bs_real sq[BS_MAX_MODES];
    bs_real stretch_energy = BS_R(0.0); /* q^T S q */
    bs_real sq_norm2 = BS_R(0.0);       /* |S q|^2 */
    int j;

    for (i = 0; i < n; ++i) {
        bs_real acc = BS_R(0.0);
        for (j = 0; j < n; ++j)
            acc += scene->stretch[i][j] * q[j];
        sq[i] = acc;
        stretch_energy += q[i] * acc;
        sq_norm2 += acc * acc;
    }
    for (i = 0; i < n; ++i)
        force[i] = -scene->gamma[i] * base_accel - scene->omega_sq[i] * q[i]
                   - scene->damping[i] * u[i] - stretch_energy * sq[i];
    return BS_R(2.0) * sq_norm2 + stretch_energy * scene->stretch_norm;
#else
    for (i = 0; i < n; ++i)
        force[i] = -scene->gamma[i] * base_accel - scene->omega_sq[i] * q[i] - scene->damping[i] * u[i];
    return BS_R(0.0);
#endif
}
