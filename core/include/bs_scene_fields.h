/* bs_scene_fields.h - the fields of a scene, written once.
 *
 * BS_SCENE_FIELDS(X) calls X once per field of bs_scene, in struct order:
 *
 *   X(kind, name, dim1, dim2, dim3, rule, unit, meaning)
 *
 *   kind     REAL (bs_real), INT (int) or U64 (uint64_t)
 *   dimN     the array dimensions: ONE (none), MODES (BS_MAX_MODES, used:
 *            n_modes), PIECES (BS_SHAPE_MAX_PIECES, used: shape_pieces),
 *            COEFS (BS_SHAPE_COEFS), CORNERS (BS_CORNERS), XZ (2)
 *   rule     what bs_scene_check requires of every used element:
 *            FINITE, POSITIVE (> 0), NONNEGATIVE (>= 0), UNIT (in [0, 1]),
 *            or CROSS (checked with other fields, core/src/bs_scene.c)
 *   unit     SI unit ("" for a pure number)
 *   meaning  what the field is (docs/model.md, docs/design.md)
 *
 * From this one table come the struct (bs_scene.h), the core's checks
 * (core/src/bs_scene.c), and on the host the double-precision copy the scene
 * is computed in, its rounding to bs_real, the `beamslider gen` printer and
 * the field reference docs/fields.md (host/lib/scene_data.h, scene_build.c,
 * host/cli/cli_gen.c, cli_fields.c). Coordinates: x along the beam from the
 * left clamp, z up; modes are mass-normalised (modal mass 1).
 */
#ifndef BS_SCENE_FIELDS_H
#define BS_SCENE_FIELDS_H

#define BS_SCENE_FIELDS(X)                                                                            \
    /* Beam: N mass-normalised bending modes (N = 0: a rigid beam that follows the base) */           \
    X(INT, n_modes, ONE, ONE, ONE, CROSS, "", "N, beam modes: 0 .. BS_MAX_MODES")                     \
    X(REAL, omega_sq, MODES, ONE, ONE, POSITIVE, "1/s^2", "omega_k^2, squared natural frequencies")   \
    X(REAL, damping, MODES, ONE, ONE, NONNEGATIVE, "1/s", "2 D omega_k, modal damping")               \
    X(REAL, gamma, MODES, ONE, ONE, FINITE, "sqrt(kg)", "gamma_k = rho A L int phi_k, base-excitation factor") \
    X(REAL, stretch, MODES, MODES, ONE, CROSS, "1/(m sqrt(kg))",                                      \
      "S = sqrt(k_ax / (2 L^2)) I, I_ij = int phi_i' phi_j' (N(q) = (q^T S q) S q); symmetric, 0 without stretching") \
    X(REAL, phi_sensor, MODES, ONE, ONE, FINITE, "1/sqrt(kg)", "phi_k(4/7): w(4L/7) = sum phi_k q_k") \
    /* Mode shapes: shape_pieces equal polynomial pieces over [0, L] */                               \
    X(INT, shape_pieces, ONE, ONE, ONE, CROSS, "", "pieces of the mode-shape polynomials: 1 .. BS_SHAPE_MAX_PIECES") \
    X(REAL, shape_scale, ONE, ONE, ONE, CROSS, "1/m", "shape_pieces / length")                        \
    X(REAL, shape_coef, PIECES, MODES, COEFS, FINITE, "1/sqrt(kg)",                                   \
      "phi_k on piece j = sum_c coef[j][k][c] u^c, u in [-1, 1] across the piece")                    \
    /* Geometry */                                                                                    \
    X(REAL, length, ONE, ONE, ONE, POSITIVE, "m", "L, free length between the clamps")                \
    X(REAL, half_thickness, ONE, ONE, ONE, POSITIVE, "m", "h/2, half the beam thickness")             \
    X(REAL, corner, CORNERS, XZ, ONE, CROSS, "m",                                                     \
      "r_CP,i = P_i - r_GC, slot corners P1..P4 from the centre of mass, slider frame")                \
    X(REAL, com_offset, ONE, ONE, ONE, FINITE, "m", "d, centre of mass below the slot centre")        \
    X(REAL, stop_min, ONE, ONE, ONE, CROSS, "m", "left clamp stop: x_C >= stop_min")                  \
    X(REAL, stop_max, ONE, ONE, ONE, CROSS, "m", "right clamp stop: x_C <= stop_max")                 \
    /* Slider */                                                                                      \
    X(REAL, mass_inv, ONE, ONE, ONE, POSITIVE, "1/kg", "1/m, inverse slider mass")                    \
    X(REAL, inertia_inv, ONE, ONE, ONE, NONNEGATIVE, "1/(kg m^2)", "1/J_C (0: rotation locked)")      \
    X(REAL, gravity, XZ, ONE, ONE, FINITE, "m/s^2", "acceleration of gravity in the beam frame (x, z)") \
    /* Contact laws */                                                                                \
    X(REAL, mu, ONE, ONE, ONE, NONNEGATIVE, "", "Coulomb friction coefficient")                       \
    X(REAL, e_n, ONE, ONE, ONE, UNIT, "", "Newton normal restitution")                                \
    /* Piezoelectric transducer and its load (docs/model.md 11); load 0: none, the rest unused */     \
    X(INT, load, ONE, ONE, ONE, CROSS, "", "BS_LOAD_NONE, BS_LOAD_RESISTOR (R_l) or BS_LOAD_RECTIFIER (a full bridge into C_s || R_s)") \
    X(REAL, piezo_theta, MODES, ONE, ONE, FINITE, "N/(V sqrt(kg))",                                   \
      "theta_k = Theta (phi_k'(x_2) - phi_k'(x_1)), the patch's modal coupling")                      \
    X(REAL, piezo_capacitance_inv, ONE, ONE, ONE, CROSS, "1/F", "1 / C_p, the patch's inverse capacitance") \
    X(REAL, load_decay, ONE, ONE, ONE, UNIT, "",                                                      \
      "over half a step: exp(-dt / (2 R_l C_p)) of the patch voltage (resistor), exp(-dt / (2 R_s C_s)) of the storage's (rectifier)") \
    X(REAL, load_gain, ONE, ONE, ONE, NONNEGATIVE, "Ohm",                                             \
      "R_l (1 - load_decay): volts over half a step per ampere of patch current (resistor)")           \
    X(REAL, load_conductance, ONE, ONE, ONE, NONNEGATIVE, "1/Ohm",                                    \
      "1 / R_l (resistor) or 1 / R_s (rectifier): the load's power is this times its voltage squared") \
    X(REAL, storage_capacitance_inv, ONE, ONE, ONE, NONNEGATIVE, "1/F", "1 / C_s (rectifier)")       \
    X(REAL, bridge_drop, ONE, ONE, ONE, NONNEGATIVE, "V", "2 V_f, the two conducting diodes' drop (rectifier)") \
    /* Harmonic base excitation d2w0/dt2 = -a cos(Omega t), the start of a run's */                 \
    /* (bs_sim_set_excitation changes it, bs_sim_step_measured replaces it) */                        \
    X(REAL, base_accel, ONE, ONE, ONE, NONNEGATIVE, "m/s^2", "a, amplitude of the base acceleration") \
    X(REAL, frequency, ONE, ONE, ONE, POSITIVE, "Hz", "f_ex, the excitation frequency")                \
    X(U64, phase_step_half, ONE, ONE, ONE, CROSS, "turns 2^-64",                                      \
      "f_ex dt / 2 in units of 2^-64 turns: the exact phase advances by twice this per step")         \
    /* Time step */                                                                                   \
    X(REAL, dt, ONE, ONE, ONE, POSITIVE, "s", "time step (explicit step: omega_max dt < 2)")          \
    X(INT, implicit, ONE, ONE, ONE, CROSS, "", "0: explicit midpoint step, 1: linearly implicit theta step") \
    X(REAL, theta, ONE, ONE, ONE, CROSS, "", "theta of the implicit step, [1/2, 1]; 1/2 when explicit") \
    X(REAL, mode_gain, MODES, ONE, ONE, CROSS, "",                                                    \
      "1 / (1 + theta dt 2 D omega_k + theta^2 dt^2 omega_k^2) when implicit, (0, 1]; 1 when explicit")

/* Declared sizes of the dimensions (the struct's arrays). */
#define BS_DIM_ONE
#define BS_DIM_MODES [BS_MAX_MODES]
#define BS_DIM_PIECES [BS_SHAPE_MAX_PIECES]
#define BS_DIM_COEFS [BS_SHAPE_COEFS]
#define BS_DIM_CORNERS [BS_CORNERS]
#define BS_DIM_XZ [2]

/* Used extent of a dimension in scene s (what checks and printers visit). */
#define BS_USED_ONE(s) 1
#define BS_USED_MODES(s) ((s)->n_modes)
#define BS_USED_PIECES(s) ((s)->shape_pieces)
#define BS_USED_COEFS(s) BS_SHAPE_COEFS
#define BS_USED_CORNERS(s) BS_CORNERS
#define BS_USED_XZ(s) 2

/* 1 for a dimension that is one (an array), 0 for ONE: the rank of a field
 * is the sum over its three. */
#define BS_ARRAY_ONE 0
#define BS_ARRAY_MODES 1
#define BS_ARRAY_PIECES 1
#define BS_ARRAY_COEFS 1
#define BS_ARRAY_CORNERS 1
#define BS_ARRAY_XZ 1

/* Declared extent of a dimension, as a number. */
#define BS_SIZE_ONE 1
#define BS_SIZE_MODES BS_MAX_MODES
#define BS_SIZE_PIECES BS_SHAPE_MAX_PIECES
#define BS_SIZE_COEFS BS_SHAPE_COEFS
#define BS_SIZE_CORNERS BS_CORNERS
#define BS_SIZE_XZ 2

#endif
