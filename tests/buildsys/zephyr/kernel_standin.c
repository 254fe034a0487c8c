/* kernel_standin.c - the kernel the beamslider sample sees in the stand-in
 * image (tests/buildsys/zephyr), run under QEMU with port/cortex-m's startup:
 * printk is newlib's vprintf over semihosting; the uptime advances only while
 * the thread sleeps, as on a part infinitely fast, so the sample never falls
 * behind and prints the same lines on every run. */
#include <stdarg.h>
#include <stdio.h>
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>

static int64_t uptime_ms;

void printk(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    (void)vprintf(fmt, args);
    va_end(args);
}

int64_t k_uptime_get(void)
{
    return uptime_ms;
}

int32_t k_msleep(int32_t ms)
{
    if (ms > 0)
        uptime_ms += ms;
    return 0;
}
