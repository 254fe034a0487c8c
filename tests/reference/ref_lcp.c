/* ref_lcp.c - the contact problem of one Moreau step (docs/model.md 4, 5;
 * the rectifier's bridge of docs/model.md 11 is a 1-row unknown like an end stop).
 *
 *   xi = G P + c; per contact i (rows N, T):
 *     Signorini  0 <= P_N  _|_  xi_N >= 0
 *     Coulomb    |P_T| <= mu P_N,  P_T = -mu P_N sign(xi_T) if xi_T != 0
 *   End stops have the normal row only.
 *   Natural map (prox form, r_i = 1 / max diag G_ii):
 *     P_N = max(0, P_N - r xi_N),  P_T = clamp(P_T - r xi_T, -mu P_N, mu P_N)
 *   P solves the problem iff P equals its image; residual = sum |P - image|.
 *
 *   Enumeration: a mode per contact fixes the unknowns and equations:
 *     TAKEOFF  P = 0                          (no equation)
 *     STICK    unknowns P_N, P_T              xi_N = 0, xi_T = 0
 *     SLIP+-   unknown P_N, P_T = -+mu P_N    xi_N = 0
 *   giving K x = -E c with K = E G S (S: unknowns -> P, E: equation rows),
 *   solved in long double; the mode holds if the natural-map residual of
 *   P = S x vanishes (<= REF_LCP_ACCEPT relative). Two solutions give the
 *   same velocities iff dP^T G dP = 0 (G = W^T M^-1 W: kinetic metric; with
 *   the bridge only G's symmetric part, still PSD, enters the quadratic form).
 *
 *   PGS: for each contact in order, xi_N from the current P, update P_N,
 *   then xi_T with the new P_N, update P_T; sweep until
 *   sum |dP| <= tol_rel sum |P|. */
#include "ref_lcp.h"

#include <math.h>
#include "ref_linalg.h"

#define REF_LCP_PIVOT 1e-13L     /* relative pivot below which a mode's system is singular */
#define REF_LCP_DISTINCT 1e-8    /* relative kinetic-metric distance of two distinct solutions */
#define REF_LCP_KEEP 32          /* solutions kept for the ambiguity check */

void ref_lcp_layout(ref_lcp *p, int n, const int *dim, const double *mu)
{
    int i, rows = 0;
    p->n = n;
    for (i = 0; i < n; ++i) {
        p->dim[i] = dim[i];
        p->mu[i] = mu[i];
        p->row[i] = rows;
        rows += dim[i];
    }
    p->rows = rows;
}

static double step_size(const ref_lcp *p, int i)
{
    const int r = p->row[i];
    double diag = p->g[r][r];
    if (p->dim[i] == 2 && p->g[r + 1][r + 1] > diag)
        diag = p->g[r + 1][r + 1];
    return diag > 0.0 ? 1.0 / diag : 0.0;
}

static long double row_velocity(const ref_lcp *p, int r, const double *percussion)
{
    long double xi = p->c[r];
    int j;
    for (j = 0; j < p->rows; ++j)
        xi += (long double)p->g[r][j] * percussion[j];
    return xi;
}

static long double clampl(long double v, long double lo, long double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

double ref_lcp_residual(const ref_lcp *p, const double *percussion, double *rel)
{
    long double res = 0.0L, scale = 0.0L;
    int i;

    for (i = 0; i < p->n; ++i) {
        const int r = p->row[i];
        const long double step = step_size(p, i);
        const long double pn = percussion[r];
        const long double pn_new = fmaxl(0.0L, pn - step * row_velocity(p, r, percussion));
        res += fabsl(pn - pn_new);
        scale += fabsl(pn) + step * fabsl((long double)p->c[r]);
        if (p->dim[i] == 2) {
            const long double pt = percussion[r + 1];
            const long double bound = (long double)p->mu[i] * pn_new;
            const long double pt_new = clampl(pt - step * row_velocity(p, r + 1, percussion), -bound, bound);
            res += fabsl(pt - pt_new);
            scale += fabsl(pt) + step * fabsl((long double)p->c[r + 1]);
        }
    }
    if (rel)
        *rel = scale > 0.0L ? (double)(res / scale) : 0.0;
    return (double)res;
}

/* P for one mode vector; returns 0, or -1 if its system is singular. */
static int solve_mode(const ref_lcp *p, const ref_mode *mode, double *percussion)
{
    long double s[REF_MAX_ROWS][REF_MAX_ROWS]; /* S: row of P x unknown */
    long double k[REF_MAX_ROWS * REF_MAX_ROWS], x[REF_MAX_ROWS];
    int eq[REF_MAX_ROWS];
    int unknowns = 0, i, a, b, r;

    for (r = 0; r < p->rows; ++r)
        for (b = 0; b < p->rows; ++b)
            s[r][b] = 0.0L;
    for (i = 0; i < p->n; ++i) {
        const int r0 = p->row[i];
        switch (mode[i]) {
        case REF_TAKEOFF:
            break;
        case REF_STICK:
            s[r0][unknowns] = 1.0L;
            eq[unknowns++] = r0;
            if (p->dim[i] == 2) {
                s[r0 + 1][unknowns] = 1.0L;
                eq[unknowns++] = r0 + 1;
            }
            break;
        case REF_SLIP_POS:
        case REF_SLIP_NEG:
            s[r0][unknowns] = 1.0L;
            s[r0 + 1][unknowns] = (mode[i] == REF_SLIP_POS ? -1.0L : 1.0L) * (long double)p->mu[i];
            eq[unknowns++] = r0;
            break;
        }
    }
    for (r = 0; r < p->rows; ++r)
        percussion[r] = 0.0;
    if (unknowns == 0)
        return 0;
    for (a = 0; a < unknowns; ++a) {
        for (b = 0; b < unknowns; ++b) {
            long double sum = 0.0L;
            for (r = 0; r < p->rows; ++r)
                sum += (long double)p->g[eq[a]][r] * s[r][b];
            k[a * unknowns + b] = sum;
        }
        x[a] = -(long double)p->c[eq[a]];
    }
    if (ref_linalg_solve(unknowns, k, x, REF_LCP_PIVOT) != 0)
        return -1;
    for (r = 0; r < p->rows; ++r) {
        long double sum = 0.0L;
        for (b = 0; b < unknowns; ++b)
            sum += s[r][b] * x[b];
        percussion[r] = (double)sum;
    }
    return 0;
}

/* dP^T G dP */
static double kinetic_distance2(const ref_lcp *p, const double *a, const double *b)
{
    long double sum = 0.0L;
    int i, j;
    for (i = 0; i < p->rows; ++i)
        for (j = 0; j < p->rows; ++j)
            sum += ((long double)a[i] - b[i]) * p->g[i][j] * ((long double)a[j] - b[j]);
    return (double)sum;
}

int ref_lcp_enumerate(const ref_lcp *p, double *percussion, ref_mode *mode, int exhaustive, ref_lcp_info *info)
{
    static const double zero[REF_MAX_ROWS];
    double trial[REF_MAX_ROWS], best[REF_MAX_ROWS];
    double kept[REF_LCP_KEEP][REF_MAX_ROWS];
    ref_mode current[REF_MAX_UNILATERAL], best_mode[REF_MAX_UNILATERAL];
    double best_rel = HUGE_VAL, rel;
    long combos = 1, index;
    int n_kept = 0, i, r;

    info->iterations = 0;
    info->exhaustive = 0;
    info->solutions = 0;
    info->ambiguous = 0;
    if (!exhaustive) {
        ++info->iterations;
        if (solve_mode(p, mode, trial) == 0) {
            info->residual = ref_lcp_residual(p, trial, &rel);
            if (rel <= REF_LCP_ACCEPT) {
                for (r = 0; r < p->rows; ++r)
                    percussion[r] = trial[r];
                info->residual_rel = rel;
                info->converged = 1;
                return 0;
            }
        }
    }
    info->exhaustive = 1;
    for (i = 0; i < p->n; ++i)
        combos *= p->dim[i] == 2 ? 4 : 2;
    for (r = 0; r < p->rows; ++r)
        best[r] = 0.0;
    for (i = 0; i < p->n; ++i)
        best_mode[i] = REF_TAKEOFF;
    for (index = 0; index < combos; ++index) {
        long rest = index;
        for (i = 0; i < p->n; ++i) {
            const int count = p->dim[i] == 2 ? 4 : 2;
            current[i] = (ref_mode)(rest % count);
            rest /= count;
        }
        ++info->iterations;
        if (solve_mode(p, current, trial) != 0)
            continue;
        ref_lcp_residual(p, trial, &rel);
        if (rel <= REF_LCP_ACCEPT) {
            ++info->solutions;
            if (n_kept < REF_LCP_KEEP) {
                for (r = 0; r < p->rows; ++r)
                    kept[n_kept][r] = trial[r];
                ++n_kept;
            }
        }
        if (rel < best_rel) {
            best_rel = rel;
            for (r = 0; r < p->rows; ++r)
                best[r] = trial[r];
            for (i = 0; i < p->n; ++i)
                best_mode[i] = current[i];
        }
    }
    for (i = 0; i < n_kept; ++i) {
        const double size2 = kinetic_distance2(p, best, zero);
        if (kinetic_distance2(p, kept[i], best) > REF_LCP_DISTINCT * REF_LCP_DISTINCT * size2)
            info->ambiguous = 1;
    }
    for (r = 0; r < p->rows; ++r)
        percussion[r] = best[r];
    for (i = 0; i < p->n; ++i)
        mode[i] = best_mode[i];
    info->residual = ref_lcp_residual(p, percussion, &info->residual_rel);
    info->converged = info->residual_rel <= REF_LCP_ACCEPT;
    return info->converged ? 0 : -1;
}

int ref_lcp_pgs(const ref_lcp *p, double *percussion, double tol_rel, long max_sweeps, ref_lcp_info *info)
{
    double step[REF_MAX_UNILATERAL];
    long sweep;
    int i;

    for (i = 0; i < p->n; ++i)
        step[i] = step_size(p, i);
    info->exhaustive = info->solutions = info->ambiguous = 0;
    info->converged = 0;
    for (sweep = 1; sweep <= max_sweeps; ++sweep) {
        long double change = 0.0L, size = 0.0L;
        for (i = 0; i < p->n; ++i) {
            const int r = p->row[i];
            const double pn = percussion[r];
            const double pn_new = fmax(0.0, pn - step[i] * (double)row_velocity(p, r, percussion));
            percussion[r] = pn_new;
            change += fabs(pn_new - pn);
            size += fabs(pn_new);
            if (p->dim[i] == 2) {
                const double pt = percussion[r + 1];
                const double bound = p->mu[i] * pn_new;
                const double pt_new = fmin(bound, fmax(-bound, pt - step[i] * (double)row_velocity(p, r + 1, percussion)));
                percussion[r + 1] = pt_new;
                change += fabs(pt_new - pt);
                size += fabs(pt_new);
            }
        }
        if (change == 0.0L || change <= (long double)tol_rel * size) {
            info->converged = 1;
            break;
        }
    }
    info->iterations = sweep > max_sweeps ? max_sweeps : sweep;
    info->residual = ref_lcp_residual(p, percussion, &info->residual_rel);
    return info->converged ? 0 : -1;
}
