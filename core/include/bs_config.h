/* bs_config.h - compile-time sizes and features of the core.
 *
 * Every array in the core is sized here, so a bs_sim has a size known at
 * compile time and the caller can place it statically. The host build uses
 * generous limits, a run-time mode count and every feature. An embedded build
 * is compiled against exactly one scene: its generated bs_build_config.h
 * defines BS_SCENE_CONFIG (e.g. "configs/NAME.h", the scene's header written
 * by `beamslider gen`), which fixes the mode count and piece count and switches
 * off what the scene does not need. Switches are always defined to 0 or 1 and
 * tested with #if (-Wundef catches a misspelt one).
 */
#ifndef BS_CONFIG_H
#define BS_CONFIG_H

#include "bs_build_config.h"

#ifdef BS_SCENE_CONFIG
#include BS_SCENE_CONFIG
#endif

/* Largest number of beam modes a scene may use. */
#ifndef BS_MAX_MODES
#define BS_MAX_MODES 20
#endif

/* Mode count of the loops: the compiled scene's constant (the compiler then
 * unrolls them), or the scene's run-time value. */
#ifdef BS_SCENE_MODES
#define BS_NMODES(scene) ((void)(scene), BS_SCENE_MODES)
#else
#define BS_NMODES(scene) ((scene)->n_modes)
#endif

/* Mode shapes are piecewise polynomials of this many coefficients (degree 7),
 * fitted on the host (core/src/bs_shape.c writes its Horner loop out for
 * exactly 8). */
#define BS_SHAPE_COEFS 8

/* Largest number of polynomial pieces over the beam length. */
#ifndef BS_SHAPE_MAX_PIECES
#define BS_SHAPE_MAX_PIECES 128
#endif

/* Features (1: compiled in). */
#ifndef BS_WITH_FRICTION        /* Coulomb friction at the slot corners */
#define BS_WITH_FRICTION 1
#endif
#ifndef BS_WITH_RESTITUTION     /* Newton restitution e_N > 0 */
#define BS_WITH_RESTITUTION 1
#endif
#ifndef BS_WITH_GRAVITY         /* gravity on the slider */
#define BS_WITH_GRAVITY 1
#endif
#ifndef BS_WITH_ROTATION        /* the slider may rotate (else beta = 0 always) */
#define BS_WITH_ROTATION 1
#endif
#ifndef BS_WITH_STRETCHING      /* the beam's cubic bending-stretching term */
#define BS_WITH_STRETCHING 1
#endif
#ifndef BS_WITH_PCS             /* the pseudo-constrained slider model */
#define BS_WITH_PCS 1
#endif
#ifndef BS_WITH_IMPLICIT        /* the linearly implicit theta variant of the step */
#define BS_WITH_IMPLICIT 1
#endif
#ifndef BS_WITH_PIEZO           /* the piezoelectric transducer and its load (docs/model.md 11) */
#define BS_WITH_PIEZO 1
#endif
#ifndef BS_WITH_SUBSPACE        /* the active-set solve of three or more contacts (core/src/bs_pgs.c); */
#define BS_WITH_SUBSPACE 1      /* 0: plain sweeps for those (one and two contacts stay exact) */
#endif

/* Rows of the contact problem per contact: normal, and tangential with friction. */
#define BS_ROWS (BS_WITH_FRICTION ? 2 : 1)

/* Slider degrees of freedom that receive percussions: x_C, z_C (, beta). */
#define BS_SLIDER_DOF (BS_WITH_ROTATION ? 3 : 2)

/* Contacts: the four slot corners P1..P4, then the left and right clamp end
 * stops (normal-only contacts acting on x_C). */
#define BS_CORNERS 4
#define BS_MAX_CONTACTS 6
#define BS_STOP_LEFT 4
#define BS_STOP_RIGHT 5

#endif
