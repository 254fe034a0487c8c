/* ref_step.h - one Moreau midpoint step of the reference model in the base
 * frame (docs/model.md 5, 6, 10) with the piezoelectric transducer
 * (docs/model.md 11). */
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
    double compliance;       /* diagnostic, not docs/model.md: G_ii (1 + compliance) on the contact rows; 0 by default */
} ref_step_options;

/* Default: enumeration; PGS tolerance 1e-13, safety stop 1e8 sweeps; no compliance. */
void ref_step_default_options(ref_step_options *options);

typedef struct ref_state {
    uint64_t step;                           /* Moreau steps of dt_sub done */
    double q[REF_MAX_Q], u[REF_MAX_Q];       /* (q_1..q_N, x_C, z_r, beta), z_r = z_C - w0, and velocities */
    double voltage;                          /* v, the patch voltage [V] (0 without a patch) */
    double storage_voltage;                  /* V_s, over the storage capacitor [V] (rectifier) */
    double load_energy;                      /* energy into the load R_l or R_s since the start [J] */
    double percussion[REF_MAX_CONTACTS][2];  /* last percussion per contact id (warm start) */
    ref_mode mode[REF_MAX_CONTACTS];         /* last mode per contact id */
    int active[REF_MAX_CONTACTS];            /* took part in the last step */
    double bridge_flux;                      /* last bridge unknown Lambda = dt Q / (2 C_p) [V s] (warm start) */
    ref_mode bridge_mode;                    /* last bridge mode: REF_TAKEOFF blocking, REF_STICK conducting */
} ref_state;

typedef struct ref_step_report {
    int active;             /* contacts in the step (the bridge not counted) */
    unsigned mask;          /* which: bits 0-3 corners P1..P4, bit 4 left stop, bit 5 right stop */
    int solved;             /* 1: a complementarity problem was solved (contacts and/or the bridge) */
    long iterations;        /* solver iterations (enumeration: linear solves; PGS: sweeps) */
    double residual;        /* natural-map residual [N s; the bridge's in V s] */
    double residual_rel;
    int converged;
    int exhaustive;         /* enumeration fell back to (or was asked for) all modes */
    int ambiguous;          /* more than one solution with different velocities */
    double base_accel;      /* the step's mean base acceleration [m/s^2] */
    double contact_work;    /* work of the percussions, P . W^T (u_B + u_E) / 2 [J] (<= 0: dissipated) */
    double load_energy;     /* energy into the load R_l or R_s in this step [J] */
    double bridge_charge;   /* Q, through the bridge in this step [C] (rectifier; >= 0) */
    int bridge_branch;      /* sigma: +1 / -1, the branch that may conduct (rectifier), else 0 */
} ref_step_report;

/* docs/model.md 6 in the base frame (docs/model.md 10): q_b = 0, u = 0,
 * beta = 0, x_C = s0 L (PCS: s~ L), z_r = -d; v = V_s = 0. */
void ref_state_init(const ref_scene *scene, ref_state *state);

/* One step of dt_sub driven by the scene's excitation: the mean base
 * acceleration of the step from ref_scene_step_accel (harmonic or schedule).
 * Returns 0, or -1 if the complementarity solve failed or the state is no
 * longer finite (the report says more). */
int ref_step(const ref_scene *scene, const ref_step_options *options, ref_state *state, ref_step_report *report);

/* The same with the step's mean base acceleration given by the caller
 * (docs/model.md 10: a measured signal, (dw0(t_E) - dw0(t_B)) / dt) [m/s^2]. */
int ref_step_with_accel(const ref_scene *scene, const ref_step_options *options, double base_accel,
                        ref_state *state, ref_step_report *report);

#endif
