/* bs_real.h - the one place that decides the working precision of the core.
 *
 * Build with -DBS_REAL_FLOAT=1 for float, -DBS_REAL_FLOAT=0 for double (the
 * Makefile does this from REAL=float|double). Every floating literal in core/
 * goes through BS_R() so that a float build never silently computes in double
 * (the build adds -Wdouble-promotion -Wfloat-conversion to catch slips).
 */
#ifndef BS_REAL_H
#define BS_REAL_H

#ifndef BS_REAL_FLOAT
#error "BS_REAL_FLOAT must be defined to 0 (double) or 1 (float)"
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
