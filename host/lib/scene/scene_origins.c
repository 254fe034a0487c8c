/* scene_origins.c - where each derived quantity comes from (scene_origins.h).
 *
 * The held quantities come first, in the order scene_limits_check tries
 * them (the first out of its limits is the one reported); the rows that
 * only name inputs follow. Powers from docs/model.md 3 and 8 and
 * host/lib/scene/modal.c; lambda_k and the shape constants are bounded
 * (scene_limits.c).
 */
#include "scene_origins.h"

#include <string.h>

#define LENGTH(p) { "beam", "length", p }
#define THICKNESS(p) { "beam", "thickness", p }
#define DENSITY(p) { "beam", "density", p }
#define YOUNG(p) { "beam", "youngs_modulus", p }
#define BEAM_MASS(p) { "beam", "mass", p }
#define INPUT(section, key) { section, key, 0.0 }
#define MODAL_INPUTS LENGTH(0), THICKNESS(0), DENSITY(0), YOUNG(0), BEAM_MASS(0), INPUT("clamps", "rotational_stiffness")
#define MODAL_DATA "omega_sq gamma phi_sensor shape_coef shape_pieces n_modes damping stretch mode_gain modal *"

const scene_origin scene_origins[] = {
    /* the host's modal analysis, in double (modal.c) */
    { "", "density thickness length (in the beam width)", ORIGIN_IN_DOUBLE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { DENSITY(1), THICKNESS(1), LENGTH(1) } },
    { "", "the beam width b = mass / (density thickness length)", ORIGIN_IN_DOUBLE, ORIGIN_BOTH, ORIGIN_ALWAYS,
      ORIGIN_K_ONE, { BEAM_MASS(1), DENSITY(-1), THICKNESS(-1), LENGTH(-1) } },
    { "", "E b (in the bending stiffness)", ORIGIN_IN_DOUBLE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { YOUNG(1), BEAM_MASS(1), DENSITY(-1), THICKNESS(-1), LENGTH(-1) } },
    { "", "thickness^3 (in the bending stiffness)", ORIGIN_IN_DOUBLE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { THICKNESS(3) } },
    { "", "the bending stiffness EI = E b h^3 / 12", ORIGIN_IN_DOUBLE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_TWELFTH,
      { YOUNG(1), BEAM_MASS(1), THICKNESS(2), DENSITY(-1), LENGTH(-1) } },
    { "", "k_r L (in kappa)", ORIGIN_IN_DOUBLE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "clamps", "rotational_stiffness", 1 }, LENGTH(1) } },
    { "", "the clamp stiffness kappa = k_r L / EI", ORIGIN_IN_DOUBLE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_TWELVE,
      { { "clamps", "rotational_stiffness", 1 }, LENGTH(2), DENSITY(1), YOUNG(-1), BEAM_MASS(-1), THICKNESS(-2) } },
    { "", "mass length^3 (in the modal frequencies)", ORIGIN_IN_DOUBLE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { BEAM_MASS(1), LENGTH(3) } },
    { "", "the mode normalisation 1 / mass", ORIGIN_IN_DOUBLE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { BEAM_MASS(-1) } },
    { "", "the slope integrals I_ij ~ lambda^2 / mass", ORIGIN_IN_DOUBLE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_SLOPE,
      { BEAM_MASS(-1) } },
    /* what the core holds, in bs_real (scene_build.c, scene_data_round; the solver options) */
    { "omega_sq", "omega_k^2 = lambda_k^4 E h^2 / (12 rho L^4)", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_ALWAYS,
      ORIGIN_K_OMEGA_SQ, { YOUNG(1), THICKNESS(2), DENSITY(-1), LENGTH(-4) } },
    { "damping", "the modal damping 2 D omega_k", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_DAMPING,
      { { "beam", "damping_ratio", 1 }, YOUNG(0.5), THICKNESS(1), DENSITY(-0.5), LENGTH(-2) } },
    { "gamma", "the modal masses gamma_k ~ sqrt(mass)", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { BEAM_MASS(0.5) } },
    { "phi_sensor shape_coef", "the mode shapes phi_k ~ 1 / sqrt(mass)", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS,
      ORIGIN_K_FOUR, { BEAM_MASS(-0.5) } },
    { "stretch modal", "the stretching matrix sqrt(k_t / 2 L^2) I_ij", ORIGIN_IN_CORE, ORIGIN_ABOVE,
      ORIGIN_IF_AXIAL_STRETCH, ORIGIN_K_STRETCH, { { "clamps", "axial_stiffness", 0.5 }, LENGTH(-1), BEAM_MASS(-1) } },
    { "stretch", "the stretching matrix sqrt(EA / 2 L^3) I_ij", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_IF_BEAM_STRETCH,
      ORIGIN_K_STRETCH, { YOUNG(0.5), DENSITY(-0.5), LENGTH(-2), BEAM_MASS(-0.5) } },
    { "length", "the beam length", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE, { LENGTH(1) } },
    { "shape_scale", "the shape table's scale pieces / L", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_PIECES,
      { LENGTH(-1) } },
    { "half_thickness", "the half thickness h / 2", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_HALF,
      { THICKNESS(1) } },
    { "corner stop_min/stop_max", "the slot corners' B / 2", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_ALWAYS,
      ORIGIN_K_HALF, { { "slider", "slot_width", 1 } } },
    { "corner", "the slot corners' R / 2 = r_h h / 2", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_HALF,
      { { "slider", "play_ratio", 1 }, THICKNESS(1) } },
    { "corner com_offset", "the slot corners' offset d (and the start height)", ORIGIN_IN_CORE, ORIGIN_ABOVE,
      ORIGIN_ALWAYS, ORIGIN_K_TWO, { { "slider", "com_offset", 1 } } },
    { "mass_inv", "1 / slider mass", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "slider", "mass", -1 } } },
    { "inertia_inv", "1 / slider inertia", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_IF_ROTATION, ORIGIN_K_ONE,
      { { "slider", "inertia", -1 } } },
    { "gravity", "gravity", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "environment", "gravity", 1 } } },
    { "mu", "the friction coefficient", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "contact", "friction", 1 } } },
    { "base_accel", "the base acceleration a", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "excitation", "acceleration", 1 } } },
    { "frequency", "the excitation frequency", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "excitation", "frequency", 1 } } },
    { "phase_step_half frequency/phase_step_half", "f_ex dt (the phase step f_ex dt 2^63 must not round to 0)",
      ORIGIN_PHASE_STEP, ORIGIN_BELOW, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "excitation", "frequency", 1 }, { "numerics", "dt", 1 } } },
    { "dt", "the time step", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE, { { "numerics", "dt", 1 } } },
    { "mode_gain", "theta^2 dt^2 omega_N^2 (the implicit step's mode gain must not round to 0)", ORIGIN_MODE_GAIN,
      ORIGIN_ABOVE, ORIGIN_IF_IMPLICIT, ORIGIN_K_GAIN,
      { { "numerics", "dt", 2 }, YOUNG(1), THICKNESS(2), DENSITY(-1), LENGTH(-4) } },
    { "", "the relative tolerance of the contact solve", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "solver", "tol_rel", 1 } } },
    /* the transducer's (scene_build.c, compute_transducer) */
    { "piezo_capacitance_inv", "1 / C_p, the patch's inverse capacitance", ORIGIN_IN_CORE, ORIGIN_BOTH,
      ORIGIN_IF_TRANSDUCER, ORIGIN_K_ONE, { { "transducer", "capacitance", -1 } } },
    { "load_conductance", "the load's conductance 1 / R", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_IF_RESISTOR,
      ORIGIN_K_ONE, { { "transducer", "resistance", -1 } } },
    { "load_conductance", "the storage's conductance 1 / R_s", ORIGIN_IN_CORE, ORIGIN_BOTH, ORIGIN_IF_RECTIFIER,
      ORIGIN_K_ONE, { { "transducer", "storage_resistance", -1 } } },
    { "storage_capacitance_inv", "1 / C_s, the storage's inverse capacitance", ORIGIN_IN_CORE, ORIGIN_BOTH,
      ORIGIN_IF_RECTIFIER, ORIGIN_K_ONE, { { "transducer", "storage_capacitance", -1 } } },
    { "bridge_drop", "the bridge's drop 2 V_d", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_IF_RECTIFIER, ORIGIN_K_TWO,
      { { "transducer", "diode_drop", 1 } } },
    { "", "the absolute tolerance of the contact solve", ORIGIN_IN_CORE, ORIGIN_ABOVE, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { { "solver", "tol_abs", 1 } } },
    /* inputs without a limit of their own */
    { MODAL_DATA, "the modal data", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE, { MODAL_INPUTS } },
    { "stop_min/stop_max stop_min stop_max", "the clamp stops B / 2 and L - B / 2", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS,
      ORIGIN_K_ONE, { INPUT("slider", "slot_width"), LENGTH(0) } },
    { "gravity", "the gravity vector's direction", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { INPUT("environment", "tilt") } },
    { "e_n", "the restitution coefficient", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { INPUT("contact", "restitution") } },
    { "implicit", "the integrator", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { INPUT("numerics", "integrator") } },
    { "theta mode_gain", "the implicit step's theta", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { INPUT("numerics", "theta") } },
    { "load", "the transducer's load", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { INPUT("transducer", "load") } },
    { "piezo_theta", "the patch's modal couplings theta_k", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS,
      ORIGIN_K_ONE,
      { INPUT("transducer", "coupling"), INPUT("transducer", "capacitance"), INPUT("numerics", "dt"),
        INPUT("transducer", "patch_start"), INPUT("transducer", "patch_end") } },
    { "load_decay", "the load's decay over half a step", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { INPUT("transducer", "resistance"), INPUT("transducer", "capacitance"),
        INPUT("transducer", "storage_resistance"), INPUT("transducer", "storage_capacitance") } },
    { "load_gain", "the load's gain", ORIGIN_UNCHECKED, ORIGIN_BOTH, ORIGIN_ALWAYS, ORIGIN_K_ONE,
      { INPUT("transducer", "resistance"), INPUT("transducer", "capacitance") } },
};

const int scene_origin_count = (int)(sizeof scene_origins / sizeof scene_origins[0]);

/* 1 if the blank-separated list names word (length characters). */
static int names(const char *list, const char *word, size_t length)
{
    while (*list) {
        const size_t n = strcspn(list, " ");
        if (n == length && !strncmp(list, word, length))
            return 1;
        list += n;
        list += strspn(list, " ");
    }
    return 0;
}

/* Adds the inputs of row o not yet in inputs. */
static int add_inputs(const scene_origin *o, scene_input *inputs, int count, int max)
{
    int j, k;
    for (j = 0; j < SCENE_ORIGIN_FACTORS && o->factors[j].section && count < max; ++j) {
        for (k = 0; k < count; ++k)
            if (!strcmp(inputs[k].section, o->factors[j].section) && !strcmp(inputs[k].key, o->factors[j].key))
                break;
        if (k == count) {
            inputs[count].section = o->factors[j].section;
            inputs[count].key = o->factors[j].key;
            ++count;
        }
    }
    return count;
}

int scene_origin_inputs(const char *core_field, scene_input *inputs, int max)
{
    const size_t length = strcspn(core_field, " ");
    int i, count = 0;
    for (i = 0; i < scene_origin_count; ++i)
        if (names(scene_origins[i].core_fields, core_field, length))
            count = add_inputs(&scene_origins[i], inputs, count, max);
    if (count == 0) /* a field no row names: the modal data's */
        for (i = 0; i < scene_origin_count; ++i)
            if (names(scene_origins[i].core_fields, "*", 1))
                count = add_inputs(&scene_origins[i], inputs, count, max);
    return count;
}
