/* beamslider.h - public API of the beamslider core.
 *
 * A fixed-step simulator of a clamped beam under base excitation carrying a
 * rigid slider with play, friction and impacts (docs/design.md). The caller
 * owns all memory: a bs_sim is a plain struct of compile-time size, e.g.
 *
 *     static bs_sim sim;
 *     if (bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)) != BS_OK) ...
 *     for (;;) { if (bs_sim_step(&sim) != BS_OK) ...; }
 *
 * The core is freestanding C99: no allocation, no I/O, no globals. Math comes
 * from the port (bs_port.h). Members of bs_sim are private; read results
 * through the functions below.
 */
#ifndef BEAMSLIDER_H
#define BEAMSLIDER_H

#include <stdint.h>
#include "bs_config.h"
#include "bs_real.h"
#include "bs_scene.h"

/* Status of every fallible call; negative values are errors. */
typedef enum bs_status {
    BS_OK = 0,
    BS_E_NULL = -1,        /* a required pointer was NULL */
    BS_E_SCENE = -2,       /* a scene field is outside its valid range (bs_scene_check names it) */
    BS_E_ARGUMENT = -3,    /* an argument is outside its range (model, start position) */
    BS_E_UNSTABLE = -4,    /* limit omega dt < 2 of the explicitly integrated stiffness violated
                              (explicit step: the modes, at init and with the cubic stiffening
                              during a step; implicit step: the cubic stiffening) */
    BS_E_NONFINITE = -5    /* the step produced NaN or infinity */
} bs_status;

/* Model variants (MODEL.md 6). */
typedef enum bs_model {
    BS_MODEL_FREE = 0,     /* free slider */
    BS_MODEL_PCS = 1       /* pseudo-constrained slider: contact kinematics at a prescribed x */
} bs_model;

/* What the contact solve of the last step did. */
typedef struct bs_step_report {
    unsigned active;       /* bit i set: contact i took part (bits 0-3: P1..P4, 4/5: left/right stop) */
    int sweeps;            /* Gauss-Seidel sweeps used (0 when no contact was active) */
    bs_real residual;      /* natural-map residual of the returned percussions [N s] */
    int converged;         /* residual <= pgs_tol_rel * scale + pgs_tol_abs (docs/design.md 6) */
} bs_step_report;

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
 * which is certainly open (bs_contact.c); computed once by bs_sim_init. */
typedef struct bs_shape_bound {
    bs_real slope[BS_MAX_MODES];       /* >= max |phi_k'| on [0, L] [1/(m sqrt(kg))] */
    bs_real jump[BS_MAX_MODES];        /* piece mismatch and rounding of phi_k [1/sqrt(kg)] */
} bs_shape_bound;

typedef struct bs_sim {
    const bs_scene *scene;
    bs_model model;
    bs_real x_pcs;                     /* PCS: prescribed x_C for the kinematics [m] */
    uint64_t step;                     /* steps taken */
    uint64_t phase;                    /* excitation phase, turns * 2^64 (wraps each period) */
    bs_real q_beam[BS_MAX_MODES];      /* modal coordinates q_k */
    bs_real u_beam[BS_MAX_MODES];      /* modal velocities */
    bs_real slider[3];                 /* x_C, z_C [m], beta [rad] */
    bs_real slider_velocity[3];
    bs_real x_c_low;                   /* compensated-sum remainder of x_C (MODEL.md 9.2) */
    bs_real percussion[BS_MAX_CONTACTS][BS_ROWS]; /* last step's percussions, warm start */
    bs_step_report report;
    bs_contact_set contacts;
    bs_shape_bound shape_bound;
} bs_sim;

/* Checks every field of a scene: BS_OK, BS_E_NULL, BS_E_SCENE (a field out of
 * its range) or BS_E_UNSTABLE (omega_max dt >= 2). On error *field (if not
 * NULL) names the offending field. */
bs_status bs_scene_check(const bs_scene *scene, const char **field);

/* Starts a run: beam at rest, beta = 0, slot centred on the beam axis,
 * x_C = s0 L. For BS_MODEL_FREE, s0 must lie within the clamp end stops
 * [stop_min, stop_max] / L; for BS_MODEL_PCS, s0 is the prescribed position
 * s~ in [0, 1]. The scene must outlive the sim.
 * Returns BS_OK, BS_E_NULL, BS_E_SCENE, BS_E_UNSTABLE or BS_E_ARGUMENT. */
bs_status bs_sim_init(bs_sim *sim, const bs_scene *scene, bs_model model, bs_real s0);

/* PCS only: moves the prescribed position to s~ in [0, 1] keeping the state
 * (continuation in a quasi-static sweep). Returns BS_OK, BS_E_NULL or BS_E_ARGUMENT. */
bs_status bs_sim_set_pcs_position(bs_sim *sim, bs_real s);

/* Advances one time step dt. On error the state stays at the last good step.
 * Returns BS_OK, BS_E_NULL, BS_E_UNSTABLE or BS_E_NONFINITE. Hitting the sweep
 * cap is not an error: see bs_sim_report(). */
bs_status bs_sim_step(bs_sim *sim);

/* Contact report of the last step. */
const bs_step_report *bs_sim_report(const bs_sim *sim);

/* Elastic deflection at the sensor, w(4L/7, t) [m] (no base motion). */
bs_real bs_sim_sensor(const bs_sim *sim);

/* Relative slider position s = x_C / L. */
bs_real bs_sim_position(const bs_sim *sim);

/* Copies the state out: modal coordinates q_k and velocities (n_modes values
 * each), slider (x_C [m], z_C [m], beta [rad]) and its velocities. Any
 * pointer may be NULL to skip that part. */
void bs_sim_get_state(const bs_sim *sim, bs_real *q_beam, bs_real *u_beam, bs_real *slider,
                      bs_real *slider_velocity);

/* Overwrites the state (a digital twin re-synchronising with measurements,
 * tests setting initial conditions); NULL leaves that part as it is. Every
 * value must be finite and, in the free model, x_C within the clamp stops;
 * otherwise nothing changes and BS_E_ARGUMENT is returned. Percussions of the
 * warm start are cleared. Returns BS_OK, BS_E_NULL or BS_E_ARGUMENT. */
bs_status bs_sim_set_state(bs_sim *sim, const bs_real *q_beam, const bs_real *u_beam,
                           const bs_real *slider, const bs_real *slider_velocity);

/* Excitation phase as a fraction of a period, [0, 1). */
bs_real bs_sim_phase(const bs_sim *sim);

/* FNV-1a hash of the complete dynamic state (bit patterns), for determinism checks. */
uint32_t bs_sim_hash(const bs_sim *sim);

/* Short English text of a status, for messages. */
const char *bs_status_text(bs_status status);

#endif
