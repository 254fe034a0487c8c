/* bs_platform_host.c - clock and console on a POSIX host. */
#define _POSIX_C_SOURCE 199309L
#include "bs_platform.h"

#include <stdio.h>
#include <time.h>

double bs_platform_seconds(void)
{
    struct timespec now;
    if (clock_gettime(CLOCK_MONOTONIC, &now) != 0)
        return 0.0;
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

int bs_platform_write(const char *text)
{
    return fputs(text, stdout) < 0 ? -1 : 0;
}
