/* bs_pgs.c - the per-step contact problem, solved exactly where it is small
 * and with a bounded number of active-set systems and sweeps where it is not.
 *
 * Unknowns: percussions P = (P_N,1, P_T,1, ..., P_N,n, P_T,n) [N s] (P_N only
 * when the build has no friction). Velocities after the step (Newton-modified):
 * xi = G P + c, G = W^T M^-1 W. Contact laws for each contact i (docs/model.md 4):
 *   0 <= P_N  _|_  xi_N >= 0,   |P_T| <= mu P_N,   P_T = -mu P_N sign(xi_T) if xi_T != 0.
 * Each contact is in one of four modes, and the modes turn the laws into
 * linear equations, rows per contact:
 *   take-off   P_N = 0, P_T = 0                    (valid if xi_N >= 0)
 *   stick      xi_N = 0, xi_T = 0                  (valid if P_N >= 0, |P_T| <= mu P_N)
 *   slip s     xi_N = 0, P_T + s mu P_N = 0        (valid if P_N >= 0, s xi_T >= 0)
 *
 * One contact (most contact steps): the 2x2 problem solved exactly,
 * solve_contact below: with v = c_i + sum_{j != i} G_ij P_j and the block
 * G_ii = [a b; b d] the candidates are
 *   take-off   P = 0                                 if v_N >= 0
 *   stick      G_ii P = -v                           if P_N >= 0, |P_T| <= mu P_N
 *   slip s=+-1 P_T = -s mu P_N, P_N = -v_N / (a - s mu b)
 *                                                    if s ((b - s mu d) P_N + v_T) >= 0
 * which is the fixed point of the prox update the published model iterates,
 *   P_i <- prox(P_i - r_i (G_i: P + c_i)),  r_i = 1 / max(a, d),
 * reached in one visit instead of many. The prox update stays as a fall-back
 * for a block where no candidate is consistent (only possible when mu |b| is
 * comparable with a). The same solve is a Gauss-Seidel sweep's visit of
 * contact i when there are more.
 *
 * Two contacts (the rest of the contact steps of the scenes): exact too. Two
 * corners on the same face of the slot see almost the same beam motion, so
 * their rows of G are nearly parallel and Gauss-Seidel crawls (hundreds of
 * sweeps, docs/model.md 9.5). solve_pair runs the active-set method from
 * the last step's modes (the warm start's; a contact new to the set:
 * sticking if it approaches, else lifting off), which in a lasting contact
 * are the solution's (on fig6 in 71 % of the two-contact steps): the modes
 * define a linear system in the unknowns they leave unset, solved by
 * Cramer's rule with one reciprocal (pair_system: up to three unknowns,
 * every mode pair but stick-stick; that one by Gaussian elimination with
 * partial pivoting written out for its four unknowns, stick_pair_solve,
 * and a system near singular by the general elimination, active_set_solve,
 * where redundant rows get the basic solution). A solution whose laws hold by
 * sign (P_N >= 0 and inside the cone while sticking, xi_T along the slip
 * while slipping, xi_N >= 0 while lifting off) is the solution; the
 * residual is computed only where the signs do not settle it. Else
 * next_modes picks the modes of the next trial (below) and the system is
 * solved again; a mode pair that repeats is replaced by the first one not
 * yet tried. So at most MODES^2 = 16 systems of at most 4 unknowns: a hard
 * bound, and with the right modes the exact solution (Box2D's block solver
 * does the same enumeration for the two normal rows of a face; here the
 * tangential rows are in the block too).
 *
 * Next modes: a breach on the percussion's side (P_N < 0, P_T outside the
 * cone) is the surest sign of a wrong mode, so every contact with one moves;
 * failing those, only the contact with the largest velocity breach (xi_N < 0
 * lifting off, xi_T against its slip) moves, since velocities depend on every
 * contact's P and two corners of one face often breach together when only
 * one is wrong. A moving contact takes the mode of its own exact solution
 * with the others held at the trial's P (the mode its breach points to if
 * that is its present one). On fig6 this needs 1.25 systems per two-contact
 * step on average and at most 8 (docs/design.md 6).
 *
 * Three or more contacts (a preloaded slot, all four corners and a stop):
 * the same active-set method over all contacts, started from the warm
 * start's modes (a contact new to the set: sticking if it approaches, else
 * lifting off); in a lasting contact the first system is the right one. If
 * none meets the laws, Gauss-Seidel sweeps, each followed by the active-set
 * method from the modes the sweep reached, until converged, the cap
 * max_sweeps, or a sweep that does not lower the residual; SYSTEMS_MAX
 * systems of at most 2n unknowns per step in all, a hard bound on the work.
 * (Projected Gauss-Seidel with subspace minimisation: Silcowitz, Niebe,
 * Erleben 2010.) A build with BS_WITH_SUBSPACE 0 leaves the active-set step
 * out here: at most max_sweeps plain sweeps, and redundant contacts end the
 * step unconverged (reported).
 *
 * Warm start: P comes in holding each contact's percussion of the last step.
 * Residual: the natural-map residual of P,
 *   e = sum_i | P_i - prox(P_i - r_i xi_i) |_1,
 * (1-norms: no square roots; the reference's criterion leaves the norm open);
 * a solve has converged when e <= tol_rel s + tol_abs, with the percussion
 * scale s = sum_i r_i |c_i|_1 that would stop each contact's free motion on its
 * own. The reference measures against |P| instead; but redundant contacts (two
 * corners on one face, a preloaded slot) admit internal squeeze that cancels
 * in W P, warm starts let it drift from step to step, and a tolerance relative
 * to |P| then loosens with it until the step diverges. s comes from the data
 * and cannot be inflated that way. The residual returned is the one of the P
 * returned, whether converged or not (docs/model.md 9.5: report it, never hide
 * it). With measure_residual off it is computed only where a solve needs it:
 * a single contact's exact solve then reports -1 and whether it was exact.
 */
#include "bs_pgs.h"
#include "bs_inline.h"
#include "bs_port.h"

#define ROWS BS_ROWS
#define MAX_ROWS (BS_ROWS * BS_MAX_CONTACTS)
#define SYSTEMS_MAX 4 /* systems per step for three or more contacts */

enum { MODE_TAKEOFF, MODE_STICK, MODE_SLIP_POS, MODE_SLIP_NEG }; /* slip +: xi_T > 0, P_T = -mu P_N */

/* When a solve is done: a residual within tolerance (tol_rel s + tol_abs);
 * for a trial of the active-set method also the laws holding by sign, unless
 * its residual is at the floor of rounding (exact, 64 eps s), where the
 * signs of values at a law's boundary are themselves rounding. */
typedef struct bs_goal {
    bs_real tolerance;
    bs_real exact;
} bs_goal;
#define MODES (BS_WITH_FRICTION ? 4 : 2) /* modes a contact can take */

/* sum + term for a sum of absolute values, or term alone for its first:
 * 0 + |x| is |x| bit for bit, and the 0 would be a literal that a
 * controller loads from flash. */
#define SUM_OF_ABS(first, sum, term) ((first) ? (term) : (sum) + (term))

/* xi of contact a's rows with the current P: both rows in one pass over P, a
 * contact's pair of columns at a time; each sum still adds in the order of j. */
BS_INLINE void velocity(const bs_contact_set *set, int a, bs_real *xi)
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

/* prox of the contact laws with step r: P_N first, then P_T in the new cone
 * (a P_N of +0 from a core register, BS_ZERO, not a literal from flash). */
BS_INLINE void prox(const bs_contact_set *set, int a, bs_real step, const bs_real *xi, const bs_real *p,
                 bs_real *out)
{
    const bs_real p_n = p[0] - step * xi[0];
    out[0] = p_n > BS_R(0.0) ? p_n : BS_ZERO;
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

/* Contact a's exact solution (the candidates of the header comment) against
 * v, the velocity of its rows without its own percussion, into its P.
 * Returns 1, or 0 when no candidate held: P is then unchanged, and the
 * caller falls back to the prox update (fall_back). */
BS_INLINE int solve_local(bs_contact_set *set, int a, const bs_real *v)
{
    bs_real *p = &set->percussion[ROWS * a];
    const bs_real g_nn = set->delassus[ROWS * a][ROWS * a];
    const bs_real v_n = v[0];
#if BS_WITH_FRICTION
    const bs_real mu = set->mu[a];
    const bs_real g_nt = set->delassus[2 * a][2 * a + 1];
    const bs_real g_tt = set->delassus[2 * a + 1][2 * a + 1];
    const bs_real v_t = v[1];
    bs_real det, sign;
    int attempt;

    if (v_n >= BS_R(0.0)) { /* take-off */
        p[0] = BS_R(0.0);
        p[1] = BS_R(0.0);
        return 1;
    }
    if (mu == BS_R(0.0)) { /* frictionless contact (a stop): normal only */
        p[0] = -v_n / g_nn;
        p[1] = BS_R(0.0);
        return 1;
    }
    det = g_nn * g_tt - g_nt * g_nt;
    if (det > BS_R(0.0)) {
        const bs_real inverse = BS_R(1.0) / det;
        const bs_real p_n = (g_nt * v_t - g_tt * v_n) * inverse;
        const bs_real p_t = (g_nt * v_n - g_nn * v_t) * inverse;
        if (p_n >= BS_R(0.0) && p_t <= mu * p_n && p_t >= -mu * p_n) { /* stick */
            p[0] = p_n;
            p[1] = p_t;
            return 1;
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
                return 1;
            }
        }
    }
    return 0;
#else
    p[0] = v_n >= BS_R(0.0) ? BS_R(0.0) : -v_n / g_nn;
    return 1;
#endif
}

/* The prox update of contact a from xi, its velocity at the present P: the
 * fall-back where solve_local found no candidate (header comment). Returns 0. */
BS_INLINE int fall_back(bs_contact_set *set, const bs_real *step, int a, const bs_real *xi)
{
    bs_real *p = &set->percussion[ROWS * a];
    prox(set, a, step[a], xi, p, p);
    return 0;
}

/* Exact solution of contact a's problem with the other contacts frozen
 * (solve_local against v = xi - G_aa P_a), xi its velocity at the present
 * P. Returns 1, or 0 when it fell back to the prox update (no candidate
 * held). */
BS_INLINE int solve_contact_at(bs_contact_set *set, const bs_real *step, int a, const bs_real *xi)
{
    const bs_real *p = &set->percussion[ROWS * a];
    const bs_real *g_n = set->delassus[ROWS * a];
    bs_real v[ROWS];

    v[0] = xi[0] - g_n[ROWS * a] * p[0];
#if BS_WITH_FRICTION
    v[0] -= g_n[2 * a + 1] * p[1];
    v[1] = xi[1] - set->delassus[2 * a + 1][2 * a] * p[0] - set->delassus[2 * a + 1][2 * a + 1] * p[1];
#endif
    return solve_local(set, a, v) || fall_back(set, step, a, xi);
}

/* The same with xi not known: a Gauss-Seidel sweep's visit. */
static int solve_contact(bs_contact_set *set, const bs_real *step, int a)
{
    bs_real xi[ROWS];
    velocity(set, a, xi);
    return solve_contact_at(set, step, a, xi);
}

/* The residual at P = set->percussion from its velocities xi, known, of a
 * set of count contacts (a constant where it is inlined: the loops
 * unrolled, and a step[] of that length visibly filled). */
BS_INLINE bs_real residual_at(const bs_contact_set *set, int count, const bs_real *step, const bs_real *xi)
{
    bs_real sum = BS_R(0.0); /* 0 + |x| is |x|: the sum starts at its first term (SUM_OF_ABS) */
    int a, r;
    for (a = 0; a < count; ++a) {
        const bs_real *p = &set->percussion[ROWS * a];
        bs_real projected[ROWS];
        prox(set, a, step[a], &xi[ROWS * a], p, projected);
        for (r = 0; r < ROWS; ++r)
            sum = SUM_OF_ABS(a == 0 && r == 0, sum, bs_fabs(p[r] - projected[r]));
    }
    return sum;
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
BS_INLINE void step_sizes(const bs_contact_set *set, int count, bs_real *step)
{
    int a;
    for (a = 0; a < count; ++a) {
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
BS_INLINE bs_real percussion_scale(const bs_contact_set *set, int count, const bs_real *step)
{
    bs_real scale = BS_R(0.0);
    int a, r;
    for (a = 0; a < count; ++a)
        for (r = 0; r < ROWS; ++r) /* step > 0 (G_ii holds m^-1 |n|^2): no term is -0 */
            scale = SUM_OF_ABS(a == 0 && r == 0, scale, step[a] * bs_fabs(set->free_velocity[ROWS * a + r]));
    return scale;
}

bs_real bs_pgs_residual(const bs_contact_set *set)
{
    bs_real step[BS_MAX_CONTACTS];
    step_sizes(set, set->count, step);
    return residual(set, step);
}

/* Mode contact a shows at percussion p. */
BS_INLINE int mode_of(const bs_contact_set *set, int a)
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

/* Solves the linear system the modes define into trial, condensed to the
 * unknowns the modes leave free: a sticking contact has P_N and P_T (equations
 * xi_N = 0, xi_T = 0), a slipping one P_N alone (P_T = -s mu P_N folded into
 * its column: G_:N - s mu G_:T; equation xi_N = 0), one lifting off none
 * (P = 0). So k <= ROWS n unknowns; [A | b] is built in m (k rows) and
 * brought to row echelon form by Gaussian elimination with partial pivoting.
 * A column whose best pivot is below 16 eps of the column's size is taken as
 * dependent on the others (redundant contacts: two corners of one face
 * sticking, a preloaded slot) and its unknown set to 0: the basic solution,
 * instead of one whose huge components cancel in W P and poison the next
 * warm start. Whether the result obeys the contact laws is for the residual
 * to say. */
static void active_set_solve(const bs_contact_set *set, const int *mode, bs_real (*m)[MAX_ROWS + 1],
                             bs_real *trial)
{
    int row[MAX_ROWS];          /* row (and column) of G of each unknown */
#if BS_WITH_FRICTION
    bs_real fold[MAX_ROWS];     /* P_T / P_N of a slipping contact's unknown, else 0 */
#endif
    bs_real inverse[MAX_ROWS];  /* 1 / pivot of each echelon row */
    bs_real unknown[MAX_ROWS];
    int pivot_column[MAX_ROWS];
    int a, i, j, col, k = 0, rank = 0;

    for (a = 0; a < set->count; ++a) {
        if (mode[a] == MODE_TAKEOFF)
            continue;
        row[k++] = ROWS * a;
#if BS_WITH_FRICTION
        fold[k - 1] = BS_R(0.0);
        if (mode[a] == MODE_STICK) {
            row[k] = ROWS * a + 1;
            fold[k++] = BS_R(0.0);
        } else {
            fold[k - 1] = mode[a] == MODE_SLIP_POS ? -set->mu[a] : set->mu[a];
        }
#endif
    }
    for (i = 0; i < k; ++i) {
        const bs_real *g = set->delassus[row[i]];
        for (j = 0; j < k; ++j) {
            m[i][j] = g[row[j]];
#if BS_WITH_FRICTION
            if (fold[j] != BS_R(0.0))
                m[i][j] += fold[j] * g[row[j] + 1];
#endif
        }
        m[i][k] = -set->free_velocity[row[i]];
    }
    for (col = 0; col < k && rank < k; ++col) {
        bs_real size = BS_R(0.0);
        int pivot = rank;
        for (i = 0; i < k; ++i)
            size += bs_fabs(m[i][col]);
        for (i = rank + 1; i < k; ++i)
            if (bs_fabs(m[i][col]) > bs_fabs(m[pivot][col]))
                pivot = i;
        if (!(bs_fabs(m[pivot][col]) > BS_ROUNDING(16) * size))
            continue; /* dependent column: its unknown stays 0 */
        if (pivot != rank)
            for (j = col; j <= k; ++j) {
                const bs_real swap = m[rank][j];
                m[rank][j] = m[pivot][j];
                m[pivot][j] = swap;
            }
        inverse[rank] = BS_R(1.0) / m[rank][col]; /* one division per pivot */
        for (i = rank + 1; i < k; ++i) {
            const bs_real factor = m[i][col] * inverse[rank];
            for (j = col; j <= k; ++j)
                m[i][j] -= factor * m[rank][j];
        }
        pivot_column[rank++] = col;
    }
    for (j = 0; j < k; ++j)
        unknown[j] = BS_R(0.0);
    for (i = rank - 1; i >= 0; --i) {
        const int c = pivot_column[i];
        bs_real value = m[i][k];
        for (j = c + 1; j < k; ++j)
            value -= m[i][j] * unknown[j];
        unknown[c] = value * inverse[i];
    }
    for (j = 0; j < ROWS * set->count; ++j)
        trial[j] = BS_R(0.0);
    for (j = 0; j < k; ++j) {
        trial[row[j]] = unknown[j];
#if BS_WITH_FRICTION
        if (fold[j] != BS_R(0.0))
            trial[row[j] + 1] = fold[j] * unknown[j];
#endif
    }
}

#if BS_WITH_FRICTION
/* active_set_solve for two sticking contacts (four unknowns: both P), its
 * sizes constants: the same operations in the same order, bit for bit,
 * while no column is dependent; every index a constant once the loops are
 * unrolled (a row exchange too: tested against each row below), so that the
 * matrix lives in registers. The pivot column below the pivot, which
 * active_set_solve updates to about 0 and never reads again, is left.
 * Returns 0 at a dependent column (trial untouched), for active_set_solve.
 * Measured on mid-fig6-float: a stick-stick system 1242 -> 353 instructions
 * (1934 -> 579 estimated cycles), the worst step of the window 7826 ->
 * 6465 cycles, the mean 2403.1 -> 2364.8; with the rows exchanged by
 * pointers instead, the matrix on the stack, 605 instructions and 2389.7. */
BS_INLINE int stick_pair_solve(const bs_contact_set *set, bs_real *trial)
{
    bs_real m[4][5], inverse[4], unknown[4];
    int i, j, col;

    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j)
            m[i][j] = set->delassus[i][j];
        m[i][4] = -set->free_velocity[i];
    }
    for (col = 0; col < 4; ++col) {
        bs_real size = BS_R(0.0), best;
        int pivot = col;
        for (i = 0; i < 4; ++i)
            size += bs_fabs(m[i][col]);
        best = bs_fabs(m[col][col]);
        for (i = col + 1; i < 4; ++i)
            if (bs_fabs(m[i][col]) > best) {
                pivot = i;
                best = bs_fabs(m[i][col]);
            }
        if (!(best > BS_ROUNDING(16) * size))
            return 0;
        for (i = col + 1; i < 4; ++i)
            if (i == pivot)
                for (j = col; j <= 4; ++j) {
                    const bs_real swap = m[col][j];
                    m[col][j] = m[i][j];
                    m[i][j] = swap;
                }
        inverse[col] = BS_R(1.0) / m[col][col];
        for (i = col + 1; i < 4; ++i) {
            const bs_real factor = m[i][col] * inverse[col];
            for (j = col + 1; j <= 4; ++j)
                m[i][j] -= factor * m[col][j];
        }
    }
    for (i = 3; i >= 0; --i) {
        bs_real value = m[i][4];
        for (j = i + 1; j < 4; ++j)
            value -= m[i][j] * unknown[j];
        unknown[i] = value * inverse[i];
    }
    for (i = 0; i < 4; ++i)
        trial[i] = unknown[i];
    return 1;
}
#endif

/* The mode contact a's trial solution points to (its own mode if it obeys
 * its law). A stick breach is checked first: a nearly singular stick pair
 * gives wild P_T and P_N of either sign, and only the slip row tames P_T. */
static int pointed_mode(const bs_contact_set *set, int a, int mode, const bs_real *xi)
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

/* How far contact a's trial breaks its law on the velocity's side (xi_N < 0
 * lifting off, xi_T against a slip), or -1 when the breach is on the
 * percussion's side (P_N < 0, P_T outside the cone). */
static bs_real breach_size(const bs_contact_set *set, int a, int mode, const bs_real *xi)
{
    const bs_real *p = &set->percussion[ROWS * a];
    if (mode == MODE_TAKEOFF)
        return -xi[0];
#if BS_WITH_FRICTION
    if (mode == MODE_STICK)
        return BS_R(-1.0);
    if (!(p[0] < BS_R(0.0)))
        return bs_fabs(xi[1]);
#endif
    (void)p;
    return BS_R(-1.0);
}

/* The mode contact a takes in its own exact solution with the others held
 * at their trial percussions, or, where that is its present mode, the one
 * its breach points to. */
static int next_mode(bs_contact_set *set, const bs_real *step, int a, int mode, const bs_real *xi)
{
    bs_real *p = &set->percussion[ROWS * a];
    bs_real saved[ROWS];
    int r, local;
    for (r = 0; r < ROWS; ++r)
        saved[r] = p[r];
    solve_contact_at(set, step, a, xi);
    local = mode_of(set, a);
    for (r = 0; r < ROWS; ++r)
        p[r] = saved[r];
    return local != mode ? local : pointed_mode(set, a, mode, xi);
}

/* The modes of the next trial from the present trial's P (in set) and xi:
 * a breach on the percussion's side is the surest sign of a wrong mode, so
 * where there is one, every contact with one moves; else the contact with
 * the largest velocity breach alone (velocities depend on every contact's
 * P, and two corners of one face often breach together when only one is
 * wrong). Each moving contact takes the mode of its own exact solution
 * against the others (the pointed one if that is its present mode). Returns
 * the number of contacts whose law broke (0: all laws hold). */
BS_INLINE int next_modes_of(bs_contact_set *set, int count, const bs_real *step, int *mode, const bs_real *xi)
{
    int next[BS_MAX_CONTACTS];
    int a, broken = 0, percussion_side = 0, largest = -1;
    bs_real size = BS_R(0.0);

    for (a = 0; a < count; ++a) {
        next[a] = pointed_mode(set, a, mode[a], &xi[ROWS * a]);
        if (next[a] != mode[a]) {
            const bs_real velocity_side = breach_size(set, a, mode[a], &xi[ROWS * a]);
            ++broken;
            if (velocity_side < BS_R(0.0))
                percussion_side = 1;
            else if (largest < 0 || velocity_side > size) {
                largest = a;
                size = velocity_side;
            }
        }
    }
    for (a = 0; a < count; ++a)
        if (next[a] != mode[a]
            && (percussion_side ? breach_size(set, a, mode[a], &xi[ROWS * a]) < BS_R(0.0) : a == largest))
            next[a] = next_mode(set, step, a, mode[a], &xi[ROWS * a]);
        else
            next[a] = mode[a];
    for (a = 0; a < count; ++a)
        mode[a] = next[a];
    return broken;
}

/* next_modes_of for a pair, the count a constant (its loops unrolled), and
 * for three or more contacts */
static int next_pair_modes(bs_contact_set *set, const bs_real *step, int *mode, const bs_real *xi)
{
    return next_modes_of(set, 2, step, mode, xi);
}

#if BS_WITH_SUBSPACE
static int next_modes(bs_contact_set *set, const bs_real *step, int *mode, const bs_real *xi)
{
    return next_modes_of(set, set->count, step, mode, xi);
}
#endif

/* sum_a |P_N,a| of the warm start, which warm_mode weighs a P_N against. */
BS_INLINE bs_real warm_total(const bs_contact_set *set, int count)
{
    bs_real total = BS_R(0.0);
    int b;
    for (b = 0; b < count; ++b)
        total = SUM_OF_ABS(b == 0, total, bs_fabs(set->percussion[ROWS * b]));
    return total;
}

/* The mode of contact a to start from: the one its warm start shows, or
 * for a contact without a percussion sticking if it approaches (under the
 * others' warm percussions), else lifting off. total: warm_total. */
BS_INLINE int warm_mode(const bs_contact_set *set, int a, bs_real total)
{
    const bs_real *p = &set->percussion[ROWS * a];
    int b;
    /* a P_N within rounding (16 eps) of 0 against the set's total is 0, as
     * the step leaves it after a take-off (again a warm start from elsewhere
     * may not) */
    if (!(p[0] > BS_ROUNDING(16) * total)) {
        /* no percussion: sticking if it approaches under the others' warm
         * percussions, else lifting off */
        const bs_real *g = set->delassus[ROWS * a];
        bs_real v = set->free_velocity[ROWS * a];
        for (b = 0; b < ROWS * set->count; ++b)
            if (b / ROWS != a)
                v += g[b] * set->percussion[b];
        return v < BS_R(0.0) ? MODE_STICK : MODE_TAKEOFF;
    }
#if BS_WITH_FRICTION
    {
        /* on the cone to rounding (16 eps): slipping. A slip leaves P_T at
         * -s mu P_N exactly, but a warm start from elsewhere (a solver's
         * answer, a checkpoint's) may sit an ulp inside it */
        const bs_real limit = set->mu[a] * p[0] * (BS_R(1.0) - BS_ROUNDING(16));
        if (!(p[1] < limit && p[1] > -limit))
            return p[1] > BS_R(0.0) ? MODE_SLIP_NEG : MODE_SLIP_POS;
    }
#endif
    return MODE_STICK;
}

/* x = A^-1 b for 2 x 2 A by Cramer's rule (one reciprocal); 0 when A is
 * near singular: |det A| not above 16 eps of the square of its size
 * (redundant contacts, left to active_set_solve's basic solution). */
BS_INLINE int cramer2(bs_real a00, bs_real a01, bs_real a10, bs_real a11, bs_real b0, bs_real b1, bs_real *x)
{
    const bs_real det = a00 * a11 - a01 * a10;
    const bs_real size = bs_fabs(a00) + bs_fabs(a01) + bs_fabs(a10) + bs_fabs(a11);
    bs_real inverse;
    if (!(bs_fabs(det) > BS_ROUNDING(16) * size * size))
        return 0;
    inverse = BS_R(1.0) / det;
    x[0] = (b0 * a11 - a01 * b1) * inverse;
    x[1] = (a00 * b1 - a10 * b0) * inverse;
    return 1;
}

#if BS_WITH_FRICTION
/* The same for 3 x 3 A (rows a[i]) by cofactors. */
BS_INLINE int cramer3(const bs_real (*a)[3], const bs_real *b, bs_real *x)
{
    const bs_real c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1], c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    const bs_real c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    const bs_real det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    bs_real size = BS_R(0.0), inverse;
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j)
            size += bs_fabs(a[i][j]);
    if (!(bs_fabs(det) > BS_ROUNDING(16) * size * size * size))
        return 0;
    inverse = BS_R(1.0) / det;
    x[0] = (c00 * b[0] + (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * b[1] + (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * b[2])
           * inverse;
    x[1] = (c01 * b[0] + (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * b[1] + (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * b[2])
           * inverse;
    x[2] = (c02 * b[0] + (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * b[1] + (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * b[2])
           * inverse;
    return 1;
}

/* P_T / P_N of a slipping contact (slip +: xi_T > 0, P_T = -mu P_N). */
BS_INLINE bs_real fold_of(const bs_contact_set *set, int a, int mode)
{
    return mode == MODE_SLIP_POS ? -set->mu[a] : set->mu[a];
}
#endif

/* The system two contacts' modes define (header comment), solved in closed
 * form into trial: rows and columns 0..3 are P_N,0, P_T,0, P_N,1, P_T,1 (with
 * friction); a slipping contact's P_T is its fold times P_N, folded into the
 * P_N column; a contact lifting off has P = 0. Every pair of modes but
 * stick-stick has at most three unknowns, written out here with constant
 * indices. Returns 1, or 0 for stick-stick and near-singular systems, which
 * stick_pair_solve and active_set_solve take instead. */
BS_INLINE int pair_system(const bs_contact_set *set, const int *mode, bs_real *trial)
{
    const bs_real (*g)[MAX_ROWS] = (const bs_real(*)[MAX_ROWS])set->delassus;
    const bs_real *c = set->free_velocity;
    bs_real x[3];
    int j;
#if BS_WITH_FRICTION
    const int kind0 = mode[0] == MODE_TAKEOFF ? 0 : (mode[0] == MODE_STICK ? 2 : 1);
    const int kind1 = mode[1] == MODE_TAKEOFF ? 0 : (mode[1] == MODE_STICK ? 2 : 1);
    const bs_real f0 = kind0 == 1 ? fold_of(set, 0, mode[0]) : BS_R(0.0);
    const bs_real f1 = kind1 == 1 ? fold_of(set, 1, mode[1]) : BS_R(0.0);
    /* each case writes all four: a contact lifting off its zeros */
    switch (3 * kind0 + kind1) {
    case 0: /* both lift off */
        for (j = 0; j < 4; ++j)
            trial[j] = BS_R(0.0);
        return 1;
    case 1: /* 0 lifts off, 1 slips */
    case 3: { /* 0 slips, 1 lifts off */
        const int n = kind0 ? 0 : 2;
        const bs_real f = kind0 ? f0 : f1;
        const bs_real a = g[n][n] + f * g[n][n + 1];
        if (!(bs_fabs(a) > BS_ROUNDING(16) * (bs_fabs(g[n][n]) + bs_fabs(f * g[n][n + 1]))))
            return 0;
        trial[n] = -c[n] / a;
        trial[n + 1] = f * trial[n];
        trial[2 - n] = trial[3 - n] = BS_R(0.0);
        return 1;
    }
    case 2: /* 0 lifts off, 1 sticks */
    case 6: { /* 0 sticks, 1 lifts off */
        const int n = kind0 ? 0 : 2;
        if (!cramer2(g[n][n], g[n][n + 1], g[n + 1][n], g[n + 1][n + 1], -c[n], -c[n + 1], x))
            return 0;
        trial[n] = x[0];
        trial[n + 1] = x[1];
        trial[2 - n] = trial[3 - n] = BS_R(0.0);
        return 1;
    }
    case 4: /* both slip */
        if (!cramer2(g[0][0] + f0 * g[0][1], g[0][2] + f1 * g[0][3], g[2][0] + f0 * g[2][1], g[2][2] + f1 * g[2][3],
                     -c[0], -c[2], x))
            return 0;
        trial[0] = x[0];
        trial[1] = f0 * x[0];
        trial[2] = x[1];
        trial[3] = f1 * x[1];
        return 1;
    case 5: { /* 0 slips, 1 sticks: unknowns P_N,0, P_N,1, P_T,1 */
        const bs_real a[3][3] = { { g[0][0] + f0 * g[0][1], g[0][2], g[0][3] },
                                  { g[2][0] + f0 * g[2][1], g[2][2], g[2][3] },
                                  { g[3][0] + f0 * g[3][1], g[3][2], g[3][3] } };
        const bs_real b[3] = { -c[0], -c[2], -c[3] };
        if (!cramer3(a, b, x))
            return 0;
        trial[0] = x[0];
        trial[1] = f0 * x[0];
        trial[2] = x[1];
        trial[3] = x[2];
        return 1;
    }
    case 7: { /* 0 sticks, 1 slips: unknowns P_N,0, P_T,0, P_N,1 */
        const bs_real a[3][3] = { { g[0][0], g[0][1], g[0][2] + f1 * g[0][3] },
                                  { g[1][0], g[1][1], g[1][2] + f1 * g[1][3] },
                                  { g[2][0], g[2][1], g[2][2] + f1 * g[2][3] } };
        const bs_real b[3] = { -c[0], -c[1], -c[2] };
        if (!cramer3(a, b, x))
            return 0;
        trial[0] = x[0];
        trial[1] = x[1];
        trial[2] = x[2];
        trial[3] = f1 * x[2];
        return 1;
    }
    default: /* both stick: four unknowns */
        return 0;
    }
#else
    trial[0] = trial[1] = BS_R(0.0);
    if (mode[0] == MODE_TAKEOFF && mode[1] == MODE_TAKEOFF)
        return 1;
    if (mode[0] == MODE_TAKEOFF || mode[1] == MODE_TAKEOFF) {
        const int n = mode[0] == MODE_TAKEOFF;
        if (!(g[n][n] > BS_R(0.0)))
            return 0;
        trial[n] = -c[n] / g[n][n];
        return 1;
    }
    if (!cramer2(g[0][0], g[0][1], g[1][0], g[1][1], -c[0], -c[1], x))
        return 0;
    trial[0] = x[0];
    trial[1] = x[1];
    (void)j;
    return 1;
#endif
}

/* G_ij from G's upper triangle: G is symmetric, bs_contact.c writes G_ij and
 * G_ji as one value. (With constant indices; fewer loads where the trial's
 * system has just read the upper entries.) */
#define UPPER(g, i, j) ((i) <= (j) ? (g)[i][j] : (g)[j][i])

/* xi = G P + c of the two contacts' rows at P = set->percussion. */
BS_INLINE void pair_velocities(const bs_contact_set *set, bs_real *xi)
{
    const bs_real (*g)[MAX_ROWS] = (const bs_real(*)[MAX_ROWS])set->delassus;
    const bs_real *p = set->percussion;
    int i, j;
    for (i = 0; i < 2 * ROWS; ++i) {
        bs_real v = set->free_velocity[i] + UPPER(g, i, 0) * p[0];
        for (j = 1; j < 2 * ROWS; ++j)
            v += UPPER(g, i, j) * p[j];
        xi[i] = v;
    }
}

/* 1 if both contacts' laws hold by sign at P = set->percussion, xi its
 * velocities: P_N >= 0 and inside the cone while sticking, xi_T along the
 * slip while slipping, xi_N >= 0 while lifting off. */
BS_INLINE int pair_laws_hold(const bs_contact_set *set, const int *mode, const bs_real *xi)
{
    int a;
    for (a = 0; a < 2; ++a) {
        const bs_real *p = &set->percussion[ROWS * a];
        if (mode[a] == MODE_TAKEOFF) {
            if (!(xi[ROWS * a] >= BS_R(0.0)))
                return 0;
            continue;
        }
        if (!(p[0] >= BS_R(0.0)))
            return 0;
#if BS_WITH_FRICTION
        if (mode[a] == MODE_STICK ? !(p[1] <= set->mu[a] * p[0] && p[1] >= -set->mu[a] * p[0])
                                  : !((mode[a] == MODE_SLIP_POS ? xi[ROWS * a + 1] : -xi[ROWS * a + 1]) >= BS_R(0.0)))
            return 0;
#endif
    }
    return 1;
}

/* Two contacts (docs/design.md 6): the active-set method from the warm
 * start's modes, which in a lasting contact are the solution's (71 % of
 * fig6's two-contact steps); each trial's system solved in closed form
 * (pair_system; stick-stick by stick_pair_solve; active_set_solve for
 * redundant contacts); a trial whose laws hold by sign is the solution.
 * Otherwise the mode each broken law points to (next_pair_modes), and a
 * mode pair that repeats gives way to the first not yet tried, in a fixed
 * order: at most MODES^2 small systems, a hard bound on the work. Only
 * where the signs do not settle it is the residual computed: a trial at
 * rounding's floor (exact, 64 eps s) is the solution whatever its signs,
 * and if none holds, the P with the smallest residual is kept. The
 * near-parallel rows of two corners on one face, where Gauss-Seidel crawls,
 * cost nothing extra here. */
static void solve_pair(bs_contact_set *set, const bs_real *step, bs_goal goal, int measure, bs_step_report *report)
{
    bs_real m[2 * ROWS][MAX_ROWS + 1]; /* [A | b] for active_set_solve */
    bs_real best[2 * ROWS], trial[2 * ROWS], xi[2 * ROWS];
    bs_real best_residual = BS_R(-1.0), trial_residual;
    unsigned tried = 0; /* bit MODES * mode[0] + mode[1]: that pair solved */
    int mode[2], index, j, closed;
    const bs_real total = warm_total(set, 2);

    mode[0] = warm_mode(set, 0, total);
    mode[1] = warm_mode(set, 1, total);
    report->sweeps = 0;
    for (j = 0; j < 2 * ROWS; ++j) /* best: replaced by the first trial */
        best[j] = set->percussion[j];
    for (;;) {
        index = MODES * mode[0] + mode[1];
        if (tried >> index & 1u) { /* a repeat: the first pair not yet tried */
            for (index = 0; index < MODES * MODES && (tried >> index & 1u); ++index)
                ;
            if (index == MODES * MODES)
                break; /* every pair tried: the best one stays */
            mode[0] = index / MODES;
            mode[1] = index % MODES;
        }
        tried |= 1u << index;
        closed = pair_system(set, mode, trial);
#if BS_WITH_FRICTION
        if (!closed && !(mode[0] == MODE_STICK && mode[1] == MODE_STICK && stick_pair_solve(set, trial)))
#else
        if (!closed)
#endif
            active_set_solve(set, mode, m, trial);
        ++report->systems;
        for (j = 0; j < 2 * ROWS; ++j)
            set->percussion[j] = trial[j];
        pair_velocities(set, xi);
        if (pair_laws_hold(set, mode, xi)) {
            if (closed) { /* the exact solution of the right modes */
                report->residual = measure ? residual_at(set, 2, step, xi) : BS_R(-1.0);
                report->converged = measure ? report->residual <= goal.tolerance : 1;
                return;
            }
            /* a dependent column may have left an equation unmet */
            trial_residual = residual_at(set, 2, step, xi);
            if (trial_residual <= goal.tolerance) {
                report->residual = trial_residual;
                report->converged = 1;
                return;
            }
        } else {
            /* at rounding's floor it is the solution whatever the signs */
            trial_residual = residual_at(set, 2, step, xi);
            if (trial_residual <= goal.exact) {
                report->residual = trial_residual;
                report->converged = trial_residual <= goal.tolerance;
                return;
            }
        }
        if (best_residual < BS_R(0.0) || trial_residual < best_residual) {
            best_residual = trial_residual;
            for (j = 0; j < 2 * ROWS; ++j)
                best[j] = trial[j];
        }
        next_pair_modes(set, step, mode, xi); /* unchanged modes: the next pair not tried */
    }
    for (j = 0; j < 2 * ROWS; ++j)
        set->percussion[j] = best[j];
    report->residual = best_residual;
    report->converged = best_residual <= goal.tolerance;
}

#if BS_WITH_SUBSPACE

/* The active-set method over three or more contacts from the modes given,
 * while *budget lasts (one system each) and some law breaks; the P with the
 * smallest residual (and it) is left in place if no trial meets the laws
 * within the tolerance. Returns 1 when one did. */
static int solve_active_set(bs_contact_set *set, const bs_real *step, bs_goal goal, int *mode,
                            int *budget, bs_step_report *report)
{
    const int rows = ROWS * set->count;
    bs_real best[MAX_ROWS];
    bs_real trial[MAX_ROWS];
    bs_real xi[MAX_ROWS];
    bs_real trial_residual;
    int j, broken = 1, solved = 0;

    for (j = 0; j < rows; ++j)
        best[j] = set->percussion[j];
    while (*budget > 0 && broken) {
        active_set_solve(set, mode, set->system, trial);
        ++report->systems;
        --*budget;
        for (j = 0; j < rows; ++j)
            set->percussion[j] = trial[j];
        trial_residual = residual_of(set, step, xi);
        /* laws that hold above the tolerance: a dependent column left an
         * equation unmet, which the same modes will not meet again */
        broken = trial_residual <= goal.exact ? 0 : next_modes(set, step, mode, xi);
        solved = trial_residual <= goal.exact || (broken == 0 && trial_residual <= goal.tolerance);
        if (solved || trial_residual < report->residual) {
            report->residual = trial_residual;
            for (j = 0; j < rows; ++j)
                best[j] = trial[j];
        }
    }
    for (j = 0; j < rows; ++j)
        set->percussion[j] = best[j];
    return solved;
}
#endif /* BS_WITH_SUBSPACE */

/* Three or more contacts: first the active-set method from the warm start's
 * modes (a contact new to the set: sticking if it approaches, else lifting
 * off), which in a lasting contact gets it right at once; failing that,
 * Gauss-Seidel sweeps, each not converged followed by the active-set method
 * from the modes the sweep reached, until converged, the cap, or a sweep
 * that does not lower the residual. */
static void solve_many(bs_contact_set *set, const bs_real *step, bs_goal goal, int max_sweeps,
                       bs_step_report *report)
{
    bs_real previous;
    int a;
#if BS_WITH_SUBSPACE
    int mode[BS_MAX_CONTACTS];
    int budget = SYSTEMS_MAX;
    const bs_real total = warm_total(set, set->count);

    for (a = 0; a < set->count; ++a)
        mode[a] = warm_mode(set, a, total);
    report->residual = residual(set, step);
    if (report->residual <= goal.tolerance) { /* the warm start stands */
        report->sweeps = 0;
        report->converged = 1;
        return;
    }
    if (solve_active_set(set, step, goal, mode, &budget, report)) { /* within tolerance, or at rounding's floor */
        report->sweeps = 0;
        report->converged = report->residual <= goal.tolerance;
        return;
    }
#endif
    previous = BS_R(0.0);
    report->sweeps = 0;
    for (;;) {
        for (a = 0; a < set->count; ++a)
            solve_contact(set, step, a);
        ++report->sweeps;
        report->residual = residual(set, step);
#if BS_WITH_SUBSPACE
        if (report->residual > goal.tolerance && budget > 0) {
            for (a = 0; a < set->count; ++a)
                mode[a] = mode_of(set, a);
            if (solve_active_set(set, step, goal, mode, &budget, report)) {
                report->converged = report->residual <= goal.tolerance;
                return;
            }
        }
#endif
        report->converged = report->residual <= goal.tolerance;
        /* stop at the cap, or when a round made no progress: then the
         * residual sits at what the precision can resolve for this G */
        if (report->converged || report->sweeps >= max_sweeps
            || (report->sweeps > 1 && !(report->residual < previous)))
            return;
        previous = report->residual;
    }
}

/* The goal of a solve of count contacts with step sizes r_i (step_sizes;
 * inlined with the count a constant where it is 1 or 2: the loops
 * unrolled). */
BS_INLINE bs_goal goal_of(const bs_contact_set *set, int count, const bs_solver_options *options, const bs_real *step)
{
    const bs_real scale = percussion_scale(set, count, step);
    bs_goal goal;
    goal.tolerance = options->tol_rel * scale + options->tol_abs;
    goal.exact = BS_ROUNDING(64) * scale;
    /* A scale that overflowed would take any residual, an infinite one
     * included, as within tolerance: such a solve never converges. (scale
     * >= 0; the test needs no constant, which a controller reads from
     * flash.) */
    if (!(scale - scale == BS_R(0.0)))
        goal.tolerance = goal.exact = BS_R(-1.0);
    return goal;
}

/* xi = G P + c of a lone contact at its present P. */
BS_INLINE void one_velocity(const bs_contact_set *set, bs_real *xi)
{
    int r;
    for (r = 0; r < ROWS; ++r)
        xi[r] = set->free_velocity[r] + set->delassus[r][0] * set->percussion[0]
#if BS_WITH_FRICTION
                + set->delassus[r][1] * set->percussion[1]
#endif
            ;
}

/* One contact: exact by itself, v = c (xi at the warm start for the
 * fall-back); the residual only when asked. */
static void solve_one(bs_contact_set *set, const bs_solver_options *options, bs_step_report *report)
{
    bs_real step[1], xi[ROWS];
    int exact;
    step_sizes(set, 1, step);
    one_velocity(set, xi);
    exact = solve_local(set, 0, set->free_velocity) || fall_back(set, step, 0, xi);
    report->sweeps = 1;
    if (options->measure_residual) {
        one_velocity(set, xi);
        report->residual = residual_at(set, 1, step, xi);
        report->converged = report->residual <= goal_of(set, 1, options, step).tolerance;
    } else {
        report->residual = BS_R(-1.0);
        report->converged = exact;
    }
}

/* Inlined into a compiled scene's step (BS_STEP_STAGE, bs_inline.h); the
 * pair solve stays a call. */
BS_STEP_STAGE
void bs_pgs_solve(bs_contact_set *set, const bs_solver_options *options, bs_step_report *report)
{
    bs_real step[BS_MAX_CONTACTS];
    report->systems = 0;
    if (set->count == 1) {
        solve_one(set, options, report);
    } else if (set->count == 2) {
        step_sizes(set, 2, step);
        solve_pair(set, step, goal_of(set, 2, options, step), options->measure_residual, report);
    } else {
        step_sizes(set, set->count, step);
        solve_many(set, step, goal_of(set, set->count, options, step), options->max_sweeps, report);
    }
}
