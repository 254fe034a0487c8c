/* attached.c - Rayleigh-Ritz on the bare-beam modes with the slider rigidly
 * attached at s:
 *   K = diag(omega_k^2),  M = I + m phi phi^T + (J_C + m d^2) phi' phi'^T
 * (phi, phi' = d phi/dx at s; the centre of mass, d below the axis, moves
 * horizontally by d times the slope). The lowest eigenvalue of M^-1 K comes
 * from inverse iteration with the Rayleigh quotient. docs/model.md 8 quotes
 * ~248 Hz at s = 0.05, ~88 Hz at s = 0.5, 124 Hz near s = 0.25.
 */
#include "attached.h"

#include <math.h>

double attached_frequency(const modal_set *modes, const scene_params *p, double s)
{
    const int n = modes->n;
    const double rotary = p->slider_inertia + p->slider_mass * p->com_offset * p->com_offset;
    double mass[BS_MAX_MODES][BS_MAX_MODES];
    double phi[BS_MAX_MODES], slope[BS_MAX_MODES], v[BS_MAX_MODES];
    double lambda = 0.0;
    int i, j, iteration;

    for (i = 0; i < n; ++i) {
        modal_shape(modes, i, s, &phi[i], &slope[i]);
        slope[i] /= p->beam.length;
        v[i] = 1.0;
    }
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            mass[i][j] = (i == j) + p->slider_mass * phi[i] * phi[j] + rotary * slope[i] * slope[j];
    for (iteration = 0; iteration < 1000; ++iteration) {
        /* K y = M v with K diagonal, then v = y / |y| */
        double y[BS_MAX_MODES], norm = 0.0, kinetic = 0.0, elastic = 0.0, previous = lambda;
        for (i = 0; i < n; ++i) {
            y[i] = 0.0;
            for (j = 0; j < n; ++j)
                y[i] += mass[i][j] * v[j];
            y[i] /= modes->omega[i] * modes->omega[i];
            norm += y[i] * y[i];
        }
        for (i = 0; i < n; ++i)
            v[i] = y[i] / sqrt(norm);
        for (i = 0; i < n; ++i) {
            elastic += modes->omega[i] * modes->omega[i] * v[i] * v[i];
            for (j = 0; j < n; ++j)
                kinetic += v[i] * mass[i][j] * v[j];
        }
        lambda = elastic / kinetic;
        if (fabs(lambda - previous) <= 1e-14 * lambda)
            break;
    }
    return sqrt(lambda) / (2.0 * 3.14159265358979323846);
}

double attached_position(const modal_set *modes, const scene_params *p, double frequency)
{
    double low = 0.5 * p->slot_width / p->beam.length, high = 0.5;
    int i;
    /* the attached frequency falls from the clamp to the centre */
    if (!(attached_frequency(modes, p, low) >= frequency && attached_frequency(modes, p, high) <= frequency))
        return -1.0;
    for (i = 0; i < 60; ++i) {
        const double mid = 0.5 * (low + high);
        if (attached_frequency(modes, p, mid) > frequency)
            low = mid;
        else
            high = mid;
    }
    return 0.5 * (low + high);
}
