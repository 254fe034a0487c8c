/* twin_fifo.c - the single-producer, single-consumer sample FIFO and its
 * overrun policy (twin_fifo.h). */
#include "twin_fifo.h"

/* Keeps the compiler from moving the entry's loads or stores across the
 * index that publishes it. No DMB: producer (an interrupt) and consumer run
 * on one core, which sees its own memory accesses in program order; a
 * producer on another core or a DMA engine would need one here. */
#define TWIN_FIFO_BARRIER() __asm__ __volatile__("" ::: "memory")

void twin_fifo_init(twin_fifo *fifo)
{
    fifo->head = 0;
    fifo->tail = 0;
    fifo->dropped = 0;
    fifo->most = 0;
    fifo->gap = 0;
}

int twin_fifo_push(twin_fifo *fifo, float base_accel, float signal)
{
    const uint32_t head = fifo->head;
    const uint32_t queued = head - fifo->tail; /* modulo 2^32: right across the wrap */
    twin_fifo_entry *entry;

    if (queued == TWIN_FIFO_SAMPLES) {
        fifo->dropped = fifo->dropped + 1u;
        fifo->gap += 1u;
        return 0;
    }
    entry = &fifo->entry[head & (TWIN_FIFO_SAMPLES - 1u)];
    entry->base_accel = base_accel;
    entry->signal = signal;
    entry->gap = fifo->gap;
    fifo->gap = 0;
    TWIN_FIFO_BARRIER();
    fifo->head = head + 1u;
    if (queued + 1u > fifo->most)
        fifo->most = queued + 1u;
    return 1;
}

int twin_fifo_pop(twin_fifo *fifo, twin_fifo_entry *entry)
{
    const uint32_t tail = fifo->tail;
    if (fifo->head == tail)
        return 0;
    TWIN_FIFO_BARRIER();
    *entry = fifo->entry[tail & (TWIN_FIFO_SAMPLES - 1u)];
    TWIN_FIFO_BARRIER();
    fifo->tail = tail + 1u;
    return 1;
}

uint32_t twin_fifo_queued(const twin_fifo *fifo)
{
    return fifo->head - fifo->tail;
}
