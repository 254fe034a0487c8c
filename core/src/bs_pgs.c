/* bs_pgs.c - bounded projected Gauss-Seidel with subspace minimisation for
 * the per-step contact problem.
 *
 * Unknowns: percussions P = (P_N,1, P_T,1, ..., P_N,n, P_T,n) [N s] (P_N only
 * when the build has no friction). Velocities after the step (Newton-modified):
 * xi = G P + c, G = W^T M^-1 W. Contact laws for each contact i (docs/model.md 4):
 *   0 <= P_N  _|_  xi_N >= 0,   |P_T| <= mu P_N,   P_T = -mu P_N sign(xi_T) if xi_T != 0.
 *
 * Gauss-Seidel sweep: visit the contacts in order and solve contact i's 2x2
 * problem exactly with the others frozen: with v = c_i + sum_{j != i} G_ij P_j
 * and the block G_ii = [a b; b d] the candidates are
 *   take-off   P = 0                                 if v_N >= 0
 *   stick      G_ii P = -v                           if P_N >= 0, |P_T| <= mu P_N
 *   slip s=+-1 P_T = -s mu P_N, P_N = -v_N / (a - s mu b)
 *                                                    if s ((b - s mu d) P_N + v_T) >= 0
 * which is the fixed point of the prox update the published model iterates,
 *   P_i <- prox(P_i - r_i (G_i: P + c_i)),  r_i = 1 / max(a, d),
 * reached in one visit instead of many. The prox update stays as a fall-back
 * for a block where no candidate is consistent (only possible when mu |b| is
 * comparable with a).
 *
 * Subspace step: two corners on the same face of the slot see almost the same
 * beam motion, so their rows of G are nearly parallel and Gauss-Seidel crawls
 * (hundreds of sweeps, docs/model.md 9.5). After each sweep that has not converged,
 * the modes the sweep reached (take-off, stick, slip +-) define a linear
 * system, rows per contact:
 *   take-off   P_N = 0, P_T = 0
 *   stick      xi_N = 0, xi_T = 0
 *   slip s     xi_N = 0, P_T + s mu P_N = 0
 * solved directly (Gaussian elimination, partial pivoting, 2n <= 12 unknowns;
 * redundant rows get the basic solution, see subspace_solve).
 * If the solution breaks a law, the first breaching contact moves to the mode
 * the breach points to (Murty's least-index rule: moving all at once can
 * cycle) and the system is solved again, until the laws hold, a mode set
 * repeats or SUBSPACE_TRIES sets were tried; the P with the smallest residual
 * is kept. With the right modes that is the exact solution. (Projected
 * Gauss-Seidel subspace minimisation: Silcowitz, Niebe, Erleben 2010.)
 * A build with BS_WITH_SUBSPACE 0 leaves the step out: each solve is then at
 * most max_sweeps plain sweeps, a hard bound on its cost for a real-time
 * loop, and redundant contacts end the step unconverged (reported).
 *
 * Warm start: P comes in holding each contact's percussion of the last step.
 * Stop: after each sweep (and subspace step) the natural-map residual of the
 * current P,
 *   e = sum_i | P_i - prox(P_i - r_i xi_i) |_1,
 * is computed (1-norms: no square roots; the reference's criterion leaves the
 * norm open); the solve stops when e <= tol_rel s + tol_abs (converged), with
 * the percussion scale s = sum_i r_i |c_i|_1 that would stop each contact's
 * free motion on its own. The reference measures against |P| instead; but
 * redundant contacts (two corners on one face, a preloaded slot) admit
 * internal squeeze that cancels in W P, warm starts let it drift from step to
 * step, and a tolerance relative to |P| then loosens with it until the step
 * diverges. s comes from the data and cannot be inflated that way. The solve
 * also stops when max_sweeps sweeps are done, or when a sweep did not lower e
 * (stalled: e is at the floor the precision reaches for this G). The residual
 * returned is the one of the P returned, whether converged or not
 * (docs/model.md 9.5: report it, never hide it).
 * With measure_residual off the solve is exactly max_sweeps sweeps: no
 * residual, no stop on it, no subspace step (which picks its result by the
 * residual); the report says "not measured" (residual -1, converged -1).
 */
#include "bs_pgs.h"
#include "bs_port.h"

#define ROWS BS_ROWS
#define MAX_ROWS (BS_ROWS * BS_MAX_CONTACTS)
#define SUBSPACE_TRIES 4 /* mode sets tried per subspace step */

enum { MODE_TAKEOFF, MODE_STICK, MODE_SLIP_POS, MODE_SLIP_NEG }; /* slip +: xi_T > 0, P_T = -mu P_N */

/* xi of contact a's rows with the current P: both rows in one pass over P, a
 * contact's pair of columns at a time; each sum still adds in the order of j. */
static void velocity(const bs_contact_set *set, int a, bs_real *xi)
{
    const bs_real *p = set->percussion;
    const bs_real *const end = p + ROWS * set->count;
    const bs_real *g_n = set->delassus[ROWS * a];
    bs_real v_n = set->free_velocity[ROWS * a];
#if BS_WITH_FRICTION
    const bs_real *g_t = set->delassus[ROWS * a + 1];
    bs_real v_t = set->free_velocity[ROWS * a + 1];
    for (; p < end; p += 2, g_n += 2, g_t += 2) {
        v_n += g_n[0] * p[0];
        v_t += g_t[0] * p[0];
        v_n += g_n[1] * p[1];
        v_t += g_t[1] * p[1];
    }
    xi[1] = v_t;
#else
    for (; p < end; ++p, ++g_n)
        v_n += g_n[0] * p[0];
#endif
    xi[0] = v_n;
}

/* prox of the contact laws with step r: P_N first, then P_T in the new cone. */
static void prox(const bs_contact_set *set, int a, bs_real step, const bs_real *xi, const bs_real *p,
                 bs_real *out)
{
    const bs_real p_n = p[0] - step * xi[0];
    out[0] = p_n > BS_R(0.0) ? p_n : BS_R(0.0);
#if BS_WITH_FRICTION
    {
        const bs_real limit = set->mu[a] * out[0];
        const bs_real p_t = p[1] - step * xi[1];
        out[1] = p_t < -limit ? -limit : (p_t > limit ? limit : p_t);
    }
#else
    (void)set;
    (void)a;
#endif
}

/* Exact solution of contact a's problem with the other contacts frozen. */
static void solve_contact(bs_contact_set *set, const bs_real *step, int a)
{
    bs_real *p = &set->percussion[ROWS * a];
    const bs_real g_nn = set->delassus[ROWS * a][ROWS * a];
    bs_real xi[ROWS];
    bs_real v_n;

    velocity(set, a, xi);
#if BS_WITH_FRICTION
    {
        const bs_real mu = set->mu[a];
        const bs_real g_nt = set->delassus[2 * a][2 * a + 1];
        const bs_real g_tt = set->delassus[2 * a + 1][2 * a + 1];
        const bs_real v_t = xi[1] - g_nt * p[0] - g_tt * p[1];
        bs_real det, sign;
        int attempt;

        v_n = xi[0] - g_nn * p[0] - g_nt * p[1];
        if (v_n >= BS_R(0.0)) { /* take-off */
            p[0] = BS_R(0.0);
            p[1] = BS_R(0.0);
            return;
        }
        if (mu == BS_R(0.0)) { /* frictionless contact (a stop): normal only */
            p[0] = -v_n / g_nn;
            p[1] = BS_R(0.0);
            return;
        }
        det = g_nn * g_tt - g_nt * g_nt;
        if (det > BS_R(0.0)) {
            const bs_real inverse = BS_R(1.0) / det;
            const bs_real p_n = (g_nt * v_t - g_tt * v_n) * inverse;
            const bs_real p_t = (g_nt * v_n - g_nn * v_t) * inverse;
            if (p_n >= BS_R(0.0) && p_t <= mu * p_n && p_t >= -mu * p_n) { /* stick */
                p[0] = p_n;
                p[1] = p_t;
                return;
            }
        }
        /* slip: try first the direction the tangential velocity takes without
         * friction, xi_T = g_nt (-v_n / g_nn) + v_t (times g_nn > 0: no division) */
        sign = (g_nn * v_t - g_nt * v_n) >= BS_R(0.0) ? BS_R(1.0) : BS_R(-1.0);
        for (attempt = 0; attempt < 2; ++attempt, sign = -sign) {
            const bs_real denominator = g_nn - sign * mu * g_nt;
            if (denominator > BS_R(0.0)) {
                const bs_real p_n = -v_n / denominator;
                const bs_real xi_t = (g_nt - sign * mu * g_tt) * p_n + v_t;
                if (sign * xi_t >= BS_R(0.0)) {
                    p[0] = p_n;
                    p[1] = -sign * mu * p_n;
                    return;
                }
            }
        }
        prox(set, a, step[a], xi, p, p); /* fall-back, see the header comment */
    }
#else
    (void)step;
    v_n = xi[0] - g_nn * p[0];
    p[0] = v_n >= BS_R(0.0) ? BS_R(0.0) : -v_n / g_nn;
#endif
}

/* Natural-map residual of the current P; xi receives xi = G P + c of every
 * row on the way. */
static bs_real residual_of(const bs_contact_set *set, const bs_real *step, bs_real *xi)
{
    bs_real sum = BS_R(0.0);
    int a, r;

    for (a = 0; a < set->count; ++a) {
        const bs_real *p = &set->percussion[ROWS * a];
        bs_real projected[ROWS];
        velocity(set, a, &xi[ROWS * a]);
        prox(set, a, step[a], &xi[ROWS * a], p, projected);
        for (r = 0; r < ROWS; ++r)
            sum += bs_fabs(p[r] - projected[r]);
    }
    return sum;
}

static bs_real residual(const bs_contact_set *set, const bs_real *step)
{
    bs_real xi[MAX_ROWS];
    return residual_of(set, step, xi);
}

/* r_i = 1 / max(diag G_ii), once per solve. */
static void step_sizes(const bs_contact_set *set, bs_real *step)
{
    int a;
    for (a = 0; a < set->count; ++a) {
        bs_real largest = set->delassus[ROWS * a][ROWS * a];
#if BS_WITH_FRICTION
        if (set->delassus[2 * a + 1][2 * a + 1] > largest)
            largest = set->delassus[2 * a + 1][2 * a + 1];
#endif
        step[a] = BS_R(1.0) / largest;
    }
}

/* sum_i r_i |c_i|_1: the percussion that would stop each contact's free
 * motion on its own. */
static bs_real percussion_scale(const bs_contact_set *set, const bs_real *step)
{
    bs_real scale = BS_R(0.0);
    int a, r;
    for (a = 0; a < set->count; ++a)
        for (r = 0; r < ROWS; ++r)
            scale += step[a] * bs_fabs(set->free_velocity[ROWS * a + r]);
    return scale;
}

bs_real bs_pgs_residual(const bs_contact_set *set)
{
    bs_real step[BS_MAX_CONTACTS];
    step_sizes(set, step);
    return residual(set, step);
}

bs_real bs_pgs_scale(const bs_contact_set *set)
{
    bs_real step[BS_MAX_CONTACTS];
    step_sizes(set, step);
    return percussion_scale(set, step);
}

#if BS_WITH_SUBSPACE
/* Mode contact a shows at percussion p. */
static int mode_of(const bs_contact_set *set, int a)
{
    const bs_real *p = &set->percussion[ROWS * a];
    if (!(p[0] > BS_R(0.0)))
        return MODE_TAKEOFF;
#if BS_WITH_FRICTION
    {
        const bs_real limit = set->mu[a] * p[0];
        if (!(p[1] < limit && p[1] > -limit))
            return p[1] > BS_R(0.0) ? MODE_SLIP_NEG : MODE_SLIP_POS;
    }
#endif
    return MODE_STICK;
}

/* Solves the linear system the modes define into trial, by Gaussian
 * elimination to row echelon form with partial pivoting. A column whose best
 * pivot is below 16 eps of the column's size is taken as dependent on the
 * others (redundant contacts: two corners of one face sticking, a preloaded
 * slot) and its unknown set to 0: the basic solution, instead of one whose
 * huge components cancel in W P and poison the next warm start. Whether the
 * result obeys the contact laws is for the residual to say. */
static void subspace_solve(bs_contact_set *set, const int *mode, bs_real *trial)
{
    const int rows = ROWS * set->count;
    bs_real (*m)[MAX_ROWS + 1] = set->system; /* [A | b]: scratch in the struct, not on the stack */
    bs_real inverse[MAX_ROWS];         /* 1 / pivot of each echelon row */
    int pivot_column[MAX_ROWS];
    int i, j, col, rank = 0;

    for (i = 0; i < ROWS * set->count; ++i) { /* rows of a law on P alone */
        const int a = i / ROWS;
        if (mode[a] == MODE_TAKEOFF || (i % ROWS && mode[a] != MODE_STICK)) {
            for (j = 0; j <= rows; ++j)
                m[i][j] = BS_R(0.0);
            m[i][i] = BS_R(1.0);
#if BS_WITH_FRICTION
            if (i % ROWS && mode[a] != MODE_TAKEOFF) /* slip: P_T + s mu P_N = 0 */
                m[i][i - 1] = mode[a] == MODE_SLIP_POS ? set->mu[a] : -set->mu[a];
#endif
        } else { /* xi = 0 */
            for (j = 0; j < rows; ++j)
                m[i][j] = set->delassus[i][j];
            m[i][rows] = -set->free_velocity[i];
        }
    }
    for (col = 0; col < rows && rank < rows; ++col) {
        bs_real size = BS_R(0.0);
        int pivot = rank;
        for (i = 0; i < rows; ++i)
            size += bs_fabs(m[i][col]);
        for (i = rank + 1; i < rows; ++i)
            if (bs_fabs(m[i][col]) > bs_fabs(m[pivot][col]))
                pivot = i;
        if (!(bs_fabs(m[pivot][col]) > BS_R(16.0) * BS_REAL_EPS * size))
            continue; /* dependent column: its unknown stays 0 */
        if (pivot != rank)
            for (j = col; j <= rows; ++j) {
                const bs_real swap = m[rank][j];
                m[rank][j] = m[pivot][j];
                m[pivot][j] = swap;
            }
        inverse[rank] = BS_R(1.0) / m[rank][col]; /* one division per pivot */
        for (i = rank + 1; i < rows; ++i) {
            const bs_real factor = m[i][col] * inverse[rank];
            for (j = col; j <= rows; ++j)
                m[i][j] -= factor * m[rank][j];
        }
        pivot_column[rank++] = col;
    }
    for (j = 0; j < rows; ++j)
        trial[j] = BS_R(0.0);
    for (i = rank - 1; i >= 0; --i) {
        const int c = pivot_column[i];
        bs_real value = m[i][rows];
        for (j = c + 1; j < rows; ++j)
            value -= m[i][j] * trial[j];
        trial[c] = value * inverse[i];
    }
}

/* The mode contact a's trial solution points to (its own mode if it obeys
 * its law). A stick breach is checked first: a nearly singular stick pair
 * gives wild P_T and P_N of either sign, and only the slip row tames P_T. */
static int corrected_mode(const bs_contact_set *set, int a, int mode, const bs_real *xi)
{
    const bs_real *p = &set->percussion[ROWS * a];

    if (mode == MODE_TAKEOFF)
        return xi[0] < BS_R(0.0) ? MODE_STICK : MODE_TAKEOFF;
#if BS_WITH_FRICTION
    {
        const bs_real limit = set->mu[a] * p[0];
        if (mode == MODE_STICK && (p[1] > limit || p[1] < -limit))
            return p[1] > BS_R(0.0) ? MODE_SLIP_NEG : MODE_SLIP_POS;
    }
#endif
    if (p[0] < BS_R(0.0))
        return MODE_TAKEOFF;
#if BS_WITH_FRICTION
    if (mode == MODE_SLIP_POS ? xi[1] < BS_R(0.0) : (mode == MODE_SLIP_NEG && xi[1] > BS_R(0.0)))
        return MODE_STICK;
#endif
    return mode;
}

/* Moves the first contact whose trial solution breaks its law (Murty's
 * least-index rule). Returns 1 if a contact moved, 0 if all laws hold. */
static int correct_modes(const bs_contact_set *set, int *mode, const bs_real *xi)
{
    int a;
    for (a = 0; a < set->count; ++a) {
        const int next = corrected_mode(set, a, mode[a], &xi[ROWS * a]);
        if (next != mode[a]) {
            mode[a] = next;
            return 1;
        }
    }
    return 0;
}

/* Subspace step (see the header comment); keeps the best P seen. */
static void try_subspace(bs_contact_set *set, const bs_real *step, bs_real *best_residual)
{
    const int rows = ROWS * set->count;
    bs_real best[MAX_ROWS];
    bs_real trial[MAX_ROWS];
    bs_real xi[MAX_ROWS];
    int tried[SUBSPACE_TRIES][BS_MAX_CONTACTS];
    int mode[BS_MAX_CONTACTS];
    int count, j;

    for (j = 0; j < rows; ++j)
        best[j] = set->percussion[j];
    for (j = 0; j < set->count; ++j)
        mode[j] = mode_of(set, j);
    for (count = 0; count < SUBSPACE_TRIES; ++count) {
        bs_real trial_residual;
        int seen, earlier;
        for (seen = 0, earlier = 0; earlier < count && !seen; ++earlier)
            for (seen = 1, j = 0; j < set->count; ++j)
                seen &= tried[earlier][j] == mode[j];
        if (seen)
            break;
        subspace_solve(set, mode, trial);
        for (j = 0; j < set->count; ++j)
            tried[count][j] = mode[j];
        for (j = 0; j < rows; ++j)
            set->percussion[j] = trial[j];
        trial_residual = residual_of(set, step, xi);
        if (trial_residual < *best_residual) {
            *best_residual = trial_residual;
            for (j = 0; j < rows; ++j)
                best[j] = trial[j];
        }
        if (correct_modes(set, mode, xi) == 0)
            break;
    }
    for (j = 0; j < rows; ++j)
        set->percussion[j] = best[j];
}

#endif /* BS_WITH_SUBSPACE */

void bs_pgs_solve(bs_contact_set *set, const bs_solver_options *options, bs_step_report *report)
{
    bs_real step[BS_MAX_CONTACTS];
    bs_real tolerance;
    bs_real previous = BS_R(0.0);
    int a;

    step_sizes(set, step); /* the prox fall-back of solve_contact needs them too */
    report->sweeps = 0;
    if (!options->measure_residual) { /* a fixed number of plain sweeps, nothing measured */
        for (; report->sweeps < options->max_sweeps; ++report->sweeps)
            for (a = 0; a < set->count; ++a)
                solve_contact(set, step, a);
        report->residual = BS_R(-1.0);
        report->converged = -1;
        return;
    }
    tolerance = options->tol_rel * percussion_scale(set, step) + options->tol_abs;
    for (;;) { /* at least one sweep: the warm start is not trusted unchecked */
        for (a = 0; a < set->count; ++a)
            solve_contact(set, step, a);
        ++report->sweeps;
        report->residual = residual(set, step);
#if BS_WITH_SUBSPACE
        if (report->residual > tolerance && set->count > 1)
            try_subspace(set, step, &report->residual);
#endif
        report->converged = report->residual <= tolerance;
        /* stop at the cap, or when a round made no progress: then the
         * residual sits at what the precision can resolve for this G */
        if (report->converged || report->sweeps >= options->max_sweeps
            || (report->sweeps > 1 && !(report->residual < previous)))
            return;
        previous = report->residual;
    }
}
