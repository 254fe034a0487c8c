/* bs_excitation.h - the harmonic base excitation: its phase, the mean base
 * acceleration over a step, and the phase step of a frequency. */
#ifndef BS_EXCITATION_H
#define BS_EXCITATION_H

#include <stdint.h>
#include "bs_real.h"

/* sin and cos of 2 pi phase / 2^64, to about an ulp of bs_real. */
void bs_excitation_sincos(uint64_t phase, bs_real *sine, bs_real *cosine);

/* Mean of d2w0/dt2 = -a cos(Omega t) over the step whose midpoint is at
 * phase_mid, given step_accel = a sinc(Omega dt / 2). */
bs_real bs_excitation_step_mean(uint64_t phase_mid, bs_real step_accel);

/* f dt / 2 in 2^-64 turns for a frequency f [Hz] and step dt [s] (0 when
 * f dt is not in (0, 1/2), the range of a usable excitation). */
uint64_t bs_excitation_phase_step_half(double frequency, double dt);

/* sinc(Omega dt / 2) = sin(x) / x, x = 2 pi phase_step_half / 2^64. */
double bs_excitation_step_factor(uint64_t phase_step_half);

#endif
