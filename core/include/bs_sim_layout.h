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
    bs_real system[BS_ROWS * BS_MAX_CONTACTS][BS_ROWS * BS_MAX_CONTACTS + 1]; /* active-set [A | b], 3+ contacts */
#endif
} bs_contact_set;

/* The mode shapes near one side of the slot, expanded once and used while
 * the slider stays within reach (core/src/bs_shape.c): the two corners of a
 * side lie micrometres apart along the beam and move slowly. */
/* Terms of the expansion: cubic in float, quartic in double (its error must
 * stay under the double fit's 1e-9 too; core/src/bs_shape.c). */
#define BS_SHAPE_TERMS (BS_REAL_FLOAT ? 4 : 5)

typedef struct bs_shape_cache {
    bs_real centre;                    /* x of the expansion [m]; below 0: empty */
    bs_real coef[BS_MAX_MODES][BS_SHAPE_TERMS]; /* phi_k = sum_m coef[k][m] t^m, t in the pieces' local units */
} bs_shape_cache;

typedef struct bs_sim {
    uint32_t ready;                    /* BS_SIM_READY after a successful bs_sim_init, else not */
    const bs_scene *scene;
    bs_model model;
    bs_solver_options solver;
    bs_real x_pcs;                     /* PCS: prescribed x_C for the kinematics [m] */
    uint64_t step;                     /* steps taken */
    uint64_t phase;                    /* excitation phase, turns * 2^64 (wraps each period) */
    uint64_t phase_step_half;          /* f dt / 2 in 2^-64 turns (bs_sim_set_excitation) */
    bs_real excitation[2];             /* frequency [Hz] and amplitude a [m/s^2] as set */
    bs_real step_accel;                /* a sinc(Omega dt / 2): amplitude of the step mean [m/s^2] */
    bs_real base_accel;                /* mean base acceleration the last step used [m/s^2] */
    bs_real q_beam[BS_MAX_MODES];      /* modal coordinates q_k */
    bs_real u_beam[BS_MAX_MODES];      /* modal velocities */
    bs_real slider[3];                 /* x_C, z_C [m], beta [rad] */
    bs_real slider_velocity[3];
    bs_real x_c_low;                   /* compensated-sum remainder of x_C (docs/model.md 9.2) */
    bs_real percussion[BS_MAX_CONTACTS][BS_ROWS]; /* last step's percussions, warm start */
    bs_step_report report;
    bs_contact_set contacts;
    bs_shape_cache side[2];            /* mode shapes about the left (P1, P2) and right (P4, P3) corners */
    bs_real shape_reach;               /* how far they serve (core/src/bs_shape.c) */
    bs_real stretch_rows[BS_MAX_MODES]; /* sum_j |S_ij|, for the stability bound (core/src/bs_beam.c) */
#if BS_WITH_PIEZO
    bs_real voltage;                   /* v across the patch [V] */
    bs_real storage_voltage;           /* V_s (rectifier) [V] */
    bs_real power;                     /* into the load over the last step [W] */
    bs_real energy, energy_low;        /* into the load since init [J], a compensated sum */
    bs_real piezo_stiffness;           /* max_k |theta_k| sum_j |theta_j| / C_p (stability bound) */
#endif
} bs_sim;

#endif
