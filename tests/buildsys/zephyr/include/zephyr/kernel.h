/* zephyr/kernel.h - stand-in (tests/buildsys/zephyr): the kernel calls the
 * beamslider sample makes, with Zephyr's signatures; kernel_standin.c. */
#ifndef STANDIN_ZEPHYR_KERNEL_H
#define STANDIN_ZEPHYR_KERNEL_H
#include <stdint.h>

int64_t k_uptime_get(void);
int32_t k_msleep(int32_t ms);

#endif
