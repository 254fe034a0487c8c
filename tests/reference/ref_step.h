/* ref_step.h - one Moreau midpoint step of the reference model (docs/model.md 5, 6). */
#ifndef REF_STEP_H
#define REF_STEP_H

#include <stdint.h>
#include "ref_lcp.h"
#include "ref_scene.h"

typedef enum ref_solver { REF_SOLVER_ENUM = 0, REF_SOLVER_PGS = 1 } ref_solver;

typedef struct ref_step_options {
    ref_solver solver;
    int exhaustive;          /* enumeration: try every mode in every step (ambiguity check) */
    double pgs_tol_rel;      /* PGS: sum |dP| <= tol sum |P| */
    long pgs_max_sweeps;     /* PGS: safety stop (a failure, not a cap) */
    double compliance;       /* diagnostic, not docs/model.md: G_ii (1 + compliance); 0 by default */
} ref_step_options;

/* Default: enumeration; PGS tolerance 1e-13, safety stop 1e8 sweeps; no compliance. */
void ref_step_default_options(ref_step_options *options);

typedef struct ref_state {
    uint64_t step;                           /* Moreau steps of dt_sub done */
    double q[REF_MAX_Q], u[REF_MAX_Q];       /* (q_1..q_N, x_C, z_C, beta) and velocities */
    double percussion[REF_MAX_CONTACTS][2];  /* last percussion per contact id (warm start) */
    ref_mode mode[REF_MAX_CONTACTS];         /* last mode per contact id */
    int active[REF_MAX_CONTACTS];            /* took part in the last step */
} ref_state;

typedef struct ref_step_report {
    int active;             /* contacts in the step */
    unsigned mask;          /* which: bits 0-3 corners P1..P4, bit 4 left stop, bit 5 right stop */
    long iterations;        /* solver iterations (enumeration: linear solves; PGS: sweeps) */
    double residual;        /* natural-map residual [N s] */
    double residual_rel;
    int converged;
    int exhaustive;         /* enumeration fell back to (or was asked for) all modes */
    int ambiguous;          /* more than one solution with different velocities */
} ref_step_report;

/* docs/model.md 6: q_b = 0, u = 0, beta = 0, x_C = s0 L (PCS: s~ L), z_C = -d + w0(0). */
void ref_state_init(const ref_scene *scene, ref_state *state);

/* One step of dt_sub. Returns 0, or -1 if the contact solve failed or the
 * state is no longer finite (the report says more). */
int ref_step(const ref_scene *scene, const ref_step_options *options, ref_state *state, ref_step_report *report);

#endif
