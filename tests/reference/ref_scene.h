/* ref_scene.h - the reference model's scene: every constant of docs/model.md 2-6
 * in double, from the project's scene parameters (host/lib/scene_params.h). */
#ifndef REF_SCENE_H
#define REF_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "ref_config.h"
#include "ref_modes.h"
#include "scene_params.h"

typedef enum ref_model { REF_MODEL_FREE = 0, REF_MODEL_PCS = 1 } ref_model;

/* Base motion at one instant: w0 = (a/Omega^2) cos(Omega t). */
typedef struct ref_excitation {
    double w0;        /* [m] */
    double w0_dot;    /* [m/s] */
    double w0_ddot;   /* [m/s^2] = -a cos(Omega t) */
} ref_excitation;

typedef struct ref_scene {
    ref_modes modes;
    int n_modes;                  /* N (0: rigid beam) */
    int n_q;                      /* N + 3; x_C, z_C, beta at n_modes, +1, +2 */
    int i_x, i_z, i_beta;         /* indices of x_C, z_C, beta in q */
    double length, half_thickness; /* L, h/2 [m] */
    double damping;               /* D */
    double stretch_factor;        /* k_ax / (2 L^2) [N/m^3]; 0 when stretching is off */
    double slider_mass, slider_inertia; /* m [kg], J_C [kg m^2] */
    int rotation;                 /* 1: beta free, 0: locked at 0 */
    double slot_width, com_offset, slot_height; /* B, d, R = r_h h [m] */
    double corner[REF_CORNERS][2]; /* r_CP,i = P_i - r_GC in the slider frame [m] */
    double zeta[REF_CORNERS];     /* +1 top corners (P1, P4), -1 bottom (P2, P3) */
    double mu, e_n;
    double gravity[2];            /* (-g sin tilt, -g cos tilt) [m/s^2] */
    double frequency, acceleration, omega_ex; /* f_ex [Hz], a [m/s^2], Omega [rad/s] */
    double dt;                    /* outer step [s] (the scene's dt) */
    int substeps;                 /* K: the Moreau step is dt / K */
    double dt_sub;                /* dt / K [s] */
    ref_model model;
    double s_pcs;                 /* PCS: prescribed x_C / L */
    double s0;                    /* free: start x_C / L */
    int end_stops;                /* 1: unilateral stops on x_C at [B/2, L - B/2] */
    double mass[REF_MAX_Q][REF_MAX_Q];     /* M, dense */
    double mass_inv[REF_MAX_Q][REF_MAX_Q]; /* M^-1 on the free coordinates (beta row/column 0 when locked) */
    double sensor_phi[REF_MAX_MODES];      /* phi_k(4/7) [1/sqrt(kg)] */
} ref_scene;

/* Builds the reference scene from p with n_modes = p->modes (0 allowed:
 * rigid beam), model and start position from p->model and p->s0 and K
 * substeps per dt. Returns 0 or -1 with a message in err. */
int ref_scene_init(ref_scene *scene, const scene_params *p, int substeps, char *err, size_t err_size);

/* Time of half-substep index j (t = j dt_sub / 2) in long double: never accumulated. */
long double ref_scene_time(const ref_scene *scene, uint64_t half_steps);

/* Base motion at t; the phase Omega t is reduced exactly: Omega t = 2 pi frac(f_ex t). */
void ref_scene_excitation(const ref_scene *scene, long double t, ref_excitation *ex);

/* Elastic deflection w(x) and slope w'(x) = dw/dx of the beam at x for
 * modal coordinates q_b (zero outside [0, L]); phi, phi_x receive phi_k(x/L)
 * and d phi_k / dx when not NULL. */
void ref_scene_beam(const ref_scene *scene, const double *q_b, double x, double *w, double *w_x,
                    double *phi, double *phi_x);

/* Sensor signal w(4L/7) [m]. */
double ref_scene_sensor(const ref_scene *scene, const double *q);

#endif
