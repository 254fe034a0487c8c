/* twin_fifo.h - the sample FIFO between the producer (the sample-rate
 * interrupt, or its simulation) and the twin (the main loop): one producer,
 * one consumer, no lock, no allocation.
 *
 * Each side writes only its own index (head: the producer, tail: the
 * consumer), both free-running 32-bit counters, so a push and a pop never
 * race: an aligned 32-bit load or store is atomic on a Cortex-M, and a
 * compiler barrier orders the entry against its index (twin_fifo.c).
 *
 * Overrun policy. When the FIFO is full the producer drops the NEW sample:
 * the queued ones stay, in order, because the twin needs its record without
 * holes it does not know of. The drop is counted (dropped) and carried into
 * the next sample stored (gap: the samples lost right before it), so the
 * consumer learns of every loss at the sample after it, and where. The twin
 * firmware steps through a gap without measurement (twin_main.c,
 * bs_observer_predict), so that its time stays the plant's.
 */
#ifndef TWIN_FIFO_H
#define TWIN_FIFO_H

#include <stdint.h>

/* Capacity in samples, a power of two (the index is the counter's low bits).
 * Size it from the largest backlog of your scene and part (docs/embedded.md,
 * "Twin firmware"): 12 bytes a sample. */
#ifndef TWIN_FIFO_SAMPLES
#define TWIN_FIFO_SAMPLES 1024u
#endif
#if TWIN_FIFO_SAMPLES < 2 || (TWIN_FIFO_SAMPLES & (TWIN_FIFO_SAMPLES - 1)) != 0
#error "TWIN_FIFO_SAMPLES must be a power of two"
#endif

typedef struct twin_fifo_entry {
    float base_accel; /* as the sensor gave it (twin_stream.h) */
    float signal;
    uint32_t gap;     /* samples dropped right before this one */
} twin_fifo_entry;

/* Members are private; the counters may be read from either side. */
/* The counters first, so that they and the entries are reached from one
 * base address (after 12 KiB of entries, the counters took one of their
 * own, a literal read from flash on each side: twin-cost-friction-off
 * 2515.4 -> 2501.3 estimated cycles a sample, flash). */
typedef struct twin_fifo {
    volatile uint32_t head;    /* samples stored (producer) */
    volatile uint32_t tail;    /* samples taken (consumer) */
    volatile uint32_t dropped; /* samples dropped, all told (producer) */
    volatile uint32_t most;    /* the largest number queued at once (producer) */
    uint32_t gap;              /* dropped since the last stored (producer) */
    twin_fifo_entry entry[TWIN_FIFO_SAMPLES];
} twin_fifo;

void twin_fifo_init(twin_fifo *fifo);

/* Producer: stores a sample; returns 1, or 0 if the FIFO was full and the
 * sample was dropped (and counted). */
int twin_fifo_push(twin_fifo *fifo, float base_accel, float signal);

/* Consumer: takes the oldest sample into *entry; returns 1, or 0 if empty. */
int twin_fifo_pop(twin_fifo *fifo, twin_fifo_entry *entry);

/* Samples queued now (either side; a snapshot). */
uint32_t twin_fifo_queued(const twin_fifo *fifo);

#endif
