/* test_shape.c - the core's mode shapes (core/src/bs_shape.c, in bs_real) against
 * the cancellation-free closed form in double (host/lib/scene/modal.c).
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

/* Max error of phi and phi' over a fine grid of x in [0, L], every mode:
 * evaluated directly, or (expanded = 1) from an expansion about a point up to
 * the reach away, as the contact detection evaluates them. */
static void check_all_modes(int modes, int expanded)
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
        if (expanded) { /* centres on both sides of x, up to 0.99 of the reach away */
            const double reach = (double)bs_shape_reach(&scene) / (2.0 * (double)scene.shape_scale);
            bs_shape_cache cache;
            bs_shape_expand(&scene, (bs_real)fmin(length, fmax(0.0, (double)x + (i % 2 ? 0.99 : -0.99) * reach
                                                                         * ((i % 7) / 6.0))), &cache);
            bs_shape_expanded(scene.n_modes, &cache, bs_shape_offset(&scene, &cache, x), 1, BS_R(2.0) * scene.shape_scale,
                              phi, slope);
        } else {
            bs_shape_eval(&scene, x, phi, slope);
        }
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
        print_message("%d modes, %s, %s: worst relative error %.2e (phi), %.2e (slope); tolerance %.1e\n",
                      modes, BS_REAL_NAME, expanded ? "expanded" : "direct", worst_phi, worst_slope, tolerance());
        if (expanded)
            print_message("  (expansions about points up to their reach %.4g away)\n", (double)bs_shape_reach(&scene));
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
    check_all_modes(5, 0);
    check_all_modes(5, 1);
}

static void test_twenty_modes_match_closed_form(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    check_all_modes(BS_MAX_MODES, 0);
    check_all_modes(BS_MAX_MODES, 1);
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_five_modes_match_closed_form),
        cmocka_unit_test(test_twenty_modes_match_closed_form),
        cmocka_unit_test(test_inside_the_clamps_shapes_are_zero),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
