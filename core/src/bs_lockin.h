/* bs_lockin.h - the observer's lock-in: the first-harmonic response of a
 * signal to the excitation a (core/src/bs_lockin.c has the equations;
 * docs/twin.md, "Observer" 3). Per sample: the reference's step and one
 * low-pass per product, inlined (the observer runs them every sample); per
 * estimate: the basis from the reference's means and the responses. */
#ifndef BS_LOCKIN_H
#define BS_LOCKIN_H

#include "bs_inline.h"
#include "bs_lockin_layout.h"
#include <stddef.h>

/* x into the two stages; alpha = dt / tau. */
BS_INLINE void bs_lowpass2_step(bs_lowpass2 *f, bs_real x, bs_real alpha)
{
    f->stage[0] += alpha * (x - f->stage[0]);
    f->stage[1] += alpha * (f->stage[0] - f->stage[1]);
}

/* ya into with_a and yb into with_b, the pair of a signal's products with
 * a and b~, with_b the filter after with_a in memory (the observer's
 * pairs): their four stages in one load and one store (bs_load_4,
 * bs_store_4) where that is one vldm and one vstm. */
BS_INLINE void bs_lowpass2_pair_step(bs_lowpass2 *with_a, bs_lowpass2 *with_b, bs_real ya, bs_real yb,
                                     bs_real alpha)
{
#if BS_LOAD_4_VLDM
    bs_real stage[4];
    (void)with_b;
    bs_load_4(with_a->stage, stage);
    stage[0] += alpha * (ya - stage[0]);
    stage[1] += alpha * (stage[0] - stage[1]);
    stage[2] += alpha * (yb - stage[2]);
    stage[3] += alpha * (stage[2] - stage[3]);
    bs_store_4(with_a->stage, stage);
#else
    bs_lowpass2_step(with_a, ya, alpha);
    bs_lowpass2_step(with_b, yb, alpha);
#endif
}

/* <x>: the second stage. */
BS_INLINE bs_real bs_lowpass2_mean(const bs_lowpass2 *f)
{
    return f->stage[1];
}

/* The reference moved between memory and the FPU's registers as blocks: a
 * Cortex-M4F moves N consecutive words in 1 + N cycles with one vldm or
 * vstm, in 2N with the vldr and vstr GCC issues. With its FPU and float, the
 * step reads all twelve words (dt to ab) with one vldm into s0-s11 and
 * writes the nine it changes (quadrature to ab) with one vstm from s3-s11
 * (registers named: a vldm/vstm list is consecutive); the "m" operands order
 * them with the other accesses to *r. Elsewhere member copies. */
#if BS_LOAD_4_VLDM
/* a build where the twelve words are not one block, in this order, fails here */
typedef char reference_is_one_block[sizeof(bs_lockin_reference) == 12 * sizeof(bs_real)
                                            && offsetof(bs_lockin_reference, quadrature) == 3 * sizeof(bs_real)
                                            && offsetof(bs_lockin_reference, ab) == 10 * sizeof(bs_real)
                                        ? 1
                                        : -1];

BS_INLINE void bs_lockin_reference_load(const bs_lockin_reference *r, bs_lockin_reference *copy)
{
    register bs_real w0 __asm__("s0"), w1 __asm__("s1"), w2 __asm__("s2"), w3 __asm__("s3");
    register bs_real w4 __asm__("s4"), w5 __asm__("s5"), w6 __asm__("s6"), w7 __asm__("s7");
    register bs_real w8 __asm__("s8"), w9 __asm__("s9"), w10 __asm__("s10"), w11 __asm__("s11");
    __asm__("vldmia %12, {%0, %1, %2, %3, %4, %5, %6, %7, %8, %9, %10, %11}"
            : "=t"(w0), "=t"(w1), "=t"(w2), "=t"(w3), "=t"(w4), "=t"(w5), "=t"(w6), "=t"(w7), "=t"(w8),
              "=t"(w9), "=t"(w10), "=t"(w11)
            : "r"(r), "m"(*r));
    copy->dt = w0;
    copy->alpha = w1;
    copy->retain = w2;
    copy->quadrature = w3;
    copy->mean_b.stage[0] = w4;
    copy->mean_b.stage[1] = w5;
    copy->aa.stage[0] = w6;
    copy->aa.stage[1] = w7;
    copy->bb.stage[0] = w8;
    copy->bb.stage[1] = w9;
    copy->ab.stage[0] = w10;
    copy->ab.stage[1] = w11;
}

BS_INLINE void bs_lockin_reference_store(bs_lockin_reference *r, const bs_lockin_reference *copy)
{
    register bs_real w3 __asm__("s3") = copy->quadrature;
    register bs_real w4 __asm__("s4") = copy->mean_b.stage[0], w5 __asm__("s5") = copy->mean_b.stage[1];
    register bs_real w6 __asm__("s6") = copy->aa.stage[0], w7 __asm__("s7") = copy->aa.stage[1];
    register bs_real w8 __asm__("s8") = copy->bb.stage[0], w9 __asm__("s9") = copy->bb.stage[1];
    register bs_real w10 __asm__("s10") = copy->ab.stage[0], w11 __asm__("s11") = copy->ab.stage[1];
    __asm__("vstmia %1, {%2, %3, %4, %5, %6, %7, %8, %9, %10}"
            : "=m"(*(bs_real(*)[9]) & r->quadrature)
            : "r"(&r->quadrature), "t"(w3), "t"(w4), "t"(w5), "t"(w6), "t"(w7), "t"(w8), "t"(w9), "t"(w10),
              "t"(w11));
}
#else
/* stage by stage: a struct assignment may become a call of memcpy */
BS_INLINE void bs_lowpass2_copy(bs_lowpass2 *to, const bs_lowpass2 *from)
{
    to->stage[0] = from->stage[0];
    to->stage[1] = from->stage[1];
}

BS_INLINE void bs_lockin_reference_load(const bs_lockin_reference *r, bs_lockin_reference *copy)
{
    copy->dt = r->dt;
    copy->alpha = r->alpha;
    copy->retain = r->retain;
    copy->quadrature = r->quadrature;
    bs_lowpass2_copy(&copy->mean_b, &r->mean_b);
    bs_lowpass2_copy(&copy->aa, &r->aa);
    bs_lowpass2_copy(&copy->bb, &r->bb);
    bs_lowpass2_copy(&copy->ab, &r->ab);
}

BS_INLINE void bs_lockin_reference_store(bs_lockin_reference *r, const bs_lockin_reference *copy)
{
    r->quadrature = copy->quadrature;
    bs_lowpass2_copy(&r->mean_b, &copy->mean_b);
    bs_lowpass2_copy(&r->aa, &copy->aa);
    bs_lowpass2_copy(&r->bb, &copy->bb);
    bs_lowpass2_copy(&r->ab, &copy->ab);
}
#endif

/* One sample a of the excitation into the reference; returns b~, the
 * quadrature without its offset, to demodulate the sample's signals with
 * (<y a>, <y b~>: bs_lowpass2_step with r->alpha). On a copy of *r in
 * registers, stored back at the end. */
BS_INLINE bs_real bs_lockin_reference_step(bs_lockin_reference *r, bs_real a)
{
    bs_lockin_reference c;
    bs_real b;
    bs_lockin_reference_load(r, &c);
    c.quadrature = c.retain * c.quadrature + c.dt * a;
    bs_lowpass2_step(&c.mean_b, c.quadrature, c.alpha);
    b = c.quadrature - bs_lowpass2_mean(&c.mean_b);
    bs_lowpass2_step(&c.aa, a * a, c.alpha);
    bs_lowpass2_step(&c.bb, b * b, c.alpha);
    bs_lowpass2_step(&c.ab, a * b, c.alpha);
    bs_lockin_reference_store(r, &c);
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

/* The same from the products' values ya (<y a>) and yb (<y b~>), of any
 * stage (the observer's jump hold reads the first stages too). */
void bs_lockin_response_of(const bs_lockin_basis *basis, bs_real ya, bs_real yb, bs_real *re, bs_real *im);

#endif
