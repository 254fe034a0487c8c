/* bs_sim_layout.h - PRIVATE: the sized layout of bs_sim.
 *
 * This header is public only so that a program can own a bs_sim without
 * allocation (`static bs_sim sim;`): its size must be known where the program
 * is compiled. Its members are private: they change between releases without
 * notice, and a program that reads or writes them directly is unsupported.
 * Use the functions of beamslider.h. (Chipmunk2D keeps its sized structs in
 * chipmunk_structs.h for the same reason.)
 */
#ifndef BS_SIM_LAYOUT_H
#define BS_SIM_LAYOUT_H

#include <stdint.h>
#include "bs_config.h"
#include "bs_real.h"
#include "bs_scene.h"
#include "bs_types.h"

/* Scratch of one step's contact problem; lives in bs_sim, not on the stack.
 * Each contact has BS_ROWS rows: normal (0) and, with friction, tangential (1). */
typedef struct bs_contact_set {
    int count;                                   /* active contacts */
    int id[BS_MAX_CONTACTS];                     /* contact index 0..5 of each active contact */
    bs_real dir_beam[BS_ROWS * BS_MAX_CONTACTS][BS_MAX_MODES];    /* W column of row BS_ROWS a + r, modal part */
    bs_real dir_slider[BS_ROWS * BS_MAX_CONTACTS][BS_SLIDER_DOF]; /* W column, slider part */
    bs_real delassus[BS_ROWS * BS_MAX_CONTACTS][BS_ROWS * BS_MAX_CONTACTS]; /* G = W^T M^-1 W */
    bs_real free_velocity[BS_ROWS * BS_MAX_CONTACTS];  /* c: xi = G P + c */
#if BS_WITH_FRICTION
    bs_real mu[BS_MAX_CONTACTS];                 /* friction coefficient (0 at the stops) */
#endif
    bs_real percussion[BS_ROWS * BS_MAX_CONTACTS];     /* P [N s] */
#if BS_WITH_SUBSPACE
    bs_real system[BS_ROWS * BS_MAX_CONTACTS][BS_ROWS * BS_MAX_CONTACTS + 1]; /* subspace step's [A | b] */
#endif
} bs_contact_set;

/* Bounds on the mode shapes that let a step skip evaluating a slot corner
 * which is certainly open (core/src/bs_contact.c); computed once by bs_sim_init. */
typedef struct bs_shape_bound {
    bs_real slope[BS_MAX_MODES];       /* >= max |phi_k'| on [0, L] [1/(m sqrt(kg))] */
    bs_real jump[BS_MAX_MODES];        /* piece mismatch and rounding of phi_k [1/sqrt(kg)] */
} bs_shape_bound;

typedef struct bs_sim {
    uint32_t ready;                    /* BS_SIM_READY after a successful bs_sim_init, else not */
    const bs_scene *scene;
    bs_model model;
    bs_solver_options solver;
    bs_real x_pcs;                     /* PCS: prescribed x_C for the kinematics [m] */
    uint64_t step;                     /* steps taken */
    uint64_t phase;                    /* excitation phase, turns * 2^64 (wraps each period) */
    bs_real q_beam[BS_MAX_MODES];      /* modal coordinates q_k */
    bs_real u_beam[BS_MAX_MODES];      /* modal velocities */
    bs_real slider[3];                 /* x_C, z_C [m], beta [rad] */
    bs_real slider_velocity[3];
    bs_real x_c_low;                   /* compensated-sum remainder of x_C (docs/model.md 9.2) */
    bs_real percussion[BS_MAX_CONTACTS][BS_ROWS]; /* last step's percussions, warm start */
    bs_step_report report;
    bs_contact_set contacts;
    bs_shape_bound shape_bound;
    bs_real stretch_rows[BS_MAX_MODES]; /* sum_j |S_ij|, for the stability bound (core/src/bs_beam.c) */
} bs_sim;

#endif
