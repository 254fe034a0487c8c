/* scene_fields.c - the table of every field a scene file may hold
 * (scene_fields.h), for the INI reader, its messages and the docs' field list;
 * and how its ranges and bounds are written in messages. */
#include "scene_params.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const scene_models[] = { "free", "pcs", 0 };
const char *const scene_rotations[] = { "locked", "free", 0 };
const char *const scene_switches[] = { "off", "on", 0 };
const char *const scene_integrators[] = { "explicit", "implicit", 0 };
const char *const scene_loads[] = { "none", "resistor", "rectifier", 0 };

#define SPEC(kind, section, key, member, where, low, high, low_open, high_open, default_text, unit, meaning, \
             choices)                                                                                    \
    { section, key, FIELD_##kind, offsetof(scene_params, member), low, high, low_open, high_open, unit,  \
      meaning, choices, default_text },

const field_spec scene_fields[] = {
    SCENE_FIELDS(SPEC)
    { 0, 0, FIELD_REAL, 0, 0, 0, 0, 0, 0, 0, 0, 0 }
};

#define FEW_DIGITS 6   /* what %g prints */
#define ALL_DIGITS 17  /* enough for any double to read back exactly */

static void number_text(double value, int digits, char *out, size_t size)
{
    if (isinf(value))
        snprintf(out, size, value < 0.0 ? "-inf" : "inf");
    else
        snprintf(out, size, "%.*g", digits, value);
}

/* 1 if text, read back, lies on the allowed side of the bound value. */
static int on_allowed_side(const char *text, double value, int side)
{
    const double read = strtod(text, NULL);
    return side < 0 ? read >= value : side > 0 ? read <= value : 1;
}

/* The fewest digits (FEW_DIGITS .. ALL_DIGITS) keeping value on its side. */
static int bound_digits(double value, int side)
{
    char text[40];
    int digits;
    for (digits = FEW_DIGITS; digits < ALL_DIGITS; ++digits) {
        number_text(value, digits, text, sizeof text);
        if (on_allowed_side(text, value, side))
            break;
    }
    return digits;
}

void bound_text(double value, int side, char *out, size_t size)
{
    number_text(value, bound_digits(value, side), out, size);
}

/* a and b with at least digits_a, digits_b digits, more for both until they
 * read differently (a != b) */
static void pair_text(double a, double b, int digits_a, int digits_b, char *a_text, char *b_text, size_t size)
{
    for (;;) {
        number_text(a, digits_a, a_text, size);
        number_text(b, digits_b, b_text, size);
        if (a == b || strcmp(a_text, b_text) || (digits_a >= ALL_DIGITS && digits_b >= ALL_DIGITS))
            return;
        digits_a = digits_b = (digits_a > digits_b ? digits_a : digits_b) + 1;
    }
}

void range_ends_text(double low, double high, char *low_text, char *high_text, size_t size)
{
    pair_text(low, high, bound_digits(low, -1), bound_digits(high, 1), low_text, high_text, size);
}

void values_text(double a, double b, char *a_text, char *b_text, size_t size)
{
    pair_text(a, b, FEW_DIGITS, FEW_DIGITS, a_text, b_text, size);
}

void field_range_text(const field_spec *f, char *out, size_t size)
{
    char low[40];
    char high[40];

    if (f->kind == FIELD_CHOICE) {
        const char *const *name;
        size_t used = (size_t)snprintf(out, size, "one of:");
        for (name = f->choices; *name && used < size; ++name)
            used += (size_t)snprintf(out + used, size - used, "%s %s", name == f->choices ? "" : ",", *name);
        return;
    }
    if (f->kind == FIELD_TEXT) {
        snprintf(out, size, "text of at most %d characters", SCENE_TEXT - 1);
        return;
    }
    if (f->kind == FIELD_INT) { /* the table's integer bounds are small */
        snprintf(out, size, "an integer in [%ld, %ld]", (long)f->low, (long)f->high);
        return;
    }
    range_ends_text(f->low, f->high, low, high, sizeof low);
    snprintf(out, size, "a finite number in %c%s, %s%c%s%s", f->low_open ? '(' : '[', low, high,
             f->high_open ? ')' : ']', *f->unit ? " " : "", f->unit);
}
