/* ref_config.h - sizes and constants of the double-precision reference model
 * (tests/reference/, the oracle for core/). Independent of core/: built from
 * docs/model.md only. */
#ifndef REF_CONFIG_H
#define REF_CONFIG_H

#define REF_MAX_MODES 12                /* beam modes N (0: rigid beam) */
#define REF_MAX_Q (REF_MAX_MODES + 3)   /* q = (q_1..q_N, x_C, z_r, beta) */
#define REF_CORNERS 4                   /* slot corners P1..P4 */
#define REF_MAX_CONTACTS (REF_CORNERS + 2) /* corners + left/right end stop */
#define REF_MAX_UNILATERAL (REF_MAX_CONTACTS + 1) /* unknowns of the per-step problem: contacts + the bridge */
#define REF_MAX_ROWS (2 * REF_MAX_CONTACTS + 1) /* rows of the per-step problem: contacts + the bridge */
#define REF_GL_POINTS 8                 /* Gauss-Legendre points per piece of a scheduled step mean */

/* pi to long double precision (strict C99 has no M_PI) */
#define REF_PI 3.14159265358979323846264338327950288L

#endif
