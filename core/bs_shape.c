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

void bs_shape_eval(const bs_scene *scene, bs_real x, bs_real *phi, bs_real *slope)
{
    const int n = BS_NMODES(scene);
    const bs_real scale = scene->shape_scale;
    const bs_real slope_scale = BS_R(2.0) * scale;
    bs_real t;
    bs_real u;
    int j;
    int k;

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
    }
}
