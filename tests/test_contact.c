/* test_contact.c - contact laws on a rigid beam (n_modes = 0, no excitation):
 * Newton impacts rebound with e_N, Coulomb friction holds or lets go at
 * mu = tan(tilt), the clamp end stops hold the slider on the beam. And the
 * detection's shortcut (a corner that is certainly open is not evaluated)
 * changes no result. */
#include "support.h"

#include <math.h>
#include "bs_contact.h"
#include "bs_shape.h"

/* The contact problem carries a relative compliance (bs_contact.c): closed
 * contacts give way by about that fraction of their velocity. */
#define COMPLIANCE ((double)BS_CONTACT_COMPLIANCE)
#define COMPLIANCE_T ((double)BS_CONTACT_COMPLIANCE_T)

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_sim sim;

static const double pi = 3.14159265358979323846;

/* Rigid, motionless beam; the parameters of fig6 otherwise. */
static void rigid_beam(double restitution, double friction, double tilt_deg, double gravity)
{
    support_load("configs/fig6.ini", &file, &scene, &model);
    file.params.acceleration = 0.0;
    file.params.e_n = restitution;
    file.params.mu = friction;
    file.params.tilt = tilt_deg;
    file.params.gravity = gravity;
    support_build(&file, &scene, &model);
    scene.n_modes = 0;
}

/* Steps until the given corners are active; returns the slider's vertical
 * velocity before and after that step. */
static void first_impact(unsigned corners, double *before, double *after)
{
    int n;
    for (n = 0; n < 100000; ++n) {
        bs_real velocity[3];
        bs_sim_get_state(&sim, NULL, NULL, NULL, velocity);
        *before = (double)velocity[1];
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        if (support_report(&sim).active) {
            assert_int_equal(support_report(&sim).active, corners);
            bs_sim_get_state(&sim, NULL, NULL, NULL, velocity);
            *after = (double)velocity[1];
            return;
        }
    }
    fail_msg("no impact");
}

/* Moreau-Newton: xi_N = gamma+ + e_N gamma- = 0 for both corners of the
 * face, so u_z after = -e_N u_z before (gravity's impulse over the step is
 * absorbed by the percussion), to the compliance. */
static void test_slider_dropped_on_rigid_beam_rebounds_with_e_n(void **state)
{
    static const double restitution[] = { 0.0, 0.5, 1.0 };
    unsigned i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        const bs_real drop[3] = { 0, BS_R(-0.1), 0 };
        double before, after;
        rigid_beam(restitution[i], 0.2, 0.0, 9.81);
        assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
        assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, NULL, drop), BS_OK);
        first_impact(0x9u /* P1 and P4: the top corners land on the top face */, &before, &after);
        assert_true(before < -0.09);
        assert_close("rebound velocity", after, -restitution[i] * before,
                     (2.0 * COMPLIANCE + 64 * SUPPORT_EPS) * fabs(before), 0.0);
    }
}

static void test_slider_thrown_up_rebounds_from_bottom_corners(void **state)
{
    const bs_real throw_up[3] = { 0, BS_R(0.1), 0 };
    double before, after;
    (void)state;
    rigid_beam(0.5, 0.2, 0.0, 0.0);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, NULL, throw_up), BS_OK);
    first_impact(0x6u /* P2 and P3 */, &before, &after);
    assert_close("rebound velocity", after, -0.5 * before, (2.0 * COMPLIANCE + 64 * SUPPORT_EPS) * fabs(before),
                 0.0);
}

/* The slider resting on its top corners on a beam tilted by theta: friction
 * holds it when mu > tan(theta); below, it slides down with
 * a = -g (sin theta - mu cos theta) (leapfrog is exact for constant
 * acceleration: x_n = x_0 + a (n h)^2 / 2). */
static double slide(double friction, double tilt_deg, double seconds)
{
    const double h = file.params.dt;
    const long steps = (long)(seconds / h + 0.5);
    bs_real pose[3];
    double x0;
    long n;

    rigid_beam(0.0, friction, tilt_deg, 9.81);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK);
    bs_sim_get_state(&sim, NULL, NULL, pose, NULL);
    /* top corners on the top face, z_C = h/2 - R/2 - d, and 1 nm into it so
     * that the contact takes part from the first step */
    pose[1] = (bs_real)(0.5 * file.params.beam.thickness
                        - 0.5 * file.params.play_ratio * file.params.beam.thickness - file.params.com_offset
                        - 1e-9);
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, pose, NULL), BS_OK);
    x0 = (double)pose[0];
    for (n = 0; n < steps; ++n) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        assert_int_equal(support_report(&sim).active, 0x9u);
        assert_true(support_report(&sim).converged);
    }
    bs_sim_get_state(&sim, NULL, NULL, pose, NULL);
    return (double)pose[0] - x0;
}

static void test_tilted_beam_holds_slider_when_mu_above_tan_tilt(void **state)
{
    const double tilt = atan(0.1) * 180.0 / pi;
    (void)state;
    /* sliding would cover ~1 mm (mu = 0.09) to 12 cm (mu = 0) in this time */
    assert_close("displacement, mu = 0.11 > tan = 0.1 [m]", slide(0.11, tilt, 0.5), 0.0, 1e-9, 0.0);
    assert_close("displacement, mu = 0.5 [m]", slide(0.5, tilt, 0.5), 0.0, 1e-9, 0.0);
}

static void test_tilted_beam_lets_slider_slide_when_mu_below_tan_tilt(void **state)
{
    const double tilt = atan(0.1), seconds = 0.2, g = 9.81; /* 2 cm at most: the stop is 6.5 cm away */
    static const double friction[] = { 0.09, 0.05, 0.0 };
    unsigned i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        const double a = -g * (sin(tilt) - friction[i] * cos(tilt));
        assert_close("sliding displacement [m]", slide(friction[i], tilt * 180.0 / pi, seconds),
                     0.5 * a * seconds * seconds, 0.0, BS_REAL_FLOAT ? 1e-4 : 1e-9 + 10.0 * COMPLIANCE_T);
    }
}

/* The clamp stops: a slider thrown at the left clamp bounces back with e_N
 * and never passes stop_min by more than one step's travel. */
static void test_slider_thrown_at_clamp_bounces_off_end_stop(void **state)
{
    const bs_real throw_left[3] = { BS_R(-0.5), 0, 0 };
    double x_min = 1.0;
    bs_real pose[3], velocity[3];
    int n;
    (void)state;
    rigid_beam(0.5, 0.0, 0.0, 0.0);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, (bs_real)(0.04)), BS_OK);
    assert_int_equal(bs_sim_set_state(&sim, NULL, NULL, NULL, throw_left), BS_OK);
    for (n = 0; n < 5000; ++n) {
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        bs_sim_get_state(&sim, NULL, NULL, pose, velocity);
        x_min = fmin(x_min, (double)pose[0]);
    }
    assert_true(x_min >= (double)scene.stop_min - 0.5 * (double)scene.dt);
    assert_close("velocity after the stop", velocity[0], 0.25, 0.0, 4.0 * COMPLIANCE);
}

static void test_slider_started_at_clamp_stays_on_beam(void **state)
{
    bs_real pose[3];
    int n;
    (void)state;
    support_load("configs/fig6.ini", &file, &scene, &model); /* full model, excited */
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, scene.stop_min / scene.length), BS_OK);
    for (n = 0; n < 100000; ++n) { /* 2 s */
        assert_int_equal(bs_sim_step(&sim), BS_OK);
        bs_sim_get_state(&sim, NULL, NULL, pose, NULL);
        assert_true(pose[0] >= scene.stop_min - BS_R(1e-6));
    }
}

static uint32_t random_state = 1u;

static double uniform(double low, double high) /* LCG, reproducible */
{
    random_state = random_state * 1664525u + 1013904223u;
    return low + (high - low) * ((double)(random_state >> 8) / 16777216.0);
}

/* Random poses of the slot around a vibrating beam, the slot's centre within
 * 1.2 times the play of the beam axis (so corners sit on both sides of
 * contact, many within a hair of it), also at the clamps, with the side
 * expansions fresh or up to their reach away: the contacts detection finds
 * and their force directions are those of the mode shapes evaluated
 * directly, to the expansions' error (far below the fit's) except where a
 * corner sits within that error of touching. */
static void check_detection_against_direct_shapes(const char *path, double deflection)
{
    static bs_contact_set set;
    bs_real q[BS_MAX_MODES], phi[BS_MAX_MODES], slope[BS_MAX_MODES];
    bs_shape_cache cache[2];
    double play, worst_w = 0.0, scale_w = 0.0;
    long active = 0, borderline = 0;
    int i, k;

    support_load(path, &file, &scene, &model);
    assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, BS_R(0.5)), BS_OK); /* its prepared constants */
    play = 0.5 * (file.params.play_ratio - 1.0) * file.params.beam.thickness;
    bs_shape_eval(&scene, BS_R(0.5) * scene.length, phi, slope); /* scale q to the deflection */
    for (i = 0; i < 200000; ++i) {
        bs_contact_frame frame;
        double w = 0.0;
        int corner, side;
        for (k = 0; k < scene.n_modes; ++k)
            q[k] = (bs_real)(uniform(-1.0, 1.0) * deflection / fabs((double)phi[0]) /* forced response ~ 1/omega^2 */
                             * (double)scene.omega_sq[0] / (double)scene.omega_sq[k]);
        frame.q_beam = q;
        frame.x_kinematic = (bs_real)(i % 10 == 0 ? uniform(-0.01, 0.01) + (i % 20 ? 0.0 : (double)scene.length)
                                                  : uniform(0.0, (double)scene.length));
        frame.x_stops = frame.x_kinematic;
        frame.beta = (bs_real)(i % 3 ? uniform(-0.005, 0.005) : 0.0);
        frame.stops = 1;
        bs_shape_eval(&scene, frame.x_kinematic, phi, slope);
        for (k = 0; k < scene.n_modes; ++k)
            w += (double)phi[k] * (double)q[k];
        frame.z = (bs_real)(w - (double)scene.com_offset + uniform(-1.2, 1.2) * play); /* relative to the base */
        for (side = 0; side < 2; ++side) { /* fresh, or expanded up to the reach away */
            const double corner_x = (double)frame.x_kinematic + (side ? 1.0 : -1.0) * 0.5 * file.params.slot_width;
            bs_shape_forget(&cache[side]);
            if (i % 2)
                bs_shape_expand(&scene, (bs_real)(corner_x + uniform(-0.9, 0.9) * (double)bs_shape_reach(&scene)
                                                             / (2.0 * (double)scene.shape_scale)), &cache[side]);
        }
        frame.cache = cache;
        frame.reach = bs_shape_reach(&scene);
        frame.warm = (const bs_real(*)[BS_ROWS])sim.percussion;
        if (bs_contact_detect(&scene, &sim.k, &frame, &set) != BS_OK)
            continue; /* a corner across the beam's axis: no contacts to compare */
        for (corner = 0; corner < BS_CORNERS; ++corner) {
            const double zeta = corner == 0 || corner == 3 ? 1.0 : -1.0;
            const double hh = (double)scene.half_thickness;
            const double rho_x = (double)scene.corner[corner][0], rho_z = (double)scene.corner[corner][1];
            const double beta = (double)frame.beta;
            const double x = (double)frame.x_kinematic + cos(beta) * rho_x + sin(beta) * rho_z;
            const double z = (double)frame.z - sin(beta) * rho_x + cos(beta) * rho_z;
            double wx = 0.0, ws = 0.0, test;
            int a, found = -1;
            bs_shape_eval(&scene, (bs_real)x, phi, slope);
            for (k = 0; k < scene.n_modes; ++k) {
                wx += (double)phi[k] * (double)q[k];
                ws += (double)slope[k] * (double)q[k];
            }
            test = zeta * (z - wx - zeta * hh) - hh * ws * ws;
            for (a = 0; a < set.count; ++a)
                if (set.id[a] == corner)
                    found = a;
            /* within the expansions' error of touching, or the rounding of the gap's terms */
            if (fabs(test) < 1e-6 * play + 8.0 * SUPPORT_EPS * (fabs(z) + hh)) {
                ++borderline;
                continue;
            }
            assert_int_equal(found >= 0, test < 0.0);
            if (found >= 0) { /* the normal row's modal part: -n_z phi_k + (-n_x a1 - n_z a2 + g_T) phi_k' */
                const double cos_alpha = 1.0 / sqrt(1.0 + ws * ws), sin_alpha = ws * cos_alpha;
                const double n_x = -zeta * sin_alpha, n_z = zeta * cos_alpha;
                const double t_x = -zeta * cos_alpha, t_z = -zeta * sin_alpha;
                const double d_x = zeta * hh * ws, d_z = z - wx - zeta * hh;
                const double a1 = zeta * hh * (ws * ws - 1.0), a2 = -zeta * hh * ws;
                const double coef_s = -n_x * a1 - n_z * a2 + (BS_WITH_FRICTION ? t_x * d_x + t_z * d_z : 0.0);
                ++active;
                for (k = 0; k < scene.n_modes; ++k) { /* the set's W_N,k: coef[0] phi_k + coef[1] phi'_k */
                    const double direct = -n_z * (double)phi[k] + coef_s * (double)slope[k];
                    const double found_w = (double)set.beam_coef[found][0][0] * (double)set.phi[found][k]
                                           + (double)set.beam_coef[found][0][1] * (double)set.slope[found][k];
                    worst_w = fmax(worst_w, fabs(found_w - direct));
                    scale_w = fmax(scale_w, fabs(direct));
                }
            }
        }
    }
    print_message("%s, %s: 200000 poses, %ld corners in contact agree, %ld within rounding or 1e-6 of the play of "
                  "touching; force directions within %.2e of the direct ones (relative)\n",
                  path, BS_REAL_NAME, active, borderline, worst_w / scale_w);
    assert_true(active > 100000);
    assert_true(worst_w <= (BS_REAL_FLOAT ? 1e-5 : 1e-9) * scale_w);
}

static void test_detection_from_expansions_matches_direct_shapes(void **state)
{
    (void)state;
    check_detection_against_direct_shapes("configs/fig6_1mode.ini", 3e-3);
    check_detection_against_direct_shapes("configs/fig6.ini", 3e-3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_slider_dropped_on_rigid_beam_rebounds_with_e_n),
        cmocka_unit_test(test_slider_thrown_up_rebounds_from_bottom_corners),
        cmocka_unit_test(test_tilted_beam_holds_slider_when_mu_above_tan_tilt),
        cmocka_unit_test(test_tilted_beam_lets_slider_slide_when_mu_below_tan_tilt),
        cmocka_unit_test(test_slider_thrown_at_clamp_bounces_off_end_stop),
        cmocka_unit_test(test_slider_started_at_clamp_stays_on_beam),
        cmocka_unit_test(test_detection_from_expansions_matches_direct_shapes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
