/* scene_origins.h - the one table of where each derived quantity comes
 * from: which input fields of the scene file (with the power each enters
 * with), which core scene fields it becomes, and where it is held (which
 * number type limits it). Every refusal that names inputs reads it:
 *   - scene_limits.c checks each held quantity against its number type
 *     before anything is computed, and the range each input may take with
 *     the others as set (docs/robustness.md section 6);
 *   - scene_build.c names, when the core refuses a scene anyway
 *     (bs_scene_check's field), the inputs of that core field.
 *
 * Adding a derived quantity: a row. Its factors are the inputs and their
 * powers (q = c prod f_i^p_i up to the bounded factor c); a row held
 * nowhere (ORIGIN_UNCHECKED) only says which inputs make a core field, its
 * powers unused.
 */
#ifndef SCENE_ORIGINS_H
#define SCENE_ORIGINS_H

#include "scene_params.h"

#define SCENE_ORIGIN_FACTORS 6

/* One input field of a derived quantity. */
typedef struct scene_input {
    const char *section, *key;
} scene_input;

typedef struct scene_factor {
    const char *section, *key;
    double power;
} scene_factor;

/* Where the quantity is held, which sets its limits. */
typedef enum origin_holder {
    ORIGIN_UNCHECKED,   /* no limit of its own: the row only names inputs */
    ORIGIN_IN_DOUBLE,   /* the host computes it in double */
    ORIGIN_IN_CORE,     /* the core holds it in bs_real */
    ORIGIN_PHASE_STEP,  /* in 2^-64 turns: must not round to 0 */
    ORIGIN_MODE_GAIN    /* 1 / the implicit step's mode gain, in bs_real */
} origin_holder;
typedef enum origin_bound { ORIGIN_BELOW = 1, ORIGIN_ABOVE = 2, ORIGIN_BOTH = 3 } origin_bound;
/* When the quantity exists for a scene. */
typedef enum origin_condition {
    ORIGIN_ALWAYS, ORIGIN_IF_ROTATION, ORIGIN_IF_IMPLICIT, ORIGIN_IF_AXIAL_STRETCH, ORIGIN_IF_BEAM_STRETCH,
    ORIGIN_IF_TRANSDUCER, ORIGIN_IF_RESISTOR, ORIGIN_IF_RECTIFIER
} origin_condition;
/* The bounded factor c (scene_limits.c takes it at its bound). */
typedef enum origin_constant {
    ORIGIN_K_ONE, ORIGIN_K_HALF, ORIGIN_K_TWO, ORIGIN_K_FOUR, ORIGIN_K_TWELFTH, ORIGIN_K_TWELVE,
    ORIGIN_K_OMEGA_SQ, ORIGIN_K_DAMPING, ORIGIN_K_SLOPE, ORIGIN_K_STRETCH, ORIGIN_K_PIECES, ORIGIN_K_GAIN
} origin_constant;

typedef struct scene_origin {
    const char *core_fields;  /* the bs_scene fields it makes, separated by blanks ("" none: a host
                                 quantity; "*": also every core field no row names) */
    const char *what;         /* the quantity in messages */
    origin_holder held;
    origin_bound bounds;      /* which of the holder's limits apply */
    origin_condition when;
    origin_constant c;
    scene_factor factors[SCENE_ORIGIN_FACTORS]; /* ends at section NULL */
} scene_origin;

/* The table, in the order the limits are checked; scene_origin_count rows. */
extern const scene_origin scene_origins[];
extern const int scene_origin_count;

/* The inputs core field core_field (bs_scene_check's name, up to a blank)
 * comes from: the factors of every row that makes it, each input once, in
 * the table's order, at most max of them. Returns their count. */
int scene_origin_inputs(const char *core_field, scene_input *inputs, int max);

#endif
