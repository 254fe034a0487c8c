/* bs_beam.h - the beam's cubic stiffening and the explicit stability limit. */
#ifndef BS_BEAM_H
#define BS_BEAM_H

#include "bs_inline.h"
#include "bs_sim_layout.h"

/* Whether S_ij and gamma_k can be other than 0: with a compiled scene of up
 * to 8 modes its masks (`beamslider gen`, bs_scene_check holds a scene to
 * them), so that the unrolled loops drop the zeros; else always. */
#ifdef BS_SCENE_STRETCH_USED
#define BS_STRETCH_USED(i, j) ((BS_SCENE_STRETCH_USED >> (BS_SCENE_MODES * (i) + (j))) & 1u)
#define BS_GAMMA_USED(i) ((BS_SCENE_GAMMA_USED >> (i)) & 1u)
#else
#define BS_STRETCH_USED(i, j) 1
#define BS_GAMMA_USED(i) 1
#endif

#if BS_WITH_STRETCHING
/* S'_ij from the upper triangle: S is symmetric bit for bit (bs_scene_check),
 * so S' too; read there, each entry is loaded once for the two rows that use
 * it. */
#define UPPER_STRETCH(k, i, j) ((i) <= (j) ? (k)->stretch[i][j] : (k)->stretch[j][i])

/* sq = S' q and returns E' = q^T S' q (S' = sqrt(dt) S, bs_step_constants):
 * dt N(q) = E' sq. Inlined: the step's loops are unrolled for a compiled
 * scene, and its zeros dropped. */
BS_INLINE bs_real bs_beam_stretch(const bs_step_constants *k, int n, const bs_real *q, bs_real *sq)
{
    bs_real energy = BS_ZERO;
    int i, j;
#ifndef BS_SCENE_STRETCH_USED
    if (k->stretch_parity) { /* a run-time scene of symmetric and antisymmetric modes: S_ij = 0 for odd i + j */
        for (i = 0; i < n; ++i) {
            bs_real acc = BS_ZERO;
            for (j = i & 1; j < n; j += 2)
                acc += UPPER_STRETCH(k, i, j) * q[j];
            sq[i] = acc;
            energy += q[i] * acc;
        }
        return energy;
    }
#endif
    for (i = 0; i < n; ++i) {
        bs_real acc = BS_ZERO;
        for (j = 0; j < n; ++j)
            if (BS_STRETCH_USED(i, j))
                acc += UPPER_STRETCH(k, i, j) * q[j];
        sq[i] = acc;
        energy += q[i] * acc;
    }
    return energy;
}
#endif

/* 1 if the explicitly integrated stiffness is within the limit omega dt < 2:
 * omega_sq_dt the dt omega_k^2 integrated explicitly (NULL: none, the
 * implicit step), sq and energy from bs_beam_stretch, extra a further
 * stiffness [1/s^2] (the open patch's). */
int bs_beam_stable(const bs_step_constants *k, int n, const bs_real *omega_sq_dt, const bs_real *sq, bs_real energy,
                   bs_real extra);

#endif
