/* bs_port.h (host) - the math the core needs, from the C library's libm.
 *
 * Every port provides exactly these four functions for bs_real. The core
 * includes this header through the port's include path and uses nothing else
 * from the platform.
 */
#ifndef BS_PORT_H
#define BS_PORT_H

#include <math.h>
#include "bs_real.h"

#if BS_REAL_FLOAT
static inline bs_real bs_sqrt(bs_real x) { return sqrtf(x); }
static inline bs_real bs_sin(bs_real x) { return sinf(x); }
static inline bs_real bs_cos(bs_real x) { return cosf(x); }
static inline bs_real bs_fabs(bs_real x) { return fabsf(x); }
#else
static inline bs_real bs_sqrt(bs_real x) { return sqrt(x); }
static inline bs_real bs_sin(bs_real x) { return sin(x); }
static inline bs_real bs_cos(bs_real x) { return cos(x); }
static inline bs_real bs_fabs(bs_real x) { return fabs(x); }
#endif

#endif
