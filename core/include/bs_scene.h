/* bs_scene.h - the constant data of one scene, as the core consumes it.
 *
 * A scene is everything that stays fixed during a run: modal data of the beam,
 * geometry, slider inertia, contact laws, excitation and numerics. The host
 * tool fills it in double precision from physical parameters (host/lib/scene_build.c);
 * an embedded build takes it as const data from a generated header in configs/.
 * The core never computes modal data; it only reads this struct.
 *
 * Coordinates and symbols follow docs/design.md (and MODEL.md): modes are
 * mass-normalised, so the modal mass matrix is the identity; x along the beam
 * from the left clamp, z up.
 */
#ifndef BS_SCENE_H
#define BS_SCENE_H

#include <stdint.h>
#include "bs_config.h"
#include "bs_real.h"

typedef struct bs_scene {
    /* Beam: N mass-normalised bending modes. N = 0 is a rigid beam that only
     * follows the base (used by tests). */
    int n_modes;                         /* N, 0 .. BS_MAX_MODES */
    bs_real omega_sq[BS_MAX_MODES];      /* omega_k^2 [1/s^2], > 0 */
    bs_real damping[BS_MAX_MODES];       /* 2 D omega_k [1/s], >= 0 */
    bs_real gamma[BS_MAX_MODES];         /* gamma_k = rho A L int phi_k [sqrt(kg)] */
    /* Bending-stretching: S = sqrt(k_ax / (2 L^2)) I with I_ij = int phi_i,xi phi_j,xi,
     * so that N(q) = (q^T S q) S q. Symmetric, positive semidefinite; all zero
     * when the scene leaves the term out. */
    bs_real stretch[BS_MAX_MODES][BS_MAX_MODES];   /* [1/(m sqrt(kg))] */
    bs_real phi_sensor[BS_MAX_MODES];    /* phi_k(4/7) [1/sqrt(kg)]: w(4L/7) = sum phi_k q_k */

    /* Mode shapes on [0, L] as shape_pieces equal polynomial pieces; on piece j
     * with local coordinate u in [-1, 1]: phi_k = sum_c shape_coef[j][k][c] u^c.
     * Fitted on the host in double from the cancellation-free closed form. */
    int shape_pieces;                    /* 1 .. BS_SHAPE_MAX_PIECES */
    bs_real shape_scale;                 /* shape_pieces / length [1/m] */
    bs_real shape_coef[BS_SHAPE_MAX_PIECES][BS_MAX_MODES][BS_SHAPE_COEFS];

    /* Geometry [m]. */
    bs_real length;                      /* L, > 0 */
    bs_real half_thickness;              /* h/2, > 0 */
    bs_real corner[BS_CORNERS][2];       /* r_CP,i = P_i - r_GC in the slider frame (P1..P4) */
    bs_real com_offset;                  /* d: centre of mass below the slot centre G */
    bs_real stop_min, stop_max;          /* clamp end stops: allowed x_C is [stop_min, stop_max] */

    /* Slider. */
    bs_real mass_inv;                    /* 1/m [1/kg], > 0 */
    bs_real inertia_inv;                 /* 1/J_C [1/(kg m^2)], >= 0 (0: rotation locked) */
    bs_real gravity[2];                  /* acceleration of gravity in the beam frame (x, z) [m/s^2] */

    /* Contact laws. */
    bs_real mu;                          /* Coulomb friction coefficient, >= 0 */
    bs_real e_n;                         /* Newton normal restitution, 0 .. 1 */

    /* Base excitation w0 = (a/Omega^2) cos(Omega t). The phase advances by
     * exactly 2 * phase_step_half per step (units: turns * 2^64), so it never
     * drifts however long the run (MODEL.md 9.1). */
    bs_real base_accel;                  /* a [m/s^2] */
    bs_real base_velocity;               /* a/Omega [m/s] */
    bs_real base_displacement;           /* a/Omega^2 [m] */
    uint64_t phase_step_half;            /* f_ex dt / 2 * 2^64, > 0 */

    /* Numerics. */
    bs_real dt;                          /* time step [s], > 0; explicit: omega_max dt < 2 */
    /* Integrator of the modal stiffness and damping (docs/design.md 4):
     * implicit = 0: the explicit midpoint step (theta = 1/2, gains 1);
     * implicit = 1: theta in [1/2, 1] and mode_gain[k] = 1 / (1 + theta dt 2 D omega_k
     * + theta^2 dt^2 omega_k^2), the inverse of the modal effective mass. */
    int implicit;
    bs_real theta;
    bs_real mode_gain[BS_MAX_MODES];
    int pgs_max_sweeps;                  /* cap on Gauss-Seidel sweeps per step, >= 1 */
    bs_real pgs_tol_rel;                 /* converged when residual <= tol_rel |P| + tol_abs */
    bs_real pgs_tol_abs;                 /* [N s] */
} bs_scene;

/* Tells a compile-time scene header (configs/NAME.h) that bs_scene exists,
 * so that its second inclusion defines bs_compiled_scene. */
#define BS_SCENE_TYPE_DEFINED 1

#endif
