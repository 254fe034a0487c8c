/* bs_port.h (generic embedded) - the math the core needs on a bare-metal
 * target: no OS, no stdio, no libc headers.
 *
 * sqrt and fabs are the functions of every step. __builtin_sqrt(f) (once per
 * active slot corner) becomes the FPU's square-root instruction on targets
 * that have one (with -fno-math-errno), and the toolchain's correctly rounded
 * software sqrtf/sqrt elsewhere. __builtin_fabs(f) is one vabs, or a cleared
 * sign bit without an FPU, and never a branch. sin and cos are only reached for a slider
 * rotation above 0.05 rad (core/src/bs_contact.c uses exact polynomials below;
 * the excitation uses none, core/src/bs_excitation.c), which the paper's scenes
 * never see, so the toolchain's libm serves: its cost does not matter and its
 * accuracy is an ulp or two.
 */
#ifndef BS_PORT_H
#define BS_PORT_H

#include "bs_real.h"

#if BS_REAL_FLOAT
static inline bs_real bs_sqrt(bs_real x) { return __builtin_sqrtf(x); }
static inline bs_real bs_sin(bs_real x) { return __builtin_sinf(x); }
static inline bs_real bs_cos(bs_real x) { return __builtin_cosf(x); }
static inline bs_real bs_fabs(bs_real x) { return __builtin_fabsf(x); }
#else
static inline bs_real bs_sqrt(bs_real x) { return __builtin_sqrt(x); }
static inline bs_real bs_sin(bs_real x) { return __builtin_sin(x); }
static inline bs_real bs_cos(bs_real x) { return __builtin_cos(x); }
static inline bs_real bs_fabs(bs_real x) { return __builtin_fabs(x); }
#endif

#endif
