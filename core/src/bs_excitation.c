/* bs_excitation.c - base excitation from an exact phase accumulator.
 *
 *   w0 = (a / Omega^2) cos(theta),  dw0/dt = -(a / Omega) sin(theta),
 *   d2w0/dt2 = -a cos(theta),        theta = Omega t.
 *
 * theta is never formed from a floating time t (in float, Omega t = 46 700 rad
 * after 60 s of a 124 Hz excitation has an ulp of 0.004 rad). The simulator
 * keeps the phase as an unsigned 64-bit fraction of a turn that advances by an
 * integer each step and wraps every period (docs/model.md 9.1).
 *
 * sin and cos of the phase need no library: the range reduction is exact on
 * the integer. Its top two bits are the quadrant; within the quadrant the
 * angle x in [0, pi/2) is folded to d = x or d = pi/2 - x in [0, pi/4], and
 * sin d, cos d are Taylor polynomials in Horner form:
 *   double: to d^15 and d^16, truncation < (pi/4)^17/17! = 5e-17
 *   float:  to d^9 and d^10,  truncation < (pi/4)^11/11! = 2e-9
 * so that the result is within about an ulp, as exact at hour 100 as at step 1,
 * and bit for bit the same on every IEEE machine (no libm involved).
 */
#include "bs_excitation.h"

#define QUADRANT ((uint64_t)1 << 62)

static bs_real sine_series(bs_real d)
{
    const bs_real d2 = d * d;
    bs_real s = BS_R(1.0);
#if !BS_REAL_FLOAT
    s = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(210.0)) * s; /* 14 * 15 */
    s = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(156.0)) * s;
    s = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(110.0)) * s;
#endif
    s = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(72.0)) * s;  /* 8 * 9 */
    s = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(42.0)) * s;
    s = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(20.0)) * s;
    s = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(6.0)) * s;
    return d * s;
}

static bs_real cosine_series(bs_real d)
{
    const bs_real d2 = d * d;
    bs_real c = BS_R(1.0);
#if !BS_REAL_FLOAT
    c = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(240.0)) * c; /* 15 * 16 */
    c = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(182.0)) * c;
    c = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(132.0)) * c;
#endif
    c = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(90.0)) * c;  /* 9 * 10 */
    c = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(56.0)) * c;
    c = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(30.0)) * c;
    c = BS_R(1.0) - d2 * (BS_R(1.0) / BS_R(12.0)) * c;
    return BS_R(1.0) - d2 * BS_R(0.5) * c;
}

void bs_excitation_sincos(uint64_t phase, bs_real *sine, bs_real *cosine)
{
    const unsigned quadrant = (unsigned)(phase >> 62);
    const uint64_t within = phase & (QUADRANT - 1);
    const int folded = within > QUADRANT / 2;
    const uint64_t from_axis = folded ? QUADRANT - within : within; /* d in quarter turns * 2^62 */
#if BS_REAL_FLOAT
    /* 31 bits are plenty for float, and u32 -> float is one instruction */
    const bs_real d = (bs_real)(uint32_t)(from_axis >> 30) * (BS_R(1.5707963267948966) / BS_R(4294967296.0));
#else
    const bs_real d = (bs_real)from_axis * (BS_R(1.5707963267948966) / BS_R(4611686018427387904.0));
#endif
    const bs_real s_d = sine_series(d);
    const bs_real c_d = cosine_series(d);
    const bs_real s = folded ? c_d : s_d; /* sin and cos of the angle within the quadrant */
    const bs_real c = folded ? s_d : c_d;

    switch (quadrant) {
    case 0: *sine = s; *cosine = c; break;
    case 1: *sine = c; *cosine = -s; break;
    case 2: *sine = -s; *cosine = -c; break;
    default: *sine = -c; *cosine = s; break;
    }
}

bs_base bs_excitation_at(const bs_scene *scene, uint64_t phase)
{
    bs_real s, c;
    bs_base base;
    bs_excitation_sincos(phase, &s, &c);
    base.displacement = scene->base_displacement * c;
    base.velocity = -scene->base_velocity * s;
    base.acceleration = -scene->base_accel * c;
    return base;
}
