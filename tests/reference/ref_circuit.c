/* ref_circuit.c - exact one-step factors of C y' + y/R = i, i constant
 * (docs/model.md 11; see ref_circuit.h).
 *
 *   e = e^(-s/tau), x = dt/tau; means over s in [0, dt]:
 *     mean   = (1 - e^-x)/x        = sum_{n>=0} (-x)^n / (n+1)!
 *     mean2  = (1 - e^-2x)/(2x)    = sum_{n>=0} (-2x)^n / (n+1)!
 *     rise   = 1 - mean            = -sum_{n>=1} (-x)^n / (n+1)!
 *     cross  = mean - mean2        = sum_{n>=1} (-x)^n (1 - 2^n) / (n+1)!
 *     square = 1 - 2 mean + mean2  = sum_{n>=2} (-x)^n (2^n - 2) / (n+1)!
 *   The closed forms cancel for small x (rise ~ x/2, square ~ x^2/3), the
 *   series converge fast there: series below x = 1/2 (40 terms, the last
 *   below 1e-40), closed forms above (square loses at most ~1.3 digits). */
#include "ref_circuit.h"

#include <math.h>

#define REF_CIRCUIT_SERIES_BELOW 0.5L
#define REF_CIRCUIT_TERMS 40

void ref_circuit_factors_init(long double x, ref_circuit_factors *f)
{
    f->decay = expl(-x);
    f->gain = -expm1l(-x);
    if (x < REF_CIRCUIT_SERIES_BELOW) {
        long double power = 1.0L, two_n = 1.0L, factorial = 1.0L; /* (-x)^n, 2^n, (n+1)! */
        long double mean = 0.0L, mean2 = 0.0L, rise = 0.0L, cross = 0.0L, square = 0.0L;
        int n;
        for (n = 0; n < REF_CIRCUIT_TERMS; ++n) {
            const long double term = power / factorial;
            mean += term;
            mean2 += term * two_n;
            if (n >= 1) {
                rise -= term;
                cross += term * (1.0L - two_n);
            }
            if (n >= 2)
                square += term * (two_n - 2.0L);
            power *= -x;
            two_n *= 2.0L;
            factorial *= (long double)(n + 2);
        }
        f->mean = mean;
        f->mean2 = mean2;
        f->rise = rise;
        f->cross = cross;
        f->square = square;
    } else {
        f->mean = f->gain / x;
        f->mean2 = -expm1l(-2.0L * x) / (2.0L * x);
        f->rise = 1.0L - f->mean;
        f->cross = f->mean - f->mean2;
        f->square = 1.0L - 2.0L * f->mean + f->mean2;
    }
}

long double ref_circuit_mean(const ref_circuit_factors *f, long double y_b, long double a)
{
    return f->mean * y_b + f->rise * a;
}

long double ref_circuit_mean_square(const ref_circuit_factors *f, long double y_b, long double a)
{
    return f->mean2 * y_b * y_b + 2.0L * f->cross * y_b * a + f->square * a * a;
}
