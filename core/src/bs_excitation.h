/* bs_excitation.h - base motion at a given excitation phase. */
#ifndef BS_EXCITATION_H
#define BS_EXCITATION_H

#include <stdint.h>
#include "bs_scene.h"

typedef struct bs_base {
    bs_real displacement;   /* w0 [m] */
    bs_real velocity;       /* dw0/dt [m/s] */
    bs_real acceleration;   /* d2w0/dt2 [m/s^2] */
} bs_base;

/* Base motion at phase (turns * 2^64). */
bs_base bs_excitation_at(const bs_scene *scene, uint64_t phase);

/* sin and cos of 2 pi phase / 2^64, to about an ulp of bs_real. */
void bs_excitation_sincos(uint64_t phase, bs_real *sine, bs_real *cosine);

#endif
