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
 *
 * The contact detection needs the shapes at the slot corners every step.
 * The two corners of one side of the slot lie a few micrometres apart along
 * the beam and the slider moves slowly, so it keeps, per side, the cubic
 * Taylor polynomial of each mode about a point (bs_shape_expand),
 *   phi_k(centre + t / (2 shape_scale)) = sum_m b[k][m] t^m,   m < BS_SHAPE_TERMS,
 * and expands again only when a corner leaves |t| <= reach (at most
 * BS_SHAPE_REACH, 1/32 of a piece; less where the scene's shapes need it,
 * bs_shape_reach): 3 or 4 multiply-adds a mode instead of 7, and the deflection of both
 * corners from four sums over the modes (bs_contact.c). The remainder is
 * sum_{m>=4} b_m t^m, at most (1/16)^4 = 1.5e-5 times the polynomial's
 * fourth and higher coefficients, which the fit keeps at the 1e-4 level and
 * below: far under the fit's own error (tests/test_shape.c measures it).
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

/* The reach of an expansion: the largest of 1/16, 1/32, ... (in the pieces'
 * local units) where the higher terms left out stay under BS_SHAPE_ERROR of
 * every mode's size, value and slope, on every piece. On piece j with
 * coefficients a_c the Taylor coefficients about any u0 in [-1, 1] obey
 * |b_m| <= B_m = sum_{c>=m} C(c, m) |a_c|, so the remainder is at most
 * sum_{m>=M} B_m r^m, its slope sum_{m>=M} m B_m r^(m-1). */
bs_real bs_shape_reach(const bs_scene *scene)
{
    static const bs_real binomial[BS_SHAPE_COEFS][BS_SHAPE_COEFS] = {
        { BS_R(1.0) }, { BS_R(1.0), BS_R(1.0) }, { BS_R(1.0), BS_R(2.0), BS_R(1.0) },
        { BS_R(1.0), BS_R(3.0), BS_R(3.0), BS_R(1.0) }, { BS_R(1.0), BS_R(4.0), BS_R(6.0), BS_R(4.0), BS_R(1.0) },
        { BS_R(1.0), BS_R(5.0), BS_R(10.0), BS_R(10.0), BS_R(5.0), BS_R(1.0) },
        { BS_R(1.0), BS_R(6.0), BS_R(15.0), BS_R(20.0), BS_R(15.0), BS_R(6.0), BS_R(1.0) },
        { BS_R(1.0), BS_R(7.0), BS_R(21.0), BS_R(35.0), BS_R(35.0), BS_R(21.0), BS_R(7.0), BS_R(1.0) } };
    bs_real reach = BS_SHAPE_REACH;
    int j, k, m, c, fits = 0;

    while (!fits && reach > BS_R(1e-3)) {
        fits = 1;
        for (k = 0; k < BS_NMODES(scene) && fits; ++k) {
            bs_real size = BS_R(0.0), size_slope = BS_R(0.0); /* bounds of |p|, |p'| over all pieces */
            for (j = 0; j < scene->shape_pieces; ++j) {
                bs_real piece = BS_R(0.0), piece_slope = BS_R(0.0);
                for (c = 0; c < BS_SHAPE_COEFS; ++c) {
                    piece += bs_fabs(scene->shape_coef[j][k][c]);
                    piece_slope += (bs_real)c * bs_fabs(scene->shape_coef[j][k][c]);
                }
                size = piece > size ? piece : size;
                size_slope = piece_slope > size_slope ? piece_slope : size_slope;
            }
            for (j = 0; j < scene->shape_pieces && fits; ++j) {
                bs_real rest = BS_R(0.0), rest_slope = BS_R(0.0), power = BS_R(1.0);
                for (m = 1; m < BS_SHAPE_TERMS; ++m)
                    power *= reach; /* reach^(M-1) */
                for (m = BS_SHAPE_TERMS; m < BS_SHAPE_COEFS; ++m) {
                    bs_real bound = BS_R(0.0);
                    for (c = m; c < BS_SHAPE_COEFS; ++c)
                        bound += binomial[c][m] * bs_fabs(scene->shape_coef[j][k][c]);
                    rest_slope += (bs_real)m * bound * power;
                    power *= reach;
                    rest += bound * power;
                }
                fits = rest <= BS_SHAPE_ERROR * size && rest_slope <= BS_SHAPE_ERROR * size_slope;
            }
        }
        if (!fits)
            reach *= BS_R(0.5);
    }
    return reach;
}

void bs_shape_forget(bs_shape_cache *cache)
{
    cache->centre = BS_R(-1.0);
    cache->on_beam = 0;
}

/* Twice the farthest reach (BS_SHAPE_REACH, in units of 2 per piece) on
 * either side of the centre, so that a point that rounding puts within an
 * expansion's reach is on the beam with a wide margin; NaN is not. */
int bs_shape_on_beam(const bs_scene *scene, bs_real centre)
{
    const bs_real margin = BS_SHAPE_REACH / scene->shape_scale;
    return centre - margin >= BS_R(0.0) && centre + margin <= scene->length;
}

/* Taylor shift by repeated synthetic division: with b = a, the passes
 * m = 0, 1, ... of b_c += u0 b_(c+1) (c from 6 down to m) leave
 * b_m = p^(m)(u0) / m!, the coefficients of p(u0 + t) = sum_m b_m t^m;
 * 22 multiply-adds a mode for four terms, 25 for five. */
void bs_shape_expand(const bs_scene *scene, bs_real x, bs_shape_cache *cache)
{
    const bs_real scale = scene->shape_scale;
    bs_real t, u0;
    int j, k, m, c;

    if (!(x >= BS_R(0.0)))
        x = BS_R(0.0);
    if (x > scene->length)
        x = scene->length;
    t = x * scale;
    j = (int)t;
    if (j >= scene->shape_pieces) /* x == L */
        j = scene->shape_pieces - 1;
    u0 = BS_R(2.0) * (t - (bs_real)j) - BS_R(1.0);
    for (k = 0; k < BS_NMODES(scene); ++k) {
        bs_real b[BS_SHAPE_COEFS];
        for (c = 0; c < BS_SHAPE_COEFS; ++c)
            b[c] = scene->shape_coef[j][k][c];
        for (m = 0; m < BS_SHAPE_TERMS; ++m) {
            for (c = BS_SHAPE_COEFS - 2; c >= m; --c)
                b[c] += u0 * b[c + 1];
            cache->coef[k][m] = b[m];
        }
    }
    /* the centre in the pieces' own coordinate, so that offsets are exact
     * from where the coefficients were taken */
    cache->centre = ((bs_real)j + BS_R(0.5) * (u0 + BS_R(1.0))) / scale;
    cache->on_beam = bs_shape_on_beam(scene, cache->centre);
}
