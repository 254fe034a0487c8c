/* bs_inline.h - BS_INLINE: a static function the compiler is to inline.
 *
 * The step's stages are small functions for reading's sake; called from a
 * few places, GCC weighs them too big to inline, and each call then moves
 * the step's data through memory (docs/design.md 4). Where a stage must be
 * inlined for the step to cost its arithmetic, it says so; compilers without
 * the attribute treat it as a hint. */
#ifndef BS_INLINE_H
#define BS_INLINE_H

#include "bs_real.h"

#if defined(__GNUC__)
#define BS_INLINE static inline __attribute__((always_inline))
#else
#define BS_INLINE static inline
#endif

/* BS_STEP_STAGE: a stage of another file that the step calls, inlined into
 * the step where the whole program is optimised at once (-flto, as every
 * Cortex-M image is built) and the scene is compiled in: left to GCC,
 * whether it is depends on the step's size, and a few instructions more
 * made one a call (mid-fig6-float 2414.6 -> 2532.9 cycles a step for
 * problem and apply, 2484.8 for the solve). Not with a run-time scene: its
 * step has a copy per mode count (BS_MODES_SWITCH) and so would each stage
 * within each, which doubled the host's -flto link for the same speed.
 * Elsewhere an ordinary function. */
#if defined(__GNUC__) && defined(BS_SCENE_MODES)
#define BS_STEP_STAGE __attribute__((always_inline)) inline
#else
#define BS_STEP_STAGE
#endif

/* BS_STEP_STAGE_ALWAYS: such a stage inlined with a run-time scene too
 * (the contact detection: bs_contact.c says why). */
#if defined(__GNUC__)
#define BS_STEP_STAGE_ALWAYS __attribute__((always_inline)) inline
#else
#define BS_STEP_STAGE_ALWAYS
#endif

/* BS_FORGET(p): the compiler no longer knows pointer p's value (an empty
 * asm statement that may change it; GCC and Clang, elsewhere nothing), so
 * it reads what it reads through p from here on instead of keeping what it
 * read before, and takes p for an address in a register, not for a
 * link-time constant. For values it would keep over a long stretch in
 * registers it does not have (it spills them, a store and a load where a
 * load would do), and for a firmware's static sim or observer (GCC reads
 * the address of each member from a literal in flash otherwise). Each use
 * says which, and what it saved. */
#if defined(__GNUC__)
#define BS_FORGET(p) __asm__("" : "+r"(p))
#else
#define BS_FORGET(p) ((void)0)
#endif

/* BS_ZERO: +0 for a sum to start at. A Cortex-M's FPU has no immediate 0,
 * and GCC reads a float 0 from a literal in flash; this one is an integer
 * 0 moved into the FPU (movs, vmov), the same bits. BS_ROUNDING(m): m eps
 * (m a power of two), the same way (its bits a Thumb-2 immediate: a mov).
 * BS_CONSTANT(value, bits): value, which has the float bits given, so too. */
#if defined(__GNUC__) && defined(__ARM_FP) && BS_REAL_FLOAT
#include <stdint.h>
static inline bs_real bs_real_of_bits(uint32_t bits)
{
    union {
        uint32_t bits;
        bs_real value;
    } x;
    x.bits = bits;
    __asm__("" : "+r"(x.bits)); /* else GCC sees the constant and reads it from flash */
    return x.value;
}
#define BS_ZERO bs_real_of_bits(0)
/* 2^(e - 127) has the bits e << 23; eps = 2^-23 */
#define BS_ROUNDING(m) bs_real_of_bits((uint32_t)(127 - 23 + BS_LOG2_##m) << 23)
#define BS_LOG2_16 4
#define BS_LOG2_64 6
#define BS_CONSTANT(value, bits) bs_real_of_bits(bits)
#else
#define BS_ZERO BS_R(0.0)
#define BS_ROUNDING(m) (BS_R(m##.0) * BS_REAL_EPS)
#define BS_CONSTANT(value, bits) (value)
#endif

/* Which way the step's tests mostly go, for the compiler to lay the common
 * path out straight (GCC and Clang; elsewhere nothing): on a Cortex-M a
 * taken branch costs a pipeline refill. No effect on any result. */
#if defined(__GNUC__)
#define BS_LIKELY(x) __builtin_expect(!!(x), 1)
#define BS_UNLIKELY(x) __builtin_expect(!!(x), 0)
#else
#define BS_LIKELY(x) (x)
#define BS_UNLIKELY(x) (x)
#endif

/* v[i] = p[i], i < 4. A Cortex-M4F loads N consecutive words in 1 + N
 * cycles with one vldm, in 2N with the vldr that GCC issues: with its FPU
 * and float, one vldm into s0-s3 (named: a vldm fills consecutive
 * registers), the "m" operand ordering it after stores to p[0..3]; the
 * values are to be used where they were loaded. Elsewhere a copy. */
#if defined(__GNUC__) && defined(__ARM_FP) && BS_REAL_FLOAT
#define BS_LOAD_4_VLDM 1
BS_INLINE void bs_load_4(const bs_real *p, bs_real *v)
{
    register bs_real v0 __asm__("s0"), v1 __asm__("s1"), v2 __asm__("s2"), v3 __asm__("s3");
    __asm__("vldmia %4, {%0, %1, %2, %3}"
            : "=t"(v0), "=t"(v1), "=t"(v2), "=t"(v3)
            : "r"(p), "m"(*(const bs_real(*)[4])p));
    v[0] = v0;
    v[1] = v1;
    v[2] = v2;
    v[3] = v3;
}

/* v[i] = p[i], i < 16: as bs_load_4, one vldm into s0-s15 (17 cycles, 32
 * with a vldr each). */
BS_INLINE void bs_load_16(const bs_real *p, bs_real *v)
{
    register bs_real v0 __asm__("s0"), v1 __asm__("s1"), v2 __asm__("s2"), v3 __asm__("s3");
    register bs_real v4 __asm__("s4"), v5 __asm__("s5"), v6 __asm__("s6"), v7 __asm__("s7");
    register bs_real v8 __asm__("s8"), v9 __asm__("s9"), v10 __asm__("s10"), v11 __asm__("s11");
    register bs_real v12 __asm__("s12"), v13 __asm__("s13"), v14 __asm__("s14"), v15 __asm__("s15");
    __asm__("vldmia %16, {%0-%15}"
            : "=t"(v0), "=t"(v1), "=t"(v2), "=t"(v3), "=t"(v4), "=t"(v5), "=t"(v6), "=t"(v7), "=t"(v8),
              "=t"(v9), "=t"(v10), "=t"(v11), "=t"(v12), "=t"(v13), "=t"(v14), "=t"(v15)
            : "r"(p), "m"(*(const bs_real(*)[16])p));
    v[0] = v0;
    v[1] = v1;
    v[2] = v2;
    v[3] = v3;
    v[4] = v4;
    v[5] = v5;
    v[6] = v6;
    v[7] = v7;
    v[8] = v8;
    v[9] = v9;
    v[10] = v10;
    v[11] = v11;
    v[12] = v12;
    v[13] = v13;
    v[14] = v14;
    v[15] = v15;
}

/* p[i] = v[i], i < 17: one vstm from s0-s16 (18 cycles, 34 with a vstr
 * each), the "=m" operand ordering it before later reads of p[0..16]. */
BS_INLINE void bs_store_17(bs_real *p, const bs_real *v)
{
    register bs_real v0 __asm__("s0") = v[0], v1 __asm__("s1") = v[1], v2 __asm__("s2") = v[2];
    register bs_real v3 __asm__("s3") = v[3], v4 __asm__("s4") = v[4], v5 __asm__("s5") = v[5];
    register bs_real v6 __asm__("s6") = v[6], v7 __asm__("s7") = v[7], v8 __asm__("s8") = v[8];
    register bs_real v9 __asm__("s9") = v[9], v10 __asm__("s10") = v[10], v11 __asm__("s11") = v[11];
    register bs_real v12 __asm__("s12") = v[12], v13 __asm__("s13") = v[13], v14 __asm__("s14") = v[14];
    register bs_real v15 __asm__("s15") = v[15], v16 __asm__("s16") = v[16];
    __asm__("vstmia %1, {%2-%18}"
            : "=m"(*(bs_real(*)[17])p)
            : "r"(p), "t"(v0), "t"(v1), "t"(v2), "t"(v3), "t"(v4), "t"(v5), "t"(v6), "t"(v7), "t"(v8), "t"(v9),
              "t"(v10), "t"(v11), "t"(v12), "t"(v13), "t"(v14), "t"(v15), "t"(v16));
}

/* bs_load_4 of *p, then *p += 4: consecutive groups of four, the address
 * advanced by the load itself (vldmia with write-back), no arithmetic. */
BS_INLINE void bs_load_4_next(const bs_real **p, bs_real *v)
{
    register bs_real v0 __asm__("s0"), v1 __asm__("s1"), v2 __asm__("s2"), v3 __asm__("s3");
    __asm__("vldmia %4!, {%0, %1, %2, %3}"
            : "=t"(v0), "=t"(v1), "=t"(v2), "=t"(v3), "+r"(*p)
            : "m"(*(const bs_real(*)[4])*p));
    v[0] = v0;
    v[1] = v1;
    v[2] = v2;
    v[3] = v3;
}

/* p[i] = v[i], i < 4: bs_load_4's store, one vstm from s0-s3 (1 + N cycles
 * for the 2N of vstr). */
BS_INLINE void bs_store_4(bs_real *p, const bs_real *v)
{
    register bs_real v0 __asm__("s0") = v[0], v1 __asm__("s1") = v[1], v2 __asm__("s2") = v[2],
                                      v3 __asm__("s3") = v[3];
    __asm__("vstmia %1, {%2, %3, %4, %5}"
            : "=m"(*(bs_real(*)[4])p)
            : "r"(p), "t"(v0), "t"(v1), "t"(v2), "t"(v3));
}
#else
#define BS_LOAD_4_VLDM 0
BS_INLINE void bs_load_4(const bs_real *p, bs_real *v)
{
    v[0] = p[0];
    v[1] = p[1];
    v[2] = p[2];
    v[3] = p[3];
}

BS_INLINE void bs_load_16(const bs_real *p, bs_real *v)
{
    int i;
    for (i = 0; i < 16; ++i)
        v[i] = p[i];
}

BS_INLINE void bs_store_17(bs_real *p, const bs_real *v)
{
    int i;
    for (i = 0; i < 17; ++i)
        p[i] = v[i];
}

BS_INLINE void bs_load_4_next(const bs_real **p, bs_real *v)
{
    bs_load_4(*p, v);
    *p += 4;
}

BS_INLINE void bs_store_4(bs_real *p, const bs_real *v)
{
    p[0] = v[0];
    p[1] = v[1];
    p[2] = v[2];
    p[3] = v[3];
}
#endif

/* BS_MODES_SWITCH(count, statement): statement with the identifier MODES, the
 * mode count, a compile-time constant: the scene's with a compiled scene,
 * else count itself for 1..8 modes (one copy of the statement each), so that
 * a run-time scene's loops over its modes are unrolled too, as a compiled
 * scene's are (docs/design.md 4); count as a variable beyond.
 * BS_UNROLL_MODES 0 keeps the variable copy alone: the same results, and a
 * build that does not optimise (the sanitizer smoke of make test, at -O0)
 * compiles bs_contact.c in a sixth of the time. */
#ifndef BS_UNROLL_MODES
#define BS_UNROLL_MODES 1
#endif
#ifdef BS_SCENE_MODES
#define BS_MODES_SWITCH(count, statement) \
    do {                                  \
        enum { MODES = BS_SCENE_MODES };  \
        (void)(count);                    \
        statement;                        \
    } while (0)
#elif !BS_UNROLL_MODES
#define BS_MODES_SWITCH(count, statement) \
    do {                                  \
        const int MODES = (count);        \
        statement;                        \
    } while (0)
#else
#define BS_MODES_CASE(k, statement) \
    case k: {                        \
        enum { MODES = k };          \
        statement;                   \
    } break;
#define BS_MODES_SWITCH(count, statement)                                                              \
    do {                                                                                               \
        switch (count) {                                                                               \
            BS_MODES_CASE(1, statement) BS_MODES_CASE(2, statement) BS_MODES_CASE(3, statement)         \
            BS_MODES_CASE(4, statement) BS_MODES_CASE(5, statement) BS_MODES_CASE(6, statement)         \
            BS_MODES_CASE(7, statement) BS_MODES_CASE(8, statement)                                    \
        default: {                                                                                     \
            const int MODES = (count);                                                                 \
            statement;                                                                                 \
        } break;                                                                                       \
        }                                                                                              \
    } while (0)
#endif

#endif
