/* zephyr/sys/printk.h - stand-in (tests/buildsys/zephyr): printk with
 * Zephyr's signature; kernel_standin.c. */
#ifndef STANDIN_ZEPHYR_SYS_PRINTK_H
#define STANDIN_ZEPHYR_SYS_PRINTK_H

void printk(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif
