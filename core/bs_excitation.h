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

/* Phase as an angle in [-pi, pi). */
bs_real bs_excitation_angle(uint64_t phase);

#endif
