/* twin_clock_sim.c - a simulated sample clock (twin_board.h): time is
 * counted in CPU cycles, a sample period is TWIN_SAMPLE_CYCLES of them, and
 * each twin step takes TWIN_STEP_CYCLES. After every step the producer runs
 * once for every sample period that has passed, as the interrupt would have.
 *
 * Why simulate: QEMU's SysTick follows the host's clock (or, with -icount,
 * the instruction count), not the cycles of a Cortex-M4, so which samples a
 * real-time interrupt drops would depend on the machine that runs QEMU. This
 * clock makes the interleaving of producer and twin a function of the stated
 * costs alone: the same on QEMU and on the host, bit for bit, and a stated
 * overload exercises the overrun policy the same way on both. The real cost
 * of a step is measured separately (docs/embedded.md, "Twin firmware").
 *
 * TWIN_STEP_CYCLES = TWIN_SAMPLE_CYCLES: one sample per step, never a
 * backlog (the cost images, which measure instead of simulating).
 */
#include <stdio.h>
#include "twin_board.h"

/* The sample period: 168 MHz x dt = 2e-5 s. */
#ifndef TWIN_SAMPLE_CYCLES
#define TWIN_SAMPLE_CYCLES 3360u
#endif
/* A twin step's stated cost (measured or not). */
#ifndef TWIN_STEP_CYCLES
#define TWIN_STEP_CYCLES TWIN_SAMPLE_CYCLES
#endif

/* Cycles from now to the end of the next sample period; 0 or less once it
 * has passed (the producer is owed a call). 64 bits: a stated overload owes
 * more than 2^31 cycles over a long stream. */
static int64_t until_sample;

/* The value is kept in a local while the producer runs: its marks (a memory
 * clobber) would have the static read again after each call. */
static void run_producer(void)
{
    int64_t until = until_sample;
    while (until <= 0) {
        twin_produce();
        until += TWIN_SAMPLE_CYCLES;
    }
    until_sample = until;
}

void twin_clock_start(void)
{
    until_sample = TWIN_SAMPLE_CYCLES; /* sample 1 is the mean over the first period */
}

void twin_clock_spent(uint32_t steps)
{
    until_sample -= (int64_t)steps * TWIN_STEP_CYCLES;
    run_producer();
}

void twin_clock_wait(void)
{
    if (until_sample > 0)
        until_sample = 0;
    run_producer();
}

void twin_clock_stop(void)
{
}

const char *twin_clock_describe(void)
{
    static char text[96];
    snprintf(text, sizeof text, "simulated, a twin step %lu cycles, a sample period %lu",
             (unsigned long)TWIN_STEP_CYCLES, (unsigned long)TWIN_SAMPLE_CYCLES);
    return text;
}
