/* test_observer.c - the twin's observer (core/src/bs_observer.c) and its
 * design (host/lib/twin/observer_design.c) on fig6: a plant (a bs_sim stepped
 * under the scene's excitation) and a twin (a bs_sim stepped by the observer
 * on the plant's base acceleration and w(4L/7), with white noise 40 dB below
 * their RMS) run side by side. The thresholds are the figures of docs/twin.md
 * ("Observer") with margin: the runs are chaotic, and float and double take
 * different trajectories. */
#include "support.h"

#include <math.h>
#include <string.h>
#include "bs_lockin.h"
#include "bs_observer.h"
#include "observer_design.h"

#define SIGNAL_NOISE 7.5e-6 /* 40 dB below the RMS of fig6's w(4L/7) over 60 s [m] */
#define ACCEL_NOISE 0.099   /* 40 dB below the RMS of its base acceleration [m/s^2] */

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_observer_gains gains;
static bs_sim plant, twin;
static bs_observer obs;

/* fig6 and its observer's constants (designed once: the response map takes
 * two PCS sweeps). */
static void load_fig6(void)
{
    static int designed;
    char err[256];
    observer_design_options o = observer_design_defaults(SIGNAL_NOISE);
    support_load("configs/fig6.ini", &file, &scene, &model);
    if (designed)
        return;
    o.accel_noise = ACCEL_NOISE;
    if (observer_design(&file, &model, &scene, &o, &gains, err, sizeof err) != 0)
        fail_msg("%s", err);
    designed = 1;
}

/* The lock-in (core/src/bs_lockin.c) on a response of known amplitude and
 * phase: y = A cos(Omega t + phi) against a = a_0 cos(Omega t), each with
 * white noise 40 dB under its RMS, sampled at fig6's dt = 2e-5 s, tau =
 * 0.1 s, at 100, 124 and 130 Hz and phi from 14 to 166 degrees every 8 (the
 * phases the observer meets: the low branches near 0 and 180 degrees, the
 * high one near 150). After 1.5 s |H| is A within 0.1 %, its phase phi
 * within 0.05 degrees (0.1 % of |H| across), and the frequency kappa / 2 pi
 * within 1e-4 of Omega / 2 pi. Before 0.8.0 the leaky integral itself was the quadrature:
 * |H| off by up to +1.08 % (142 degrees at 100 Hz; +0.90 % at 150 degrees,
 * 124 Hz), the phase by up to -1.2 degrees, the frequency 2.6e-4 to 3.6e-4
 * low. All phases are demodulated against one reference run per frequency. */
static void test_lockin_measures_every_phase_without_bias(void **state)
{
    enum { PHASES = 20 };
    const double frequencies[] = { 100.0, 124.0, 130.0 };
    const double dt = 2e-5, tau = 0.1, accel = 14.0, response = 8.4e-5; /* fig6's high branch [m/(m/s^2)] */
    const long steps = lround(1.5 / dt);
    static bs_lowpass2 with_a[PHASES], with_b[PHASES];
    double cos_phi[PHASES], sin_phi[PHASES], worst_abs = 0.0, worst_phase = 0.0, worst_frequency = 0.0;
    size_t f;
    int i;
    (void)state;
    for (i = 0; i < PHASES; ++i) {
        cos_phi[i] = cos((14.0 + 8.0 * i) * 3.141592653589793 / 180.0);
        sin_phi[i] = sin((14.0 + 8.0 * i) * 3.141592653589793 / 180.0);
    }
    for (f = 0; f < sizeof frequencies / sizeof frequencies[0]; ++f) {
        const double omega = 6.283185307179586 * frequencies[f];
        bs_lockin_reference reference;
        bs_lockin_basis basis;
        long k;
        support_gaussian_seed(0x9e3779b97f4a7c15u);
        bs_lockin_reference_init(&reference, (bs_real)dt, (bs_real)tau);
        memset(with_a, 0, sizeof with_a);
        memset(with_b, 0, sizeof with_b);
        for (k = 1; k <= steps; ++k) {
            const double c = cos(omega * (double)k * dt), sn = sin(omega * (double)k * dt);
            const double y_noise = response * accel / (100.0 * sqrt(2.0)) * support_gaussian();
            const bs_real a = (bs_real)(accel * c + accel / (100.0 * sqrt(2.0)) * support_gaussian());
            const bs_real b = bs_lockin_reference_step(&reference, a);
            for (i = 0; i < PHASES; ++i) {
                const bs_real y = (bs_real)(response * accel * (cos_phi[i] * c - sin_phi[i] * sn) + y_noise);
                bs_lowpass2_step(&with_a[i], y * a, reference.alpha);
                bs_lowpass2_step(&with_b[i], y * b, reference.alpha);
            }
        }
        assert_int_equal(bs_lockin_basis_of(&reference, &basis), 1);
        worst_frequency = fmax(worst_frequency, fabs((double)basis.kappa / omega - 1.0));
        for (i = 0; i < PHASES; ++i) {
            const double phi = 14.0 + 8.0 * i;
            bs_real re, im;
            double abs_error, phase_error;
            bs_lockin_response(&basis, &with_a[i], &with_b[i], &re, &im);
            abs_error = hypot((double)re, (double)im) / response - 1.0;
            phase_error = atan2((double)im, (double)re) * 180.0 / 3.141592653589793 - phi;
            worst_abs = fmax(worst_abs, fabs(abs_error));
            worst_phase = fmax(worst_phase, fabs(phase_error));
            if (fabs(abs_error) > 1e-3 || fabs(phase_error) > 0.05)
                print_message("%g Hz, phi %g deg: |H| off by %+.4f %%, phase by %+.4f deg\n", frequencies[f], phi,
                              100.0 * abs_error, phase_error);
        }
    }
    print_message("lock-in over 14-166 deg at 100-130 Hz: |H| within %.4f %%, phase within %.4f deg, frequency "
                  "within %.2g\n", 100.0 * worst_abs, worst_phase, worst_frequency);
    assert_true(worst_abs < 1e-3);
    assert_true(worst_phase < 0.05);
    assert_true(worst_frequency < 1e-4);
}

/* What a side-by-side run measured. */
typedef struct pair_result {
    double error_rms;    /* RMS of w_plant - w_twin over the window [m] */
    double s_error;      /* s_twin - s_plant at the end */
    double s_error_max;  /* largest |s_twin - s_plant| over the window */
    bs_observer_estimate last;
} pair_result;

/* Steps plant and twin (already initialised; obs on twin) for `seconds`;
 * the window is [from, seconds]. Noise: noise_factor times SIGNAL_NOISE on
 * w(4L/7), ACCEL_NOISE on the base acceleration if noise_factor > 0. */
static void run_pair(double seconds, double from, double noise_factor, pair_result *r)
{
    const long steps = lround(seconds / (double)scene.dt), first = lround(from / (double)scene.dt);
    double sum = 0.0;
    long k;
    memset(r, 0, sizeof *r);
    support_gaussian_seed(0x9e3779b97f4a7c15u);
    for (k = 1; k <= steps; ++k) {
        double a, y, s_error;
        assert_int_equal(bs_sim_step(&plant), BS_OK);
        a = (double)bs_sim_base_acceleration(&plant) + (noise_factor > 0.0) * ACCEL_NOISE * support_gaussian();
        y = (double)bs_sim_sensor(&plant) + noise_factor * SIGNAL_NOISE * support_gaussian();
        assert_int_equal(bs_observer_step(&obs, &twin, (bs_real)a, (bs_real)y), BS_OK);
        if (k < first)
            continue;
        {
            const double w = (double)bs_sim_sensor(&plant) - (double)bs_sim_sensor(&twin);
            sum += w * w;
        }
        s_error = (double)bs_sim_position(&twin) - (double)bs_sim_position(&plant);
        r->s_error_max = fmax(r->s_error_max, fabs(s_error));
        r->s_error = s_error;
    }
    r->error_rms = sqrt(sum / (double)(steps - first + 1));
    assert_int_equal(bs_observer_get(&obs, &r->last), BS_OK);
}

/* Plant from rest at s0 = 0.3; the twin at twin_s0, with options. */
static void start_pair(double twin_s0, const bs_observer_options *options)
{
    assert_int_equal(bs_sim_init(&plant, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, (bs_real)twin_s0), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &gains, options), BS_OK);
}

/* A twin whose beam state is wrong (it was shaken for 0.1 s while the plant
 * rested) follows the plant's w(4L/7) within 0.1 s with the correction; left
 * open loop, it is still off by more than a third of its initial error
 * after 0.2 s (the beam's modal damping is 0.1 %: ~1.3 s at 124 Hz). */
static void test_beam_correction_converges_faster_than_open_loop(void **state)
{
    bs_observer_options options = bs_observer_defaults();
    pair_result corrected, open_loop, initial;
    int closed;
    (void)state;
    load_fig6();
    options.correct_position = 0;
    for (closed = 1; closed >= 0; --closed) {
        pair_result *r = closed ? &corrected : &open_loop;
        long k;
        options.correct_beam = closed;
        start_pair(0.3, &options);
        for (k = 0; k < 5000; ++k) /* the wrong beam state: 0.1 s of shaking */
            assert_int_equal(bs_sim_step(&twin), BS_OK);
        assert_int_equal(bs_observer_init(&obs, &twin, &gains, &options), BS_OK);
        run_pair(0.02, 0.0, 0.0, &initial);
        run_pair(0.2, 0.1, 1.0, r);
        print_message("beam %s: w error %.3g m in the first 0.02 s, %.3g m over [0.12, 0.22] s\n",
                      closed ? "corrected" : "open loop", initial.error_rms, r->error_rms);
        if (!closed)
            assert_true(r->error_rms > initial.error_rms / 3.0);
    }
    /* the corrected twin sits at the noise floor (1.0-1.4 sigma, both precisions
     * and every build since 0.8.0; the open loop is 4-5 times above it) */
    assert_true(corrected.error_rms < open_loop.error_rms / 3.0);
    assert_true(corrected.error_rms < 2.0 * SIGNAL_NOISE);
}

/* L_q(s) and L_u(s) of the gain schedule at s, interpolated here in double
 * (held beyond its ends), and the size of the two points' gains (what the
 * interpolation in the precision rounds against). */
static void schedule_at(double s, double *gain_q, double *gain_u, double *size_q, double *size_u)
{
    const int last = gains.gain_count - 1;
    int i = 0, k;
    double t;
    if (s < (double)gains.gain_s[0])
        s = (double)gains.gain_s[0];
    if (s > (double)gains.gain_s[last])
        s = (double)gains.gain_s[last];
    while (i < last - 1 && s > (double)gains.gain_s[i + 1])
        ++i;
    t = (s - (double)gains.gain_s[i]) / ((double)gains.gain_s[i + 1] - (double)gains.gain_s[i]);
    for (k = 0; k < scene.n_modes; ++k) {
        const double q0 = (double)gains.gain_q[i][k], q1 = (double)gains.gain_q[i + 1][k];
        const double u0 = (double)gains.gain_u[i][k], u1 = (double)gains.gain_u[i + 1][k];
        gain_q[k] = q0 + t * (q1 - q0);
        gain_u[k] = u0 + t * (u1 - u0);
        size_q[k] = fabs(q0) + fabs(q1);
        size_u[k] = fabs(u0) + fabs(u1);
    }
}

/* The beam correction is L(s) e with L interpolated in the gain schedule at
 * the twin's s, wherever the slider is and however it got there: one
 * observer visits positions in every interval of fig6's schedule, forward,
 * back, on a knot and beyond both ends (the observer keeps the interval of
 * the last step and enters another only when s leaves it), and each
 * sample's change of q and u, against a sim stepped alike without the
 * observer, is L_q e and L_u e as this test interpolates them. */
static void test_beam_correction_follows_the_gain_schedule(void **state)
{
    bs_observer_options options = bs_observer_defaults();
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES], slider[3], velocity[3];
    const int last = gains.gain_count - 1;
    int visit, k;
    (void)state;
    load_fig6();
    options.correct_position = 0;
    start_pair(0.3, &options);
    for (k = 0; k < 2000; ++k) /* a beam in motion */
        assert_int_equal(bs_sim_step(&twin), BS_OK);
    assert_int_equal(bs_sim_get_state(&twin, q, u, slider, velocity), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &gains, &options), BS_OK);
    for (visit = 0; visit < 4 * last + 4; ++visit) {
        /* intervals 0, last-1, 1, last-2, ... a third of the way in, then two
         * thirds; then a knot, both ends and beyond them */
        const int i = visit % 2 ? last - 1 - (visit / 2) % last : (visit / 2) % last;
        double s = (double)gains.gain_s[i] + (visit / (2 * last) + 1) / 3.0
                                                  * ((double)gains.gain_s[i + 1] - (double)gains.gain_s[i]);
        double gain_q[BS_MAX_MODES], gain_u[BS_MAX_MODES], size_q[BS_MAX_MODES], size_u[BS_MAX_MODES], e;
        bs_real q_twin[BS_MAX_MODES], u_twin[BS_MAX_MODES], q_alone[BS_MAX_MODES], u_alone[BS_MAX_MODES];
        bs_real scratch[6], prediction;
        bs_observer_estimate estimate;
        int aligned;
        if (visit >= 4 * last)
            s = visit == 4 * last     ? (double)gains.gain_s[last / 2]
                : visit == 4 * last + 1 ? 0.0
                : visit == 4 * last + 2 ? (double)gains.gain_s[last]
                                        : 1.0;
        if (s < (double)scene.stop_min / (double)scene.length)
            s = (double)scene.stop_min / (double)scene.length;
        if (s > (double)scene.stop_max / (double)scene.length)
            s = (double)scene.stop_max / (double)scene.length;
        slider[0] = (bs_real)(s * (double)scene.length);
        /* the twin and, alongside, the same sim without the observer: both
         * fresh (no warm start of their own) in the same state */
        assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
        assert_int_equal(bs_sim_set_state(&twin, q, u, slider, velocity), BS_OK);
        assert_int_equal(bs_sim_init(&plant, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
        assert_int_equal(bs_sim_set_state(&plant, q, u, slider, velocity), BS_OK);
        assert_int_equal(bs_sim_step_measured(&plant, BS_R(1.0)), BS_OK);
        /* the twin's prediction of this sample (its signal latency steps ago,
         * or the step's own), and a measurement 2 sigma of noise from it:
         * inside the outlier gate */
        aligned = (obs.head + 1) % (BS_OBSERVER_MAX_LATENCY + 1) - gains.latency;
        if (aligned < 0)
            aligned += BS_OBSERVER_MAX_LATENCY + 1;
        prediction = gains.latency == 0 ? bs_sim_sensor(&plant) : obs.past_signal[aligned];
        assert_int_equal(bs_observer_step(&obs, &twin, BS_R(1.0), prediction + (bs_real)(2.0 * SIGNAL_NOISE)), BS_OK);
        assert_int_equal(bs_observer_get(&obs, &estimate), BS_OK);
        assert_int_equal(estimate.outliers, 0);
        e = (double)estimate.innovation;
        assert_true(fabs(e - 2.0 * SIGNAL_NOISE) < 0.01 * SIGNAL_NOISE);
        schedule_at((double)bs_sim_position(&plant), gain_q, gain_u, size_q, size_u);
        assert_int_equal(bs_sim_get_state(&twin, q_twin, u_twin, scratch, scratch + 3), BS_OK);
        assert_int_equal(bs_sim_get_state(&plant, q_alone, u_alone, scratch, scratch + 3), BS_OK);
        for (k = 0; k < scene.n_modes; ++k) {
            /* q + dq rounds to half an ulp of the sum; the interpolation in
             * the precision to a few ulps of the two points' gains */
            const double ulp = BS_REAL_FLOAT ? 6e-8 : 1.2e-16;
            const double dq = (double)q_twin[k] - (double)q_alone[k], du = (double)u_twin[k] - (double)u_alone[k];
            if (fabs(dq - gain_q[k] * e) > 4.0 * ulp * (fabs((double)q_twin[k]) + size_q[k] * fabs(e))
                || fabs(du - gain_u[k] * e) > 4.0 * ulp * (fabs((double)u_twin[k]) + size_u[k] * fabs(e)))
                fail_msg("visit %d at s = %.6f, mode %d: dq %.9g against L_q e %.9g, du %.9g against L_u e %.9g",
                         visit, s, k + 1, dq, gain_q[k] * e, du, gain_u[k] * e);
        }
    }
}

/* A twin started 0.05 L from the plant (0.35 against 0.3) is brought back:
 * within 0.01 over [10, 12] s, where the open-loop twin is further off. */
static void test_position_tracker_recovers_a_twin_started_off(void **state)
{
    bs_observer_options options = bs_observer_defaults();
    pair_result tracked, open_loop;
    (void)state;
    load_fig6();
    start_pair(0.35, &options);
    run_pair(12.0, 10.0, 1.0, &tracked);
    options.correct_beam = options.correct_position = 0;
    start_pair(0.35, &options);
    run_pair(12.0, 10.0, 1.0, &open_loop);
    print_message("s_twin - s_plant over [10, 12] s: tracked max %.4f (end %.4f, s_sigma %.4f), open loop max %.4f\n",
                  tracked.s_error_max, tracked.s_error, (double)tracked.last.s_sigma, open_loop.s_error_max);
    assert_true(tracked.s_error_max <= 0.01);
    assert_true(open_loop.s_error_max > tracked.s_error_max);
    assert_true((double)tracked.last.s_sigma < 0.01);
}

/* Confidence follows the signal-to-noise ratio: at 40 dB s_sigma is small;
 * with the response buried 20 dB under the noise s_sigma exceeds the hold
 * threshold and s is left alone. */
static void test_confidence_is_low_where_the_response_is_tiny(void **state)
{
    static bs_observer_gains buried;
    bs_observer_options options = bs_observer_defaults();
    pair_result clear, noisy;
    (void)state;
    load_fig6();
    options.correct_beam = 0;
    start_pair(0.3, &options);
    run_pair(3.0, 2.0, 1.0, &clear);
    buried = gains;
    buried.noise = (bs_real)(1000.0 * SIGNAL_NOISE);
    assert_int_equal(bs_sim_init(&plant, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &buried, &options), BS_OK);
    run_pair(3.0, 2.0, 1000.0, &noisy);
    print_message("s_sigma: %.4g at 40 dB, %.4g at -20 dB\n", (double)clear.last.s_sigma,
                  (double)noisy.last.s_sigma);
    assert_true((double)clear.last.s_sigma < 0.01);
    assert_true(noisy.last.s_sigma > options.sigma_hold);
}

/* A measurement or base acceleration that is not finite is refused and
 * changes nothing, in the observer or in the twin. */
static void test_nan_measurement_is_refused_without_change(void **state)
{
    static bs_observer before;
    bs_observer_estimate e_before, e_after;
    uint32_t hash;
    int k;
    (void)state;
    load_fig6();
    start_pair(0.3, NULL);
    for (k = 0; k < 100; ++k)
        assert_int_equal(bs_observer_step(&obs, &twin, BS_R(1.0), BS_R(1e-6)), BS_OK);
    before = obs;
    hash = bs_sim_hash(&twin);
    assert_int_equal(bs_observer_get(&obs, &e_before), BS_OK);
    assert_int_equal(bs_observer_step(&obs, &twin, BS_R(1.0), (bs_real)NAN), BS_E_ARGUMENT);
    assert_int_equal(bs_observer_step(&obs, &twin, BS_R(1.0), (bs_real)INFINITY), BS_E_ARGUMENT);
    assert_int_equal(bs_observer_step(&obs, &twin, (bs_real)NAN, BS_R(1e-6)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_hash(&twin), hash);
    assert_int_equal(bs_observer_get(&obs, &e_after), BS_OK);
    assert_memory_equal(&e_before, &e_after, sizeof e_before);
    assert_memory_equal(&before, &obs, sizeof obs);
    assert_int_equal(bs_observer_step(&obs, &twin, BS_R(1.0), BS_R(1e-6)), BS_OK);
}

/* Sensor glitches (docs/twin.md, "Outliers"): a sample of 1e10 m in the
 * middle of a run is skipped, counted and flagged, the twin steps on
 * without it and stays with the plant; the same sample as the very first
 * one, before the gate's scale knows anything, would have thrown the slider
 * off the beam through the correction: skipped too. The flag clears after
 * one lock-in time. Another sim than the observer's is refused. */
static void test_outliers_are_skipped_counted_and_flagged(void **state)
{
    static bs_sim other;
    bs_observer_estimate e;
    pair_result before, after;
    bs_real slider[3];
    uint32_t hash;
    (void)state;
    load_fig6();
    start_pair(0.3, NULL);
    run_pair(1.0, 0.5, 1.0, &before);
    assert_int_equal(before.last.outliers, 0);
    assert_int_equal(bs_sim_step(&plant), BS_OK);
    assert_int_equal(bs_observer_step(&obs, &twin, bs_sim_base_acceleration(&plant), BS_R(1e10)), BS_OK);
    assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
    assert_int_equal(e.outliers, 1);
    assert_int_equal(e.health, BS_OBSERVER_HEALTH_OUTLIERS);
    assert_true((double)e.innovation > 1e9);
    run_pair(0.05, 0.0, 1.0, &after);
    assert_int_equal(after.last.health, BS_OBSERVER_HEALTH_OUTLIERS); /* within 0.1 s of it */
    run_pair(0.5, 0.0, 1.0, &after);
    print_message("a glitch of 1e10 m: s_twin - s_plant %.2g (max %.2g) over the next 0.5 s, w error %.3g m "
                  "(%.3g before)\n", after.s_error, after.s_error_max, after.error_rms, before.error_rms);
    assert_int_equal(after.last.outliers, 1);
    assert_int_equal(after.last.health, 0);
    assert_true(after.s_error_max < 0.005);
    assert_true(after.error_rms < 2.0 * before.error_rms);

    start_pair(0.3, NULL); /* the glitch first */
    assert_int_equal(bs_sim_step(&plant), BS_OK);
    assert_int_equal(bs_observer_step(&obs, &twin, bs_sim_base_acceleration(&plant), BS_R(1e10)), BS_OK);
    assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
    assert_int_equal(e.outliers, 1);
    assert_int_equal(bs_sim_get_state(&twin, NULL, NULL, slider, NULL), BS_OK);
    assert_true(fabs((double)slider[0] / (double)scene.length - 0.3) < 1e-4);
    run_pair(0.2, 0.1, 1.0, &after);
    assert_int_equal(after.last.outliers, 1);
    assert_true(after.error_rms < 3.0 * SIGNAL_NOISE);
    {   /* a gate wide open: the state check alone stands between the
         * correction and a slider thrown off the beam (x_C / L ~ 7e7) */
        bs_observer_options open = bs_observer_defaults();
        open.outlier_gate = BS_R(1e18);
        start_pair(0.3, &open);
        assert_int_equal(bs_sim_step(&plant), BS_OK);
        assert_int_equal(bs_observer_step(&obs, &twin, bs_sim_base_acceleration(&plant), BS_R(1e10)), BS_OK);
        assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
        assert_int_equal(e.outliers, 1);
        assert_int_equal(bs_sim_get_state(&twin, NULL, NULL, slider, NULL), BS_OK);
        assert_true(fabs((double)slider[0] / (double)scene.length - 0.3) < 1e-4);
    }

    assert_int_equal(bs_sim_init(&other, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    hash = bs_sim_hash(&other);
    assert_int_equal(bs_observer_step(&obs, &other, BS_R(1.0), BS_R(1e-6)), BS_E_ARGUMENT);
    assert_int_equal(bs_observer_predict(&obs, &other, BS_R(1.0)), BS_E_ARGUMENT);
    assert_int_equal(bs_sim_hash(&other), hash);
}

/* A lost measurement (bs_observer_predict): the twin runs open loop, bit
 * for bit as bs_sim_step_measured would step it, the lock-in is not fed,
 * and the delay line moves on, so that the next measurement meets the
 * prediction of its own time (here with a latency of 3 steps). A base
 * acceleration that is not finite is refused and changes nothing. */
static void test_predict_steps_open_loop_and_keeps_the_delay_line(void **state)
{
    static bs_observer_gains late;
    static bs_sim reference;
    static bs_observer before;
    static unsigned char saved[BS_CHECKPOINT_SIZE];
    bs_real w[64];
    bs_lowpass2 lockin;
    bs_observer_estimate e;
    int k;
    (void)state;
    load_fig6();
    late = gains;
    late.latency = 3;
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_init(&reference, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &late, NULL), BS_OK);
    for (k = 0; k < 20; ++k) /* a measured start, so that the lock-in holds something */
        assert_int_equal(bs_observer_step(&obs, &twin, BS_R(10.0), BS_R(1e-6)), BS_OK);
    assert_int_equal(bs_sim_save(&twin, saved, sizeof saved), BS_OK); /* the reference: the twin's copy */
    assert_int_equal(bs_sim_restore(&reference, saved, sizeof saved), BS_OK);
    lockin = obs.meas_a;
    for (k = 0; k < 40; ++k) {
        const bs_real a = (bs_real)(14.0 * cos(0.05 * k));
        assert_int_equal(bs_observer_predict(&obs, &twin, a), BS_OK);
        assert_int_equal(bs_sim_step_measured(&reference, a), BS_OK);
        w[k] = bs_sim_sensor(&reference);
        assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
        assert_true(e.innovation == BS_R(0.0));
    }
    assert_int_equal(bs_sim_hash(&twin), bs_sim_hash(&reference));
    assert_memory_equal(&lockin, &obs.meas_a, sizeof lockin);
    before = obs;
    assert_int_equal(bs_observer_predict(&obs, &twin, (bs_real)NAN), BS_E_ARGUMENT);
    assert_memory_equal(&before, &obs, sizeof obs);
    assert_int_equal(bs_sim_hash(&twin), bs_sim_hash(&reference));
    assert_int_equal(bs_observer_step(&obs, &twin, BS_R(1.0), BS_R(2e-6)), BS_OK);
    assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
    assert_true(e.prediction == w[40 - 3]); /* the twin's signal 3 steps before this 41st step */
}

static void test_init_refuses_what_does_not_fit(void **state)
{
    static bs_observer_gains bad;
    static bs_observer unready;
    bs_observer_options options = bs_observer_defaults();
    bs_observer_estimate e;
    (void)state;
    load_fig6();
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_observer_init(NULL, &twin, &gains, NULL), BS_E_NULL);
    assert_int_equal(bs_observer_init(&obs, &twin, NULL, NULL), BS_E_NULL);
    memset(&unready, 0, sizeof unready);
    assert_int_equal(bs_observer_step(&unready, &twin, BS_R(0.0), BS_R(0.0)), BS_E_UNINITIALISED);
    assert_int_equal(bs_observer_get(&unready, &e), BS_E_UNINITIALISED);
    bad = gains;
    bad.n_modes = 1; /* another scene's */
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad = gains;
    bad.signal = BS_SIGNAL_VOLTAGE; /* fig6 has no transducer */
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad = gains;
    bad.latency = BS_OBSERVER_MAX_LATENCY + 1;
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad = gains;
    bad.gain_u[3][0] = (bs_real)NAN;
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad = gains;
    bad.map_count = 0;
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad.map_count = BS_OBSERVER_MAPS + 1;
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad = gains;
    bad.map_count = 2; /* a second map at the same frequency: not ascending */
    bad.map_frequency[1] = bad.map_frequency[0];
    bad.map_accel[1] = bad.map_accel[0];
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad.map_friction[1] = BS_R(2.0) * bad.map_friction[0]; /* ... unless it is a map at another mu */
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_OK);
    bad.map_accel[1] = BS_R(2.0) * bad.map_accel[0]; /* of the same excitation */
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad.map_accel[1] = bad.map_accel[0];
    bad.map_friction[1] = (bs_real)NAN;
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    bad.map_friction[1] = bad.map_friction[0];
    bad.map_frequency[1] = BS_R(1.5) * bad.map_frequency[0];
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_OK);
    bad.table_soft[1][7] = (bs_real)NAN;
    assert_int_equal(bs_observer_init(&obs, &twin, &bad, NULL), BS_E_ARGUMENT);
    options.lockin_time = BS_R(0.0);
    assert_int_equal(bs_observer_init(&obs, &twin, &gains, &options), BS_E_ARGUMENT);
    assert_int_equal(bs_observer_step(&obs, &twin, BS_R(0.0), BS_R(0.0)), BS_E_UNINITIALISED);
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_PCS, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &gains, NULL), BS_E_ARGUMENT);
}

/* The s the observer measures, on the plant its map was made from: a PCS
 * plant taken up the stiff branch from the clamp (40 periods at each point
 * of the table: enough to stay on the branch) and held at the point nearest
 * s = 0.33, where fig6's slider settles on its high branch (phase ~150
 * degrees), as long as the design holds and records there. The twin
 * observes it (40 dB noise) with its own s left alone; what it measures,
 * s_twin + s_error, averaged over [1, 2] s, is that point within 0.0005
 * (issue 30's target for the nominal plant). Before 0.8.0 it read +0.0023:
 * +0.0016 from the lock-in (|H| 0.9 % high at 150 degrees), +0.0007 from
 * the map (60 periods held at each point were too few for the high branch
 * to settle: |H| 0.4 % low). */
static void test_measured_s_on_the_maps_own_plant_is_unbiased(void **state)
{
    const observer_design_options design = observer_design_defaults(SIGNAL_NOISE);
    bs_observer_options options = bs_observer_defaults();
    double s_point, sum = 0.0;
    long k, count = 0;
    int j, point = 0;
    (void)state;
    load_fig6();
    for (j = 1; j < gains.table_count; ++j)
        if (fabs((double)gains.table_s[j] - 0.33) < fabs((double)gains.table_s[point] - 0.33))
            point = j;
    s_point = (double)gains.table_s[point];
    assert_int_equal(bs_sim_init(&plant, &scene, BS_MODEL_PCS, gains.table_s[0]), BS_OK);
    for (j = 0; j <= point; ++j) {
        const int hold = j < point ? 40 : design.map_hold + design.map_record;
        int periods = 0;
        assert_int_equal(bs_sim_set_pcs_position(&plant, gains.table_s[j]), BS_OK);
        while (periods < hold) {
            const bs_real phase = bs_sim_phase(&plant);
            assert_int_equal(bs_sim_step(&plant), BS_OK);
            periods += bs_sim_phase(&plant) < phase;
        }
    }
    options.correct_position = 0;
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, gains.table_s[point]), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &gains, &options), BS_OK);
    support_gaussian_seed(0x9e3779b97f4a7c15u);
    for (k = 1; k <= lround(2.0 / (double)scene.dt); ++k) {
        bs_observer_estimate e;
        double a, y;
        assert_int_equal(bs_sim_step(&plant), BS_OK);
        a = (double)bs_sim_base_acceleration(&plant) + ACCEL_NOISE * support_gaussian();
        y = (double)bs_sim_sensor(&plant) + SIGNAL_NOISE * support_gaussian();
        assert_int_equal(bs_observer_step(&obs, &twin, (bs_real)a, (bs_real)y), BS_OK);
        if ((double)k * (double)scene.dt < 1.0 || k % 16 != 0)
            continue;
        assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
        assert_true(e.s_sigma < options.sigma_hold); /* the map's excitation, its stiff branch */
        sum += (double)e.s + (double)e.s_error - s_point;
        count += 1;
    }
    print_message("PCS plant at s = %.4f on the stiff branch: measured s - s %+.5f (mean over [1, 2] s)\n", s_point,
                  sum / (double)count);
    assert_true(fabs(sum / (double)count) < 5e-4);
}

/* |H|(s) of map 0's stiff branch, linear between its points (as the
 * observer inverts it). */
static double stiff_response(double s)
{
    int j = 0;
    while (j + 2 < gains.table_count && (double)gains.table_s[j + 1] < s)
        ++j;
    return (double)gains.table_stiff[0][j]
           + (s - (double)gains.table_s[j]) / ((double)gains.table_s[j + 1] - (double)gains.table_s[j])
                 * ((double)gains.table_stiff[0][j + 1] - (double)gains.table_stiff[0][j]);
}

/* One sample of a synthetic plant on map 0's stiff branch at s_plant (|H|
 * of the map, 150 degrees, the map's excitation; no noise) to the observer,
 * with the twin's x_C set to s_twin first (its own drift overridden). */
static void synthetic_sample(long k, double s_plant, double s_twin)
{
    const double t = (double)k * (double)scene.dt, phase = 150.0 * 3.141592653589793 / 180.0;
    const double omega = 6.283185307179586 * (double)gains.map_frequency[0];
    const double a = (double)gains.map_accel[0] * cos(omega * t);
    const double y = stiff_response(s_plant) * (double)gains.map_accel[0] * cos(omega * t + phase);
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES], slider[3], velocity[3];
    assert_int_equal(bs_sim_get_state(&twin, q, u, slider, velocity), BS_OK);
    slider[0] = (bs_real)(s_twin * (double)scene.length);
    assert_int_equal(bs_sim_set_state(&twin, q, u, slider, velocity), BS_OK);
    assert_int_equal(bs_observer_step(&obs, &twin, (bs_real)a, (bs_real)y), BS_OK);
}

/* A twin on fig6's map, its position correction off, for synthetic_sample. */
static void start_synthetic(double s0)
{
    bs_observer_options options = bs_observer_defaults();
    load_fig6();
    assert_int_equal(gains.latency, 0); /* synthetic_sample's y is not delayed */
    options.correct_position = 0;
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, (bs_real)s0), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &gains, &options), BS_OK);
}

/* A climbing slider. The lock-in's two stages average the products over
 * the last ~2 tau, so a plant moving at ds/dt is measured 2 tau ds/dt
 * behind; the observer compares it with its twin's s delayed alike (its
 * own drift through the same stages). The plant at s(t) = 0.30 + v t with
 * v = 0.01 /s and the twin moved along the same s(t): the measured s,
 * s_twin + s_error, is s(t) within 0.0003 on average over [1, 2] s.
 * Without the delayed twin it read 2 tau v = 0.002 behind. */
static void test_measured_s_of_a_climbing_slider_is_not_behind(void **state)
{
    const double v = 0.01;
    double sum = 0.0;
    long k, count = 0;
    (void)state;
    start_synthetic(0.30);
    for (k = 1; k <= lround(2.0 / (double)scene.dt); ++k) {
        const double t = (double)k * (double)scene.dt, s = 0.30 + v * t;
        bs_observer_estimate e;
        synthetic_sample(k, s, s);
        if (t < 1.0 || k % 16 != 0)
            continue;
        assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
        assert_true(e.s_sigma < obs.options.sigma_hold);
        sum += (double)e.s + (double)e.s_error - s;
        count += 1;
    }
    print_message("climbing at %g /s on the stiff branch: measured s - s %+.5f (mean over [1, 2] s)\n", v,
                  sum / (double)count);
    assert_true(fabs(sum / (double)count) < 3e-4);
}

/* A twin state set from outside the observer (a re-synchronisation, a
 * restored checkpoint) is no drift of the plant's: the plant held at 0.30,
 * the twin moved from 0.30 to 0.31 at 1 s; 0.2 s later the s error is
 * the whole -0.01 within 0.0005. Taken for drift, the jump's lag would
 * still cancel 0.0041 of it (3 e^-2 of 0.01). */
static void test_a_state_set_from_outside_is_no_drift(void **state)
{
    bs_observer_estimate e;
    long k;
    (void)state;
    start_synthetic(0.30);
    for (k = 1; k <= lround(1.2 / (double)scene.dt); ++k)
        synthetic_sample(k, 0.30, (double)k * (double)scene.dt < 1.0 ? 0.30 : 0.31);
    assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
    print_message("twin moved from outside by +0.01: s error %+.5f 0.2 s later\n", (double)e.s_error);
    assert_true(e.s_sigma < obs.options.sigma_hold);
    assert_true(fabs((double)e.s_error + 0.01) < 5e-4);
}

/* Maps of one excitation at several mu follow the twin's mu: fig6's map at
 * mu 0.1, and at mu 0.3 the same map moved 0.01 up in s (|H|(s - 0.01)).
 * A plant at 0.30 on the first map, the twin beside it: the measured s
 * reads 0.30 with the twin at mu 0.1, 0.31 at 0.3 and beyond it (0.4: the
 * last map alone), and between them what the interpolated map gives at 0.2
 * (+0.005 to first order), each within 0.0005 after 1.2 s. */
static void test_maps_follow_the_twins_friction(void **state)
{
    static bs_observer_gains two;
    static const double mu[] = { 0.1, 0.2, 0.3, 0.4 }, shift[] = { 0.0, 0.005, 0.01, 0.01 };
    bs_observer_options options = bs_observer_defaults();
    int i, j;
    long k;
    (void)state;
    start_synthetic(0.30);
    two = gains;
    two.map_count = 2;
    two.map_frequency[1] = two.map_frequency[0];
    two.map_accel[1] = two.map_accel[0];
    two.map_friction[0] = BS_R(0.1);
    two.map_friction[1] = BS_R(0.3);
    for (j = 0; j < two.table_count; ++j) {
        two.table_stiff[1][j] = (bs_real)stiff_response((double)two.table_s[j] - 0.01);
        two.table_soft[1][j] = two.table_soft[0][j];
    }
    options.correct_position = 0;
    for (i = 0; i < 4; ++i) {
        bs_observer_estimate e;
        assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, BS_R(0.30)), BS_OK);
        assert_int_equal(bs_sim_set_contact_laws(&twin, (bs_real)mu[i], scene.e_n), BS_OK);
        assert_int_equal(bs_observer_init(&obs, &twin, &two, &options), BS_OK);
        for (k = 1; k <= lround(1.2 / (double)scene.dt); ++k)
            synthetic_sample(k, 0.30, 0.30);
        assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
        print_message("maps at mu 0.1 and 0.3 (moved +0.01), twin at mu %.1f: s error %+.5f\n", mu[i],
                      (double)e.s_error);
        assert_true(e.s_sigma < obs.options.sigma_hold);
        assert_true(fabs((double)e.s_error - shift[i]) < 5e-4);
    }
}

/* The jump hold: a plant whose response falls to 0.27 of itself at once
 * (fig6's stiff branch from s = 0.33 to 0.233; a jump to the low branch
 * falls to a few percent) at 1 s, the twin at 0.30. Without a hold the
 * lock-in's second stages, still holding the old response, are read as an
 * s between the two: 0.3 s after the fall the measured s is more than 0.01
 * from 0.233. With jump_hold 1 s, s stays unmeasured (s_sigma 1) from 0.2 s
 * to 1 s after the fall, and 3 s after it s is measured again, 0.233
 * within 0.002 (with or without the hold). */
static void test_a_falling_response_holds_the_s_correction(void **state)
{
    static const double hold[] = { 0.0, 1.0 };
    const double s_from = 0.33, s_to = 0.233;
    int i;
    (void)state;
    for (i = 0; i < 2; ++i) {
        bs_observer_options options = bs_observer_defaults();
        bs_observer_estimate e;
        double held = 1.0, reading = 0.0;
        long k;
        start_synthetic(0.30);
        options.correct_position = 0;
        options.jump_hold = (bs_real)hold[i];
        assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, BS_R(0.30)), BS_OK);
        assert_int_equal(bs_observer_init(&obs, &twin, &gains, &options), BS_OK);
        for (k = 1; k <= lround(4.0 / (double)scene.dt); ++k) {
            const double t = (double)k * (double)scene.dt;
            synthetic_sample(k, t < 1.0 ? s_from : s_to, 0.30);
            if (k % 16 != 0)
                continue;
            assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
            if (t >= 1.2 && t <= 2.0 && (double)e.s_sigma < held)
                held = (double)e.s_sigma;
            if (t >= 1.3 && reading == 0.0) /* the first update from 1.3 s on */
                reading = (double)e.s_sigma < 1.0 ? (double)(e.s + e.s_error) : -1.0;
        }
        assert_int_equal(bs_observer_get(&obs, &e), BS_OK);
        print_message("response falling at 1 s, jump_hold %.0f s: s_sigma at least %.3g over [1.2, 2] s, measured s "
                      "%.4f at 1.3 s (-1: not measured), %.4f at 4 s\n", hold[i], held, reading,
                      (double)(e.s + e.s_error));
        if (hold[i] > 0.0) {
            assert_true(held >= 1.0);
            assert_true(reading < 0.0);
        } else {
            assert_true(held < 1.0);
            assert_true(reading > 0.0 && fabs(reading - s_to) > 0.01);
        }
        assert_true((double)e.s_sigma < 1.0); /* measured again (its spread still wide after the jump in s) */
        assert_true(fabs((double)(e.s + e.s_error) - s_to) < 0.002);
    }
}

/* The design: finite gains, each taking a part of the innovation in (0, 1)
 * at the sensor (C K of a Kalman filter), and a response map on both
 * branches around fig6's turning point. */
static void test_design_gives_kalman_gains_and_a_map(void **state)
{
    int j, k, soft = 0;
    (void)state;
    load_fig6();
    for (j = 0; j < gains.gain_count; ++j) {
        double ck = 0.0;
        for (k = 0; k < gains.n_modes; ++k)
            ck += (double)scene.phi_sensor[k] * (double)gains.gain_q[j][k];
        assert_true(ck > 0.0 && ck < 1.0);
    }
    for (j = 0; j < gains.table_count; ++j) {
        assert_true(gains.table_stiff[0][j] > 0);
        soft += gains.table_soft[0][j] > 0;
    }
    assert_true(soft > gains.table_count / 3); /* the low branch beyond ~0.26 */
}

/* The ambient frequency moved: with the plant shaken at 110 Hz, fig6's own
 * map (124 Hz) does not apply and s is reported unknown, uncorrected; with
 * gains carrying a map at 110 Hz too, the twin started 0.05 L off is
 * brought back as at 124 Hz, and closer than with the single map. The 124 Hz map of the two is fig6's own.
 * A second design (two maps): 8 CPU-s, `make test-long` only. */
static void test_maps_at_a_moved_excitation(void **state)
{
    static bs_observer_gains two;
    bs_observer_options options = bs_observer_defaults();
    observer_design_options o = observer_design_defaults(SIGNAL_NOISE);
    pair_result single, tracked;
    char err[256];
    int j;
    (void)state;
    support_long_only();
    load_fig6();
    o.accel_noise = ACCEL_NOISE;
    o.map_count = 2;
    o.map_frequency[0] = 110.0;
    o.map_frequency[1] = (double)scene.frequency;
    if (observer_design(&file, &model, &scene, &o, &two, err, sizeof err) != 0)
        fail_msg("%s", err);
    assert_int_equal(two.map_count, 2);
    for (j = 0; j < two.table_count; ++j) {
        assert_true(two.table_stiff[1][j] == gains.table_stiff[0][j]);
        assert_true(two.table_soft[1][j] == gains.table_soft[0][j]);
    }
    start_pair(0.35, &options);
    assert_int_equal(bs_sim_set_excitation(&plant, BS_R(110.0), scene.base_accel), BS_OK);
    run_pair(12.0, 10.0, 1.0, &single);
    assert_int_equal(bs_sim_init(&plant, &scene, BS_MODEL_FREE, BS_R(0.3)), BS_OK);
    assert_int_equal(bs_sim_set_excitation(&plant, BS_R(110.0), scene.base_accel), BS_OK);
    assert_int_equal(bs_sim_init(&twin, &scene, BS_MODEL_FREE, BS_R(0.35)), BS_OK);
    assert_int_equal(bs_observer_init(&obs, &twin, &two, &options), BS_OK);
    run_pair(12.0, 10.0, 1.0, &tracked);
    print_message("at 110 Hz, s_twin - s_plant over [10, 12] s: 124 Hz map only: max %.4f, s_sigma %.3g, frequency "
                  "%.2f Hz; with a 110 Hz map: max %.4f, s_sigma %.4f\n", single.s_error_max,
                  (double)single.last.s_sigma, (double)single.last.frequency, tracked.s_error_max,
                  (double)tracked.last.s_sigma);
    assert_true(fabs((double)single.last.frequency - 110.0) < 0.5);
    assert_true(single.last.s_sigma > options.sigma_hold);
    assert_true(tracked.s_error_max <= 0.01);
    assert_true(single.s_error_max > 2.0 * tracked.s_error_max);
    assert_true(tracked.last.s_sigma < options.sigma_hold);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lockin_measures_every_phase_without_bias),
        cmocka_unit_test(test_design_gives_kalman_gains_and_a_map),
        cmocka_unit_test(test_measured_s_on_the_maps_own_plant_is_unbiased),
        cmocka_unit_test(test_measured_s_of_a_climbing_slider_is_not_behind),
        cmocka_unit_test(test_a_state_set_from_outside_is_no_drift),
        cmocka_unit_test(test_maps_follow_the_twins_friction),
        cmocka_unit_test(test_a_falling_response_holds_the_s_correction),
        cmocka_unit_test(test_init_refuses_what_does_not_fit),
        cmocka_unit_test(test_nan_measurement_is_refused_without_change),
        cmocka_unit_test(test_outliers_are_skipped_counted_and_flagged),
        cmocka_unit_test(test_predict_steps_open_loop_and_keeps_the_delay_line),
        cmocka_unit_test(test_beam_correction_converges_faster_than_open_loop),
        cmocka_unit_test(test_beam_correction_follows_the_gain_schedule),
        cmocka_unit_test(test_position_tracker_recovers_a_twin_started_off),
        cmocka_unit_test(test_confidence_is_low_where_the_response_is_tiny),
        cmocka_unit_test(test_maps_at_a_moved_excitation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
