/* bs_shape.c - evaluation of the mode shapes.
 *
 * phi_k(xi) = c1 sin(l xi) + c2 cos(l xi) + c3 sinh(l xi) + c4 cosh(l xi)
 * cancels catastrophically near xi = 1 when written out (cosh(17) ~ 1e7), and
 * four transcendental calls per mode and point are too dear on a
 * microcontroller. The host therefore fits each mode, from a cancellation-free
 * closed form in double, with shape_pieces polynomial pieces of degree 7 in a
 * local coordinate u in [-1, 1] (error figures: docs/validation.md). Here:
 *
 *   t = x * shape_scale (= x / L * pieces),   j = floor(t),   u = 2 (t - j) - 1
 *   phi_k   = sum_c a[j][k][c] u^c                        (Horner)
 *   phi_k'  = d phi_k / dx = (2 pieces / L) sum_c c a[j][k][c] u^(c-1)
 */
#include "bs_shape.h"
#include "bs_port.h"

/* phi, slope and, when q is not NULL, w = sum phi_k q_k and w' = sum phi_k' q_k
 * accumulated in the same loop (no second pass over phi and slope). */
static inline void evaluate(const bs_scene *scene, bs_real x, const bs_real *q, bs_real *phi,
                            bs_real *slope, bs_real *w, bs_real *w_slope)
{
    const int n = BS_NMODES(scene);
    const bs_real scale = scene->shape_scale;
    const bs_real slope_scale = BS_R(2.0) * scale;
    bs_real t;
    bs_real u;
    int j;
    int k;

    if (q) {
        *w = BS_R(0.0);
        *w_slope = BS_R(0.0);
    }
    if (!(x >= BS_R(0.0) && x <= scene->length)) { /* inside a clamp (or NaN) */
        for (k = 0; k < n; ++k) {
            phi[k] = BS_R(0.0);
            slope[k] = BS_R(0.0);
        }
        return;
    }
    t = x * scale;
    j = (int)t;
    if (j >= scene->shape_pieces) /* x == L */
        j = scene->shape_pieces - 1;
    u = BS_R(2.0) * (t - (bs_real)j) - BS_R(1.0);

    for (k = 0; k < n; ++k) { /* Horner for p and p', written out for BS_SHAPE_COEFS = 8 */
        const bs_real *a = scene->shape_coef[j][k];
        bs_real value = a[7];
        bs_real derivative = value;
        value = value * u + a[6];
        derivative = derivative * u + value;
        value = value * u + a[5];
        derivative = derivative * u + value;
        value = value * u + a[4];
        derivative = derivative * u + value;
        value = value * u + a[3];
        derivative = derivative * u + value;
        value = value * u + a[2];
        derivative = derivative * u + value;
        value = value * u + a[1];
        derivative = derivative * u + value;
        phi[k] = value * u + a[0];
        slope[k] = slope_scale * derivative;
        if (q) {
            *w += phi[k] * q[k];
            *w_slope += slope[k] * q[k];
        }
    }
}

void bs_shape_eval(const bs_scene *scene, bs_real x, bs_real *phi, bs_real *slope)
{
    evaluate(scene, x, (const bs_real *)0, phi, slope, (bs_real *)0, (bs_real *)0);
}

void bs_shape_deflection(const bs_scene *scene, bs_real x, const bs_real *q, bs_real *phi,
                         bs_real *slope, bs_real *w, bs_real *w_slope)
{
    evaluate(scene, x, q, phi, slope, w, w_slope);
}

/* On piece j, |p'(u)| <= sum_c c |a_c| for |u| <= 1; u leaves [-1, 1] only by
 * rounding, which the factor 1 + 1/64 covers many times over. Neighbouring
 * pieces are separate interpolants and disagree at their common end by about
 * the fit error; each evaluation rounds by a few eps times sum_c |a_c|. The
 * jump bound takes twice the largest disagreement plus 64 eps of that sum. */
void bs_shape_bounds(const bs_scene *scene, bs_shape_bound *bound)
{
    const int pieces = scene->shape_pieces;
    int j, k, c;

    for (k = 0; k < BS_NMODES(scene); ++k) {
        bs_real slope = BS_R(0.0), size = BS_R(0.0), mismatch = BS_R(0.0);
        for (j = 0; j < pieces; ++j) {
            const bs_real *a = scene->shape_coef[j][k];
            bs_real piece_slope = BS_R(0.0), piece_size = BS_R(0.0);
            for (c = 0; c < BS_SHAPE_COEFS; ++c) {
                piece_slope += (bs_real)c * bs_fabs(a[c]);
                piece_size += bs_fabs(a[c]);
            }
            slope = piece_slope > slope ? piece_slope : slope;
            size = piece_size > size ? piece_size : size;
            if (j + 1 < pieces) { /* p_j(1) against p_j+1(-1) */
                const bs_real *next = scene->shape_coef[j + 1][k];
                bs_real gap = BS_R(0.0);
                for (c = 0; c < BS_SHAPE_COEFS; ++c)
                    gap += a[c] - (c % 2 ? -next[c] : next[c]);
                gap = bs_fabs(gap);
                mismatch = gap > mismatch ? gap : mismatch;
            }
        }
        bound->slope[k] = BS_R(2.0) * scene->shape_scale * slope * (BS_R(1.0) + BS_R(0.015625));
        bound->jump[k] = BS_R(2.0) * mismatch + BS_R(64.0) * BS_REAL_EPS * size;
    }
}
