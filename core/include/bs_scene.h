/* bs_scene.h - the constant data of one scene, as the core consumes it.
 *
 * A scene is everything that stays fixed during a run: modal data of the beam,
 * geometry, slider inertia, contact laws, excitation and time step. The host
 * tool fills it in double precision from physical parameters
 * (host/lib/scene_build.c); an embedded build takes it as const data from a
 * generated header in configs/. The core never computes modal data; it only
 * reads this struct. Its fields, with their units, ranges and meanings, are
 * listed once in bs_scene_fields.h (and in docs/fields.md); the contact-solve
 * settings are not part of it (bs_solver_options, bs_types.h).
 */
#ifndef BS_SCENE_H
#define BS_SCENE_H

#include <stdint.h>
#include "bs_config.h"
#include "bs_real.h"
#include "bs_scene_fields.h"

#define BS_SCENE_TYPE_REAL bs_real
#define BS_SCENE_TYPE_INT int
#define BS_SCENE_TYPE_U64 uint64_t
#define BS_SCENE_MEMBER(kind, name, dim1, dim2, dim3, rule, unit, meaning) \
    BS_SCENE_TYPE_##kind name BS_DIM_##dim1 BS_DIM_##dim2 BS_DIM_##dim3;

typedef struct bs_scene {
    BS_SCENE_FIELDS(BS_SCENE_MEMBER)
} bs_scene;

/* Tells a compile-time scene header (configs/NAME.h) that bs_scene exists,
 * so that its second inclusion defines bs_compiled_scene. */
#define BS_SCENE_TYPE_DEFINED 1

#endif
