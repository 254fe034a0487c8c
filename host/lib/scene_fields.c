/* scene_fields.c - every field a scene file may hold, with unit and range.
 * The INI reader, the error messages and the docs' field list all come from
 * this one table. */
#include "scene_params.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REAL(section, key, member, low, high, low_open, high_open, unit, meaning) \
    { section, key, FIELD_REAL, offsetof(scene_params, member), low, high, low_open, high_open, unit, meaning, 0, 0 }
#define INT(section, key, member, low, high, unit, meaning) \
    { section, key, FIELD_INT, offsetof(scene_params, member), low, high, 0, 0, unit, meaning, 0, 0 }
#define CHOICE(section, key, member, choices, default_text, meaning) \
    { section, key, FIELD_CHOICE, offsetof(scene_params, member), 0, 0, 0, 0, "", meaning, choices, default_text }
#define REAL_OPTIONAL(section, key, member, low, high, default_text, unit, meaning) \
    { section, key, FIELD_REAL, offsetof(scene_params, member), low, high, 0, 0, unit, meaning, 0, default_text }
#define INT_OPTIONAL(section, key, member, low, high, default_text, unit, meaning) \
    { section, key, FIELD_INT, offsetof(scene_params, member), low, high, 0, 0, unit, meaning, 0, default_text }
#define TEXT(section, key, member, meaning) \
    { section, key, FIELD_TEXT, offsetof(scene_params, member), 0, 0, 0, 0, "", meaning, 0, "" }

/* The text of a macro's value (the library's solver defaults). */
#define TEXT_OF(macro) TEXT_OF_(macro)
#define TEXT_OF_(value) #value

/* Choice lists: the index of the name is the stored value. */
static const char *const models[] = { "free", "pcs", 0 };           /* = bs_model */
static const char *const rotations[] = { "locked", "free", 0 };     /* rotation = 1: free */
static const char *const switches[] = { "off", "on", 0 };
static const char *const integrators[] = { "explicit", "implicit", 0 };

const field_spec scene_fields[] = {
    TEXT("scene", "name", name, "scene name"),
    TEXT("scene", "description", description, "one line on what the scene shows"),
    REAL("beam", "length", beam.length, 0, HUGE_VAL, 1, 1, "m", "free length L between the clamps"),
    REAL("beam", "thickness", beam.thickness, 0, HUGE_VAL, 1, 1, "m", "thickness h"),
    REAL("beam", "density", beam.density, 0, HUGE_VAL, 1, 1, "kg/m^3", "density rho"),
    REAL("beam", "youngs_modulus", beam.youngs_modulus, 0, HUGE_VAL, 1, 1, "Pa", "Young's modulus E"),
    REAL("beam", "mass", beam.mass, 0, HUGE_VAL, 1, 1, "kg", "mass rho A L of the free length (sets the width)"),
    REAL("beam", "damping_ratio", damping_ratio, 0, 1, 0, 1, "", "modal damping ratio D of every mode"),
    REAL("clamps", "rotational_stiffness", beam.k_rot, 0, HUGE_VAL, 1, 1, "N m/rad", "rotational spring k_r at each end"),
    REAL("clamps", "axial_stiffness", beam.k_axial, 0, HUGE_VAL, 1, 1, "N/m", "axial stiffness k_t of the clamps"),
    REAL("slider", "mass", slider_mass, 0, HUGE_VAL, 1, 1, "kg", "slider mass m"),
    REAL("slider", "inertia", slider_inertia, 0, HUGE_VAL, 1, 1, "kg m^2", "rotary inertia J_C about the centre of mass"),
    REAL("slider", "slot_width", slot_width, 0, HUGE_VAL, 1, 1, "m", "distance B between the slot's contact corners"),
    REAL("slider", "com_offset", com_offset, -HUGE_VAL, HUGE_VAL, 1, 1, "m", "distance d of the centre of mass below the slot centre"),
    REAL("slider", "play_ratio", play_ratio, 1, HUGE_VAL, 0, 1, "", "slot height over beam thickness r_h = R/h"),
    CHOICE("slider", "rotation", rotation, rotations, "free", "free | locked (a guided slider that cannot tilt)"),
    REAL("contact", "friction", mu, 0, HUGE_VAL, 0, 1, "", "Coulomb friction coefficient mu"),
    REAL("contact", "restitution", e_n, 0, 1, 0, 0, "", "Newton normal restitution e_N"),
    REAL("environment", "gravity", gravity, 0, HUGE_VAL, 0, 1, "m/s^2", "acceleration of gravity g"),
    REAL("environment", "tilt", tilt, -90, 90, 1, 1, "deg", "beam axis above the horizontal"),
    REAL("excitation", "frequency", frequency, 0, HUGE_VAL, 1, 1, "Hz", "excitation frequency f_ex"),
    REAL("excitation", "acceleration", acceleration, 0, HUGE_VAL, 0, 1, "m/s^2", "base acceleration amplitude a"),
    INT("numerics", "modes", modes, 1, BS_MAX_MODES, "", "number of beam modes N"),
    CHOICE("numerics", "stretching", stretching, switches, "on", "on | off: the cubic bending-stretching term"),
    REAL("numerics", "dt", dt, 0, HUGE_VAL, 1, 1, "s", "time step (explicit limit: omega_max dt < 2)"),
    CHOICE("numerics", "integrator", implicit, integrators, "explicit",
           "explicit (midpoint) | implicit (modal stiffness and damping, theta method)"),
    REAL_OPTIONAL("numerics", "theta", theta, 0.5, 1.0, "0.5", "", "theta of the implicit step"),
    INT_OPTIONAL("solver", "max_sweeps", solver_max_sweeps, 1, BS_SOLVER_MAX_SWEEPS,
                 TEXT_OF(BS_SOLVER_DEFAULT_MAX_SWEEPS), "", "cap on contact-solve sweeps per step"),
    REAL_OPTIONAL("solver", "tol_rel", solver_tol_rel, 0, HUGE_VAL, TEXT_OF(BS_SOLVER_DEFAULT_TOL_REL), "",
                  "relative tolerance of the contact solve"),
    REAL_OPTIONAL("solver", "tol_abs", solver_tol_abs, 0, HUGE_VAL, TEXT_OF(BS_SOLVER_DEFAULT_TOL_ABS), "N s",
                  "absolute tolerance of the contact solve"),
    CHOICE("solver", "residual", solver_residual, switches, "on",
           "on | off: measure the residual after each sweep (off: exactly max_sweeps sweeps)"),
    REAL("run", "s0", s0, 0, 1, 0, 0, "", "start position x_C / L (PCS: prescribed position)"),
    REAL("run", "t_end", t_end, 0, HUGE_VAL, 1, 1, "s", "simulated time"),
    CHOICE("run", "model", model, models, 0, "free | pcs"),
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
