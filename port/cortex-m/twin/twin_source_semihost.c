/* twin_source_semihost.c - the twin firmware's sample source under QEMU:
 * the stream file on the host, read over semihosting (twin_board.h). The
 * data stays on the host; the image holds none of it.
 *
 * Raw semihosting calls (bkpt 0xAB), not newlib's stdio: the producer reads
 * from the SysTick interrupt, which may land while the main loop is inside
 * printf, and newlib's file layer is not reentrant; a single bkpt is. A
 * relative path is relative to QEMU's working directory.
 */
#include <string.h>
#include "twin_board.h"

enum {
    SYS_OPEN = 0x01,
    SYS_READ = 0x06,
    SYS_OPEN_MODE_RB = 1 /* fopen's "rb" */
};

static int32_t handle = -1;

static int32_t semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ __volatile__("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return (int32_t)r0;
}

/* Reads size bytes; returns how many were read (SYS_READ returns how many
 * were NOT). */
static uint32_t read_bytes(void *buffer, uint32_t size)
{
    const uint32_t args[3] = { (uint32_t)handle, (uint32_t)(uintptr_t)buffer, size };
    const int32_t left = semihost(SYS_READ, args);
    return left < 0 || (uint32_t)left > size ? 0u : size - (uint32_t)left;
}

int twin_source_open(const char *path, twin_stream_header *header)
{
    const uint32_t args[3] = { (uint32_t)(uintptr_t)path, SYS_OPEN_MODE_RB, (uint32_t)strlen(path) };
    handle = semihost(SYS_OPEN, args);
    if (handle < 0)
        return -1;
    if (read_bytes(header, sizeof *header) != sizeof *header || memcmp(header->magic, TWIN_STREAM_MAGIC, 4) != 0)
        return -1;
    return 0;
}

uint32_t twin_source_read(twin_stream_sample *samples, uint32_t max)
{
    return handle < 0 ? 0u : read_bytes(samples, max * (uint32_t)sizeof *samples) / (uint32_t)sizeof *samples;
}
