/* ref_modes.h - bending modes of the beam with rotational springs at the
 * clamps (docs/model.md 3), computed in long double for the reference model. */
#ifndef REF_MODES_H
#define REF_MODES_H

#include "ref_config.h"

/* The beam (SI units), as docs/model.md 3 and 8 define it. */
typedef struct ref_beam {
    double length;          /* L [m] */
    double thickness;       /* h [m] */
    double density;         /* rho [kg/m^3] */
    double youngs_modulus;  /* E [Pa] */
    double mass;            /* rho A L [kg] */
    double k_rot;           /* k_r at each end [N m/rad] */
    double k_axial;         /* k_t of the clamps [N/m] */
} ref_beam;

/* Mode k: phi_k(xi) = a1 sin(l xi) + a2 cos(l xi) + a3 e^(-l xi) + a4 e^(-l (1-xi)),
 * l = lambda_k; the same space as sin, cos, sinh, cosh but with every basis
 * function bounded by 1 on [0, 1], so nothing cancels. a1 = c1 > 0. */
typedef struct ref_modes {
    int n;                                    /* N, 0..REF_MAX_MODES */
    long double width;                        /* b = m / (rho h L) [m] */
    long double ei;                           /* EI [N m^2] */
    long double kappa;                        /* k_r L / EI */
    long double k_ax;                         /* (L/(EA) + 1/k_t)^-1 [N/m] */
    long double lambda[REF_MAX_MODES];
    long double coef[REF_MAX_MODES][4];       /* a1..a4 [1/sqrt(kg)] */
    double omega[REF_MAX_MODES];              /* omega_k [rad/s] */
    double gamma[REF_MAX_MODES];              /* rho A L int phi_k dxi [sqrt(kg)] */
    double slope_gram[REF_MAX_MODES][REF_MAX_MODES]; /* I_ij = int phi_i' phi_j' dxi [1/kg] */
    double mass_gram[REF_MAX_MODES][REF_MAX_MODES];  /* rho A L int phi_i phi_j dxi (identity) */
    double lambda_d[REF_MAX_MODES];           /* double copies for evaluation in the step */
    double coef_d[REF_MAX_MODES][4];
} ref_modes;

/* The 4x4 boundary determinant in the bounded basis at lambda (docs/model.md 3:
 * w = 0, phi'' = +kappa phi' at xi = 0, phi'' = -kappa phi' at xi = 1). */
long double ref_modes_det(long double lambda, long double kappa);

/* Computes n modes (0 <= n <= REF_MAX_MODES). Returns 0, or -1 for an
 * invalid beam or a root that could not be found. */
int ref_modes_compute(const ref_beam *beam, int n, ref_modes *modes);

/* phi_k(xi), d phi/d xi, d^2 phi / d xi^2 of mode k in long double. */
void ref_modes_shape(const ref_modes *modes, int k, long double xi, long double out[3]);

/* phi_k(xi) and d phi_k / d xi of every mode at xi in double (the step's
 * evaluation). Outside [0, 1] the beam is rigid: all zero. */
void ref_modes_eval(const ref_modes *modes, double xi, double *phi, double *phi_xi);

#endif
