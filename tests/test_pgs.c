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

static void test_warm_start_from_solution_needs_one_sweep(void **state)
{
    int id, i;
    (void)state;
    for (id = 0; id < 50; ++id) {
        bs_contact_set set;
        double expected[2 * BS_MAX_CONTACTS];
        bs_step_report result;
        const int n = case_to_set(cJSON_GetArrayItem(cases, id), &set, expected);
        for (i = 0; i < 2 * n; ++i)
            set.percussion[i] = (bs_real)expected[i];
        result = solve(&set, 50, BS_R(1e-5), BS_R(0.0));
        assert_true(result.converged);
        assert_int_equal(result.sweeps, 1);
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
#if BS_WITH_SUBSPACE
    assert_true(result.converged);
    for (i = 0; i < 2; ++i) {
        assert_close("P_N", set.percussion[2 * i], -c_n / (a * (2.0 - d)), 0.0, BS_REAL_FLOAT ? 1e-3 : 1e-9);
        assert_close("P_T", set.percussion[2 * i + 1], -c_t / (a * (2.0 - d)), 0.0, BS_REAL_FLOAT ? 1e-3 : 1e-9);
    }
#else
    assert_false(result.converged);
    assert_int_equal(result.sweeps, 2);
    assert_true(result.residual > BS_R(1e-5) * bs_pgs_scale(&set));
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_converged_solves_match_enumeration),
        cmocka_unit_test(test_capped_solve_reports_its_true_residual),
        cmocka_unit_test(test_residual_formula_matches_independent_one),
        cmocka_unit_test(test_warm_start_from_solution_needs_one_sweep),
        cmocka_unit_test(test_redundant_pair),
    };
    return cmocka_run_group_tests(tests, load_cases, free_cases);
}
