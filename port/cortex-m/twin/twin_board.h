/* twin_board.h - what the twin firmware (twin_main.c) needs from its board:
 * a source of samples and a clock that runs the producer once per sample
 * period. Replace both for a real board (README.md, "Porting").
 *
 *   source   twin_source_semihost.c   the stream file on the host, over semihosting (QEMU)
 *            twin_source_stdio.c      the same file through stdio (the host build)
 *            your board               the ADCs (or their DMA buffer)
 *   clock    twin_clock_systick.c     SysTick interrupt at 1/dt (a board; QEMU with -icount)
 *            twin_clock_sim.c         a simulated clock: the producer runs when a stated cost
 *                                     per twin step says a sample period has passed
 *                                     (deterministic: `make test`, cost reports)
 */
#ifndef TWIN_BOARD_H
#define TWIN_BOARD_H

#include <stdint.h>
#include "twin_stream.h"

/* Opens the source (path: the stream file; a board ignores it) and fills
 * *header. Returns 0, or -1 if it cannot be opened or read. */
int twin_source_open(const char *path, twin_stream_header *header);

/* Reads up to max samples into samples; returns how many, 0 at the end.
 * Called by the producer (in the interrupt) whenever its block is used up. */
uint32_t twin_source_read(twin_stream_sample *samples, uint32_t max);

/* Starts calling twin_produce() once per sample period. */
void twin_clock_start(void);

/* The twin did `steps` steps since the last call (the simulated clock lets
 * their cost pass and runs the producer for each sample period it covers;
 * a real clock ignores it). */
void twin_clock_spent(uint32_t steps);

/* Nothing to do: wait for the next sample period (a real clock sleeps until
 * the interrupt; the simulated one jumps to it and runs the producer). */
void twin_clock_wait(void);

/* Stops the producer's clock. */
void twin_clock_stop(void);

/* What the clock is, for the firmware's first line. */
const char *twin_clock_describe(void);

/* The producer, provided by the firmware: moves one sample from the source
 * into the FIFO (or counts it dropped). Runs in the clock's interrupt. */
void twin_produce(void);

#endif
