/* ref_lcp.h - the per-step contact problem of docs/model.md 4-5 (with a
 * rectifier also the bridge of docs/model.md 11, one more 1-row unknown) and
 * two solvers: exact enumeration of modes and uncapped projected Gauss-Seidel. */
#ifndef REF_LCP_H
#define REF_LCP_H

#include "ref_config.h"

/* Contact modes; a 1-row unknown (end stop, bridge) is TAKEOFF (open,
 * blocking) or STICK (closed, conducting). */
typedef enum ref_mode {
    REF_TAKEOFF = 0,   /* P = 0, xi_N >= 0 */
    REF_STICK = 1,     /* xi = 0, |P_T| <= mu P_N, P_N >= 0 */
    REF_SLIP_POS = 2,  /* xi_N = 0, xi_T > 0, P_T = -mu P_N */
    REF_SLIP_NEG = 3   /* xi_N = 0, xi_T < 0, P_T = +mu P_N */
} ref_mode;

/* xi = G P + c over n unknowns; unknown i owns rows row[i] (normal) and,
 * when dim[i] = 2, row[i] + 1 (tangential). */
typedef struct ref_lcp {
    int n;
    int rows;
    int dim[REF_MAX_UNILATERAL];
    int row[REF_MAX_UNILATERAL];
    double mu[REF_MAX_UNILATERAL];
    double g[REF_MAX_ROWS][REF_MAX_ROWS];   /* Delassus G = W^T M^-1 W, symmetric PSD; with the bridge
                                               not symmetric, its symmetric part PSD (ref_step.c) */
    double c[REF_MAX_ROWS];
} ref_lcp;

typedef struct ref_lcp_info {
    long iterations;    /* enumeration: linear systems solved; PGS: sweeps */
    double residual;    /* natural-map residual sum |P - prox(P - r xi)| of the result [N s] */
    double residual_rel; /* residual / (sum |P| + sum r |c|) */
    int converged;      /* 1: the result satisfies the contact laws to the tolerance */
    int exhaustive;     /* enumeration: every mode was tried */
    int solutions;      /* enumeration, exhaustive: modes that solve the problem */
    int ambiguous;      /* enumeration, exhaustive: solutions giving different velocities */
} ref_lcp_info;

#define REF_LCP_ACCEPT 1e-11   /* relative natural-map residual accepted as a solution */

/* Sets n, dim, mu, rows and row offsets (G and c are the caller's). */
void ref_lcp_layout(ref_lcp *p, int n, const int *dim, const double *mu);

/* The natural-map residual of P (see ref_lcp_info); relative value in *rel. */
double ref_lcp_residual(const ref_lcp *p, const double *percussion, double *rel);

/* Exact solve by contact-mode enumeration: tries mode (the guess) first and
 * accepts it when its residual_rel <= REF_LCP_ACCEPT, otherwise (or always
 * when exhaustive) tries all 4^n2 2^n1 modes and keeps the smallest
 * residual. percussion and mode receive the result. Returns 0 if a mode
 * solved the problem, -1 otherwise (the best found is returned). */
int ref_lcp_enumerate(const ref_lcp *p, double *percussion, ref_mode *mode, int exhaustive, ref_lcp_info *info);

/* Projected Gauss-Seidel from percussion (warm start) until
 * sum |dP| <= tol_rel sum |P| (or dP = 0), r_i = 1 / max diag G_ii.
 * max_sweeps is a safety stop, not an accuracy cap: hitting it returns -1. */
int ref_lcp_pgs(const ref_lcp *p, double *percussion, double tol_rel, long max_sweeps, ref_lcp_info *info);

#endif
