/* test_pgs.c - the contact solve (core/src/bs_pgs.c) against 50 independent
 * frictional contact problems solved by Siconos and by enumeration
 * (tests/data/fc2d_cases.json, see tests/data/README.md).
 *
 * Tolerances: double 1e-9 relative to |r_enum| (the requirement);
 * float 1e-4: the problems have cond(W) up to 1e4, so cond * FLT_EPSILON =
 * 1.2e-3 bounds a float solution's error; the solver reaches 8e-7 (printed),
 * and 1e-4 keeps a margin while still catching a wrong mode. A build without
 * the subspace step (-DBS_WITH_SUBSPACE=0, `make test` builds test_pgs so too)
 * ends on plain sweeps, whose float fixed point sits up to the bound itself
 * from r_enum (1.2e-4 measured): 1e-3 there.
 */
#include "support.h"

#include <cjson/cJSON.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "bs_pgs.h"

#define CASES_PATH "tests/data/fc2d_cases.json"

/* bs_pgs_solve under these settings, its report returned. */
static bs_step_report solve(bs_contact_set *set, int max_sweeps, bs_real tol_rel, bs_real tol_abs)
{
    bs_step_report report;
    bs_solver_options options = bs_solver_defaults();
    options.max_sweeps = max_sweeps;
    options.tol_rel = tol_rel;
    options.tol_abs = tol_abs;
    bs_pgs_solve(set, &options, &report);
    return report;
}

static cJSON *root;
static cJSON *cases;

static int load_cases(void **state)
{
    FILE *in = fopen(CASES_PATH, "rb");
    char *text;
    long size;
    (void)state;
    if (!in)
        return -1;
    fseek(in, 0, SEEK_END);
    size = ftell(in);
    fseek(in, 0, SEEK_SET);
    text = malloc((size_t)size + 1);
    if (!text || fread(text, 1, (size_t)size, in) != (size_t)size) {
        fclose(in);
        free(text);
        return -1;
    }
    text[size] = '\0';
    fclose(in);
    root = cJSON_Parse(text);
    cases = cJSON_GetObjectItem(root, "cases");
    free(text);
    return cases && cJSON_GetArraySize(cases) == 50 ? 0 : -1;
}

static int free_cases(void **state)
{
    (void)state;
    cJSON_Delete(root);
    return 0;
}

static double number(const cJSON *object, const char *key)
{
    const cJSON *item = cJSON_GetObjectItem(object, key);
    assert_non_null(item);
    return item->valuedouble;
}

/* A case as a contact set with P = 0 (no warm start); r_enum into expected. */
static int case_to_set(const cJSON *c, bs_contact_set *set, double *expected)
{
    const int n = (int)number(c, "n");
    const cJSON *w = cJSON_GetObjectItem(c, "W");
    const cJSON *q = cJSON_GetObjectItem(c, "q");
    const cJSON *r = cJSON_GetObjectItem(c, "r_enum");
    int i, j;

    assert_true(n >= 1 && n <= BS_MAX_CONTACTS);
    set->count = n;
    for (i = 0; i < n; ++i)
        set->mu[i] = (bs_real)number(c, "mu");
    for (i = 0; i < 2 * n; ++i) {
        const cJSON *row = cJSON_GetArrayItem(w, i);
        for (j = 0; j < 2 * n; ++j)
            set->delassus[i][j] = (bs_real)cJSON_GetArrayItem(row, j)->valuedouble;
        set->free_velocity[i] = (bs_real)cJSON_GetArrayItem(q, i)->valuedouble;
        set->percussion[i] = 0;
        expected[i] = cJSON_GetArrayItem(r, i)->valuedouble;
    }
    return n;
}

/* Natural-map residual of set->percussion, written out here in double
 * independently of bs_pgs.c: sum_i |P_i - prox(P_i - r_i xi_i)|_1. *rounding
 * receives how far the solver's own evaluation in bs_real may differ: the
 * rounding of xi = G P + c, 2n + 1 terms, times r, a few ulps each. */
static double natural_residual(const bs_contact_set *set, double *rounding)
{
    double residual = 0.0;
    int a, j;
    *rounding = 0.0;
    for (a = 0; a < set->count; ++a) {
        const double p_n = (double)set->percussion[2 * a], p_t = (double)set->percussion[2 * a + 1];
        const double r = 1.0 / fmax((double)set->delassus[2 * a][2 * a],
                                    (double)set->delassus[2 * a + 1][2 * a + 1]);
        double xi_n = (double)set->free_velocity[2 * a], xi_t = (double)set->free_velocity[2 * a + 1];
        double proj_n, proj_t, limit;
        double size_n = fabs(xi_n), size_t = fabs(xi_t);
        for (j = 0; j < 2 * set->count; ++j) {
            xi_n += (double)set->delassus[2 * a][j] * (double)set->percussion[j];
            xi_t += (double)set->delassus[2 * a + 1][j] * (double)set->percussion[j];
            size_n += fabs((double)set->delassus[2 * a][j] * (double)set->percussion[j]);
            size_t += fabs((double)set->delassus[2 * a + 1][j] * (double)set->percussion[j]);
        }
        *rounding += 4.0 * (2 * set->count + 1) * SUPPORT_EPS * r * (size_n + size_t);
        proj_n = fmax(0.0, p_n - r * xi_n);
        limit = (double)set->mu[a] * proj_n;
        proj_t = fmin(limit, fmax(-limit, p_t - r * xi_t));
        residual += fabs(p_n - proj_n) + fabs(p_t - proj_t);
    }
    return residual;
}

static void test_converged_solves_match_enumeration(void **state)
{
    const double tolerance = BS_REAL_FLOAT ? (BS_WITH_SUBSPACE ? 1e-4 : 1e-3) : 1e-9;
    double worst = 0.0;
    int id, i, max_sweeps = 0;
    (void)state;
    for (id = 0; id < 50; ++id) {
        bs_contact_set set;
        double expected[2 * BS_MAX_CONTACTS], error = 0.0, norm = 0.0;
        const int n = case_to_set(cJSON_GetArrayItem(cases, id), &set, expected);
        const bs_step_report result = solve(&set, 1000, BS_R(0.0), (bs_real)(10.0 * SUPPORT_EPS));
        for (i = 0; i < 2 * n; ++i) {
            error += pow((double)set.percussion[i] - expected[i], 2);
            norm += expected[i] * expected[i];
        }
        worst = fmax(worst, norm > 0.0 ? sqrt(error / norm) : sqrt(error));
        if (result.sweeps > max_sweeps)
            max_sweeps = result.sweeps;
        if (!result.converged || !(sqrt(error) <= tolerance * sqrt(norm) + 1e-300)) {
            print_error("case %d (n=%d): converged %d after %d sweeps, |P - r_enum| / |r_enum| = %.3g\n", id,
                        n, result.converged, result.sweeps, sqrt(error / norm));
            fail();
        }
    }
    print_message("50 cases, %s: worst |P - r_enum| / |r_enum| = %.2e (tolerance %.0e), at most %d sweeps\n",
                  BS_REAL_NAME, worst, tolerance, max_sweeps);
}

static void test_capped_solve_reports_its_true_residual(void **state)
{
    int id, cap, unconverged = 0;
    (void)state;
    for (cap = 1; cap <= 3; ++cap)
        for (id = 0; id < 50; ++id) {
            bs_contact_set set;
            double expected[2 * BS_MAX_CONTACTS];
            const double tol_abs = 1e-30; /* unreachable: the cap decides */
            bs_step_report result;
            double recomputed, rounding;
            case_to_set(cJSON_GetArrayItem(cases, id), &set, expected);
            result = solve(&set, cap, BS_R(0.0), (bs_real)tol_abs);
            recomputed = natural_residual(&set, &rounding);
            assert_true(result.sweeps <= cap);
            assert_close("reported residual vs recomputed", result.residual, recomputed, rounding,
                         16.0 * SUPPORT_EPS);
            assert_int_equal(result.converged, (double)result.residual <= tol_abs);
            unconverged += !result.converged;
        }
    assert_true(unconverged > 0); /* the cap did bite somewhere: the check above had work to do */
}

/* The residual the solver reports is bs_pgs_residual of its P: check that
 * formula on arbitrary (non-solution) P against the independent one. */
static void test_residual_formula_matches_independent_one(void **state)
{
    uint32_t seed = 12345u;
    int id, i, trial;
    (void)state;
    for (id = 0; id < 50; ++id)
        for (trial = 0; trial < 10; ++trial) {
            bs_contact_set set;
            double expected[2 * BS_MAX_CONTACTS], rounding, recomputed;
            bs_real reported;
            const int n = case_to_set(cJSON_GetArrayItem(cases, id), &set, expected);
            for (i = 0; i < 2 * n; ++i) { /* P in [-1, 1], a fixed pseudo-random sequence */
                seed = seed * 1664525u + 1013904223u;
                set.percussion[i] = (bs_real)((double)(seed >> 8) / 8388608.0 - 1.0);
            }
            reported = bs_pgs_residual(&set);
            recomputed = natural_residual(&set, &rounding);
            assert_true(recomputed > 1e-3); /* far from a solution: a real comparison */
            assert_close("bs_pgs_residual vs independent formula", reported, recomputed, rounding,
                         16.0 * SUPPORT_EPS);
        }
}

/* Warm-started from the solution, a solve does the least its path allows:
 * one contact one exact visit (a sweep), two one system (of the warm
 * start's modes), three or more one system or, if the warm start already
 * meets the tolerance, nothing (one sweep in a build without the active-set
 * step). */
static void test_warm_start_from_solution_needs_one_pass(void **state)
{
    int id, i;
    (void)state;
    for (id = 0; id < 50; ++id) {
        bs_contact_set set;
        double expected[2 * BS_MAX_CONTACTS];
        bs_step_report result;
        const int n = case_to_set(cJSON_GetArrayItem(cases, id), &set, expected);
        const int sweeps = n == 1 || (n >= 3 && !BS_WITH_SUBSPACE);
        const int systems = n == 2 || (n >= 3 && BS_WITH_SUBSPACE);
        for (i = 0; i < 2 * n; ++i)
            set.percussion[i] = (bs_real)expected[i];
        result = solve(&set, 50, BS_R(1e-5), BS_R(0.0));
        assert_true(result.converged);
        if (result.sweeps > sweeps || result.systems > systems)
            print_error("case %d (n = %d): %d sweeps, %d systems\n", id, n, result.sweeps, result.systems);
        assert_true(result.sweeps <= sweeps);
        assert_true(result.systems <= systems);
    }
}

/* Two contacts whose rows of G are almost parallel (two corners on one face
 * of the slot, docs/model.md 9.5): G = a [I, (1 - d) I; (1 - d) I, I], both pushed
 * in equally. The solution is symmetric and sticks:
 *   P_N = 1 / (a (2 - d)),  P_T = -c_T / (a (2 - d)).
 * Gauss-Seidel from P = 0 gives all to the first contact and then crawls, its
 * error shrinking by (1 - d)^2 a sweep; the subspace step solves it after the
 * first sweep. Without the step (BS_WITH_SUBSPACE 0) the cap of 2 must end
 * the solve unconverged, and it says so. */
static void test_redundant_pair(void **state)
{
    const double a = 2.0, d = 1e-3, c_n = -1.0, c_t = 0.01;
    bs_contact_set set;
    bs_step_report result;
    int i, j;
    (void)state;
    set.count = 2;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j)
            set.delassus[i][j] = BS_R(0.0);
        set.delassus[i][i] = (bs_real)a;
        set.delassus[i][(i + 2) % 4] = (bs_real)(a * (1.0 - d));
        set.free_velocity[i] = (bs_real)(i % 2 ? c_t : c_n);
        set.percussion[i] = BS_R(0.0);
    }
    set.mu[0] = set.mu[1] = BS_R(0.3);
    result = solve(&set, 2, BS_R(1e-5), BS_R(0.0));
    assert_true(result.converged); /* two contacts: exact in every build */
    for (i = 0; i < 2; ++i) {
        assert_close("P_N", set.percussion[2 * i], -c_n / (a * (2.0 - d)), 0.0, BS_REAL_FLOAT ? 1e-3 : 1e-9);
        assert_close("P_T", set.percussion[2 * i + 1], -c_t / (a * (2.0 - d)), 0.0, BS_REAL_FLOAT ? 1e-3 : 1e-9);
    }
}

/* A contact problem at the edge of the range: free velocities whose scaled
 * sum overflows (docs/robustness.md finding 32). The tolerance is relative
 * to that sum, so it overflowed too and took the warm start's infinite
 * residual as within it. A converged solve has a finite residual, for every
 * number of contacts. */
#if BS_REAL_FLOAT
#define LARGEST_REAL FLT_MAX
#else
#define LARGEST_REAL DBL_MAX
#endif
static void test_overflowing_scale_never_converges(void **state)
{
    bs_solver_options options = bs_solver_defaults();
    int count, i, j;
    (void)state;
    options.measure_residual = 1;
    for (count = 1; count <= 3; ++count) {
        bs_contact_set set;
        bs_step_report result;
        set.count = count;
        for (i = 0; i < 2 * count; ++i) {
            for (j = 0; j < 2 * count; ++j)
                set.delassus[i][j] = i == j ? BS_R(1.0) : BS_R(0.0);
            set.free_velocity[i] = i % 2 ? BS_R(0.0) : BS_R(-0.75) * LARGEST_REAL;
            set.percussion[i] = BS_R(0.0);
        }
        for (i = 0; i < count; ++i)
            set.mu[i] = BS_R(0.3);
        bs_pgs_solve(&set, &options, &result);
        if (result.converged && !isfinite(result.residual))
            print_error("%d contacts: converged with residual %g\n", count, (double)result.residual);
        assert_false(result.converged && !isfinite(result.residual));
        assert_false(count > 1 && result.converged); /* the scale overflows from two on */
    }
}

/* ---- two corners on one face: nearly parallel rows, solved exactly ------- */

/* A deterministic generator (the test must not depend on the C library's). */
static double next_uniform(unsigned long *state)
{
    *state = *state * 6364136223846793005ul + 1442695040888963407ul;
    return (double)(*state >> 11) / 9007199254740992.0; /* [0, 1) */
}

/* Solves the n x n system a x = b (n <= 4) in long double by Gaussian
 * elimination with partial pivoting; 0 when a pivot vanishes. */
static int solve_small(long double a[4][5], int n, long double *x)
{
    int i, j, k;
    for (k = 0; k < n; ++k) {
        int pivot = k;
        for (i = k + 1; i < n; ++i)
            if (fabsl(a[i][k]) > fabsl(a[pivot][k]))
                pivot = i;
        if (a[pivot][k] == 0.0L)
            return 0;
        for (j = 0; j <= n; ++j) {
            const long double swap = a[k][j];
            a[k][j] = a[pivot][j];
            a[pivot][j] = swap;
        }
        for (i = k + 1; i < n; ++i) {
            const long double factor = a[i][k] / a[k][k];
            for (j = k; j <= n; ++j)
                a[i][j] -= factor * a[k][j];
        }
    }
    for (i = n - 1; i >= 0; --i) {
        long double value = a[i][n];
        for (j = i + 1; j < n; ++j)
            value -= a[i][j] * x[j];
        x[i] = value / a[i][i];
    }
    return 1;
}

/* Every solution of the two-contact problem xi = G P + c under the contact
 * laws, by enumerating the 16 mode pairs (0 take-off, 1 stick, 2 slip with
 * xi_T > 0, 3 slip with xi_T < 0) in long double, written independently of
 * bs_pgs.c. Returns how many mode pairs give a solution; the first goes to
 * found. Laws are checked to a relative slack of 1e-9. */
static int enumerate_pair(const double g[4][4], const double *c, const double *mu, double *found)
{
    int solutions = 0, modes;
    for (modes = 0; modes < 16; ++modes) {
        const int mode[2] = { modes / 4, modes % 4 };
        long double a[4][5], p[4], xi[4], scale = 0.0L;
        int i, j, ok = 1;
        for (i = 0; i < 4; ++i) {
            const int contact = i / 2, tangential = i % 2;
            for (j = 0; j < 5; ++j)
                a[i][j] = 0.0L;
            if (mode[contact] == 0 || (tangential && mode[contact] != 1)) { /* a law on P */
                a[i][i] = 1.0L;
                if (tangential && mode[contact] != 0)
                    a[i][i - 1] = mode[contact] == 2 ? mu[contact] : -mu[contact];
            } else { /* xi_i = 0 */
                for (j = 0; j < 4; ++j)
                    a[i][j] = g[i][j];
                a[i][4] = -c[i];
            }
        }
        if (!solve_small(a, 4, p))
            continue;
        for (i = 0; i < 4; ++i) {
            xi[i] = c[i];
            for (j = 0; j < 4; ++j)
                xi[i] += g[i][j] * p[j];
            scale += fabsl(c[i]);
        }
        for (i = 0; i < 2 && ok; ++i) {
            const long double slack = 1e-9L * scale, p_slack = 1e-9L * (fabsl(p[2 * i]) + fabsl(p[2 * i + 1]));
            switch (mode[i]) {
            case 0: ok = xi[2 * i] >= -slack; break;
            case 1: ok = p[2 * i] >= -p_slack && fabsl(p[2 * i + 1]) <= mu[i] * p[2 * i] + p_slack; break;
            case 2: ok = p[2 * i] >= -p_slack && xi[2 * i + 1] >= -slack; break;
            default: ok = p[2 * i] >= -p_slack && xi[2 * i + 1] <= slack; break;
            }
        }
        if (ok && solutions++ == 0)
            for (i = 0; i < 4; ++i)
                found[i] = (double)p[i];
    }
    return solutions;
}

/* Two corners of one face, as the beam sees them: force directions that
 * differ by a relative delta (G ~ W W^T has cond ~ 1/delta^2, up to 1e8), a
 * free velocity into the face, friction from 0.1 to 0.6, tangential motion of
 * either sign so that stick and both slips occur. The solve must converge
 * with the default cap of two sweeps, and agree with the enumeration: on the
 * velocities xi (which the problem determines), and on P where it is unique
 * and well conditioned enough for the precision. */
static void test_one_face_pairs_are_solved_exactly(void **state)
{
    unsigned long seed = 12345;
    int id, converged = 0, compared = 0, modes_seen[4] = { 0 };
    double worst_xi = 0.0;
    (void)state;
    for (id = 0; id < 400; ++id) {
        const double log_cond = 2.0 + 6.0 * (double)(id % 100) / 99.0; /* 1e2 .. 1e8 */
        const double delta = pow(10.0, -log_cond / 2.0);
        double w[4][5], g[4][4], c[4], mu[2], p[4], found[4], scale = 0.0, xi_error = 0.0;
        bs_contact_set set;
        bs_step_report result;
        int i, j, k, solutions;
        for (k = 0; k < 5; ++k) { /* rows of corner 2 = corner 1's + delta * noise */
            w[0][k] = next_uniform(&seed) - 0.5;
            w[1][k] = next_uniform(&seed) - 0.5;
            w[2][k] = w[0][k] + delta * (next_uniform(&seed) - 0.5);
            w[3][k] = w[1][k] + delta * (next_uniform(&seed) - 0.5);
        }
        for (i = 0; i < 4; ++i)
            for (j = 0; j < 4; ++j)
                for (g[i][j] = 0.0, k = 0; k < 5; ++k)
                    g[i][j] += w[i][k] * w[j][k];
        c[0] = -0.5 - next_uniform(&seed);
        c[2] = c[0] * (1.0 + 0.1 * (next_uniform(&seed) - 0.5));
        c[1] = 2.0 * (next_uniform(&seed) - 0.5);
        c[3] = c[1] + 0.2 * (next_uniform(&seed) - 0.5);
        mu[0] = mu[1] = 0.1 + 0.5 * next_uniform(&seed);
        solutions = enumerate_pair(g, c, mu, found);
        assert_true(solutions >= 1);
        set.count = 2;
        for (i = 0; i < 4; ++i) {
            for (j = 0; j < 4; ++j)
                set.delassus[i][j] = (bs_real)g[i][j];
            set.free_velocity[i] = (bs_real)c[i];
            set.percussion[i] = BS_R(0.0);
            scale += fabs(c[i]);
        }
        set.mu[0] = (bs_real)mu[0];
        set.mu[1] = (bs_real)mu[1];
        result = solve(&set, 2, BS_R(1e-5), BS_R(0.0));
        converged += result.converged == 1;
        if (result.converged != 1)
            print_error("case %d (cond 1e%.1f): not converged, residual %.3g\n", id, log_cond,
                        (double)result.residual);
        for (i = 0; i < 4; ++i)
            p[i] = (double)set.percussion[i];
        for (i = 0; i < 4; ++i) { /* xi of the solver's P against the enumeration's, in double */
            double mine = c[i], theirs = c[i];
            for (j = 0; j < 4; ++j) {
                mine += g[i][j] * p[j];
                theirs += g[i][j] * found[j];
            }
            xi_error = fmax(xi_error, fabs(mine - theirs));
        }
        if (solutions == 1) {
            worst_xi = fmax(worst_xi, xi_error / scale);
            assert_true(xi_error <= (BS_REAL_FLOAT ? 1e-3 : 1e-7) * scale);
            if (pow(10.0, log_cond) * SUPPORT_EPS < 1e-4) { /* P itself is determined to 1e-4 */
                double error = 0.0, norm = 0.0;
                for (i = 0; i < 4; ++i) {
                    error += (p[i] - found[i]) * (p[i] - found[i]);
                    norm += found[i] * found[i];
                }
                assert_true(sqrt(error) <= 1e-3 * sqrt(norm) + 1e-12);
                ++compared;
            }
        }
        for (i = 0; i < 2; ++i) /* which modes the cases reach */
            ++modes_seen[found[2 * i] <= 0.0 ? 0
                         : fabs(found[2 * i + 1]) < mu[i] * found[2 * i] * (1.0 - 1e-9) ? 1
                         : found[2 * i + 1] < 0.0 ? 2 : 3];
    }
    print_message("400 one-face pairs, cond 1e2..1e8, %s: %d converged, worst |xi - xi_enum| / |c| = %.2e, "
                  "%d compared on P; modes off/stick/slip+/slip-: %d/%d/%d/%d\n", BS_REAL_NAME, converged,
                  worst_xi, compared, modes_seen[0], modes_seen[1], modes_seen[2], modes_seen[3]);
    assert_int_equal(converged, 400);
    assert_true(modes_seen[1] > 0 && modes_seen[2] > 0 && modes_seen[3] > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_converged_solves_match_enumeration),
        cmocka_unit_test(test_capped_solve_reports_its_true_residual),
        cmocka_unit_test(test_residual_formula_matches_independent_one),
        cmocka_unit_test(test_warm_start_from_solution_needs_one_pass),
        cmocka_unit_test(test_redundant_pair),
        cmocka_unit_test(test_overflowing_scale_never_converges),
        cmocka_unit_test(test_one_face_pairs_are_solved_exactly),
    };
    return cmocka_run_group_tests(tests, load_cases, free_cases);
}
