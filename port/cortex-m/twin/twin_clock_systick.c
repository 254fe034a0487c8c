/* twin_clock_systick.c - the sample clock of a Cortex-M board (twin_board.h):
 * SysTick interrupts at 1/dt and its handler is the producer.
 *
 * TWIN_SYSTICK_RELOAD: SysTick clock x dt - 1. On a 168 MHz part counting the
 * core clock, 3359 at dt = 2e-5 s. QEMU's MPS2 boards clock SysTick at
 * 25 MHz, so 499 there; QEMU's time then follows the host's clock unless it
 * runs with -icount (README.md, "The producer").
 *
 * The handler should be the highest-priority work (a late sample is a lost
 * sample), and short: one sample into the FIFO, a block read from the
 * source when the last one is used up.
 */
#include <stdio.h>
#include "twin_board.h"

#ifndef TWIN_SYSTICK_RELOAD
#define TWIN_SYSTICK_RELOAD 499u
#endif

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SYST_CSR_ENABLE 1u
#define SYST_CSR_TICKINT 2u
#define SYST_CSR_CORE_CLOCK 4u

/* Named as startup.c's vector table expects it (a weak default there). */
void SysTick_Handler(void);

void SysTick_Handler(void)
{
    twin_produce();
}

void twin_clock_start(void)
{
    SYST_RVR = TWIN_SYSTICK_RELOAD;
    SYST_CVR = 0;
    SYST_CSR = SYST_CSR_ENABLE | SYST_CSR_TICKINT | SYST_CSR_CORE_CLOCK;
}

void twin_clock_spent(uint32_t steps)
{
    (void)steps;
}

/* WFI may sleep one period too long when the interrupt lands between the
 * caller's empty FIFO and here; the tick keeps coming (also after the
 * stream's end), so it never sleeps for good. */
void twin_clock_wait(void)
{
    __asm__ __volatile__("wfi" ::: "memory");
}

void twin_clock_stop(void)
{
    SYST_CSR = 0;
}

const char *twin_clock_describe(void)
{
    static char text[64];
    snprintf(text, sizeof text, "SysTick, reload %lu", (unsigned long)TWIN_SYSTICK_RELOAD);
    return text;
}
