/* selftest.c - self-test firmware for port/cortex-m, built and checked by selftest.sh.
 *
 * Prints one line per check, after the measured bracket so that count.sh's "[insn] N" line
 * right before it is that bracket's count:
 *     bracket empty                      (two marks back to back)
 *     bracket mul_add n=0 / n=1000       (float multiply-add loop through a volatile pointer)
 *     bracket div_add n=0 / n=1000       (the same with a division: the cycle model's VDIV)
 *     bracket sum flash / sum ram        (64 floats read from a const table / a RAM copy)
 *     stack empty used=U                 (paint, then measure at once: U must be 0)
 *     stack nest depth=D used=U          (D+1 nested frames of selftest_nest: U = (D+1) * frame)
 *     stack printf value 316.521637      (the printf measured by the next line)
 *     stack printf used=U                (peak stack of that printf("%f"), for information)
 *     printf 3.141593 -1.500 1e+06       (%f, %.3f, %g formatting)
 *     selftest done
 * BS_SELFTEST_FAULT=1 ends in an undefined instruction (expect exit status 99) and
 * BS_SELFTEST_HANG=1 in an endless loop (expect run.sh's timeout, 124), after "selftest: ...".
 */
#include <stdio.h>

#include "bs_board.h"

#ifndef BS_SELFTEST_FAULT
#define BS_SELFTEST_FAULT 0
#endif
#ifndef BS_SELFTEST_HANG
#define BS_SELFTEST_HANG 0
#endif

/* With an FPU: vmul.f32, adds, cmp, vadd.f32, bne = 5 instructions per iteration. */
static float selftest_mul_add(float acc, float k, float c, int n)
{
    for (int i = 0; i < n; i++)
        acc = acc * k + c;
    return acc;
}

/* With an FPU: vdiv.f32, adds, cmp, vadd.f32, bne: 14 + 4 estimated cycles per iteration
 * (cycles=1 of count.sh), one branch taken. */
static float selftest_div_add(float acc, float k, float c, int n)
{
    for (int i = 0; i < n; i++)
        acc = acc / k + c;
    return acc;
}

/* Sum of n floats: one load per element, from wherever the table is. */
static float selftest_sum(const float *table, int n)
{
    float sum = 0.0f;
    for (int i = 0; i < n; i++)
        sum += table[i];
    return sum;
}

#define SELFTEST_TABLE 64
static const float selftest_flash_table[SELFTEST_TABLE] = { 1.0f, 2.0f, 3.0f, 4.0f }; /* in CODE */
static float selftest_ram_table[SELFTEST_TABLE];                                     /* in DATA */

static unsigned selftest_nest(unsigned depth);

/* Called through volatile pointers: the compiler can neither move the work across the marks
 * nor turn the recursion into a loop. */
static float (*volatile p_mul_add)(float, float, float, int) = selftest_mul_add;
static float (*volatile p_div_add)(float, float, float, int) = selftest_div_add;
static float (*volatile p_sum)(const float *, int) = selftest_sum;
static unsigned (*volatile p_nest)(unsigned) = selftest_nest;
volatile float selftest_sink_f;
volatile unsigned selftest_sink_u;

/* One frame of fixed size per level (its size is in selftest.su); every byte of the array is
 * written so that the deepest frame is used to its lowest byte. */
static unsigned selftest_nest(unsigned depth)
{
    volatile unsigned char scratch[200];
    for (unsigned i = 0; i < sizeof scratch; i++)
        scratch[i] = (unsigned char)(depth + i);
    if (depth == 0)
        return scratch[7];
    return p_nest(depth - 1) + scratch[3];
}

int main(void)
{
    unsigned used;

#ifdef __ARM_FP
    printf("selftest: start, __ARM_FP=%d\n", __ARM_FP);
#else
    printf("selftest: start, no FPU\n");
#endif

    bs_board_mark();
    bs_board_mark();
    printf("bracket empty\n");

    bs_board_mark();
    selftest_sink_f = p_mul_add(1.0f, 0.999f, 0.5f, 0);
    bs_board_mark();
    printf("bracket mul_add n=0\n");

    bs_board_mark();
    selftest_sink_f = p_mul_add(1.0f, 0.999f, 0.5f, 1000);
    bs_board_mark();
    printf("bracket mul_add n=1000\n");

    bs_board_mark();
    selftest_sink_f = p_div_add(1.0f, 1.001f, 0.5f, 0);
    bs_board_mark();
    printf("bracket div_add n=0\n");

    bs_board_mark();
    selftest_sink_f = p_div_add(1.0f, 1.001f, 0.5f, 1000);
    bs_board_mark();
    printf("bracket div_add n=1000\n");

    for (int i = 0; i < SELFTEST_TABLE; i++)
        selftest_ram_table[i] = selftest_flash_table[i];
    bs_board_mark();
    selftest_sink_f = p_sum(selftest_flash_table, SELFTEST_TABLE);
    bs_board_mark();
    printf("bracket sum flash\n");

    bs_board_mark();
    selftest_sink_f = p_sum(selftest_ram_table, SELFTEST_TABLE);
    bs_board_mark();
    printf("bracket sum ram\n");

    bs_board_stack_paint();
    used = bs_board_stack_used();
    printf("stack empty used=%u\n", used);

    bs_board_stack_paint();
    selftest_sink_u = p_nest(9);
    used = bs_board_stack_used();
    printf("stack nest depth=9 used=%u\n", used);

    bs_board_stack_paint();
    printf("stack printf value %f\n", (double)selftest_sink_f);
    used = bs_board_stack_used();
    printf("stack printf used=%u\n", used);

    printf("printf %f %.3f %g\n", (double)3.14159265f, -1.5, 1e6);

#if BS_SELFTEST_FAULT
    printf("selftest: faulting on purpose\n");
    __builtin_trap();
#endif
#if BS_SELFTEST_HANG
    printf("selftest: hanging on purpose\n");
    for (;;) {
    }
#endif
    printf("selftest done\n");
    return 0;
}
