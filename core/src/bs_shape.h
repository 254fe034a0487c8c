/* bs_shape.h - mode shapes phi_k(x) and their slopes from the scene's
 * piecewise polynomials: evaluated directly, or from a local Taylor
 * expansion that the contact detection keeps per side of the slot. */
#ifndef BS_SHAPE_H
#define BS_SHAPE_H

#include "bs_inline.h"
#include "bs_sim_layout.h"

/* phi[k] = phi_k(x) [1/sqrt(kg)] and slope[k] = d phi_k / dx [1/(m sqrt(kg))]
 * for k < n_modes. Outside [0, L] the beam is inside a clamp, which moves
 * with the base: both are 0 there (docs/model.md 9.6: never extrapolated). */
void bs_shape_eval(const bs_scene *scene, bs_real x, bs_real *phi, bs_real *slope);

/* bs_shape_eval and the beam there: w = sum_k phi_k q_k [m], w_slope = w'. */
void bs_shape_deflection(const bs_scene *scene, bs_real x, const bs_real *q, bs_real *phi,
                         bs_real *slope, bs_real *w, bs_real *w_slope);

/* Largest distance, in the pieces' local units (2 per piece), over which an
 * expansion is used, and the error allowed there relative to a mode's size
 * (below the fit's own: docs/design.md 3). */
#define BS_SHAPE_REACH BS_R(0.0625)
#define BS_SHAPE_ERROR (BS_REAL_FLOAT ? BS_R(1e-7) : BS_R(1e-10))

/* The reach of this scene's expansions (<= BS_SHAPE_REACH), once per run. */
bs_real bs_shape_reach(const bs_scene *scene);

/* Local coordinate of x relative to the expansion's centre,
 * t = 2 shape_scale (x - centre); the expansion serves x while |t| is within
 * the scene's reach. */
static inline bs_real bs_shape_offset(const bs_scene *scene, const bs_shape_cache *cache, bs_real x)
{
    return BS_R(2.0) * scene->shape_scale * (x - cache->centre);
}

/* Expands every mode about x (clamped to [0, L]) into cache: the Taylor
 * polynomial in t (BS_SHAPE_TERMS terms) of the piece polynomial there. */
void bs_shape_expand(const bs_scene *scene, bs_real x, bs_shape_cache *cache);

/* c[m] = (*row)[m], m < BS_SHAPE_TERMS, then *row += BS_SHAPE_TERMS: one
 * mode's expansion coefficients, the next mode's row after it; the float
 * expansion's four with one load (bs_load_4_next), to be used where they
 * were loaded. BS_SHAPE_TERMS_HERE(s) has the terms s[m] computed where it
 * stands, in registers (an empty asm that may change them): else GCC
 * computes sums over the modes term by term, all modes' coefficients loaded
 * first, and the registers of the next load are spilled to the stack. */
#if BS_LOAD_4_VLDM && BS_SHAPE_TERMS == 4
#define bs_shape_terms bs_load_4_next
#define BS_SHAPE_TERMS_HERE(s) __asm__("" : "+t"((s)[0]), "+t"((s)[1]), "+t"((s)[2]), "+t"((s)[3]))
#else
BS_INLINE void bs_shape_terms(const bs_real **row, bs_real *c)
{
    int m;
    for (m = 0; m < BS_SHAPE_TERMS; ++m)
        c[m] = (*row)[m];
    *row += BS_SHAPE_TERMS;
}
#define BS_SHAPE_TERMS_HERE(s) ((void)(s))
#endif

/* Value and t-derivative of sum_m c_m t^m, m < BS_SHAPE_TERMS (Horner; the
 * derivative's recurrence starts at its leading coefficient, not at 0 t + v). */
#if BS_SHAPE_TERMS < 3
#error "bs_shape_taylor needs BS_SHAPE_TERMS >= 3"
#endif
BS_INLINE void bs_shape_taylor(const bs_real *c, bs_real t, bs_real *value, bs_real *derivative)
{
    bs_real v = c[BS_SHAPE_TERMS - 1] * t + c[BS_SHAPE_TERMS - 2], d = c[BS_SHAPE_TERMS - 1];
    int m;
    for (m = BS_SHAPE_TERMS - 3; m >= 0; --m) {
        d = d * t + v;
        v = v * t + c[m];
    }
    *value = v;
    *derivative = d;
}

/* phi[k] and slope[k] as bs_shape_eval gives them, from the expansion at
 * offset t (bs_shape_offset); 0 when on_beam is 0 (inside a clamp).
 * slope_scale = 2 shape_scale; n modes. Inlined into the contact detection
 * (its loops unrolled where n is a constant). */
BS_INLINE void bs_shape_expanded(int n, const bs_shape_cache *cache, bs_real t, int on_beam, bs_real slope_scale,
                                 bs_real *phi, bs_real *slope)
{
    const bs_real *row = cache->coef[0]; /* mode k's coefficients, then k + 1's */
    int k;
    if (!on_beam) { /* inside a clamp, which moves with the base */
        for (k = 0; k < n; ++k)
            phi[k] = slope[k] = BS_R(0.0);
        return;
    }
    for (k = 0; k < n; ++k) {
        bs_real b[BS_SHAPE_TERMS], value, derivative;
        bs_shape_terms(&row, b);
        bs_shape_taylor(b, t, &value, &derivative);
        phi[k] = value;
        slope[k] = slope_scale * derivative;
    }
}

/* Marks the cache empty: the next use expands it. */
void bs_shape_forget(bs_shape_cache *cache);

/* 1 if every x within the reach of an expansion about centre is on the
 * beam (cache->on_beam, set by bs_shape_expand): the contact detection
 * then skips the test of each corner. */
int bs_shape_on_beam(const bs_scene *scene, bs_real centre);

#endif
