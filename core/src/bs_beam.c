/* bs_beam.c - modal equations of the beam without contact.
 *
 *   q_k'' = h_k = -gamma_k w0'' - omega_k^2 q_k - 2 D omega_k q_k' - N_k(q)
 *
 * Bending-stretching (docs/model.md 3): the stretching energy k_ax/(8 L^2) (q^T I q)^2
 * gives N(q) = (k_ax / 2L^2) (q^T I q) I q. With S = sqrt(k_ax / 2L^2) I held
 * by the scene that is N = (q^T S q) S q: N^2 + N multiply-adds instead of the
 * N^4 of the written triple sum. The step needs dt N(q); with S' = sqrt(dt) S
 * (prepared once, core/src/bs_prepare.c) that is E' (S' q), E' = q^T S' q.
 *
 * Its Jacobian dN/dq = 2 (Sq)(Sq)^T + (q^T S q) S stiffens the beam at large
 * amplitude. The explicit limit omega dt < 2 applies to the largest eigenvalue
 * of the explicitly integrated stiffness, diag(omega^2) + dN/dq (explicit
 * step) or dN/dq alone (implicit step). Two upper bounds of it, either of
 * which proves the step stable:
 *   - O(1), for a positive semidefinite S (every scene built from mode
 *     shapes): omega_max^2 + 3 rho E, rho >= lambda_max(S) (bs_prepare.c),
 *     tested as E' below the prepared stretch_limit: one comparison a step;
 *   - exact Gershgorin, when that fails or S is indefinite: the largest
 *     absolute row sum, tight here because the linear part is diagonal and
 *     the cubic part weighs on the low modes; row by row, with the triangle
 *     inequality,
 *       sum_j |2 (Sq)_i (Sq)_j + E S_ij| <= 2 |(Sq)_i| |Sq|_1 + |E| sum_j |S_ij|.
 * A step is refused (BS_E_UNSTABLE) only when both fail.
 */
#include "bs_beam.h"
#include "bs_port.h"


int bs_beam_stable(const bs_step_constants *k, int n, const bs_real *omega_sq_dt, const bs_real *sq, bs_real energy,
                   bs_real extra)
{
    const bs_real limit = BS_R(4.0) / k->dt; /* everything below in units of dt times a stiffness */
    bs_real bound = BS_R(0.0);
    int i;
#if BS_WITH_STRETCHING
    bs_real sq_sum = BS_R(0.0);
    if (energy >= BS_R(0.0) && energy < k->stretch_limit)
        return 1;
    for (i = 0; i < n; ++i)
        sq_sum += bs_fabs(sq[i]);
#else
    (void)sq;
    (void)energy;
#endif
    for (i = 0; i < n; ++i) {
        bs_real row = omega_sq_dt ? omega_sq_dt[i] : BS_R(0.0);
#if BS_WITH_STRETCHING
        row += BS_R(2.0) * bs_fabs(sq[i]) * sq_sum + bs_fabs(energy) * k->stretch_rows[i];
#endif
        if (row > bound)
            bound = row;
    }
    return bound + k->dt * extra < limit;
}
