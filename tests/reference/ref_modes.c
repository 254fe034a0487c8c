/* ref_modes.c - bending modes of the spring-clamped beam (docs/model.md 3).
 *
 *   phi(xi) = a1 sin(l xi) + a2 cos(l xi) + a3 E0 + a4 E1,
 *             E0 = e^(-l xi), E1 = e^(-l (1 - xi)), eps = e^(-l)
 *   (sinh, cosh of l xi are combinations of E0 and E1 e^l: same space.)
 *   Boundary conditions (kappa = k_r L / EI, ' = d/dxi):
 *     phi(0) = 0, phi''(0) = +kappa phi'(0), phi(1) = 0, phi''(1) = -kappa phi'(1)
 *   give B(l) a = 0 with (rows 2 and 4 divided by l)
 *     [ 0                      1                       1            eps        ]
 *     [ -kappa                 -l                      l + kappa    (l-kappa)eps]
 *     [ sin l                  cos l                   eps          1          ]
 *     [ -l sin l + kappa cos l -l cos l - kappa sin l  (l-kappa)eps l + kappa  ]
 *   lambda_k: k-th positive root of det B (scan for sign changes, bisection to
 *   the last bit in long double); a: null vector of B (cofactors).
 *   Scaling: rho A L int_0^1 phi^2 dxi = 1 with a1 > 0.
 *   omega_k = lambda_k^2 sqrt(EI / (rho A L^4)), gamma_k = rho A L int phi_k,
 *   I_ij = int phi_i' phi_j' (5-point Gauss-Legendre on 256 panels).
 *   b = rho A L / (rho h L), I = b h^3 / 12, A = b h, k_ax = (L/(EA) + 1/k_t)^-1. */
#include "ref_modes.h"

#include <math.h>
#include "ref_linalg.h"

#define REF_QUAD_PANELS 256
#define REF_SCAN_START 0.5L   /* below the first root for any kappa >= 0 (pinned: pi) */
#define REF_SCAN_STEP 0.02L

static void boundary_matrix(long double l, long double kappa, long double b[4][4])
{
    const long double eps = expl(-l);
    const long double s = sinl(l), c = cosl(l);

    b[0][0] = 0.0L;
    b[0][1] = 1.0L;
    b[0][2] = 1.0L;
    b[0][3] = eps;
    b[1][0] = -kappa;
    b[1][1] = -l;
    b[1][2] = l + kappa;
    b[1][3] = (l - kappa) * eps;
    b[2][0] = s;
    b[2][1] = c;
    b[2][2] = eps;
    b[2][3] = 1.0L;
    b[3][0] = -l * s + kappa * c;
    b[3][1] = -l * c - kappa * s;
    b[3][2] = (l - kappa) * eps;
    b[3][3] = l + kappa;
}

long double ref_modes_det(long double lambda, long double kappa)
{
    long double b[4][4];
    boundary_matrix(lambda, kappa, b);
    return ref_linalg_det4(b);
}

static long double find_root(long double lo, long double hi, long double kappa)
{
    long double f_lo = ref_modes_det(lo, kappa);
    int i;

    for (i = 0; i < 200; ++i) {
        const long double mid = 0.5L * (lo + hi);
        long double f_mid;
        if (mid <= lo || mid >= hi)
            break;
        f_mid = ref_modes_det(mid, kappa);
        if (f_mid == 0.0L)
            return mid;
        if ((f_mid < 0.0L) == (f_lo < 0.0L)) {
            lo = mid;
            f_lo = f_mid;
        } else {
            hi = mid;
        }
    }
    return 0.5L * (lo + hi);
}

void ref_modes_shape(const ref_modes *modes, int k, long double xi, long double out[3])
{
    const long double l = modes->lambda[k];
    const long double *a = modes->coef[k];
    const long double s = sinl(l * xi), c = cosl(l * xi);
    const long double e0 = expl(-l * xi), e1 = expl(-l * (1.0L - xi));

    out[0] = a[0] * s + a[1] * c + a[2] * e0 + a[3] * e1;
    out[1] = l * (a[0] * c - a[1] * s - a[2] * e0 + a[3] * e1);
    out[2] = l * l * (-a[0] * s - a[1] * c + a[2] * e0 + a[3] * e1);
}

void ref_modes_eval(const ref_modes *modes, double xi, double *phi, double *phi_xi)
{
    int k;
    if (!(xi >= 0.0 && xi <= 1.0)) {
        for (k = 0; k < modes->n; ++k)
            phi[k] = phi_xi[k] = 0.0;
        return;
    }
    for (k = 0; k < modes->n; ++k) {
        const double l = modes->lambda_d[k];
        const double *a = modes->coef_d[k];
        const double s = sin(l * xi), c = cos(l * xi);
        const double e0 = exp(-l * xi), e1 = exp(-l * (1.0 - xi));
        phi[k] = a[0] * s + a[1] * c + a[2] * e0 + a[3] * e1;
        phi_xi[k] = l * (a[0] * c - a[1] * s - a[2] * e0 + a[3] * e1);
    }
}

/* Gauss-Legendre 5 points on [-1, 1] */
static void quad_rule(long double node[5], long double weight[5])
{
    const long double r = sqrtl(10.0L / 7.0L);
    const long double s70 = sqrtl(70.0L);
    node[0] = 0.0L;
    weight[0] = 128.0L / 225.0L;
    node[1] = sqrtl(5.0L - 2.0L * r) / 3.0L;
    node[2] = -node[1];
    weight[1] = weight[2] = (322.0L + 13.0L * s70) / 900.0L;
    node[3] = sqrtl(5.0L + 2.0L * r) / 3.0L;
    node[4] = -node[3];
    weight[3] = weight[4] = (322.0L - 13.0L * s70) / 900.0L;
}

/* integrals over [0, 1] of the unnormalised shapes: int phi_i phi_j,
 * int phi_i' phi_j', int phi_i */
static void integrate(const ref_modes *modes, long double mass_int[REF_MAX_MODES][REF_MAX_MODES],
                      long double slope_int[REF_MAX_MODES][REF_MAX_MODES], long double mean[REF_MAX_MODES])
{
    long double node[5], weight[5];
    const long double h = 1.0L / REF_QUAD_PANELS;
    int p, g, i, j;

    quad_rule(node, weight);
    for (i = 0; i < modes->n; ++i) {
        mean[i] = 0.0L;
        for (j = 0; j < modes->n; ++j)
            mass_int[i][j] = slope_int[i][j] = 0.0L;
    }
    for (p = 0; p < REF_QUAD_PANELS; ++p) {
        for (g = 0; g < 5; ++g) {
            const long double xi = h * ((long double)p + 0.5L + 0.5L * node[g]);
            const long double w = 0.5L * h * weight[g];
            long double v[REF_MAX_MODES][3];
            for (i = 0; i < modes->n; ++i)
                ref_modes_shape(modes, i, xi, v[i]);
            for (i = 0; i < modes->n; ++i) {
                mean[i] += w * v[i][0];
                for (j = 0; j < modes->n; ++j) {
                    mass_int[i][j] += w * v[i][0] * v[j][0];
                    slope_int[i][j] += w * v[i][1] * v[j][1];
                }
            }
        }
    }
}

int ref_modes_compute(const ref_beam *beam, int n, ref_modes *modes)
{
    const long double L = beam->length, h = beam->thickness, m = beam->mass;
    long double area, lo, f_lo;
    long double mass_int[REF_MAX_MODES][REF_MAX_MODES], slope_int[REF_MAX_MODES][REF_MAX_MODES];
    long double mean[REF_MAX_MODES];
    int k, j, found = 0;

    if (n < 0 || n > REF_MAX_MODES || !(beam->length > 0.0) || !(beam->thickness > 0.0)
        || !(beam->density > 0.0) || !(beam->youngs_modulus > 0.0) || !(beam->mass > 0.0)
        || !(beam->k_rot >= 0.0) || !(beam->k_axial > 0.0))
        return -1;
    modes->n = n;
    modes->width = m / ((long double)beam->density * h * L);
    area = modes->width * h;
    modes->ei = (long double)beam->youngs_modulus * modes->width * h * h * h / 12.0L;
    modes->kappa = (long double)beam->k_rot * L / modes->ei;
    modes->k_ax = 1.0L / (L / ((long double)beam->youngs_modulus * area) + 1.0L / (long double)beam->k_axial);

    lo = REF_SCAN_START;
    f_lo = ref_modes_det(lo, modes->kappa);
    while (found < n && lo < 1000.0L) {
        const long double hi = lo + REF_SCAN_STEP;
        const long double f_hi = ref_modes_det(hi, modes->kappa);
        if (f_hi == 0.0L || (f_hi < 0.0L) != (f_lo < 0.0L))
            modes->lambda[found++] = f_hi == 0.0L ? hi : find_root(lo, hi, modes->kappa);
        lo = hi;
        f_lo = f_hi;
    }
    if (found < n)
        return -1;

    for (k = 0; k < n; ++k) {
        long double b[4][4];
        boundary_matrix(modes->lambda[k], modes->kappa, b);
        ref_linalg_null4(b, modes->coef[k]);
    }
    integrate(modes, mass_int, slope_int, mean);
    for (k = 0; k < n; ++k) {
        long double scale = 1.0L / sqrtl(m * mass_int[k][k]);
        if (modes->coef[k][0] < 0.0L)
            scale = -scale;
        for (j = 0; j < 4; ++j)
            modes->coef[k][j] *= scale;
    }
    integrate(modes, mass_int, slope_int, mean);
    for (k = 0; k < n; ++k) {
        const long double l = modes->lambda[k];
        modes->omega[k] = (double)(l * l * sqrtl(modes->ei / (m * L * L * L)));
        modes->gamma[k] = (double)(m * mean[k]);
        modes->lambda_d[k] = (double)l;
        for (j = 0; j < 4; ++j)
            modes->coef_d[k][j] = (double)modes->coef[k][j];
        for (j = 0; j < n; ++j) {
            modes->slope_gram[k][j] = (double)slope_int[k][j];
            modes->mass_gram[k][j] = (double)(m * mass_int[k][j]);
        }
    }
    return 0;
}
