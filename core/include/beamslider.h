/* beamslider.h - public API of the beamslider core.
 *
 * A fixed-step simulator of a clamped beam under base excitation carrying a
 * rigid slider with play, friction and impacts (docs/model.md; how it is
 * computed: docs/design.md). The caller owns all memory: a bs_sim is a plain
 * struct of compile-time size, e.g.
 *
 *     static bs_sim sim;
 *     if (bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.3)) != BS_OK) ...
 *     for (;;) { if (bs_sim_step(&sim) != BS_OK) ...; }
 *
 * The core is freestanding C99: no allocation, no I/O, no globals. Math comes
 * from the port (bs_port.h). The members of bs_sim are private
 * (bs_sim_layout.h); read results through the functions below.
 *
 * Every function checks its pointers and that the sim was initialised, and
 * never crashes on a NULL or never-initialised sim: fallible calls return a
 * bs_status, read functions return the value stated with each (NaN for a
 * bs_real, 0 for a count or hash). A pointer to a sim or scene that is not
 * one (freed, misaligned, random) cannot be detected.
 */
#ifndef BEAMSLIDER_H
#define BEAMSLIDER_H

#include <stddef.h>
#include <stdint.h>
#include "bs_build_config.h"
#include "bs_config.h"
#include "bs_real.h"
#include "bs_scene.h"
#include "bs_types.h"
#include "bs_sim_layout.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Version (docs/CHANGELOG.md). Until 1.0, a minor release may change the API
 * and the layout of bs_sim; BS_BUILD_TAG carries major and minor. */
#define BS_VERSION_MAJOR 0
#define BS_VERSION_MINOR 8
#define BS_VERSION_PATCH 0
#define BS_VERSION_STRING "0.8.0"
#define BS_VERSION_NUMBER (BS_VERSION_MAJOR * 10000 + BS_VERSION_MINOR * 100 + BS_VERSION_PATCH)

/* The build configuration as this translation unit sees it: version,
 * precision, switches and the compiled mode count. Passed to the library with
 * the struct sizes by the macros below (the zlib inflateInit_ pattern), so a
 * program compiled against another build than the library it links is
 * refused with BS_E_BUILD instead of corrupting memory. */
#ifdef BS_SCENE_MODES
#define BS_BUILD_SCENE_MODES ((uint32_t)(BS_SCENE_MODES) & 31u)
#else
#define BS_BUILD_SCENE_MODES 0u
#endif
#define BS_BUILD_TAG                                                                          \
    (((uint32_t)BS_VERSION_MAJOR << 24) | ((uint32_t)BS_VERSION_MINOR << 16)                  \
     | ((uint32_t)BS_WITH_PIEZO << 15) | (BS_BUILD_SCENE_MODES << 10)                         \
     | ((uint32_t)BS_WITH_SUBSPACE << 9)                                                        \
     | ((uint32_t)BS_WITH_IMPLICIT << 8) | ((uint32_t)BS_WITH_PCS << 7)                       \
     | ((uint32_t)BS_WITH_STRETCHING << 6) | ((uint32_t)BS_WITH_ROTATION << 5)                \
     | ((uint32_t)BS_WITH_GRAVITY << 4) | ((uint32_t)BS_WITH_RESTITUTION << 3)                \
     | ((uint32_t)BS_WITH_FRICTION << 2) | (uint32_t)BS_REAL_FLOAT)

/* The library's version, "MAJOR.MINOR.PATCH". */
const char *bs_version(void);

/* BS_OK if this program and the library were built alike, else BS_E_BUILD.
 * bs_sim_init and bs_scene_check make the same check; a firmware can call it
 * once at start-up. */
#define bs_build_check() bs_build_check_(BS_BUILD_TAG, sizeof(bs_sim), sizeof(bs_scene))
bs_status bs_build_check_(uint32_t tag, size_t sim_size, size_t scene_size);

/* Checks every field of a scene: BS_OK, BS_E_NULL, BS_E_BUILD, BS_E_SCENE (a
 * field out of its range) or BS_E_UNSTABLE (omega_max dt >= 2). On
 * BS_E_SCENE and BS_E_UNSTABLE, *field (if field is not NULL) names the
 * offending field.
 *
 * A scene's fields are derived together (frequency and dt make
 * phase_step_half; dt makes mode_gain and the transducer's factors; the
 * modal data come from the beam), so a changed copy of a built scene is
 * refused: for another excitation frequency or amplitude keep the scene
 * and call bs_sim_set_excitation on the sim (any time, the phase goes on);
 * for another dt, or anything else, build the scene again (libbeamslider-
 * host: bs_host_scene_load with an override such as "numerics.dt=1e-5",
 * or bs_host_scene_set; the command line: beamslider gen). */
#define bs_scene_check(scene, field) bs_scene_check_(BS_BUILD_TAG, sizeof(bs_scene), (scene), (field))
bs_status bs_scene_check_(uint32_t tag, size_t scene_size, const bs_scene *scene, const char **field);

/* Default contact-solve settings (BS_SOLVER_DEFAULT_*, bs_types.h). */
bs_solver_options bs_solver_defaults(void);

/* Starts a run: beam at rest, beta = 0, slot centred on the beam axis,
 * x_C = s0 L, solver options at their defaults. For BS_MODEL_FREE, s0 must lie
 * within the clamp end stops [stop_min, stop_max] / L; for BS_MODEL_PCS, s0 is
 * the prescribed position s~ in [0, 1]. The scene must outlive the sim.
 * Returns BS_OK, BS_E_NULL, BS_E_BUILD, BS_E_SCENE, BS_E_UNSTABLE or
 * BS_E_ARGUMENT; after an error the sim is not initialised. */
#define bs_sim_init(sim, scene, model, s0) \
    bs_sim_init_(BS_BUILD_TAG, sizeof(bs_sim), sizeof(bs_scene), (sim), (scene), (model), (s0))
bs_status bs_sim_init_(uint32_t tag, size_t sim_size, size_t scene_size, bs_sim *sim,
                       const bs_scene *scene, bs_model model, bs_real s0);

/* Contact-solve settings from the next step on. max_sweeps in
 * [1, BS_SOLVER_MAX_SWEEPS], tolerances finite and >= 0, measure_residual 0
 * or 1; otherwise nothing changes. Returns BS_OK, BS_E_NULL,
 * BS_E_UNINITIALISED or BS_E_ARGUMENT. */
bs_status bs_sim_set_solver(bs_sim *sim, const bs_solver_options *options);

/* Copies the current contact-solve settings into *options. Returns BS_OK,
 * BS_E_NULL or BS_E_UNINITIALISED. */
bs_status bs_sim_get_solver(const bs_sim *sim, bs_solver_options *options);

/* PCS only: moves the prescribed position to s~ in [0, 1] keeping the state
 * (continuation in a quasi-static sweep). Returns BS_OK, BS_E_NULL,
 * BS_E_UNINITIALISED or BS_E_ARGUMENT. */
bs_status bs_sim_set_pcs_position(bs_sim *sim, bs_real s);

/* Advances one time step dt under the harmonic excitation (the scene's, or
 * the last bs_sim_set_excitation's). On error the state stays at the last
 * good step. Returns BS_OK, BS_E_NULL, BS_E_UNINITIALISED, BS_E_UNSTABLE,
 * BS_E_NONFINITE or BS_E_ESCAPED. Hitting the sweep cap is not an error: see
 * bs_sim_get_report(). */
bs_status bs_sim_step(bs_sim *sim);

/* Advances one time step dt under a measured excitation: base_accel is the
 * mean base acceleration over the step [m/s^2], (dw0/dt(t_E) - dw0/dt(t_B)) /
 * dt, what an anti-aliased accelerometer sampled once per step delivers
 * (align its latency with the twin's other signals: docs/twin.md). Heights
 * are relative to the base, so nothing integrates it. Returns what
 * bs_sim_step returns, or BS_E_ARGUMENT (nothing changes) for a base_accel
 * that is not finite. */
bs_status bs_sim_step_measured(bs_sim *sim, bs_real base_accel);

/* The harmonic excitation d2w0/dt2 = -a cos(2 pi f t) from the next step on:
 * frequency f [Hz] with f dt in (0, 1/2), amplitude a [m/s^2] >= 0. The phase
 * continues where it is (a frequency ramp or step has no jump). Returns
 * BS_OK, BS_E_NULL, BS_E_UNINITIALISED or BS_E_ARGUMENT (nothing changes). */
bs_status bs_sim_set_excitation(bs_sim *sim, bs_real frequency, bs_real amplitude);

/* The harmonic excitation's frequency [Hz] and amplitude [m/s^2]; either
 * pointer may be NULL. Returns BS_OK, BS_E_NULL or BS_E_UNINITIALISED. */
bs_status bs_sim_get_excitation(const bs_sim *sim, bs_real *frequency, bs_real *amplitude);

/* The contact laws from the next step on: Coulomb friction mu (finite,
 * >= 0) and Newton's normal restitution e_N (in [0, 1]) at the slot's
 * corners; bs_sim_init takes the scene's. A twin that estimates its plant's
 * friction sets it here while it runs (docs/twin.md). A core built without
 * friction (BS_WITH_FRICTION 0: a compiled scene with mu = 0) takes only
 * mu = 0, one without restitution only e_N = 0. Returns BS_OK, BS_E_NULL,
 * BS_E_UNINITIALISED or BS_E_ARGUMENT (nothing changes). The laws are part
 * of a checkpoint. */
bs_status bs_sim_set_contact_laws(bs_sim *sim, bs_real mu, bs_real e_n);

/* The contact laws in use; either pointer may be NULL. Returns BS_OK,
 * BS_E_NULL or BS_E_UNINITIALISED. */
bs_status bs_sim_get_contact_laws(const bs_sim *sim, bs_real *mu, bs_real *e_n);

/* The mean base acceleration the last step used [m/s^2] (0 before the first
 * step; NaN for a NULL or uninitialised sim). */
bs_real bs_sim_base_acceleration(const bs_sim *sim);

/* What the piezoelectric transducer does (docs/model.md 11): the patch and
 * storage voltages, the power into the load over the last step and the
 * energy since bs_sim_init; out->present = 0 and zeros for a scene without
 * one. Returns BS_OK, BS_E_NULL or BS_E_UNINITIALISED. */
bs_status bs_sim_get_transducer(const bs_sim *sim, bs_transducer_output *out);

/* Copies the contact report of the last step into *report. Returns BS_OK,
 * BS_E_NULL or BS_E_UNINITIALISED. */
bs_status bs_sim_get_report(const bs_sim *sim, bs_step_report *report);

/* Elastic deflection at the sensor, w(4L/7, t) [m] (no base motion).
 * NaN for a NULL or uninitialised sim. */
bs_real bs_sim_sensor(const bs_sim *sim);

/* Relative slider position s = x_C / L. NaN for a NULL or uninitialised sim. */
bs_real bs_sim_position(const bs_sim *sim);

/* Elastic deflection w(x) [m] and slope w'(x) of the beam at x [m] (0 inside
 * a clamp, x outside [0, L]); either pointer may be NULL. Returns BS_OK,
 * BS_E_NULL, BS_E_UNINITIALISED or BS_E_ARGUMENT (x not finite). */
bs_status bs_sim_beam_at(const bs_sim *sim, bs_real x, bs_real *w, bs_real *w_slope);

/* Copies the state out: modal coordinates q_k and velocities (n_modes values
 * each), slider (x_C [m], z_r [m]: the height z_C - w0 relative to the base,
 * beta [rad]) and its velocities (relative to the base). Any array
 * may be NULL to skip that part. Returns BS_OK, BS_E_NULL or
 * BS_E_UNINITIALISED. */
bs_status bs_sim_get_state(const bs_sim *sim, bs_real *q_beam, bs_real *u_beam, bs_real *slider,
                           bs_real *slider_velocity);

/* Overwrites the state (a digital twin re-synchronising with measurements,
 * tests setting initial conditions); NULL leaves that part as it is. Every
 * value must be finite and, in the free model, x_C within the clamp stops
 * widened by the band bs_sim_step tolerates (h/2, docs/design.md 5), so that
 * every state a step produces is accepted; otherwise nothing changes and
 * BS_E_ARGUMENT is returned. Percussions of the warm start are cleared.
 * Returns BS_OK, BS_E_NULL, BS_E_UNINITIALISED or BS_E_ARGUMENT. */
bs_status bs_sim_set_state(bs_sim *sim, const bs_real *q_beam, const bs_real *u_beam,
                           const bs_real *slider, const bs_real *slider_velocity);

/* Excitation phase as a fraction of a period, [0, 1). NaN for a NULL or
 * uninitialised sim. */
bs_real bs_sim_phase(const bs_sim *sim);

/* Steps taken since bs_sim_init. 0 for a NULL or uninitialised sim. */
uint64_t bs_sim_steps(const bs_sim *sim);

/* Simulated time since bs_sim_init [s]: bs_sim_steps(sim) times the scene's
 * dt, multiplied (never summed step by step, so it does not drift); in
 * float it is exact to 2^-24 relative. NaN for a NULL or uninitialised sim. */
bs_real bs_sim_time(const bs_sim *sim);

/* FNV-1a hash of the complete dynamic state (bit patterns), for determinism
 * checks. 0 for a NULL or uninitialised sim. */
uint32_t bs_sim_hash(const bs_sim *sim);

/* FNV-1a hash of a scene's values (every used element of every field, in
 * bs_scene_fields.h's order): the identity checkpoints carry. 0 for NULL. */
uint32_t bs_scene_hash(const bs_scene *scene);

/* Checkpoints: the complete state of a sim (step count, excitation phase and
 * settings, contact laws, compensated parts, warm start, mode-shape caches,
 * transducer) as BS_CHECKPOINT_SIZE bytes in the caller's buffer, e.g. for
 * flash, a file or a twin that rewinds. The bytes carry a format mark, this build's tag
 * (version, precision, switches, modes), the scene's hash (bs_scene_hash)
 * and a checksum; they are in the machine's byte order (another byte order is
 * refused, not converted). A sim restored from a checkpoint continues bit for
 * bit as the sim saved would have. The solver options are the caller's
 * setting, not state: they are neither saved nor restored. Layout:
 * docs/twin.md. */
#define BS_CHECKPOINT_REALS                                                                   \
    (5 + 2 + 2 * BS_MAX_MODES + 6 + 1 + BS_ROWS * BS_MAX_CONTACTS + 1                       \
     + 2 * (1 + BS_MAX_MODES * BS_SHAPE_TERMS) + 5 * BS_WITH_PIEZO)
#define BS_CHECKPOINT_SIZE ((size_t)(6 * 4 + 5 * 4 + 3 * 8 + 4) + (size_t)BS_CHECKPOINT_REALS * sizeof(bs_real))

/* Writes sim's checkpoint into buffer[0 .. BS_CHECKPOINT_SIZE). Returns BS_OK,
 * BS_E_NULL, BS_E_UNINITIALISED or BS_E_CHECKPOINT_SIZE (size too small;
 * nothing written). */
bs_status bs_sim_save(const bs_sim *sim, void *buffer, size_t size);

/* Overwrites an initialised sim's state with a checkpoint (the sim must have
 * been initialised with the same scene: its hash must match). Every check
 * comes before any change: on error nothing changes. Returns BS_OK,
 * BS_E_NULL, BS_E_UNINITIALISED, BS_E_CHECKPOINT_SIZE (size below
 * BS_CHECKPOINT_SIZE, or the checkpoint records another size),
 * BS_E_CHECKPOINT_DAMAGED, BS_E_CHECKPOINT_BUILD or BS_E_CHECKPOINT_SCENE
 * (another scene, or a model or state this sim refuses: a value not finite,
 * x_C outside the band bs_sim_set_state accepts). */
bs_status bs_sim_restore(bs_sim *sim, const void *buffer, size_t size);

/* Short English text of a status, for messages ("unknown status" for a value
 * that is none). */
const char *bs_status_text(bs_status status);

#ifdef __cplusplus
}
#endif

#endif
