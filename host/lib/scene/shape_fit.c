/* shape_fit.c - piecewise Chebyshev interpolation of the mode shapes.
 *
 * On piece j of [0, 1] (width H = 1/pieces, local u in [-1, 1],
 * xi = (j + (u + 1)/2) H) each mode is interpolated at the 8 Chebyshev points
 * u_i = cos(pi (i + 1/2) / 8): p(u) = sum_m a_m T_m(u), a_m = (2 - [m = 0]) / 8
 * sum_i phi(u_i) T_m(u_i). The T_m are expanded into monomials, which the core
 * evaluates with Horner; on a piece of width H the local polynomial of a mode
 * with wave number l behaves like a Taylor series in (l H / 2) u, so the
 * monomial coefficients fall off fast and carry no cancellation.
 * Interpolation error ~ 2 (l H / 4)^8 / 8!, e.g. 1e-11 for l = 17, H = 1/32.
 */
#include "shape_fit.h"

#include <math.h>

#define FIT_CHECK_POINTS 64 /* per piece, for the error figures */

/* Monomial coefficients of T_0 .. T_7. */
static void chebyshev_monomials(double t[BS_SHAPE_COEFS][BS_SHAPE_COEFS])
{
    int m;
    int c;
    for (m = 0; m < BS_SHAPE_COEFS; ++m)
        for (c = 0; c < BS_SHAPE_COEFS; ++c)
            t[m][c] = 0.0;
    t[0][0] = 1.0;
    t[1][1] = 1.0;
    for (m = 2; m < BS_SHAPE_COEFS; ++m) /* T_m = 2 u T_{m-1} - T_{m-2} */
        for (c = 0; c < BS_SHAPE_COEFS; ++c)
            t[m][c] = (c > 0 ? 2.0 * t[m - 1][c - 1] : 0.0) - t[m - 2][c];
}

static void fit_pieces(const modal_set *modes, int pieces, shape_fit *fit)
{
    const double pi = 3.14159265358979323846;
    double t[BS_SHAPE_COEFS][BS_SHAPE_COEFS];
    int j;
    int k;

    chebyshev_monomials(t);
    fit->pieces = pieces;
    for (j = 0; j < pieces; ++j) {
        for (k = 0; k < modes->n; ++k) {
            double value[BS_SHAPE_COEFS];
            int i;
            int m;
            int c;
            for (i = 0; i < BS_SHAPE_COEFS; ++i) {
                const double u = cos(pi * (i + 0.5) / BS_SHAPE_COEFS);
                double slope;
                modal_shape(modes, k, (j + 0.5 * (u + 1.0)) / pieces, &value[i], &slope);
            }
            for (c = 0; c < BS_SHAPE_COEFS; ++c)
                fit->coef[j][k][c] = 0.0;
            for (m = 0; m < BS_SHAPE_COEFS; ++m) {
                double a = 0.0;
                for (i = 0; i < BS_SHAPE_COEFS; ++i)
                    a += value[i] * cos(m * pi * (i + 0.5) / BS_SHAPE_COEFS);
                a *= (m == 0 ? 1.0 : 2.0) / BS_SHAPE_COEFS;
                for (c = 0; c < BS_SHAPE_COEFS; ++c)
                    fit->coef[j][k][c] += a * t[m][c];
            }
        }
    }
}

void shape_fit_eval(const shape_fit *fit, int k, double xi, double *phi, double *phi_xi)
{
    const double scaled = xi * fit->pieces;
    int j = (int)scaled;
    double u;
    double value;
    double derivative = 0.0;
    int c;

    if (j >= fit->pieces)
        j = fit->pieces - 1;
    if (j < 0)
        j = 0;
    u = 2.0 * (scaled - j) - 1.0;
    value = fit->coef[j][k][BS_SHAPE_COEFS - 1];
    for (c = BS_SHAPE_COEFS - 2; c >= 0; --c) {
        derivative = derivative * u + value;
        value = value * u + fit->coef[j][k][c];
    }
    *phi = value;
    *phi_xi = 2.0 * fit->pieces * derivative;
}

static void measure_error(const modal_set *modes, shape_fit *fit)
{
    const int points = fit->pieces * FIT_CHECK_POINTS;
    int k;
    int i;

    fit->error_phi = 0.0;
    fit->error_slope = 0.0;
    for (k = 0; k < modes->n; ++k) {
        double max_phi = 0.0, max_slope = 0.0, err_phi = 0.0, err_slope = 0.0;
        for (i = 0; i <= points; ++i) {
            const double xi = (double)i / points;
            double phi, slope, fit_phi, fit_slope;
            modal_shape(modes, k, xi, &phi, &slope);
            shape_fit_eval(fit, k, xi, &fit_phi, &fit_slope);
            max_phi = fmax(max_phi, fabs(phi));
            max_slope = fmax(max_slope, fabs(slope));
            err_phi = fmax(err_phi, fabs(fit_phi - phi));
            err_slope = fmax(err_slope, fabs(fit_slope - slope));
        }
        fit->error_phi = fmax(fit->error_phi, err_phi / max_phi);
        fit->error_slope = fmax(fit->error_slope, err_slope / max_slope);
    }
}

int shape_fit_modes(const modal_set *modes, double tolerance, shape_fit *fit)
{
    int pieces;
    for (pieces = 8; pieces <= BS_SHAPE_MAX_PIECES; pieces *= 2) {
        fit_pieces(modes, pieces, fit);
        measure_error(modes, fit);
        if (fit->error_phi <= tolerance && fit->error_slope <= tolerance)
            return 0;
    }
    return -1;
}
