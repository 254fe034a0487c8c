/* bs_lockin_layout.h - PRIVATE: the sized layout of the observer's lock-in
 * (core/src/bs_lockin.c), a part of bs_observer.
 *
 * Public only so that a program can own a bs_observer without allocation;
 * its members are private and change between releases without notice (as
 * bs_sim_layout.h's).
 */
#ifndef BS_LOCKIN_LAYOUT_H
#define BS_LOCKIN_LAYOUT_H

#include "bs_real.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The lock-in's two low-pass stages of one product. */
typedef struct bs_lowpass2 {
    bs_real stage[2];
} bs_lowpass2;

/* The reference the signals are demodulated against: a and its quadrature. */
typedef struct bs_lockin_reference {
    bs_real dt;             /* the sample period [s] */
    bs_real alpha, retain;  /* dt / tau and 1 - dt / tau: each low-pass stage's weights */
    bs_real quadrature;     /* b, the leaky integral of a [m/s] */
    bs_lowpass2 mean_b;     /* <b> */
    bs_lowpass2 aa, bb, ab; /* <a^2>, <b~^2>, <a b~> (b~ = b - <b>) */
} bs_lockin_reference;

#ifdef __cplusplus
}
#endif

#endif
