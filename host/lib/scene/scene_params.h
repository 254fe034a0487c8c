/* scene_params.h - a scene as physical parameters (what the INI files hold). */
#ifndef SCENE_PARAMS_H
#define SCENE_PARAMS_H

#include <stddef.h>
#include "beamslider.h"
#include "modal.h"
#include "scene_fields.h"

/* The members of the field table that are scene_params' own; the [beam] and
 * [clamps] fields of the beam live in its modal_beam. */
#define SCENE_PARAM_TYPE_REAL(member) double member;
#define SCENE_PARAM_TYPE_INT(member) int member;
#define SCENE_PARAM_TYPE_CHOICE(member) int member;
#define SCENE_PARAM_TYPE_TEXT(member) char member[SCENE_TEXT];
#define SCENE_PARAM_OWN(kind, member) SCENE_PARAM_TYPE_##kind(member)
#define SCENE_PARAM_NESTED(kind, member)
#define SCENE_PARAM_MEMBER(kind, section, key, member, where, low, high, low_open, high_open, default_text, \
                           unit, meaning, choices)                                                        \
    SCENE_PARAM_##where(kind, member)

typedef struct scene_params {
    modal_beam beam;                /* [beam] and [clamps]: the modal analysis's input */
    SCENE_FIELDS(SCENE_PARAM_MEMBER)
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
