/* shape_fit.h - piecewise polynomial mode shapes for the core (bs_shape.c). */
#ifndef SHAPE_FIT_H
#define SHAPE_FIT_H

#include "bs_config.h"
#include "modal.h"

typedef struct shape_fit {
    int pieces;                                                    /* equal pieces on [0, 1] */
    double coef[BS_SHAPE_MAX_PIECES][BS_MAX_MODES][BS_SHAPE_COEFS]; /* monomials in u in [-1, 1] */
    double error_phi;    /* max |fit - phi_k| / max |phi_k| over modes, on a fine grid */
    double error_slope;  /* the same for d phi_k / d xi */
} shape_fit;

/* Fits every mode with the fewest pieces (8, 16, ... BS_SHAPE_MAX_PIECES)
 * whose relative error in phi and slope is at most tolerance. Returns 0, or
 * -1 when even BS_SHAPE_MAX_PIECES pieces miss it (fit holds the finest). */
int shape_fit_modes(const modal_set *modes, double tolerance, shape_fit *fit);

/* Evaluates piece polynomials of fit at xi, in double (for error checks). */
void shape_fit_eval(const shape_fit *fit, int k, double xi, double *phi, double *phi_xi);

#endif
