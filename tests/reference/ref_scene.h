/* ref_scene.h - the reference model's scene: every constant of docs/model.md 2-6,
 * 10 and 11 in double (long double where time and phase need it), from the
 * project's scene parameters (host/lib/scene/scene_params.h). */
#ifndef REF_SCENE_H
#define REF_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "ref_circuit.h"
#include "ref_config.h"
#include "ref_modes.h"
#include "scene_params.h"
#include "schedule.h"

typedef enum ref_model { REF_MODEL_FREE = 0, REF_MODEL_PCS = 1 } ref_model;

/* [transducer] load (docs/model.md 11): none = no patch (docs/model.md 3-5 exactly). */
typedef enum ref_load { REF_LOAD_NONE = 0, REF_LOAD_RESISTOR = 1, REF_LOAD_RECTIFIER = 2 } ref_load;

/* Base motion at one instant. w0 and dw0 exist in closed form only for the
 * constant harmonic (w0 = (a/Omega^2) cos(Omega t)); with a schedule they are NaN. */
typedef struct ref_excitation {
    double w0;            /* [m] */
    double w0_dot;        /* [m/s] */
    double w0_ddot;       /* [m/s^2] = -a(t) cos(phase(t)) */
    long double cycles;   /* phase(t) / (2 pi): excitation periods since t = 0 */
} ref_excitation;

typedef struct ref_scene {
    ref_modes modes;
    int n_modes;                  /* N (0: rigid beam) */
    int n_q;                      /* N + 3; x_C, z_r, beta at n_modes, +1, +2 */
    int i_x, i_z, i_beta;         /* indices of x_C, z_r = z_C - w0, beta in q */
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

    /* excitation (docs/model.md 1, 10) */
    double frequency, acceleration, omega_ex; /* f_ex [Hz], a [m/s^2], Omega [rad/s] (constant harmonic) */
    long double step_sinc;        /* sin(Omega dt_sub / 2) / (Omega dt_sub / 2): step mean of the harmonic */
    int schedule_points;          /* 0: the constant harmonic; else [excitation] schedule */
    long double schedule_t[SCHEDULE_MAX_POINTS];      /* [s] */
    long double schedule_f[SCHEDULE_MAX_POINTS];      /* [Hz] */
    long double schedule_a[SCHEDULE_MAX_POINTS];      /* [m/s^2] */
    long double schedule_cycles[SCHEDULE_MAX_POINTS]; /* int_0^t_k f dt */
    long double gl_node[REF_GL_POINTS], gl_weight[REF_GL_POINTS]; /* Gauss-Legendre on [-1, 1] */

    double dt;                    /* outer step [s] (the scene's dt) */
    int substeps;                 /* K: the Moreau step is dt / K */
    double dt_sub;                /* dt / K [s] */
    ref_model model;
    double s_pcs;                 /* PCS: prescribed x_C / L */
    double s0;                    /* free: start x_C / L */
    int end_stops;                /* 1: unilateral stops on x_C at [stop_left, stop_right] */
    double stop_left, stop_right; /* B/2 and L - B/2, or beside the patch [m] */

    /* transducer (docs/model.md 11) */
    ref_load load;
    double patch_start, patch_end; /* x_1, x_2 [m] */
    double coupling;              /* Theta [N m/V] */
    double capacitance;           /* C_p [F] */
    double resistance;            /* R_l [Ohm] (resistor) */
    double storage_capacitance, storage_resistance; /* C_s [F], R_s [Ohm] (rectifier) */
    double diode_drop;            /* V_f [V] per diode (rectifier) */
    double theta[REF_MAX_Q];      /* theta_k = Theta (phi_k'(x_2) - phi_k'(x_1)) [N/(V sqrt(kg))]; 0 on the slider */
    ref_circuit_factors patch;    /* resistor: R_l C_p over dt_sub */
    ref_circuit_factors storage;  /* rectifier: R_s C_s over dt_sub */
    double voltage_weight;        /* kappa: the step's mean voltage is kappa v_B + (terms in u): mean (resistor), 1 (rectifier) */
    double implicit_mass;         /* c of M~ = M + c theta theta^T [s^2 / F or Ohm s] */

    double mass[REF_MAX_Q][REF_MAX_Q];     /* M, dense */
    double mass_inv[REF_MAX_Q][REF_MAX_Q]; /* M~^-1 (= M^-1 without a patch) on the free coordinates
                                              (beta row/column 0 when locked) */
    double sensor_phi[REF_MAX_MODES];      /* phi_k(4/7) [1/sqrt(kg)] */
} ref_scene;

/* Builds the reference scene from p with n_modes = p->modes (0 allowed:
 * rigid beam), model and start position from p->model and p->s0 and K
 * substeps per dt. Refuses (-1, message in err) a schedule that does not
 * parse, a patch outside [0, L] or touching neither clamp, and a start
 * position over the patch. Returns 0 or -1. */
int ref_scene_init(ref_scene *scene, const scene_params *p, int substeps, char *err, size_t err_size);

/* Time of half-substep index j (t = j dt_sub / 2) in long double: never accumulated. */
long double ref_scene_time(const ref_scene *scene, uint64_t half_steps);

/* Base motion at t (phase reduced exactly: 2 pi frac(cycles)). */
void ref_scene_excitation(const ref_scene *scene, long double t, ref_excitation *ex);

/* Excitation periods completed by t: phase(t) / (2 pi) = int_0^t f dt. */
long double ref_scene_cycles(const ref_scene *scene, long double t);

/* Mean base acceleration over [t_b, t_e] (docs/model.md 10):
 * (dw0(t_e) - dw0(t_b)) / (t_e - t_b), for the harmonic in closed form,
 * for a schedule by Gauss-Legendre on each piece between schedule points. */
long double ref_scene_mean_accel(const ref_scene *scene, long double t_b, long double t_e);

/* The same over Moreau step n (from t = n dt_sub to (n+1) dt_sub). */
double ref_scene_step_accel(const ref_scene *scene, uint64_t step);

/* Elastic deflection w(x) and slope w'(x) = dw/dx of the beam at x for
 * modal coordinates q_b (zero outside [0, L]); phi, phi_x receive phi_k(x/L)
 * and d phi_k / dx when not NULL. */
void ref_scene_beam(const ref_scene *scene, const double *q_b, double x, double *w, double *w_x,
                    double *phi, double *phi_x);

/* Sensor signal w(4L/7) [m]. */
double ref_scene_sensor(const ref_scene *scene, const double *q);

/* Name of a load: "none", "resistor", "rectifier". */
const char *ref_scene_load_name(ref_load load);

#endif
