/* bs_beam.c - modal equations of the beam without contact.
 *
 *   q_k'' = h_k = -gamma_k w0'' - omega_k^2 q_k - 2 D omega_k q_k' - N_k(q)
 *
 * Bending-stretching (docs/model.md 3): the stretching energy k_ax/(8 L^2) (q^T I q)^2
 * gives N(q) = (k_ax / 2L^2) (q^T I q) I q. With S = sqrt(k_ax / 2L^2) I held
 * by the scene that is N = (q^T S q) S q: N^2 + N multiply-adds instead of the
 * N^4 of the written triple sum.
 *
 * Its Jacobian dN/dq = 2 (Sq)(Sq)^T + (q^T S q) S stiffens the beam at large
 * amplitude. The explicit limit omega dt < 2 applies to the largest eigenvalue
 * of the explicitly integrated stiffness, diag(omega^2) + dN/dq (explicit
 * step) or dN/dq alone (implicit step); Gershgorin's theorem bounds it by the
 * largest absolute row sum, which is tight here: the linear part is diagonal
 * and the cubic part weighs on the low modes, mode 5's row on mode 5. The row
 * sums are bounded once more by the triangle inequality,
 *   sum_j |2 (Sq)_i (Sq)_j + E S_ij| <= 2 |(Sq)_i| |Sq|_1 + |E| sum_j |S_ij|,
 * E = q^T S q, with the row sums of |S| computed once per run
 * (bs_beam_stretch_rows): N operations per step instead of N^2, and a bound
 * that stays tight where one mode dominates (every scene here).
 */
#include "bs_beam.h"
#include "bs_port.h"

void bs_beam_stretch_rows(const bs_scene *scene, bs_real *rows)
{
    int i, j;
    for (i = 0; i < BS_MAX_MODES; ++i) {
        rows[i] = BS_R(0.0);
        for (j = 0; i < BS_NMODES(scene) && j < BS_NMODES(scene); ++j)
            rows[i] += bs_fabs(scene->stretch[i][j]);
    }
}

bs_real bs_beam_force(const bs_scene *scene, const bs_real *stretch_rows, const bs_real *q, const bs_real *q_stiff,
                      const bs_real *u, bs_real base_accel, int linear_explicit, bs_real *force)
{
    const int n = BS_NMODES(scene);
    bs_real bound = BS_R(0.0);
    int i;
#if BS_WITH_STRETCHING
    bs_real sq[BS_MAX_MODES];
    bs_real stretch_energy = BS_R(0.0); /* q^T S q */
    bs_real sq_sum = BS_R(0.0);         /* |Sq|_1 */
    int j;

    for (i = 0; i < n; ++i) {
        bs_real acc = BS_R(0.0);
        for (j = 0; j < n; ++j)
            acc += scene->stretch[i][j] * q[j];
        sq[i] = acc;
        sq_sum += bs_fabs(acc);
        stretch_energy += q[i] * acc;
    }
    for (i = 0; i < n; ++i) {
        /* bound of Gershgorin row i of the explicitly integrated stiffness
         * (omega^2 if the linear part is explicit) + 2 (Sq)(Sq)^T + (q^T S q) S */
        const bs_real row = (linear_explicit ? scene->omega_sq[i] : BS_R(0.0))
                            + BS_R(2.0) * bs_fabs(sq[i]) * sq_sum + bs_fabs(stretch_energy) * stretch_rows[i];
        if (row > bound)
            bound = row;
        force[i] = -scene->gamma[i] * base_accel - scene->omega_sq[i] * q_stiff[i]
                   - scene->damping[i] * u[i] - stretch_energy * sq[i];
    }
#else
    (void)q;
    (void)stretch_rows;
    for (i = 0; i < n; ++i) {
        if (linear_explicit && scene->omega_sq[i] > bound)
            bound = scene->omega_sq[i];
        force[i] = -scene->gamma[i] * base_accel - scene->omega_sq[i] * q_stiff[i] - scene->damping[i] * u[i];
    }
#endif
    return bound;
}
