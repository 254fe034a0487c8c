/* modal.c - bending modes of a beam with rotational springs at both ends.
 *
 * Euler-Bernoulli beam, xi = x / L in [0, 1], w(0) = w(1) = 0,
 * phi'' = kappa phi' at xi = 0 and phi'' = -kappa phi' at xi = 1,
 * kappa = k_r L / EI. The problem is symmetric about xi = 1/2; with
 * eta = xi - 1/2 the modes split into
 *   symmetric      phi = cos(l eta) - cos(l/2) cosh(l eta) / cosh(l/2)
 *                  f_s(l) = 2 l cos(l/2) + kappa (sin(l/2) + cos(l/2) tanh(l/2)) = 0
 *   antisymmetric  phi = sin(l eta) - sin(l/2) sinh(l eta) / sinh(l/2)
 *                  f_a(l) = 2 l sin(l/2) - kappa (cos(l/2) - sin(l/2) coth(l/2)) = 0
 * and the k-th root lies in (k pi, (k+1) pi), odd k symmetric, even k
 * antisymmetric (both ends of the interval give opposite signs).
 *
 * The ratios cosh(l eta)/cosh(l/2) and sinh(l eta)/sinh(l/2) are evaluated as
 * (e^{l(eta-1/2)} +- e^{-l(eta+1/2)}) / (1 +- e^{-l}): every term is at most 1,
 * so nothing cancels (the written form c3 sinh + c4 cosh loses 7 digits at
 * l = 17 near xi = 1, docs/model.md 3).
 *
 * omega_k = l_k^2 sqrt(EI / (rho A L^4)); normalisation rho A L int phi^2 = 1
 * and sign c1 > 0 (c1: coefficient of sin(l xi) in the written form:
 * A sin(l/2) for symmetric, A cos(l/2) for antisymmetric modes).
 * Integrals by 8-point Gauss-Legendre on 256 panels (exact to rounding for
 * these smooth integrands). By symmetry gamma_k = 0 for antisymmetric modes and
 * I_ij = 0 for modes of opposite symmetry; those are set to exactly 0 rather
 * than left at quadrature noise of 1e-17.
 */
#include "modal.h"

#include <float.h>
#include <math.h>

#define PANELS 256
#define NODES 8

double modal_width(const modal_beam *beam)
{
    return beam->mass / (beam->density * beam->thickness * beam->length);
}

static double bending_stiffness(const modal_beam *beam)
{
    return beam->youngs_modulus * modal_width(beam) * pow(beam->thickness, 3) / 12.0;
}

double modal_kappa(const modal_beam *beam)
{
    return beam->k_rot * beam->length / bending_stiffness(beam);
}

static double frequency_equation(int symmetric, double kappa, double l)
{
    const double s = sin(0.5 * l);
    const double c = cos(0.5 * l);
    if (symmetric)
        return 2.0 * l * c + kappa * (s + c * tanh(0.5 * l));
    return 2.0 * l * s - kappa * (c - s / tanh(0.5 * l));
}

/* Bisection to the last bit: robust, and cost is irrelevant on the host. */
static int find_root(int symmetric, double kappa, double low, double high, double *root)
{
    double f_low = frequency_equation(symmetric, kappa, low);
    const double f_high = frequency_equation(symmetric, kappa, high);
    int i;

    if (f_low * f_high > 0.0)
        return -1;
    for (i = 0; i < 200 && high - low > 4.0 * DBL_EPSILON * high; ++i) {
        const double mid = 0.5 * (low + high);
        const double f_mid = frequency_equation(symmetric, kappa, mid);
        if (f_mid == 0.0) {
            low = high = mid;
            break;
        }
        if ((f_mid < 0.0) == (f_low < 0.0)) {
            low = mid;
            f_low = f_mid;
        } else {
            high = mid;
        }
    }
    *root = 0.5 * (low + high);
    return 0;
}

/* Unnormalised shape and its xi-derivative. */
static void raw_shape(int symmetric, double l, double xi, double *phi, double *phi_xi)
{
    const double eta = xi - 0.5;
    const double grow = exp(l * (eta - 0.5));    /* e^{l(eta - 1/2)} <= 1 */
    const double decay = exp(-l * (eta + 0.5));  /* e^{-l(eta + 1/2)} <= 1 */
    const double tail = exp(-l);
    if (symmetric) {
        const double c = cos(0.5 * l);
        const double cosh_ratio = (grow + decay) / (1.0 + tail);  /* cosh(l eta)/cosh(l/2) */
        const double sinh_ratio = (grow - decay) / (1.0 + tail);  /* sinh(l eta)/cosh(l/2) */
        *phi = cos(l * eta) - c * cosh_ratio;
        *phi_xi = -l * sin(l * eta) - c * l * sinh_ratio;
    } else {
        const double s = sin(0.5 * l);
        const double sinh_ratio = (grow - decay) / (1.0 - tail);  /* sinh(l eta)/sinh(l/2) */
        const double cosh_ratio = (grow + decay) / (1.0 - tail);  /* cosh(l eta)/sinh(l/2) */
        *phi = sin(l * eta) - s * sinh_ratio;
        *phi_xi = l * cos(l * eta) - s * l * cosh_ratio;
    }
}

void modal_shape(const modal_set *modes, int k, double xi, double *phi, double *phi_xi)
{
    raw_shape(k % 2 == 0, modes->lambda[k], xi, phi, phi_xi);
    *phi *= modes->amplitude[k];
    *phi_xi *= modes->amplitude[k];
}

/* Gauss-Legendre nodes and weights on [-1, 1] by Newton on P_n. */
static void gauss_legendre(double *x, double *w)
{
    const double pi = 3.14159265358979323846;
    int i;
    for (i = 0; i < NODES; ++i) {
        double z = cos(pi * (i + 0.75) / (NODES + 0.5));
        double derivative = 1.0;
        int iteration;
        for (iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0;
            double p1 = z;
            double z_old = z;
            int j;
            for (j = 2; j <= NODES; ++j) {
                const double p2 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p0) / j;
                p0 = p1;
                p1 = p2;
            }
            derivative = NODES * (z * p1 - p0) / (z * z - 1.0);
            z -= p1 / derivative;
            if (fabs(z - z_old) < 1e-16)
                break;
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * derivative * derivative);
    }
}

int modal_compute(const modal_beam *beam, int n, modal_set *modes)
{
    const double pi = 3.14159265358979323846;
    const double kappa = modal_kappa(beam);
    const double ei = bending_stiffness(beam);
    const double ea = beam->youngs_modulus * modal_width(beam) * beam->thickness;
    const double omega_scale = sqrt(ei / (beam->mass * pow(beam->length, 3)));
    double node[NODES];
    double weight[NODES];
    double integral_phi[BS_MAX_MODES] = {0};
    double integral_phi2[BS_MAX_MODES] = {0};
    int k;
    int i;
    int j;
    int panel;

    if (n < 1 || n > BS_MAX_MODES)
        return -1;
    modes->n = n;
    modes->mass = beam->mass;
    modes->length = beam->length;
    modes->k_axial_total = 1.0 / (beam->length / ea + 1.0 / beam->k_axial);
    for (k = 0; k < n; ++k) {
        const int symmetric = k % 2 == 0;
        if (find_root(symmetric, kappa, (k + 1) * pi, (k + 2) * pi, &modes->lambda[k]) != 0)
            return -1;
        modes->omega[k] = modes->lambda[k] * modes->lambda[k] * omega_scale;
        modes->amplitude[k] = 1.0;
    }

    gauss_legendre(node, weight);
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            modes->slope_gram[i][j] = 0.0;
    for (panel = 0; panel < PANELS; ++panel) {
        int q;
        for (q = 0; q < NODES; ++q) {
            const double xi = (panel + 0.5 * (node[q] + 1.0)) / PANELS;
            const double dxi = 0.5 * weight[q] / PANELS;
            double phi[BS_MAX_MODES];
            double phi_xi[BS_MAX_MODES];
            for (k = 0; k < n; ++k) {
                raw_shape(k % 2 == 0, modes->lambda[k], xi, &phi[k], &phi_xi[k]);
                integral_phi[k] += phi[k] * dxi;
                integral_phi2[k] += phi[k] * phi[k] * dxi;
            }
            for (i = 0; i < n; ++i)
                for (j = 0; j < n; ++j)
                    modes->slope_gram[i][j] += phi_xi[i] * phi_xi[j] * dxi;
        }
    }
    for (k = 0; k < n; ++k) {
        const double half = 0.5 * modes->lambda[k];
        const double c1_sign = (k % 2 == 0 ? sin(half) : cos(half)) >= 0.0 ? 1.0 : -1.0;
        modes->amplitude[k] = c1_sign / sqrt(beam->mass * integral_phi2[k]);
        modes->gamma[k] = k % 2 == 0 ? beam->mass * modes->amplitude[k] * integral_phi[k] : 0.0;
    }
    for (i = 0; i < n; ++i)
        for (j = i; j < n; ++j) { /* mirrored, so that I is exactly symmetric */
            modes->slope_gram[i][j] = (i + j) % 2 == 0
                ? modes->slope_gram[i][j] * (modes->amplitude[i] * modes->amplitude[j]) : 0.0;
            modes->slope_gram[j][i] = modes->slope_gram[i][j];
        }
    return 0;
}
