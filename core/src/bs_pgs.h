/* bs_pgs.h - contact solve: projected Gauss-Seidel with a cap on sweeps. */
#ifndef BS_PGS_H
#define BS_PGS_H

#include "bs_sim_layout.h"

/* Solves xi = G P + c under the contact laws for set->count contacts, from
 * set->delassus, set->free_velocity and set->mu, starting from (warm start)
 * and returning in set->percussion. Always does at least one sweep; fills
 * report's sweeps, residual and converged (bs_types.h) under the options. */
void bs_pgs_solve(bs_contact_set *set, const bs_solver_options *options, bs_step_report *report);

/* Natural-map residual sum_i |P_i - prox(P_i - r_i xi_i)|_1 of
 * set->percussion, r_i = 1 / max(diag G_ii) [N s]. */
bs_real bs_pgs_residual(const bs_contact_set *set);

#endif
