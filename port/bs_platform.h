/* bs_platform.h - what every port offers the applications around the core
 * (the CLI, the firmware images). The core itself uses only bs_port.h. */
#ifndef BS_PLATFORM_H
#define BS_PLATFORM_H

/* Monotonic wall-clock time [s] from an arbitrary origin; 0 where the
 * platform has no clock. */
double bs_platform_seconds(void);

/* Writes text to the platform's console. Returns 0, or -1 if it failed. */
int bs_platform_write(const char *text);

#endif
