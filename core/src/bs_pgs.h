/* bs_pgs.h - contact solve: projected Gauss-Seidel with a cap on sweeps. */
#ifndef BS_PGS_H
#define BS_PGS_H

#include "beamslider.h"

typedef struct bs_pgs_result {
    int sweeps;         /* sweeps done, 1 .. max_sweeps */
    bs_real residual;   /* natural-map residual of the returned P [N s] */
    int converged;      /* residual <= tol_rel * bs_pgs_scale + tol_abs */
} bs_pgs_result;

/* Solves xi = G P + c under the contact laws for set->count contacts, from
 * set->delassus, set->free_velocity and set->mu, starting from (warm start)
 * and returning in set->percussion. Always does at least one sweep. */
bs_pgs_result bs_pgs_solve(bs_contact_set *set, int max_sweeps, bs_real tol_rel, bs_real tol_abs);

/* Natural-map residual sum_i |P_i - prox(P_i - r_i xi_i)|_1 of
 * set->percussion, r_i = 1 / max(diag G_ii) [N s]. */
bs_real bs_pgs_residual(const bs_contact_set *set);

/* Percussion scale of the problem, sum_i r_i |c_i|_1 [N s]: what tol_rel is
 * relative to. */
bs_real bs_pgs_scale(const bs_contact_set *set);

#endif
