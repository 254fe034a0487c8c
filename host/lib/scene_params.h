/* scene_params.h - a scene as physical parameters (what the INI files hold). */
#ifndef SCENE_PARAMS_H
#define SCENE_PARAMS_H

#include <stddef.h>
#include "beamslider.h"
#include "modal.h"

#define SCENE_TEXT 128

typedef struct scene_params {
    char name[SCENE_TEXT];          /* [scene] name, default: file name without .ini */
    char description[SCENE_TEXT];   /* [scene] description */
    modal_beam beam;                /* [beam], [clamps] */
    double damping_ratio;           /* D, all modes */
    double slider_mass;             /* m [kg] */
    double slider_inertia;          /* J_C [kg m^2] */
    double slot_width;              /* B [m] */
    double com_offset;              /* d [m] */
    double play_ratio;              /* r_h = R / h */
    int rotation;                   /* 1: the slider may rotate, 0: locked */
    double mu;                      /* Coulomb friction */
    double e_n;                     /* normal restitution */
    double gravity;                 /* g [m/s^2] */
    double tilt;                    /* beam axis above horizontal [deg] */
    double frequency;               /* f_ex [Hz] */
    double acceleration;            /* a [m/s^2] */
    int modes;                      /* N */
    int implicit;                   /* 0: explicit midpoint step, 1: linearly implicit theta step */
    double theta;                   /* implicit step's theta, [1/2, 1] */
    int stretching;                 /* 1: cubic bending-stretching term, 0: left out */
    double dt;                      /* [s] */
    int solver_max_sweeps;          /* [solver]: the run's bs_solver_options */
    double solver_tol_rel;
    double solver_tol_abs;          /* [N s] */
    int solver_residual;            /* measure_residual */
    double s0;                      /* start position x_C / L */
    double t_end;                   /* [s] */
    int model;                      /* bs_model */
} scene_params;

typedef enum field_kind { FIELD_REAL, FIELD_INT, FIELD_CHOICE, FIELD_TEXT } field_kind;

/* One INI field: where it lives, what it means and its allowed range
 * (low/high, each open or closed; a FIELD_CHOICE stores the index of its
 * value in choices). A field with a default may be left out. */
typedef struct field_spec {
    const char *section;
    const char *key;
    field_kind kind;
    size_t offset;
    double low, high;
    int low_open, high_open;
    const char *unit;
    const char *meaning;
    const char *const *choices;     /* FIELD_CHOICE: names, NULL-terminated */
    const char *default_text;       /* NULL: required */
} field_spec;

/* The table of every field, terminated by an entry with key NULL. */
extern const field_spec scene_fields[];

/* Writes "[low, high)" style text of f's range into out. */
void field_range_text(const field_spec *f, char *out, size_t size);

/* Numbers in messages (size: at least 32 characters each). Bounds print
 * with the fewest significant digits, 6 at least and 17 at most, that keep
 * the text on the allowed side of the bound: a user who types it back is
 * accepted (%g could round 0.9642857 up to 0.964286, outside). Never %f: a
 * bound can be any double.
 *   bound_text:       side < 0: a lower bound (text >= value); side > 0: an
 *                     upper bound (text <= value); 0: %.6g
 *   range_ends_text:  both ends of [low, high] as bounds, with more digits
 *                     where 6 would print two different ends alike
 *                     ("[0.5, 0.5]")
 *   values_text:      two different values that must read differently */
void bound_text(double value, int side, char *out, size_t size);
void range_ends_text(double low, double high, char *low_text, char *high_text, size_t size);
void values_text(double a, double b, char *a_text, char *b_text, size_t size);

#endif
