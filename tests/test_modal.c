/* test_modal.c - modal data of the beam (host/lib/scene/modal.c) against docs/model.md 8
 * and against the defining equations. */
#include "support.h"

#include <math.h>
#include "attached.h"

static scene_file file;
static bs_scene scene;
static scene_model model;

static const double pi = 3.14159265358979323846;

static void test_fig6_frequencies_match_model_md(void **state)
{
    /* docs/model.md 8: bare-beam check values, to 1e-4 relative */
    static const double expected_hz[5] = { 260.28, 719.01, 1412.3, 2339.0, 3500.1 };
    int k;
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    assert_int_equal(model.modes.n, 5);
    for (k = 0; k < 5; ++k)
        assert_close("f_k [Hz]", model.modes.omega[k] / (2.0 * pi), expected_hz[k], 0.0, 1e-4);
}

static void test_fig6_gammas_match_model_md(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    assert_close("gamma_1", model.modes.gamma[0], 0.10333, 0.0, 1e-4);
    assert_close("gamma_3", model.modes.gamma[2], 0.044932, 0.0, 1e-4);
    assert_close("gamma_5", model.modes.gamma[4], 0.028315, 0.0, 1e-4);
    assert_true(model.modes.gamma[1] == 0.0 && model.modes.gamma[3] == 0.0);
}

static void test_ideal_clamp_gives_274_hz(void **state)
{
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    file.params.beam.k_rot = 1e12; /* k_r -> infinity */
    support_build(&file, &scene, &model);
    assert_close("f_1, ideal clamps [Hz]", model.modes.omega[0] / (2.0 * pi), 274.19, 0.0, 1e-4);
}

/* rho A L int phi_i phi_j = delta_ij and the clamp conditions, checked by an
 * independent rule (composite Simpson) and finite differences. */
static void test_modes_are_normalised_and_satisfy_boundary_conditions(void **state)
{
    const int points = 20000;
    const double h = 1.0 / points;
    double gram[BS_MAX_MODES][BS_MAX_MODES] = { { 0 } };
    int i, j, k;
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    file.params.modes = 8;
    support_build(&file, &scene, &model);
    for (k = 0; k <= points; ++k) {
        const double weight = (k == 0 || k == points) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        double phi[BS_MAX_MODES], slope;
        for (i = 0; i < 8; ++i)
            modal_shape(&model.modes, i, k * h, &phi[i], &slope);
        for (i = 0; i < 8; ++i)
            for (j = 0; j < 8; ++j)
                gram[i][j] += weight * h / 3.0 * file.params.beam.mass * phi[i] * phi[j];
    }
    for (i = 0; i < 8; ++i)
        for (j = 0; j < 8; ++j)
            assert_close("rho A L int phi_i phi_j", gram[i][j], i == j ? 1.0 : 0.0, 1e-9, 0.0);

    for (i = 0; i < 8; ++i) {
        const double e = 1e-4;
        double phi0, slope0, phi1, slope1, pa, sa, pb, sb;
        modal_shape(&model.modes, i, 0.0, &phi0, &slope0);
        modal_shape(&model.modes, i, 1.0, &phi1, &slope1);
        assert_close("phi(0)", phi0, 0.0, 1e-12 * fabs(slope0), 0.0);
        assert_close("phi(1)", phi1, 0.0, 1e-12 * fabs(slope1), 0.0);
        /* phi'' = kappa phi' at 0, phi'' = -kappa phi' at 1 (second differences of the slope) */
        modal_shape(&model.modes, i, e, &pa, &sa);
        modal_shape(&model.modes, i, 2 * e, &pb, &sb);
        assert_close("phi''(0) / (kappa phi'(0))", (-3 * slope0 + 4 * sa - sb) / (2 * e),
                     model.kappa * slope0, 0.0, 1e-6);
        modal_shape(&model.modes, i, 1.0 - e, &pa, &sa);
        modal_shape(&model.modes, i, 1.0 - 2 * e, &pb, &sb);
        assert_close("phi''(1) / (-kappa phi'(1))", (3 * slope1 - 4 * sa + sb) / (2 * e),
                     -model.kappa * slope1, 0.0, 1e-6);
    }
}

static void test_attached_slider_frequency_matches_model_md(void **state)
{
    /* docs/model.md 8: ~248 Hz at s = 0.05, ~88 Hz at s = 0.5, 124 Hz near s = 0.25
     * (stated to about 2 significant digits: 1 % tolerance) */
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    assert_close("attached f_1 at s = 0.05 [Hz]", attached_frequency(&model.modes, &file.params, 0.05), 248.0,
                 0.0, 0.01);
    assert_close("attached f_1 at s = 0.5 [Hz]", attached_frequency(&model.modes, &file.params, 0.5), 88.0,
                 0.0, 0.01);
    assert_close("attached f_1 at s = 0.25 [Hz]", attached_frequency(&model.modes, &file.params, 0.25), 124.0,
                 0.0, 0.01);
    assert_close("s where attached f_1 = 124 Hz", attached_position(&model.modes, &file.params, 124.0), 0.25,
                 0.01, 0.0);
}

static void test_stretch_matrix_follows_symmetry(void **state)
{
    int i, j;
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model);
    for (i = 0; i < 5; ++i)
        for (j = 0; j < 5; ++j) {
            if ((i + j) % 2)
                assert_true(scene.stretch[i][j] == 0);
            else
                assert_true(scene.stretch[i][j] == scene.stretch[j][i]);
        }
    for (i = 0; i < 5; ++i) /* I_ii = int phi_i,xi^2 > 0 */
        assert_true(scene.stretch[i][i] > 0);
    /* the host's |S| bounds every Rayleigh quotient of S from above */
    assert_true(model.stretch_norm >= model.data.stretch[4][4]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fig6_frequencies_match_model_md),
        cmocka_unit_test(test_fig6_gammas_match_model_md),
        cmocka_unit_test(test_ideal_clamp_gives_274_hz),
        cmocka_unit_test(test_modes_are_normalised_and_satisfy_boundary_conditions),
        cmocka_unit_test(test_attached_slider_frequency_matches_model_md),
        cmocka_unit_test(test_stretch_matrix_follows_symmetry),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
