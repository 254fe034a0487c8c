/* test_shape.c - the core's mode shapes (core/src/bs_shape.c, in bs_real) against
 * the cancellation-free closed form in double (host/lib/modal.c).
 *
 * Tolerances, relative to max |phi_k| (resp. max |phi_k'|) over the beam:
 *   double: the host fit tolerance, 1e-9 (scene_fit_tolerance);
 *   float:  64 FLT_EPSILON = 7.6e-6. Horner's 8 terms on |u| <= 1 with
 *           coefficients below max |phi| give ~16 eps, and x * pieces / L in
 *           float moves u by up to eps * pieces, which costs up to ~2 eps *
 *           pieces * max |dphi/du| / max |phi| more: 64 eps covers 128 pieces.
 */
#include "support.h"

#include <math.h>
#include "bs_shape.h"

static scene_file file;
static bs_scene scene;
static scene_model model;

static double tolerance(void)
{
    return BS_REAL_FLOAT ? 64.0 * SUPPORT_EPS : scene_fit_tolerance();
}

/* Max error of phi and phi' over a fine grid of x in [0, L], every mode. */
static void check_all_modes(int modes)
{
    const int points = 20000;
    const double length = file.params.beam.length;
    double max_phi[BS_MAX_MODES] = { 0 }, max_slope[BS_MAX_MODES] = { 0 };
    double err_phi[BS_MAX_MODES] = { 0 }, err_slope[BS_MAX_MODES] = { 0 };
    int i, k;

    file.params.modes = modes;
    file.params.dt = 5e-6; /* explicit limit of 20 modes: dt < 6.4e-6 s */
    support_build(&file, &scene, &model);
    for (i = 0; i <= points; ++i) {
        const bs_real x = (bs_real)(length * i / points);
        const double xi = (double)x / length; /* the abscissa the core sees */
        bs_real phi[BS_MAX_MODES], slope[BS_MAX_MODES];
        bs_shape_eval(&scene, x, phi, slope);
        for (k = 0; k < modes; ++k) {
            double exact, exact_xi;
            modal_shape(&model.modes, k, xi, &exact, &exact_xi);
            max_phi[k] = fmax(max_phi[k], fabs(exact));
            max_slope[k] = fmax(max_slope[k], fabs(exact_xi / length));
            err_phi[k] = fmax(err_phi[k], fabs((double)phi[k] - exact));
            err_slope[k] = fmax(err_slope[k], fabs((double)slope[k] - exact_xi / length));
        }
    }
    {
        double worst_phi = 0.0, worst_slope = 0.0;
        for (k = 0; k < modes; ++k) {
            worst_phi = fmax(worst_phi, err_phi[k] / max_phi[k]);
            worst_slope = fmax(worst_slope, err_slope[k] / max_slope[k]);
        }
        print_message("%d modes, %s: worst relative error %.2e (phi), %.2e (slope); tolerance %.1e\n", modes,
                      BS_REAL_NAME, worst_phi, worst_slope, tolerance());
    }
    for (k = 0; k < modes; ++k) {
        assert_close("max |phi_k error| / max |phi_k|", err_phi[k] / max_phi[k], 0.0, tolerance(), 0.0);
        assert_close("max |phi_k' error| / max |phi_k'|", err_slope[k] / max_slope[k], 0.0, tolerance(), 0.0);
    }
}

static void test_five_modes_match_closed_form(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    check_all_modes(5);
}

static void test_twenty_modes_match_closed_form(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    check_all_modes(BS_MAX_MODES);
}

static void test_inside_the_clamps_shapes_are_zero(void **state)
{
    static const double outside[] = { -1e-3, -1e-9, 0.14 + 1e-6, 0.2 };
    bs_real phi[BS_MAX_MODES], slope[BS_MAX_MODES];
    unsigned i;
    int k;
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    for (i = 0; i < sizeof outside / sizeof outside[0]; ++i) {
        bs_shape_eval(&scene, (bs_real)outside[i], phi, slope);
        for (k = 0; k < scene.n_modes; ++k)
            assert_true(phi[k] == 0 && slope[k] == 0);
    }
    bs_shape_eval(&scene, scene.length, phi, slope); /* x = L is on the beam: phi = 0, phi' != 0 */
    for (k = 0; k < scene.n_modes; ++k)
        assert_true(fabs((double)slope[k]) > 1.0);
}

/* bs_shape_bounds: the values bs_shape_eval returns at two points less than a
 * piece apart differ by at most slope |dx| + jump, and |phi'| <= slope
 * (bs_contact.c skips corners on the strength of this, so a bound that fails
 * anywhere would drop a contact). Pairs straddle every piece boundary, where
 * the separate interpolants meet, and sit at random elsewhere. The slope bound
 * must also stay within 4x the true maximum, or the skip would never fire. */
static void check_bounds(int modes)
{
    const double length = file.params.beam.length;
    bs_shape_bound bound;
    double max_slope[BS_MAX_MODES] = { 0 };
    uint32_t random = 12345u;
    int i, k;

    file.params.modes = modes;
    file.params.dt = 5e-6;
    support_build(&file, &scene, &model);
    bs_shape_bounds(&scene, &bound);
    for (i = 0; i < 40000; ++i) {
        const int boundary = i % (scene.shape_pieces + 1); /* 0 .. pieces */
        const double width = length / scene.shape_pieces;
        double x1, x2;
        bs_real phi1[BS_MAX_MODES], slope1[BS_MAX_MODES], phi2[BS_MAX_MODES], slope2[BS_MAX_MODES];
        random = random * 1664525u + 1013904223u;
        if (i % 2) { /* across (or at) a piece boundary, up to 1e-3 pieces either side */
            const double offset = width * 1e-3 * ((double)(random >> 8) / 16777216.0);
            x1 = fmax(0.0, boundary * width - offset);
            x2 = fmin(length, boundary * width + offset * 0.5);
        } else { /* anywhere, up to 0.9 pieces apart */
            x1 = length * ((double)(random >> 8) / 16777216.0);
            random = random * 1664525u + 1013904223u;
            x2 = fmin(length, x1 + 0.9 * width * ((double)(random >> 8) / 16777216.0));
        }
        bs_shape_eval(&scene, (bs_real)x1, phi1, slope1);
        bs_shape_eval(&scene, (bs_real)x2, phi2, slope2);
        for (k = 0; k < modes; ++k) {
            const double dx = fabs((double)(bs_real)x2 - (double)(bs_real)x1);
            const double change = fabs((double)phi2[k] - (double)phi1[k]);
            const double allowed = (double)bound.slope[k] * dx + (double)bound.jump[k];
            if (change > allowed)
                fail_msg("mode %d, x %.9g .. %.9g: |phi change| %.3e > bound %.3e", k + 1, x1, x2, change,
                         allowed);
            if (fabs((double)slope1[k]) > (double)bound.slope[k])
                fail_msg("mode %d, x %.9g: |phi'| %.6e > bound %.6e", k + 1, x1, fabs((double)slope1[k]),
                         (double)bound.slope[k]);
            max_slope[k] = fmax(max_slope[k], fabs((double)slope1[k]));
        }
    }
    for (k = 0; k < modes; ++k)
        assert_close("slope bound / max |phi'| (bound not uselessly loose)",
                     (double)bound.slope[k] / max_slope[k], 2.5, 1.5, 0.0);
}

static void test_shape_bounds_hold(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    check_bounds(1);
    check_bounds(5);
    check_bounds(BS_MAX_MODES);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_five_modes_match_closed_form),
        cmocka_unit_test(test_twenty_modes_match_closed_form),
        cmocka_unit_test(test_inside_the_clamps_shapes_are_zero),
        cmocka_unit_test(test_shape_bounds_hold),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
