/* scene_fields.h - every field a scene file (INI) may hold, written once.
 *
 * SCENE_FIELDS(X) calls X once per field, in the order of the docs:
 *
 *   X(kind, section, key, member, where, low, high, low_open, high_open, default, unit, meaning, choices)
 *
 *   kind      REAL (double), INT (int), CHOICE (int: the index of the value
 *             in choices) or TEXT (char[SCENE_TEXT])
 *   member    where it is stored in scene_params (offsetof designator)
 *   where     OWN: a member of scene_params, declared from this table;
 *             NESTED: inside scene_params.beam (modal_beam, the modal
 *             analysis's own input type, host/lib/scene/modal.h)
 *   low, high the allowed range (REAL, INT), each end open (1) or closed (0)
 *   default   the value when the file leaves the field out, as text; 0: required
 *   unit      SI unit ("" for a pure number)
 *   choices   the CHOICE's names (NULL-terminated list), else 0
 *
 * From it come scene_params (scene_params.h), the INI reader's table and its
 * range checks (scene_fields.c, scene_ini.c) and the field reference
 * `beamslider fields` / docs/fields.md. The core's own scene (what these
 * parameters become) has its table in core/include/bs_scene_fields.h.
 */
#ifndef SCENE_FIELDS_H
#define SCENE_FIELDS_H

#include <math.h>
#include "beamslider.h"

#define SCENE_TEXT 128

/* The text of a macro's value (the library's solver defaults). */
#define SCENE_TEXT_OF(macro) SCENE_TEXT_OF_(macro)
#define SCENE_TEXT_OF_(value) #value

/* Choice lists (scene_fields.c): the index of the name is the stored value. */
extern const char *const scene_models[];       /* free, pcs (= bs_model) */
extern const char *const scene_rotations[];    /* locked, free (rotation = 1: free) */
extern const char *const scene_switches[];     /* off, on */
extern const char *const scene_integrators[];  /* explicit, implicit */
extern const char *const scene_loads[];        /* none, resistor, rectifier (SCENE_LOAD_*) */

/* [transducer] load: what the piezoelectric patch drives (docs/model.md 11);
 * the choice's index is the core's bs_load. */
enum { SCENE_LOAD_NONE = BS_LOAD_NONE, SCENE_LOAD_RESISTOR = BS_LOAD_RESISTOR, SCENE_LOAD_RECTIFIER = BS_LOAD_RECTIFIER };

#define SCENE_FIELDS(X)                                                                                      \
    X(TEXT, "scene", "name", name, OWN, 0, 0, 0, 0, "", "", "scene name (default: the file name without .ini)", 0) \
    X(TEXT, "scene", "description", description, OWN, 0, 0, 0, 0, "", "", "one line on what the scene shows", 0) \
    X(REAL, "beam", "length", beam.length, NESTED, 0, HUGE_VAL, 1, 1, 0, "m", "free length L between the clamps", 0) \
    X(REAL, "beam", "thickness", beam.thickness, NESTED, 0, HUGE_VAL, 1, 1, 0, "m", "thickness h", 0)           \
    X(REAL, "beam", "density", beam.density, NESTED, 0, HUGE_VAL, 1, 1, 0, "kg/m^3", "density rho", 0)         \
    X(REAL, "beam", "youngs_modulus", beam.youngs_modulus, NESTED, 0, HUGE_VAL, 1, 1, 0, "Pa", "Young's modulus E", 0) \
    X(REAL, "beam", "mass", beam.mass, NESTED, 0, HUGE_VAL, 1, 1, 0, "kg",                                      \
      "mass rho A L of the free length (sets the width)", 0)                                                \
    X(REAL, "beam", "damping_ratio", damping_ratio, OWN, 0, 1, 0, 1, 0, "", "modal damping ratio D of every mode", 0) \
    X(REAL, "clamps", "rotational_stiffness", beam.k_rot, NESTED, 0, HUGE_VAL, 1, 1, 0, "N m/rad",             \
      "rotational spring k_r at each end", 0)                                                               \
    X(REAL, "clamps", "axial_stiffness", beam.k_axial, NESTED, 0, HUGE_VAL, 1, 1, 0, "N/m",                   \
      "axial stiffness k_t of the clamps", 0)                                                               \
    X(REAL, "slider", "mass", slider_mass, OWN, 0, HUGE_VAL, 1, 1, 0, "kg", "slider mass m", 0)                \
    X(REAL, "slider", "inertia", slider_inertia, OWN, 0, HUGE_VAL, 1, 1, 0, "kg m^2",                         \
      "rotary inertia J_C about the centre of mass", 0)                                                      \
    X(REAL, "slider", "slot_width", slot_width, OWN, 0, HUGE_VAL, 1, 1, 0, "m",                               \
      "distance B between the slot's contact corners", 0)                                                    \
    X(REAL, "slider", "com_offset", com_offset, OWN, -HUGE_VAL, HUGE_VAL, 1, 1, 0, "m",                       \
      "distance d of the centre of mass below the slot centre", 0)                                           \
    X(REAL, "slider", "play_ratio", play_ratio, OWN, 1, HUGE_VAL, 0, 1, 0, "",                                \
      "slot height over beam thickness r_h = R/h", 0)                                                        \
    X(CHOICE, "slider", "rotation", rotation, OWN, 0, 0, 0, 0, "free", "",                                      \
      "free | locked (a guided slider that cannot tilt)", scene_rotations)                                    \
    X(REAL, "contact", "friction", mu, OWN, 0, HUGE_VAL, 0, 1, 0, "", "Coulomb friction coefficient mu", 0)     \
    X(REAL, "contact", "restitution", e_n, OWN, 0, 1, 0, 0, 0, "", "Newton normal restitution e_N", 0)          \
    X(REAL, "environment", "gravity", gravity, OWN, 0, HUGE_VAL, 0, 1, 0, "m/s^2", "acceleration of gravity g", 0) \
    X(REAL, "environment", "tilt", tilt, OWN, -90, 90, 1, 1, 0, "deg", "beam axis above the horizontal", 0)    \
    X(REAL, "excitation", "frequency", frequency, OWN, 0, HUGE_VAL, 1, 1, 0, "Hz", "excitation frequency f_ex", 0) \
    X(REAL, "excitation", "acceleration", acceleration, OWN, 0, HUGE_VAL, 0, 1, 0, "m/s^2",                   \
      "base acceleration amplitude a", 0)                                                                   \
    X(TEXT, "excitation", "schedule", schedule, OWN, 0, 0, 0, 0, "", "s Hz m/s^2",                              \
      "a varying excitation: t:f:a[, t:f:a ...], frequency and amplitude linear in time between the points "   \
      "(held before the first and after the last; the phase stays continuous); empty: constant. Each point "   \
      "within the ranges of frequency (f dt < 1/2) and acceleration", 0)                                     \
    X(INT, "numerics", "modes", modes, OWN, 1, BS_MAX_MODES, 0, 0, 0, "", "number of beam modes N", 0)         \
    X(CHOICE, "numerics", "stretching", stretching, OWN, 0, 0, 0, 0, "on", "",                                 \
      "on | off: the cubic bending-stretching term", scene_switches)                                         \
    X(REAL, "numerics", "dt", dt, OWN, 0, HUGE_VAL, 1, 1, 0, "s", "time step (explicit limit: omega_max dt < 2)", 0) \
    X(CHOICE, "numerics", "integrator", implicit, OWN, 0, 0, 0, 0, "explicit", "",                             \
      "explicit (midpoint) | implicit (modal stiffness and damping, theta method)", scene_integrators)        \
    X(REAL, "numerics", "theta", theta, OWN, 0.5, 1.0, 0, 0, "0.5", "", "theta of the implicit step", 0)       \
    X(CHOICE, "numerics", "prewarp", prewarp, OWN, 0, 0, 0, 0, "off", "",                                    \
      "on | off: each omega_k^2 replaced by (2/dt sin(omega_k dt/2))^2, so that the explicit step's discrete " \
      "frequencies are the modes' (docs/design.md 4; explicit integrator only)", scene_switches)             \
    X(INT, "solver", "max_sweeps", solver_max_sweeps, OWN, 1, BS_SOLVER_MAX_SWEEPS, 0, 0,                     \
      SCENE_TEXT_OF(BS_SOLVER_DEFAULT_MAX_SWEEPS), "", "cap on contact-solve sweeps per step (3+ contacts)", 0) \
    X(REAL, "solver", "tol_rel", solver_tol_rel, OWN, 0, HUGE_VAL, 0, 1, SCENE_TEXT_OF(BS_SOLVER_DEFAULT_TOL_REL), "", \
      "relative tolerance of the contact solve", 0)                                                         \
    X(REAL, "solver", "tol_abs", solver_tol_abs, OWN, 0, HUGE_VAL, 0, 1, SCENE_TEXT_OF(BS_SOLVER_DEFAULT_TOL_ABS), \
      "N s", "absolute tolerance of the contact solve", 0)                                                  \
    X(CHOICE, "solver", "residual", solver_residual, OWN, 0, 0, 0, 0, "on", "",                               \
      "on | off: report the residual of every contact step (off: only where the solve needs it)", scene_switches)    \
    X(CHOICE, "transducer", "load", load, OWN, 0, 0, 0, 0, "none", "",                                        \
      "none | resistor | rectifier: the piezoelectric patch and what it drives (none: no patch)", scene_loads) \
    X(REAL, "transducer", "patch_start", patch_start, OWN, 0, HUGE_VAL, 0, 1, "0", "m",                       \
      "x_1, where the patch begins (from the left clamp)", 0)                                               \
    X(REAL, "transducer", "patch_end", patch_end, OWN, 0, HUGE_VAL, 1, 1, "0.02", "m",                         \
      "x_2, where it ends; the clamp stop on its side moves to x_2 + B/2", 0)                               \
    X(REAL, "transducer", "coupling", coupling, OWN, -HUGE_VAL, HUGE_VAL, 1, 1, "9.7e-5", "N m/V",            \
      "Theta, bending moment per volt (sign of e31)", 0)                                                    \
    X(REAL, "transducer", "capacitance", capacitance, OWN, 0, HUGE_VAL, 1, 1, "18e-9", "F", "C_p, the patch's capacitance", 0) \
    X(REAL, "transducer", "resistance", resistance, OWN, 0, HUGE_VAL, 1, 1, "71e3", "Ohm",                     \
      "R_l, the resistor load across the patch (load = resistor)", 0)                                      \
    X(REAL, "transducer", "storage_capacitance", storage_capacitance, OWN, 0, HUGE_VAL, 1, 1, "10e-6", "F",   \
      "C_s, charged through a full-bridge rectifier (load = rectifier)", 0)                                 \
    X(REAL, "transducer", "storage_resistance", storage_resistance, OWN, 0, HUGE_VAL, 1, 1, "1e6", "Ohm",      \
      "R_s, the load across C_s (load = rectifier)", 0)                                                     \
    X(REAL, "transducer", "diode_drop", diode_drop, OWN, 0, HUGE_VAL, 0, 1, "0", "V",                          \
      "forward voltage of each bridge diode (load = rectifier; two conduct at a time)", 0)                  \
    X(REAL, "run", "s0", s0, OWN, 0, 1, 0, 0, 0, "", "start position x_C / L (PCS: prescribed position)", 0)   \
    X(REAL, "run", "t_end", t_end, OWN, 0, HUGE_VAL, 1, 1, 0, "s", "simulated time", 0)                        \
    X(CHOICE, "run", "model", model, OWN, 0, 0, 0, 0, 0, "", "free | pcs (the model variant, bs_model)", scene_models)

#endif
