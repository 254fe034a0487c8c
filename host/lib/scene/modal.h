/* modal.h - bending modes of the beam with rotational springs at both clamps,
 * computed in double on the host (never in core). */
#ifndef MODAL_H
#define MODAL_H

#include "bs_config.h"

/* The beam as docs/model.md 3 defines it (SI units). */
typedef struct modal_beam {
    double length;          /* L [m] */
    double thickness;       /* h [m] */
    double density;         /* rho [kg/m^3] */
    double youngs_modulus;  /* E [Pa] */
    double mass;            /* rho A L of the free length [kg] */
    double k_rot;           /* k_r, each end [N m/rad] */
    double k_axial;         /* k_t of the clamps [N/m] */
} modal_beam;

typedef struct modal_set {
    int n;                                  /* modes */
    double lambda[BS_MAX_MODES];            /* lambda_k: roots of the frequency equation */
    double omega[BS_MAX_MODES];             /* omega_k [rad/s] */
    double amplitude[BS_MAX_MODES];         /* factor A_k making rho A L int phi^2 = 1, sign c1 > 0 */
    double gamma[BS_MAX_MODES];             /* rho A L int phi_k [sqrt(kg)] */
    double slope_gram[BS_MAX_MODES][BS_MAX_MODES]; /* I_ij = int phi_i,xi phi_j,xi dxi [1/kg] */
    double k_axial_total;                   /* k_ax = (L/EA + 1/k_t)^-1 [N/m] */
    double mass;                            /* rho A L [kg] */
    double length;                          /* L [m] */
} modal_set;

/* Width b = mass / (rho h L) [m]. */
double modal_width(const modal_beam *beam);

/* kappa = k_r L / EI, the dimensionless clamp stiffness. */
double modal_kappa(const modal_beam *beam);

/* Computes n modes (1 <= n <= BS_MAX_MODES). Returns 0, or -1 if a root
 * could not be bracketed (which would be a bug: each lambda_k lies in
 * (k pi, (k+1) pi)). */
int modal_compute(const modal_beam *beam, int n, modal_set *modes);

/* phi_k(xi) [1/sqrt(kg)] and d phi_k / d xi, k = 0..n-1, from the
 * cancellation-free closed form; xi in [0, 1]. */
void modal_shape(const modal_set *modes, int k, double xi, double *phi, double *phi_xi);

#endif
