/* bs_excitation.c - harmonic base excitation from an exact phase accumulator.
 *
 *   d2w0/dt2 = -a cos(theta),   theta = Omega t   (Omega = 2 pi f).
 *
 * The step needs only the mean base acceleration over a step (docs/model.md
 * 10): with theta_B, theta_E = theta_M -+ Omega dt / 2 at its ends,
 *   (dw0/dt(t_E) - dw0/dt(t_B)) / dt = -a (sin theta_E - sin theta_B) / (Omega dt)
 *                                    = -a sinc(Omega dt / 2) cos(theta_M),
 * the second form free of the cancellation of the first (sinc x = sin x / x);
 * sinc is a per-frequency constant (bs_excitation_step_factor).
 *
 * theta is never formed from a floating time t (in float, Omega t = 46 700 rad
 * after 60 s of a 124 Hz excitation has an ulp of 0.004 rad). The simulator
 * keeps the phase as an unsigned 64-bit fraction of a turn that advances by an
 * integer each step and wraps every period (docs/model.md 9.1); a new
 * frequency changes the integer, never the phase, which stays continuous.
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
#include "bs_inline.h"
#include "bs_sim_internal.h"

#define QUADRANT ((uint64_t)1 << 62)

/* The series' coefficients, highest term first: the sine's 1 / (k (k + 1))
 * for k = 2 m, the cosine's for k = 2 m - 1, then the angle of one unit of
 * the folded phase (its top 32 bits in float: u32 -> float is one
 * instruction; all 62 in double). The step reads a copy in the sim's RAM
 * (bs_excitation_prepare): a controller reads a literal from flash, with
 * wait states. */
#define TERMS BS_EXCITATION_TERMS
enum { SINE = 0, COSINE = TERMS, UNIT = 2 * TERMS };

static const bs_real coefficients[2 * TERMS + 1] = {
#if !BS_REAL_FLOAT
    BS_R(1.0) / BS_R(210.0), BS_R(1.0) / BS_R(156.0), BS_R(1.0) / BS_R(110.0), /* 14 * 15, ... */
#endif
    BS_R(1.0) / BS_R(72.0), BS_R(1.0) / BS_R(42.0), BS_R(1.0) / BS_R(20.0), BS_R(1.0) / BS_R(6.0), /* 8 * 9, ... */
#if !BS_REAL_FLOAT
    BS_R(1.0) / BS_R(240.0), BS_R(1.0) / BS_R(182.0), BS_R(1.0) / BS_R(132.0), /* 15 * 16, ... */
#endif
    BS_R(1.0) / BS_R(90.0), BS_R(1.0) / BS_R(56.0), BS_R(1.0) / BS_R(30.0), BS_R(1.0) / BS_R(12.0), /* 9 * 10, ... */
#if BS_REAL_FLOAT
    BS_R(1.5707963267948966) / BS_R(4294967296.0),
#else
    BS_R(1.5707963267948966) / BS_R(4611686018427387904.0),
#endif
};

void bs_excitation_prepare(bs_step_constants *k)
{
    int i;
    for (i = 0; i < 2 * TERMS + 1; ++i)
        k->excitation_series[i] = coefficients[i];
}

/* sin d / d and cos d, the coefficients c as above (Horner, from the
 * highest term; the first product by s = 1 is folded away). */
BS_INLINE bs_real sine_series(const bs_real *c, bs_real d)
{
    const bs_real d2 = d * d;
    bs_real s = BS_R(1.0);
    int m;
    for (m = 0; m < TERMS; ++m)
        s = BS_R(1.0) - d2 * c[SINE + m] * s;
    return d * s;
}

BS_INLINE bs_real cosine_series(const bs_real *c, bs_real d)
{
    const bs_real d2 = d * d;
    bs_real s = BS_R(1.0);
    int m;
    for (m = 0; m < TERMS; ++m)
        s = BS_R(1.0) - d2 * c[COSINE + m] * s;
    return BS_R(1.0) - d2 * BS_R(0.5) * s;
}

/* The folded angle d in [0, pi/4] of a phase and whether it was folded
 * (d = pi/2 - x). */
BS_INLINE bs_real folded_angle(const bs_real *c, uint64_t phase, int *folded)
{
    const uint64_t within = phase & (QUADRANT - 1);
    const uint64_t from_axis = (*folded = within > QUADRANT / 2) ? QUADRANT - within : within;
#if BS_REAL_FLOAT
    return (bs_real)(uint32_t)(from_axis >> 30) * c[UNIT];
#else
    return (bs_real)from_axis * c[UNIT];
#endif
}

void bs_excitation_sincos(uint64_t phase, bs_real *sine, bs_real *cosine)
{
    const unsigned quadrant = (unsigned)(phase >> 62);
    int folded;
    const bs_real d = folded_angle(coefficients, phase, &folded);
    const bs_real s_d = sine_series(coefficients, d);
    const bs_real c_d = cosine_series(coefficients, d);
    const bs_real s = folded ? c_d : s_d; /* sin and cos of the angle within the quadrant */
    const bs_real c = folded ? s_d : c_d;

    switch (quadrant) {
    case 0: *sine = s; *cosine = c; break;
    case 1: *sine = c; *cosine = -s; break;
    case 2: *sine = -s; *cosine = -c; break;
    default: *sine = -c; *cosine = s; break;
    }
}

/* cos of the phase alone: one series instead of two (the step needs no
 * sine), bit for bit the cosine of bs_excitation_sincos. */
BS_INLINE bs_real cosine_of(const bs_real *c, uint64_t phase)
{
    const unsigned quadrant = (unsigned)(phase >> 62);
    int folded;
    const bs_real d = folded_angle(c, phase, &folded);
    /* cos x in quadrant 0 is c, in 1 -s, in 2 -c, in 3 s, with (s, c) the
     * sine and cosine within the quadrant: of d, swapped when folded */
    const int wants_sine = (quadrant & 1u) != (unsigned)folded;
    const bs_real value = wants_sine ? sine_series(c, d) : cosine_series(c, d);
    return quadrant == 1 || quadrant == 2 ? -value : value;
}

bs_real bs_excitation_step_mean(uint64_t phase_mid, bs_real step_accel)
{
    return -step_accel * cosine_of(coefficients, phase_mid);
}

bs_real bs_excitation_step_mean_of(const bs_sim *sim)
{
    return -sim->step_accel * cosine_of(sim->k.excitation_series, sim->phase + sim->phase_step_half);
}

uint64_t bs_excitation_phase_step_half(double frequency, double dt)
{
    const double half_turns = 0.5 * frequency * dt; /* in (0, 1/4) for a usable excitation */
    if (!(half_turns > 0.0 && half_turns < 0.25))
        return 0;
    return (uint64_t)(half_turns * 18446744073709551616.0 + 0.5); /* 2^64, < 2^62 here */
}

double bs_excitation_step_factor(uint64_t phase_step_half)
{
    /* x = Omega dt / 2 <= pi / 2; the series to x^14 is exact to 4e-12 there
     * and to rounding for the steps of practice (x ~ 0.01) */
    const double x = 6.283185307179586 * ((double)phase_step_half / 18446744073709551616.0);
    const double x2 = x * x;
    double sum = 1.0;
    int k;
    for (k = 14; k >= 2; k -= 2) /* sin(x)/x = 1 - x^2/3! + x^4/5! - ... in Horner form */
        sum = 1.0 - x2 / ((double)k * (double)(k + 1)) * sum;
    return sum;
}
