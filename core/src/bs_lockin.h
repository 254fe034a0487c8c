/* bs_lockin.h - the observer's lock-in: the first-harmonic response of a
 * signal to the excitation a (core/src/bs_lockin.c has the equations;
 * docs/twin.md, "Observer" 3). Per sample: the reference's step and one
 * low-pass per product, inlined (the observer runs them every sample); per
 * estimate: the basis from the reference's means and the responses. */
#ifndef BS_LOCKIN_H
#define BS_LOCKIN_H

#include "bs_inline.h"
#include "bs_lockin_layout.h"

/* x into the two stages; alpha = dt / tau. */
BS_INLINE void bs_lowpass2_step(bs_lowpass2 *f, bs_real x, bs_real alpha)
{
    f->stage[0] += alpha * (x - f->stage[0]);
    f->stage[1] += alpha * (f->stage[0] - f->stage[1]);
}

/* <x>: the second stage. */
BS_INLINE bs_real bs_lowpass2_mean(const bs_lowpass2 *f)
{
    return f->stage[1];
}

/* One sample a of the excitation into the reference; returns b~, the
 * quadrature without its offset, to demodulate the sample's signals with
 * (<y a>, <y b~>: bs_lowpass2_step with r->alpha). */
BS_INLINE bs_real bs_lockin_reference_step(bs_lockin_reference *r, bs_real a)
{
    const bs_real alpha = r->alpha;
    bs_real b;
    r->quadrature = r->retain * r->quadrature + r->dt * a;
    bs_lowpass2_step(&r->mean_b, r->quadrature, alpha);
    b = r->quadrature - bs_lowpass2_mean(&r->mean_b);
    bs_lowpass2_step(&r->aa, a * a, alpha);
    bs_lowpass2_step(&r->bb, b * b, alpha);
    bs_lowpass2_step(&r->ab, a * b, alpha);
    return b;
}

/* A reference for samples every dt [s] through stages of time constant tau
 * [s] (dt, tau > 0), all its states 0: no excitation seen. */
void bs_lockin_reference_init(bs_lockin_reference *r, bs_real dt, bs_real tau);

/* What the responses are formed with, from the reference's means (the
 * divisions done once for all signals). */
typedef struct bs_lockin_basis {
    bs_real aa;           /* <a^2> [(m/s^2)^2] */
    bs_real projection;   /* c = <a b~> / <a^2> [s]: the part of b~ in phase with a */
    bs_real kappa;        /* sqrt(<a^2> / <b_perp^2>) [rad/s]: the excitation's angular
                             frequency Omega */
    bs_real in_phase;     /* 1 / <a^2> */
    bs_real quadrature;   /* kappa / <a^2> */
} bs_lockin_basis;

/* The basis of the reference's present means: 1, or 0 while a has no
 * oscillation to demodulate against (no excitation yet: <a^2> = 0, or b~
 * without a part orthogonal to a); *basis is then all 0. */
int bs_lockin_basis_of(const bs_lockin_reference *r, bs_lockin_basis *basis);

/* The response of the signal y whose products with the reference are
 * with_a (<y a>) and with_b (<y b~>), on a basis bs_lockin_basis_of made:
 * H = re + j im [y's unit per m/s^2], y = Re(H A e^{j Omega t}) for
 * a = A cos(Omega t). */
void bs_lockin_response(const bs_lockin_basis *basis, const bs_lowpass2 *with_a, const bs_lowpass2 *with_b,
                        bs_real *re, bs_real *im);

#endif
