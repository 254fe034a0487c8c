/* bs_types.h - the value types of the public API: status, model variant,
 * contact-solve options and the report of a step. Included by beamslider.h;
 * the core's own files include it for these types. */
#ifndef BS_TYPES_H
#define BS_TYPES_H

#include "bs_real.h"

/* Status of every fallible call; negative values are errors. */
typedef enum bs_status {
    BS_OK = 0,
    BS_E_NULL = -1,          /* a required pointer was NULL */
    BS_E_SCENE = -2,         /* a scene field is outside its valid range (bs_scene_check names it) */
    BS_E_ARGUMENT = -3,      /* an argument is outside its range (model, position, state, option) */
    BS_E_UNSTABLE = -4,      /* limit omega dt < 2 of the explicitly integrated stiffness violated
                                (explicit step: the modes, at init and with the cubic stiffening
                                during a step; implicit step: the cubic stiffening) */
    BS_E_NONFINITE = -5,     /* the step produced NaN or infinity */
    BS_E_ESCAPED = -6,       /* the slider left the beam: a slot corner went more than h/2 past
                                the beam surface it touches, or the slot centre more than h/2
                                past a clamp stop (the contacts did not hold; docs/design.md 5) */
    BS_E_BUILD = -7,         /* the program was compiled against another build of beamslider
                                (precision, sizes, switches or version) than the library it links */
    BS_E_UNINITIALISED = -8, /* the bs_sim was never initialised, or its last bs_sim_init failed */
    BS_E_CHECKPOINT_SIZE = -9,    /* a checkpoint buffer smaller than BS_CHECKPOINT_SIZE, or a
                                     checkpoint of another size */
    BS_E_CHECKPOINT_DAMAGED = -10, /* not a checkpoint, another byte order, or its checksum fails */
    BS_E_CHECKPOINT_BUILD = -11,  /* a checkpoint of another version or build (precision, switches, modes) */
    BS_E_CHECKPOINT_SCENE = -12   /* a checkpoint of another scene, or of a state this sim cannot take */
} bs_status;

/* Model variants (docs/model.md 6). */
typedef enum bs_model {
    BS_MODEL_FREE = 0,       /* free slider */
    BS_MODEL_PCS = 1         /* pseudo-constrained slider: contact kinematics at a prescribed x */
} bs_model;

/* The load of the piezoelectric transducer (bs_scene.load; docs/model.md 11). */
typedef enum bs_load {
    BS_LOAD_NONE = 0,        /* no transducer */
    BS_LOAD_RESISTOR = 1,    /* a resistor R_l across the patch */
    BS_LOAD_RECTIFIER = 2    /* a full-bridge rectifier charging C_s, with R_s across it */
} bs_load;

/* What the transducer does (bs_sim_get_transducer). */
typedef struct bs_transducer_output {
    int present;             /* 1 if the scene has a transducer (load != BS_LOAD_NONE), else all 0 */
    bs_real voltage;         /* v across the patch at the end of the last step [V] */
    bs_real storage_voltage; /* V_s across the storage capacitor [V] (rectifier; else 0) */
    bs_real power;           /* into the load over the last step [W]: v^2 / R_l or V_s^2 / R_s */
    bs_real energy;          /* into the load since bs_sim_init [J] */
} bs_transducer_output;

/* Settings of the contact solve (docs/design.md 6). They trade accuracy for
 * time and can change between steps (bs_sim_set_solver); the time step is
 * not among them, it is part of the scene's constants. */
typedef struct bs_solver_options {
    int max_sweeps;          /* cap on Gauss-Seidel sweeps per step, 1 .. BS_SOLVER_MAX_SWEEPS */
    bs_real tol_rel;         /* converged when residual <= tol_rel * scale + tol_abs; >= 0, finite */
    bs_real tol_abs;         /* [N s], >= 0, finite */
    int measure_residual;    /* 1: every report carries the natural-map residual of the result;
                                0: only where the solve needs it anyway (a pair whose laws the
                                signs do not settle, three or more contacts); a single contact,
                                solved exactly, and a pair whose laws hold by sign then report -1 */
} bs_solver_options;

/* Largest max_sweeps bs_sim_set_solver accepts. */
#define BS_SOLVER_MAX_SWEEPS 100000

/* Defaults of bs_solver_defaults(): two sweeps (the cap bounds only solves
 * of three or more contacts; one and two contacts are solved exactly,
 * docs/design.md 6). */
#define BS_SOLVER_DEFAULT_MAX_SWEEPS 2
#define BS_SOLVER_DEFAULT_TOL_REL 1e-5
#define BS_SOLVER_DEFAULT_TOL_ABS 1e-7

/* What the contact solve of the last step did. */
typedef struct bs_step_report {
    unsigned active;         /* bit i set: contact i took part (bits 0-3: P1..P4, 4/5: left/right stop) */
    int sweeps;              /* Gauss-Seidel sweeps used (0 when no contact was active, or when
                                three or more were solved from the warm start's modes) */
    int systems;             /* linear systems of the active-set method solved (two or more contacts) */
    bs_real residual;        /* natural-map residual of the returned percussions [N s];
                                -1 when not measured (measure_residual = 0 and the solve did not
                                need it: one contact, or two whose laws hold by sign); +inf or
                                NaN, with converged 0, when the contact problem overflowed (a
                                scene at the edge of the ranges: an infinite Delassus entry) */
    int converged;           /* 1: residual <= tol_rel * scale + tol_abs (or no contact; or, not
                                measured, the single contact's exact solve held); 0: not */
} bs_step_report;

#endif
