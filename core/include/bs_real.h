/* bs_real.h - the one place that decides the working precision of the core.
 *
 * BS_REAL_FLOAT comes from the generated bs_build_config.h (1: float, 0:
 * double; make REAL=float|double). Every floating literal in core/ goes
 * through BS_R() so that a float build never silently computes in double (the
 * build adds -Wdouble-promotion -Wfloat-conversion to catch slips).
 */
#ifndef BS_REAL_H
#define BS_REAL_H

#include "bs_build_config.h"

#if !defined(BS_REAL_FLOAT) || (BS_REAL_FLOAT != 0 && BS_REAL_FLOAT != 1)
#error "bs_build_config.h must define BS_REAL_FLOAT to 0 (double) or 1 (float)"
#endif

#if BS_REAL_FLOAT
typedef float bs_real;
#define BS_R(x) (x##f)
#define BS_REAL_EPS BS_R(1.1920929e-07) /* FLT_EPSILON */
#define BS_REAL_NAME "float"
#else
typedef double bs_real;
#define BS_R(x) (x)
#define BS_REAL_EPS BS_R(2.220446049250313e-16) /* DBL_EPSILON */
#define BS_REAL_NAME "double"
#endif

#endif
