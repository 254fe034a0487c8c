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
 * Each contact has BS_ROWS rows: normal (0) and, with friction, tangential (1).
 * The beam part of a corner's force direction is a combination of the mode
 * shapes and slopes at the corner, W_r,k = beam_coef[a][r][0] phi_k +
 * beam_coef[a][r][1] phi'_k (core/src/bs_contact.c): phi and phi' are kept,
 * not the rows, and every product with them is formed in one pass. */
typedef struct bs_contact_set {
    int count;                                   /* active contacts */
    int id[BS_MAX_CONTACTS];                     /* contact index 0..5 of each active contact */
    bs_real free_velocity[BS_ROWS * BS_MAX_CONTACTS];  /* c: xi = G P + c */
    bs_real percussion[BS_ROWS * BS_MAX_CONTACTS];     /* P [N s] */
#if BS_WITH_FRICTION
    bs_real mu[BS_MAX_CONTACTS];                 /* friction coefficient (0 at the stops) */
#endif
    bs_real beam_coef[BS_MAX_CONTACTS][BS_ROWS][2]; /* W_r,k = coef[0] phi_k + coef[1] phi'_k (0 at a stop) */
    bs_real dir_slider[BS_ROWS * BS_MAX_CONTACTS][BS_SLIDER_DOF]; /* W column, slider part */
    bs_real phi[BS_CORNERS][BS_MAX_MODES];       /* phi_k at active corner a (corners come first in
                                                    the set, the stops after them) */
    bs_real slope[BS_CORNERS][BS_MAX_MODES];     /* phi'_k there [1/(m sqrt(kg))] */
    bs_real delassus[BS_ROWS * BS_MAX_CONTACTS][BS_ROWS * BS_MAX_CONTACTS]; /* G = W^T M^-1 W */
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
    int on_beam;                       /* 1: every x within its reach is on the beam, in [0, L] */
} bs_shape_cache;

/* What every step reads, prepared once from the scene (core/src/bs_prepare.c)
 * into the sim's own memory, so that a firmware's step reads RAM even with
 * the scene in flash: pre-multiplied by dt where that saves work per step,
 * the contact laws settable at run time. */
/* Terms of the excitation's sine and cosine series (core/src/bs_excitation.c). */
#define BS_EXCITATION_TERMS (BS_REAL_FLOAT ? 4 : 7)

typedef struct bs_step_constants {
    bs_real dt, half_dt;
    bs_real dt_gamma[BS_MAX_MODES];     /* dt gamma_k */
    bs_real dt_omega_sq[BS_MAX_MODES];  /* dt omega_k^2 (explicit step) */
    bs_real dt_damping[BS_MAX_MODES];   /* dt 2 D omega_k (explicit step) */
    bs_real phi_sensor[BS_MAX_MODES];   /* phi_k(4/7) */
#if BS_WITH_IMPLICIT
    bs_real mode_gain[BS_MAX_MODES];    /* the scene's when implicit, else 1: the beam part of M^-1 */
#endif
#if BS_WITH_STRETCHING
    bs_real stretch[BS_MAX_MODES][BS_MAX_MODES]; /* sqrt(dt) S, so that E = q^T (sqrt(dt) S) q and
                                                    dt N(q) = E (sqrt(dt) S q) */
    bs_real stretch_rows[BS_MAX_MODES]; /* sum_j |S_ij| (sqrt(dt) S), the exact stability bound */
    bs_real stretch_limit;              /* a step with 0 <= E below this is within the stability
                                           limit (core/src/bs_beam.c); -1: no such shortcut */
    int stretch_parity;                 /* 1: S_ij = 0 wherever i + j is odd (modes alternately
                                           symmetric and antisymmetric): half the products */
#endif
    bs_real stiffness_limit;            /* 4 / dt^2 [1/s^2], less the open patch's stiffness */
    bs_real corner[BS_CORNERS][2];      /* r_CP,i */
    bs_real half_thickness, length, stop_min, stop_max;
    bs_real escape_min, escape_max;     /* the stops widened by h/2: where a step may end (bs_within_stops) */
    bs_real shape_scale, slope_scale;   /* shape_scale and 2 shape_scale: dphi/dx = slope_scale dphi/dt */
    bs_real mass_inv, inertia_inv;
    bs_real dt_gravity[2];              /* dt g (x, z) */
    bs_real mu, e_n;                    /* the contact laws (bs_sim_set_contact_laws) */
    bs_real compliance[2];              /* 1 + eps of the normal and tangential rows (bs_contact.h) */
    bs_real series[7];                  /* the contact kinematics' series coefficients and bound
                                           (core/src/bs_contact.c): read from RAM, not from flash */
    bs_real excitation_series[2 * BS_EXCITATION_TERMS + 1]; /* the excitation's (core/src/bs_excitation.c) */
} bs_step_constants;

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
    /* q_beam to x_c_low: one block, which the step reads and writes at once (bs_step.c) */
    bs_real q_beam[BS_MAX_MODES];      /* modal coordinates q_k */
    bs_real u_beam[BS_MAX_MODES];      /* modal velocities */
    bs_real slider[3];                 /* x_C, z_C [m], beta [rad] */
    bs_real slider_velocity[3];
    bs_real x_c_low;                   /* compensated-sum remainder of x_C (docs/model.md 9.2) */
    bs_real percussion[BS_MAX_CONTACTS][BS_ROWS]; /* last step's percussions, warm start */
    bs_step_report report;
#if BS_WITH_PIEZO
    bs_real voltage;                   /* v across the patch [V] */
    bs_real storage_voltage;           /* V_s (rectifier) [V] */
    bs_real power;                     /* into the load over the last step [W] */
    bs_real energy, energy_low;        /* into the load since init [J], a compensated sum */
    bs_real piezo_stiffness;           /* max_k |theta_k| sum_j |theta_j| / C_p (stability bound) */
#endif
    /* what each step reads is near the start: the offsets a step uses stay
     * short (a Cortex-M's VLDR reaches 1020 bytes) */
    bs_step_constants k;               /* the scene as the step reads it (bs_prepare) */
    bs_real shape_reach;               /* how far the expansions serve (core/src/bs_shape.c) */
    bs_contact_set contacts;           /* before the caches: the step reads its members at many offsets
                                          from the sim, each cache's through one pointer */
    bs_shape_cache side[2];            /* mode shapes about the left (P1, P2) and right (P4, P3) corners */
} bs_sim;

#endif
