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
#define BS_VERSION_MINOR 6
#define BS_VERSION_PATCH 0
#define BS_VERSION_STRING "0.6.0"
#define BS_VERSION_NUMBER (BS_VERSION_MAJOR * 10000 + BS_VERSION_MINOR * 100 + BS_VERSION_PATCH)

/* The build configuration as this translation unit sees it: version,
 * precision, switches and the compiled mode count. Passed to the library with
 * the struct sizes by the macros below (the zlib inflateInit_ pattern), so a
 * program compiled against another build than the library it links is
 * refused with BS_E_BUILD instead of corrupting memory. */
#ifdef BS_SCENE_MODES
#define BS_BUILD_SCENE_MODES ((uint32_t)(BS_SCENE_MODES) & 63u)
#else
#define BS_BUILD_SCENE_MODES 0u
#endif
#define BS_BUILD_TAG                                                                          \
    (((uint32_t)BS_VERSION_MAJOR << 24) | ((uint32_t)BS_VERSION_MINOR << 16)                  \
     | (BS_BUILD_SCENE_MODES << 10) | ((uint32_t)BS_WITH_SUBSPACE << 9)                       \
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
 * offending field. */
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

/* Advances one time step dt. On error the state stays at the last good step.
 * Returns BS_OK, BS_E_NULL, BS_E_UNINITIALISED, BS_E_UNSTABLE,
 * BS_E_NONFINITE or BS_E_ESCAPED. Hitting the sweep cap is not an error: see
 * bs_sim_get_report(). */
bs_status bs_sim_step(bs_sim *sim);

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
 * each), slider (x_C [m], z_C [m], beta [rad]) and its velocities. Any array
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

/* FNV-1a hash of the complete dynamic state (bit patterns), for determinism
 * checks. 0 for a NULL or uninitialised sim. */
uint32_t bs_sim_hash(const bs_sim *sim);

/* Short English text of a status, for messages ("unknown status" for a value
 * that is none). */
const char *bs_status_text(bs_status status);

#ifdef __cplusplus
}
#endif

#endif
