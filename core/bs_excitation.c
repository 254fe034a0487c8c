/* bs_excitation.c - base excitation from an exact phase accumulator.
 *
 *   w0 = (a / Omega^2) cos(theta),  dw0/dt = -(a / Omega) sin(theta),
 *   d2w0/dt2 = -a cos(theta),        theta = Omega t.
 *
 * theta is never formed from a floating time t (in float, Omega t = 46 700 rad
 * after 60 s of a 124 Hz excitation has an ulp of 0.004 rad). The simulator
 * keeps the phase as an unsigned 64-bit fraction of a turn that advances by an
 * integer each step and wraps every period; only its top 32 bits, as a signed
 * fraction of a turn in [-1/2, 1/2), reach floating point here, so the angle
 * is as exact at hour 100 as at step 1 (MODEL.md 9.1).
 */
#include "bs_excitation.h"
#include "bs_port.h"

#define BS_TWO_PI_OVER_2_32 BS_R(1.4629180792671596e-09) /* 2 pi / 2^32 */

bs_real bs_excitation_angle(uint64_t phase)
{
    const uint32_t top = (uint32_t)(phase >> 32);
    /* two's-complement reading of top without implementation-defined casts */
    const int32_t turns = top < 0x80000000u ? (int32_t)top : -(int32_t)(0xFFFFFFFFu - top) - 1;
    return (bs_real)turns * BS_TWO_PI_OVER_2_32;
}

bs_base bs_excitation_at(const bs_scene *scene, uint64_t phase)
{
    const bs_real theta = bs_excitation_angle(phase);
    const bs_real c = bs_cos(theta);
    const bs_real s = bs_sin(theta);
    bs_base base;
    base.displacement = scene->base_displacement * c;
    base.velocity = -scene->base_velocity * s;
    base.acceleration = -scene->base_accel * c;
    return base;
}
