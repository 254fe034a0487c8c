/* bs_observer.c - the digital twin corrected from measurements (docs/twin.md,
 * "Observer"; docs/model.md 10).
 *
 * Symbols -> variables. Per step k: a_k base_accel (mean base acceleration),
 * y_k measurement (w(4L/7) or patch voltage v), d = gains->latency (the
 * signal lags a_k by d steps), y^ the twin's own signal, w^ its w(4L/7).
 *
 * 1. Twin step: bs_sim_step_measured(sim, a_k).
 * 2. Alignment: ring buffers keep a, y^ and w^ of the last d steps; the
 *    measurement y_k is compared with y^_{k-d} and demodulated against
 *    a_{k-d} (the twin's prediction is delayed to meet the late signal).
 *    Innovation e = y_k - y^_{k-d}.
 * 3. Beam correction (output injection): q += L_q e, u += L_u e, v += L_v e,
 *    L = L(s) interpolated in the gain schedule at the twin's s. L = Phi^d K,
 *    K the steady-state Kalman gain of the linear modal model of the beam
 *    with the slider attached at s, at dt, and Phi its one-step transition
 *    (host/lib/observer_design.c): a measurement of the state d steps ago
 *    corrects the present state by the correction it asks for there,
 *    carried forward d steps. The slider is moved with the beam under it
 *    (correct_beam below), as the attached model assumes.
 * 4. Lock-in against a (core/src/bs_lockin.c; <x>: two first-order
 *    low-pass stages of time constant tau, alpha = dt / tau):
 *      b       <- (1 - dt/tau) b + dt a      leaky integral: a's quadrature
 *      b~      =  b - <b>                    (no offset)
 *      c       =  <a b~> / <a^2>             b~'s part in phase with a
 *      kappa^2 =  <a^2> / (<b~^2> - c <a b~>) ~ Omega^2: b~ - c a, orthogonal to a
 *      H_y     =  (<y a> - j kappa (<y b~> - c <y a>)) / <a^2>
 *    H_y is the response per unit base acceleration at the excitation, as a
 *    complex amplitude (y = Re(H_y A e^{j Omega t}) for a = A cos Omega t),
 *    exact for any phase (b~ itself lags a by less than 90 degrees).
 *    H_m of the measurement, H_t of the aligned prediction, H_w of the twin's
 *    w(4L/7): amplitude = |H_w| sqrt(2 <a^2>).
 * 5. Slider position, from a response map (host/lib/observer_design.c):
 *    |H|(s) of the twin's own model at the map's excitation, for the two
 *    branches a slider with play settles on (PCS sweeps from the clamp and
 *    from the centre). The branch is told by the sign of Re H_m: below the
 *    (hardened) resonance the response is opposite to a (Re H < 0, the
 *    "stiff" branch), above it in phase (Re H > 0, "soft"). On that branch
 *    the crossing of |H|(s) with |H_m| nearest to the twin's s is s_meas,
 *    and s_error = s_meas - s_twin (mirrored beyond s = 1/2: s and 1 - s
 *    respond alike, so the estimate follows the side the twin is on).
 *    s_meas is that of the lock-in's products, which lag the plant by the
 *    two stages' 2 tau: a slider climbing at ds/dt reads 2 tau ds/dt low
 *    (0.001 on fig8's high branch). So s_twin here is the twin's s less its
 *    own drift passed through the same two stages, drift_lag (what the
 *    corrections below move it by is left out: the twin's response to its
 *    correction is not delayed, only its estimate of the plant; so is a
 *    jump of its state set from outside, DRIFT_JUMP). The
 *    linearised response of the beam with the slider attached cannot serve
 *    here: on the high branch the hardening holds the response below its
 *    resonance (phase ~150 deg where the linear model says ~10 deg), and on
 *    the low branch the slider bounces instead of following the beam.
 *    The twin's x_C moves by
 *      ds/dt = clamp(position_gain (s_error -+ deadband), -rate, rate)
 *    within the clamp stops, never across s = 1/2, and only while
 *    s_sigma < sigma_hold and the measured excitation (amplitude
 *    sqrt(2 <a^2>), frequency kappa / 2 pi) is that of
 *    the map nearest in frequency within excitation_tolerance (a map holds
 *    for its excitation only; a scene whose ambient frequency moves carries
 *    maps at several, up to BS_OBSERVER_MAPS). Where the design made maps
 *    of one excitation at several mu, |H|(s) is theirs interpolated
 *    linearly at the twin's mu (the friction estimate's, 8; what that does:
 *    docs/twin.md, "Maps that follow mu").
 *    Errors up to position_deadband are not corrected: with a model whose
 *    frequencies are off, the map is off too (3 % moves it by ~0.01 on
 *    fig6), and within that band the twin's own slider dynamics, driven by
 *    the corrected beam, are the better guide (docs/twin.md).
 *    With jump_hold > 0, a response that falls fast from the high branch
 *    (the lock-in's first stages below FALLING of its second while the
 *    twin's w(4L/7) amplitude is above h/2: a jump to the low branch under
 *    way) leaves s unmeasured (s_sigma 1: no s correction, no friction
 *    learning) for jump_hold seconds: the second stages hold the old
 *    branch's response for about ten tau after such a fall (1 % of it
 *    after 11 tau when it falls to 1/40), and on the low branch, where |H|
 *    hardly changes with s, that reads as an s error of a few hundredths
 *    (docs/twin.md, "Jump hold").
 *    (5 and 6 run every POSITION_EVERY steps.)
 * 6. Confidence. White measurement noise of standard deviation sigma_n
 *    (gains->noise) through the lock-in's two stages leaves
 *    sigma_|H| = sigma_n sqrt(dt / (4 tau <a^2>)) on |H_m|, so
 *      s_sigma^2 = (sigma_|H| / |d|H|/ds|)^2 + var(s_error)
 *    with var(s_error) the spread of the raw estimate about its mean
 *    (low-passed over 4 tau: the plant's own chaotic scatter). A response
 *    buried in noise, or a branch where |H| hardly changes with s, makes
 *    it large; a measured |H_m| the branch never reaches, or an excitation
 *    the map was not made for, makes it 1.
 * 7. Outliers. A sensor glitch must neither end the twin nor throw it off
 *    the beam. The innovation's scale is a running mean of e^2 over the
 *    last few hundred samples (memory GATE_MEMORY per sample), floored at
 *    the design's sigma_n^2; a measurement with |e| beyond outlier_gate
 *    times its root is skipped, and so is one whose correction (3) would
 *    leave a state bs_sim_set_state refuses. A skipped sample enters the
 *    scale at the gate's own level, so that a lasting change of the
 *    signal (a branch jump) widens the gate by ~7 % a sample (with the
 *    default gate of 6) and is followed within a millisecond, while one
 *    glitch widens it by that once.
 * 8. Friction (docs/twin.md, "Friction"). A twin whose mu is off drifts
 *    along the high branch at another speed than the plant, and settles on
 *    another plateau, so the s correction (5) has a persistent part there:
 *    measured on fig6, a plant with 25 % more friction walks toward the
 *    centre more slowly and settles lower, and the s error reads about
 *    -0.0027 for as long as it lasts, 25 % less friction about +0.002, the
 *    nominal plant +0.0005. With friction_gain > 0, on the high branch
 *    (the twin's w(4L/7) amplitude above friction_amplitude h, h/2 by
 *    default; the low branch stays below h/4) while s is measured there
 *    (s_sigma below friction_sigma) and the plant climbs (the measured s,
 *    s + s_error, moves at friction_climb or faster, its rate low-passed
 *    over CLIMB_TIME: on a plateau the s error the map leaves need not
 *    depend on mu, and integrated it walked mu^ to its clamp) and the
 *    excitation holds still (its measured frequency within STEADY_FREQUENCY
 *    of its mean over STEADY_TIME: a ramp changes the walk as mu would), the s
 *    error is low-passed over friction_time, and what of it is beyond
 *    friction_deadband moves mu:
 *      dmu/dt = -friction_gain mu_scene (persist -+ friction_deadband),
 *    within (1 +- BS_OBSERVER_FRICTION_RANGE) mu_scene, set on the sim by
 *    bs_sim_set_contact_laws. The deadband keeps the nominal plant's own
 *    +0.0005 and the noise from moving it. mu_sigma: a uniform prior over
 *    the range shrunk by the time spent learning, plus what the persistent
 *    error left says (FRICTION_SENSITIVITY, fig6's s error per unit of
 *    relative friction error); a figure of merit, not a posterior.
 *    The estimate reads the lag a twin with the wrong mu builds up while the
 *    correction (5) pulls it along: a strong position_gain keeps the twin
 *    on the plant and leaves little lag to read. With friction_shadow > 0
 *    it reads a shadow's instead: an s that moves with the twin's own drift
 *    (what its mu makes of the slider, not the correction) and is
 *    corrected as in 5 but at friction_shadow:
 *      s_shadow += ds_own + rate(friction_shadow, s + s_error - s_shadow) dt,
 *    the error it reads s + s_error - s_shadow. At friction_shadow =
 *    position_gain the shadow is the twin's s (but for rounding).
 *    The walk (friction_walk = k > 0; docs/twin.md, "The walk"): the
 *    slider walks up the high branch at a speed that goes as mu^-k (k ~ 4
 *    on fig6 and fig8), so the twin's own walking speed v_t (its drift, the
 *    correction left out) against the measured v_p (the rate of s +
 *    s_error), both low-passed over CLIMB_TIME from 0 at the climb's start,
 *    gives mu_plant / mu^ = (v_t / v_p)^(1/k) without waiting for a lag to
 *    build up:
 *      dmu/dt = friction_gain mu^ 2 (v_t - v_p) / (k (v_t + v_p))
 *                 / (1 + learnt / WALK_LEARN_REF)
 *    (the logarithm of the ratio over k, as a bounded rational; learnt the
 *    time spent learning, so that later climbs average), under the
 *    gates above and only while both walk the same way at friction_climb
 *    or faster and v_p is at least CLIMB_PEAK_PART of its fastest in this
 *    climb (toward the plateau the plateau's place, which the model's
 *    frequencies set as much as mu, rules both speeds).
 * A step without a measurement (bs_observer_predict: a sample lost on the
 * way, e.g. a firmware's FIFO overrun) does all but what needs y: no beam
 * correction (3), and of the lock-in (4) only the reference and the twin's
 * own products go on, those with y hold; the s correction (5) goes on from
 * them, as it would between two measurements.
 */
#include "bs_observer.h"
#include "bs_lockin.h"
#include "bs_port.h"
#include "bs_shape.h"
#include "bs_sim_internal.h"
#include <stddef.h>

#define OBSERVER_READY 0x6f6f6f6fu /* "oooo": a Thumb-2 immediate, like BS_SIM_READY */
#define TWO_PI BS_R(6.283185307179586)
#define HALF_PI BS_R(1.5707963267948966)
#define PI BS_R(3.141592653589793)
#define SIGMA_UNKNOWN BS_R(1.0) /* s_sigma while nothing is known */
/* Steps between two updates of s (the lock-in moves over ~tau = 5000 steps;
 * the map search is the dearest part of a step). */
#define POSITION_EVERY 16
/* Weight of the newest sample in the running mean of e^2 (7). */
#define GATE_MEMORY BS_CONSTANT(BS_R(0.00390625), 0x3b800000u) /* 1/256 = 2^-8: bits (127 - 8) << 23 */
/* 8: the learning time over which the prior's variance halves [s], and the
 * persistent s error per unit of relative friction error (fig6). */
#define FRICTION_LEARN_REF BS_R(2.0)
#define FRICTION_SENSITIVITY BS_R(0.01)
/* the time constant of the measured s's rate for the climb gate, and of
 * the walk's two speeds (8) [s] */
#define CLIMB_TIME BS_R(1.0)
/* 8, the walk: learnt only while the plant climbs at this part of its
 * fastest so far in this climb: where it slows toward its plateau, the
 * plateau's place (which the model's frequencies set as much as mu) rules
 * both speeds */
#define CLIMB_PEAK_PART BS_R(0.5)
/* 8, the walk: the learning time over which its gain halves [s]: the
 * first climb moves mu^ at the full gain, later ones average what they
 * read (each climb's reading scatters by several per cent: fig8) */
#define WALK_LEARN_REF BS_R(10.0)
/* 8: the excitation is steady while its measured frequency stays within
 * this part of its own mean over STEADY_TIME [s]: a ramp of r Hz/s lags
 * that mean by r STEADY_TIME, so 0.1 % a second or more closes the gate */
#define STEADY_FREQUENCY BS_R(0.001)
#define STEADY_TIME BS_R(1.0)
#define INV_SQRT3 BS_R(0.5773502691896258)
/* 5: a change of s larger than this between two updates (0.001 L in 16
 * samples, 3 L/s at dt = 2e-5 s; the slider drifts at hundredths of L a
 * second) is a state set from outside the observer, not drift. */
#define DRIFT_JUMP BS_R(0.001)
/* 5: the first stages' response below this part of the second stages':
 * the response falls fast (jump_hold) */
#define FALLING BS_R(0.7)
/* the longest jump hold in steps, 2^62 (a conversion of more is undefined) */
#define HOLD_STEPS_MAX BS_R(4611686018427387904.0)

/* bs_lowpass2_pair_step moves a signal's two products as one block: with_b
 * right after with_a. */
typedef char products_in_pairs[offsetof(bs_observer, meas_b) == offsetof(bs_observer, meas_a) + sizeof(bs_lowpass2)
                                       && offsetof(bs_observer, twin_b)
                                              == offsetof(bs_observer, twin_a) + sizeof(bs_lowpass2)
                                       && offsetof(bs_observer, defl_b)
                                              == offsetof(bs_observer, defl_a) + sizeof(bs_lowpass2)
                                   ? 1
                                   : -1];

typedef struct complex_real {
    bs_real re, im;
} complex_real;

bs_observer_options bs_observer_defaults(void)
{
    bs_observer_options o;
    o.correct_beam = 1;
    o.correct_position = 1;
    o.lockin_time = (bs_real)BS_OBSERVER_DEFAULT_LOCKIN_TIME;
    o.position_gain = (bs_real)BS_OBSERVER_DEFAULT_POSITION_GAIN;
    o.position_rate = (bs_real)BS_OBSERVER_DEFAULT_POSITION_RATE;
    o.position_deadband = (bs_real)BS_OBSERVER_DEFAULT_POSITION_DEADBAND;
    o.sigma_hold = (bs_real)BS_OBSERVER_DEFAULT_SIGMA_HOLD;
    o.excitation_tolerance = (bs_real)BS_OBSERVER_DEFAULT_EXCITATION_TOLERANCE;
    o.settle_time = (bs_real)BS_OBSERVER_DEFAULT_SETTLE_TIME;
    o.outlier_gate = (bs_real)BS_OBSERVER_DEFAULT_OUTLIER_GATE;
    o.friction_gain = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_GAIN;
    o.friction_time = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_TIME;
    o.friction_deadband = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_DEADBAND;
    o.friction_sigma = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_SIGMA;
    o.friction_amplitude = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_AMPLITUDE;
    o.friction_climb = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_CLIMB;
    o.friction_shadow = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_SHADOW;
    o.friction_walk = (bs_real)BS_OBSERVER_DEFAULT_FRICTION_WALK;
    o.jump_hold = (bs_real)BS_OBSERVER_DEFAULT_JUMP_HOLD;
    return o;
}

static int finite(bs_real x)
{
    return x - x == BS_R(0.0);
}

static int valid_options(const bs_observer_options *o)
{
    return (o->correct_beam == 0 || o->correct_beam == 1) && (o->correct_position == 0 || o->correct_position == 1)
           && finite(o->lockin_time) && o->lockin_time > BS_R(0.0) && finite(o->position_gain)
           && o->position_gain >= BS_R(0.0) && finite(o->position_rate) && o->position_rate >= BS_R(0.0)
           && finite(o->position_deadband) && o->position_deadband >= BS_R(0.0)
           && finite(o->sigma_hold) && o->sigma_hold > BS_R(0.0) && finite(o->excitation_tolerance)
           && o->excitation_tolerance > BS_R(0.0) && finite(o->settle_time)
           && o->settle_time >= BS_R(0.0) && finite(o->outlier_gate) && o->outlier_gate > BS_R(1.0)
           && finite(o->outlier_gate * o->outlier_gate) && finite(o->friction_gain) && o->friction_gain >= BS_R(0.0)
           && finite(o->friction_time) && o->friction_time > BS_R(0.0) && finite(o->friction_deadband)
           && o->friction_deadband >= BS_R(0.0) && finite(o->friction_sigma) && o->friction_sigma > BS_R(0.0)
           && finite(o->friction_amplitude) && o->friction_amplitude >= BS_R(0.0) && finite(o->friction_climb)
           && o->friction_climb >= BS_R(0.0) && finite(o->friction_shadow) && o->friction_shadow >= BS_R(0.0)
           && finite(o->friction_walk) && o->friction_walk >= BS_R(0.0)
           && finite(o->jump_hold) && o->jump_hold >= BS_R(0.0);
}

/* Map m + 1 is made at map m's excitation (at another mu). */
static int same_excitation(const bs_observer_gains *g, int m)
{
    return g->map_frequency[m + 1] == g->map_frequency[m];
}

/* The maps: s ascending within (0, 1/2], everything finite (|H| < 0: no
 * such branch at that s), each with the excitation and mu it was made at,
 * in ascending frequency, and the maps of one excitation (equal frequency
 * and amplitude) in ascending mu. */
static int valid_table(const bs_observer_gains *g)
{
    int i, m;
    if (g->table_count < 2 || g->table_count > BS_OBSERVER_TABLE || g->map_count < 1
        || g->map_count > BS_OBSERVER_MAPS)
        return 0;
    for (m = 0; m < g->map_count; ++m) {
        if (!finite(g->map_frequency[m]) || !(g->map_frequency[m] > BS_R(0.0)) || !finite(g->map_accel[m])
            || !(g->map_accel[m] > BS_R(0.0)) || !finite(g->map_friction[m]) || !(g->map_friction[m] >= BS_R(0.0)))
            return 0;
        if (m > 0 && !(g->map_frequency[m] > g->map_frequency[m - 1]) && !same_excitation(g, m - 1))
            return 0;
        if (m > 0 && same_excitation(g, m - 1)
            && !(g->map_accel[m] == g->map_accel[m - 1] && g->map_friction[m] > g->map_friction[m - 1]))
            return 0;
    }
    for (i = 0; i < g->table_count; ++i) {
        if (!finite(g->table_s[i]) || !(g->table_s[i] > BS_R(0.0) && g->table_s[i] <= BS_R(0.5)))
            return 0;
        if (i > 0 && !(g->table_s[i] > g->table_s[i - 1]))
            return 0;
        for (m = 0; m < g->map_count; ++m)
            if (!finite(g->table_stiff[m][i]) || !finite(g->table_soft[m][i]))
                return 0;
    }
    return 1;
}

static int valid_schedule(const bs_observer_gains *g, int n)
{
    int i, k;
    if (g->gain_count < 2 || g->gain_count > BS_OBSERVER_GAINS)
        return 0;
    for (i = 0; i < g->gain_count; ++i) {
        if (!finite(g->gain_s[i]) || !finite(g->gain_v[i]) || (i > 0 && !(g->gain_s[i] > g->gain_s[i - 1])))
            return 0;
        for (k = 0; k < n; ++k)
            if (!finite(g->gain_q[i][k]) || !finite(g->gain_u[i][k]))
                return 0;
    }
    return 1;
}

static int valid_gains(const bs_observer_gains *g, const bs_scene *scene)
{
    /* sigma_n^2 floors the outlier gate's scale (7): it must not underflow */
    if (g->n_modes != scene->n_modes || g->latency < 0 || g->latency > BS_OBSERVER_MAX_LATENCY
        || !finite(g->noise * g->noise) || !(g->noise * g->noise >= BS_REAL_EPS * BS_REAL_EPS * BS_REAL_EPS))
        return 0;
    if (g->signal == BS_SIGNAL_VOLTAGE) {
#if BS_WITH_PIEZO
        if (scene->load != BS_LOAD_RESISTOR)
            return 0;
#else
        return 0;
#endif
    } else if (g->signal != BS_SIGNAL_DEFLECTION) {
        return 0;
    }
    return valid_schedule(g, scene->n_modes) && valid_table(g);
}

static bs_real twin_signal(const bs_sim *sim, int signal)
{
#if BS_WITH_PIEZO
    if (signal == BS_SIGNAL_VOLTAGE)
        return sim->voltage;
#else
    (void)signal;
#endif
    return bs_sim_sensor(sim);
}

static bs_real twin_power(const bs_sim *sim)
{
#if BS_WITH_PIEZO
    return sim->power;
#else
    (void)sim;
    return BS_ZERO; /* low-passed every sample: not a literal read from flash */
#endif
}

/* 8: the prior's standard deviation of mu (uniform over the range). */
static bs_real friction_prior(const bs_observer *obs)
{
    return (bs_real)BS_OBSERVER_FRICTION_RANGE * INV_SQRT3 * obs->sim->scene->mu;
}

/* 8: the s error the estimate reads: the twin's own, or with a shadow the
 * measured s (the twin's and its error) less the shadow's */
static bs_real shadow_error(const bs_observer *obs)
{
    if (!(obs->options.friction_shadow > BS_R(0.0)))
        return obs->estimate.s_error;
    return obs->estimate.s + obs->estimate.s_error - obs->shadow_s;
}

/* The persistent s error beyond the deadband (0 within it). */
static bs_real friction_drive(const bs_observer *obs)
{
    const bs_real band = obs->options.friction_deadband, p = obs->friction_persist;
    return p > band ? p - band : p < -band ? p + band : BS_R(0.0);
}

/* 8: mu_sigma, formed where it is read (bs_observer_get, _get_friction: a
 * square root and two divisions saved at each update of mu^; what it reads
 * changes only there): the prior shrunk by the time spent learning, and the
 * error in mu that the last reading leaves, the law's persistent s error
 * beyond its deadband or the walk's relative error. */
static bs_real mu_sigma_of(const bs_observer *obs)
{
    const bs_observer_options *o = &obs->options;
    const bs_real prior = friction_prior(obs);
    bs_real left;
    if (!(o->friction_gain > BS_R(0.0)))
        return BS_R(0.0);
    left = o->friction_walk > BS_R(0.0) ? obs->estimate.mu * obs->friction_persist
                                        : obs->sim->scene->mu * friction_drive(obs) / FRICTION_SENSITIVITY;
    return bs_sqrt(prior * prior / (BS_R(1.0) + obs->friction_learnt / FRICTION_LEARN_REF) + left * left);
}

bs_status bs_observer_init_(uint32_t tag, uint32_t observer_tag, size_t observer_size, size_t gains_size,
                            bs_observer *obs, const bs_sim *sim, const bs_observer_gains *gains,
                            const bs_observer_options *options)
{
    const bs_observer_options defaults = bs_observer_defaults();
    const bs_status status = bs_sim_status(sim);
    int i;

    if (!obs)
        return BS_E_NULL;
    if (tag != BS_BUILD_TAG || observer_tag != BS_OBSERVER_TAG || observer_size != sizeof(bs_observer)
        || gains_size != sizeof(bs_observer_gains))
        return BS_E_BUILD; /* an observer of another layout: not even its ready field is ours to write */
    obs->ready = 0;
    if (status != BS_OK)
        return status;
    if (!gains)
        return BS_E_NULL;
    if (!options)
        options = &defaults;
    if (sim->model != BS_MODEL_FREE || !valid_gains(gains, sim->scene) || !valid_options(options))
        return BS_E_ARGUMENT;

    obs->sim = sim;
    obs->gains = gains;
    obs->latency = gains->latency;
    obs->signal = gains->signal;
    obs->gain_last = gains->gain_count - 1;
    obs->noise_sq = gains->noise * gains->noise;
    obs->com_offset = sim->scene->com_offset;
    /* member by member: a struct assignment may become a call of memcpy,
     * which the freestanding core does not have */
    obs->options.correct_beam = options->correct_beam;
    obs->options.correct_position = options->correct_position;
    obs->options.lockin_time = options->lockin_time;
    obs->options.position_gain = options->position_gain;
    obs->options.position_rate = options->position_rate;
    obs->options.position_deadband = options->position_deadband;
    obs->options.sigma_hold = options->sigma_hold;
    obs->options.excitation_tolerance = options->excitation_tolerance;
    obs->options.settle_time = options->settle_time;
    obs->options.outlier_gate = options->outlier_gate;
    obs->options.friction_gain = options->friction_gain;
    obs->options.friction_time = options->friction_time;
    obs->options.friction_deadband = options->friction_deadband;
    obs->options.friction_sigma = options->friction_sigma;
    obs->options.friction_amplitude = options->friction_amplitude;
    obs->options.friction_climb = options->friction_climb;
    obs->options.friction_shadow = options->friction_shadow;
    obs->options.friction_walk = options->friction_walk;
    obs->options.jump_hold = options->jump_hold;
    obs->friction_persist = BS_R(0.0);
    obs->friction_learnt = BS_R(0.0);
    obs->climb_s = BS_R(-1.0);
    obs->climb_rate = BS_R(0.0);
    obs->own_ds = obs->own_rate = obs->walk_rate = obs->walk_peak = BS_R(0.0);
    obs->frequency_mean = BS_R(0.0);
    obs->drift_s = bs_sim_position(sim);
    obs->shadow_s = obs->drift_s;
    obs->drift_lag[0] = obs->drift_lag[1] = BS_R(0.0);
    obs->steps = 0;
    obs->head = 0;
    for (i = 0; i <= BS_OBSERVER_MAX_LATENCY; ++i) {
        obs->past_signal[i] = twin_signal(sim, gains->signal);
        obs->past_deflection[i] = bs_sim_sensor(sim);
        obs->past_accel[i] = BS_R(0.0);
    }
    bs_lockin_reference_init(&obs->reference, sim->scene->dt, obs->options.lockin_time);
    {
        bs_real retain = BS_R(1.0);
        for (i = 0; i < POSITION_EVERY; ++i)
            retain *= obs->reference.retain;
        obs->drift_alpha = BS_R(1.0) - retain;
    }
    /* stage by stage: a struct assignment may become a call of memcpy */
    {
        bs_lowpass2 *const filters[] = { &obs->meas_a, &obs->meas_b,
                                          &obs->twin_a, &obs->twin_b, &obs->defl_a, &obs->defl_b, &obs->power,
                                          &obs->s_error_mean, &obs->s_error_sq };
        for (i = 0; i < (int)(sizeof filters / sizeof filters[0]); ++i)
            filters[i]->stage[0] = filters[i]->stage[1] = BS_R(0.0);
    }
    obs->innovation_sq = BS_R(0.0);
    obs->last_outlier = 0;
    obs->hold_until = 0;
    obs->gain_interval = -1;
    obs->gain_s_from = obs->gain_s_to = BS_R(0.0); /* kept by no s (gains_at) */
    bs_shape_forget(&obs->shape);
    obs->estimate.s = bs_sim_position(sim);
    obs->estimate.s_sigma = SIGMA_UNKNOWN;
    obs->estimate.s_error = BS_R(0.0);
    obs->estimate.amplitude = BS_R(0.0);
    obs->estimate.power = BS_R(0.0);
    obs->estimate.phase_error = BS_R(0.0);
    obs->estimate.frequency = BS_R(0.0);
    obs->estimate.measurement = BS_R(0.0);
    obs->estimate.prediction = obs->past_signal[0];
    obs->estimate.innovation = BS_R(0.0);
    obs->estimate.outliers = 0;
    obs->estimate.mu = sim->k.mu;
    obs->estimate.mu_sigma = BS_R(0.0); /* formed where it is read: mu_sigma_of */
    obs->ready = OBSERVER_READY;
    return BS_OK;
}

/* The gain schedule's interval i into the observer: its gains at the start
 * and their change over it, formed once (the slider stays in an interval
 * for many thousand steps, and the schedule may be in flash). */
static void enter_interval(bs_observer *obs, int i, int n)
{
    const bs_observer_gains *g = obs->gains;
    int k;
    for (k = 0; k < n; ++k) {
        obs->gain_from[k] = g->gain_q[i][k];
        obs->gain_change[k] = g->gain_q[i + 1][k] - g->gain_q[i][k];
        obs->gain_from[n + k] = g->gain_u[i][k];
        obs->gain_change[n + k] = g->gain_u[i + 1][k] - g->gain_u[i][k];
    }
    obs->gain_from[2 * n] = g->gain_v[i];
    obs->gain_change[2 * n] = g->gain_v[i + 1] - g->gain_v[i];
    obs->gain_s_from = g->gain_s[i];
    /* an end interval is kept by no s: s clamped at the schedule's ends
     * (gains_at) makes the walk's interval another than the one s is in */
    obs->gain_s_to = i > 0 && i < obs->gain_last - 1 ? g->gain_s[i + 1] : g->gain_s[i];
    obs->gain_s_width = g->gain_s[i + 1] - g->gain_s[i];
    obs->gain_interval = i;
}

/* Where s lies in the gain schedule: returns t in [0, 1] within the
 * interval it enters (enter_interval), the gains there being
 * gain_from + t gain_change; held beyond the schedule's ends. The search
 * starts at the last step's interval (s moves slowly: one comparison or
 * two a step instead of a walk from the start); the interval found is the
 * one the walk from 0 finds. */
static bs_real gains_at(bs_observer *obs, bs_real s, int n)
{
    const bs_observer_gains *g = obs->gains;
    const int last = obs->gain_last;
    int i;
    if (s > obs->gain_s_from && s <= obs->gain_s_to)
        return (s - obs->gain_s_from) / obs->gain_s_width; /* still inside an inner interval: what the walk finds */
    i = obs->gain_interval;
    if (i < 0)
        i = 0;
    if (s < g->gain_s[0])
        s = g->gain_s[0];
    if (s > g->gain_s[last])
        s = g->gain_s[last];
    while (i > 0 && s <= g->gain_s[i])
        --i;
    while (i < last - 1 && s > g->gain_s[i + 1])
        ++i;
    if (i != obs->gain_interval)
        enter_interval(obs, i, n);
    return (s - obs->gain_s_from) / obs->gain_s_width;
}

/* The expansion of phi_k = 0, every mode's: the beam inside a clamp, which
 * moves with the base (bs_shape_expanded). Its Horner sums give +0 for any
 * finite t, as bs_shape_expanded's 0: the correction's loop over the modes
 * has no branch, and phi_k, phi'_k stay in registers. */
static const bs_real in_clamp[BS_MAX_MODES][BS_SHAPE_TERMS] = { { BS_R(0.0) } };

/* The sim's state as the correction changes it (3). */
typedef struct corrected_state {
    bs_real q[BS_MAX_MODES], u[BS_MAX_MODES];
    bs_real slider[3], velocity[3], x_low;
    bs_real voltage;
} corrected_state;

/* x_C += dx as the compensated pair (x_C, x_low) with TwoSum, so that
 * sub-ulp moves are kept (docs/model.md 9.2). */
static void add_compensated(bs_real *x, bs_real *x_low, bs_real dx)
{
    const bs_real b = dx + *x_low;
    const bs_real sum = *x + b;
    const bs_real b_virtual = sum - *x;
    *x_low = (*x - (sum - b_virtual)) + (b - b_virtual);
    *x = sum;
}

/* 3: output injection on the beam (and the patch voltage), the slider
 * carried along as if attached: the gains are those of the beam with the
 * slider rigidly attached, and moving the beam under a slider that stays
 * would open or close its contacts, i.e. kick it. At x_C the beam moves by
 * dw = phi^T dq and tilts by dw' = phi'^T dq; the slider follows:
 * z_r += dw, beta -= dw' (beta is clockwise), x_C += d dw' (its centre of
 * mass, d below the slot centre, swings with the tilt); likewise the
 * velocities with du. Into c; the sim is not changed. */
BS_INLINE void correction_of(bs_observer *obs, const bs_sim *sim, bs_real e, corrected_state *c)
{
    const bs_scene *scene = sim->scene;
    const int n = BS_NMODES(scene);
    const bs_real *from = obs->gain_from, *change = obs->gain_change;
    const bs_real *row; /* mode k's expansion, then k + 1's */
    bs_real dw = BS_ZERO, dw_slope = BS_ZERO, dv = BS_ZERO, dv_slope = BS_ZERO;
    const bs_real x = sim->slider[0] + sim->x_c_low;
    const bs_real within = gains_at(obs, x / sim->k.length, n);
    bs_real t = sim->k.slope_scale * (x - obs->shape.centre); /* bs_shape_offset, from the prepared constants */
    int k;

    /* phi and phi' at the slider from an expansion about it, as the contact
     * detection keeps them at the corners (core/src/bs_shape.c): the slider
     * moves slowly, and a piece polynomial per mode every step (from the
     * scene's table, in flash on a controller) cost more than the rest of
     * the correction */
    if (!(bs_fabs(t) <= sim->shape_reach)) {
        bs_shape_expand(scene, x, &obs->shape);
        t = sim->k.slope_scale * (x - obs->shape.centre);
    }
    row = x >= BS_R(0.0) && x <= sim->k.length ? obs->shape.coef[0] : in_clamp[0];
    for (k = 0; k < n; ++k) { /* bs_shape_expanded mode by mode */
        const bs_real dq = (from[k] + within * change[k]) * e, du = (from[n + k] + within * change[n + k]) * e;
        bs_real phi, slope;
        /* read in place, not with bs_shape_terms: GCC keeps every store
         * before an asm that reads memory, and c's would stay, dead */
        bs_shape_taylor(row, t, &phi, &slope);
        row += BS_SHAPE_TERMS;
        slope *= sim->k.slope_scale;
        c->q[k] = sim->q_beam[k] + dq;
        c->u[k] = sim->u_beam[k] + du;
        dw += phi * dq;
        dw_slope += slope * dq;
        dv += phi * du;
        dv_slope += slope * du;
    }
    for (k = 0; k < 3; ++k) {
        c->slider[k] = sim->slider[k];
        c->velocity[k] = sim->slider_velocity[k];
    }
    c->x_low = sim->x_c_low;
    c->slider[1] += dw;
    c->velocity[1] += dv;
#if BS_WITH_ROTATION
    c->slider[2] -= dw_slope;
    c->velocity[2] -= dv_slope;
#endif
    add_compensated(&c->slider[0], &c->x_low, obs->com_offset * dw_slope);
    c->velocity[0] += obs->com_offset * dv_slope;
    c->voltage = BS_ZERO; /* the first term of commit_correction's sum: not a literal read from flash */
#if BS_WITH_PIEZO
    if (scene->load != BS_LOAD_NONE)
        c->voltage = sim->voltage + (from[2 * n] + within * change[2 * n]) * e;
#endif
}

/* c into the sim if it is a state bs_sim_set_state accepts (and the voltage
 * finite); returns 1, or 0 and leaves the sim as it was. Finiteness as one
 * sum (a sum of finite values that overflows is refused too). */
BS_INLINE int commit_correction(bs_sim *sim, const corrected_state *c)
{
    bs_real check = c->voltage + c->slider[0] + c->slider[1] + c->slider[2] + c->velocity[0] + c->velocity[1]
                    + c->velocity[2];
    int k;
    for (k = 0; k < BS_NMODES(sim->scene); ++k)
        check += c->q[k] + c->u[k];
    if (!finite(check) || (sim->model == BS_MODEL_FREE && !bs_within_stops(&sim->k, c->slider[0])))
        return 0;
#if BS_STATE_AS_BLOCK
    if (BS_NMODES(sim->scene) == BS_MAX_MODES) {
        /* one vstm, as the step's write (no mode slot beyond n): 18 cycles
         * for 34 (twin-cost-friction-off 2306.2 -> 2292.2 cycles an
         * observer step). Not the vldm of the step's read: the correction
         * needs the values elsewhere than s0-s15, and the moves cost more
         * (2310.2). The sim's address forgotten (BS_FORGET): with a
         * firmware's static sim the vstm addresses the state from the
         * register that holds it, not from a literal read from flash. */
        bs_sim *target = sim;
        BS_FORGET(target);
        bs_store_state(target, c->q, c->u, c->slider[0], c->slider[1], c->slider[2], c->velocity, c->x_low);
    } else
#endif
    {
        for (k = 0; k < BS_NMODES(sim->scene); ++k) {
            sim->q_beam[k] = c->q[k];
            sim->u_beam[k] = c->u[k];
        }
        for (k = 0; k < 3; ++k) {
            sim->slider[k] = c->slider[k];
            sim->slider_velocity[k] = c->velocity[k];
        }
        sim->x_c_low = c->x_low;
    }
#if BS_WITH_PIEZO
    if (sim->scene->load != BS_LOAD_NONE)
        sim->voltage = c->voltage;
#endif
    return 1;
}

/* 7: 1 if e is beyond the gate; the running mean of e^2 takes e^2, or the
 * gate's level for a skipped one. */
BS_INLINE int beyond_gate(bs_observer *obs, bs_real e)
{
    const bs_real noise_sq = obs->noise_sq;
    const bs_real scale_sq = obs->innovation_sq > noise_sq ? obs->innovation_sq : noise_sq;
    const bs_real limit_sq = obs->options.outlier_gate * obs->options.outlier_gate * scale_sq;
    const bs_real e_sq = e * e;
    const int beyond = !(e_sq <= limit_sq); /* e^2 may overflow: infinity is beyond */
    obs->innovation_sq += GATE_MEMORY * ((BS_UNLIKELY(beyond) ? limit_sq : e_sq) - obs->innovation_sq);
    return beyond;
}

/* 4: one step of the lock-in with the aligned samples. Without a
 * measurement (measured 0) the products with y hold; the reference, an
 * integral over time, and the twin's own products go on. */
BS_INLINE void demodulate(bs_observer *obs, bs_real a, bs_real y, bs_real y_twin, bs_real w_twin, bs_real power,
                          int measured)
{
    const bs_real alpha = obs->reference.alpha;
    const bs_real b = bs_lockin_reference_step(&obs->reference, a);

    if (measured)
        bs_lowpass2_pair_step(&obs->meas_a, &obs->meas_b, y * a, y * b, alpha);
    if (obs->signal != BS_SIGNAL_DEFLECTION) /* else y^ is w^: its products are defl_a, defl_b */
        bs_lowpass2_pair_step(&obs->twin_a, &obs->twin_b, y_twin * a, y_twin * b, alpha);
    bs_lowpass2_pair_step(&obs->defl_a, &obs->defl_b, w_twin * a, w_twin * b, alpha);
    bs_lowpass2_step(&obs->power, power, alpha);
}

/* H of the signal whose products are with_a, with_b (bs_lockin_response). */
static complex_real transfer(const bs_lockin_basis *basis, const bs_lowpass2 *with_a, const bs_lowpass2 *with_b)
{
    complex_real h;
    bs_lockin_response(basis, with_a, with_b, &h.re, &h.im);
    return h;
}

static complex_real complex_div(complex_real x, complex_real y)
{
    const bs_real norm = y.re * y.re + y.im * y.im;
    complex_real r;
    r.re = (x.re * y.re + x.im * y.im) / norm;
    r.im = (x.im * y.re - x.re * y.im) / norm;
    return r;
}

/* atan2 to about 1e-5 rad (a reported angle only: the core has no atan). */
static bs_real angle_of(bs_real y, bs_real x)
{
    const bs_real ax = bs_fabs(x), ay = bs_fabs(y);
    const bs_real big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
    bs_real t, t2, r;
    if (big == BS_R(0.0))
        return BS_R(0.0);
    t = small / big;
    t2 = t * t;
    r = t * (BS_R(0.99997726) + t2 * (BS_R(-0.33262347) + t2 * (BS_R(0.19354346)
        + t2 * (BS_R(-0.11643287) + t2 * (BS_R(0.05265332) + t2 * BS_R(-0.01172120))))));
    if (ay > ax)
        r = HALF_PI - r;
    if (x < BS_R(0.0))
        r = PI - r;
    return y < BS_R(0.0) ? -r : r;
}

/* On one branch of the map (values h), the crossing of |H|(s) with target
 * nearest to near: *s_cross and the slope d|H|/ds of its segment. Returns
 * 0 if the branch never reaches target. */
static int invert_map(const bs_observer_gains *g, const bs_real *h, bs_real target, bs_real near, bs_real *s_cross,
                      bs_real *slope)
{
    bs_real best = BS_R(2.0);
    int i, found = 0;
    for (i = 0; i + 1 < g->table_count && g->table_s[i] - near < best; ++i) {
        const bs_real h0 = h[i], h1 = h[i + 1];
        if (h0 < BS_R(0.0) || h1 < BS_R(0.0))
            continue; /* the branch does not exist there */
        if ((h0 - target) * (h1 - target) <= BS_R(0.0) && h0 != h1) {
            const bs_real s = g->table_s[i] + (target - h0) / (h1 - h0) * (g->table_s[i + 1] - g->table_s[i]);
            if (bs_fabs(s - near) < best) {
                best = bs_fabs(s - near);
                *s_cross = s;
                *slope = (h1 - h0) / (g->table_s[i + 1] - g->table_s[i]);
                found = 1;
            }
        }
    }
    return found;
}

/* The branch of the maps of map's excitation (maps map, map + 1, ... of
 * its frequency, ascending in mu) at the twin's mu: between the two maps
 * whose mu bracket it, interpolated linearly into blend (negative where
 * either has no branch); beyond the first or last, that map's own values.
 * With room for one map there is nothing to interpolate (a firmware's
 * -DBS_OBSERVER_MAPS=1: no blend on its stack). */
#if BS_OBSERVER_MAPS > 1
#define BLEND_ROOM BS_OBSERVER_TABLE
#else
#define BLEND_ROOM 1
#endif
static const bs_real *branch_at(const bs_observer_gains *g, int map, int stiff, bs_real mu, bs_real *blend)
{
    const bs_real(*table)[BS_OBSERVER_TABLE] = stiff ? g->table_stiff : g->table_soft;
#if BS_OBSERVER_MAPS > 1
    const bs_real *low, *high;
    bs_real weight;
    int m = map, i;
    while (m + 1 < g->map_count && same_excitation(g, m) && g->map_friction[m + 1] <= mu)
        ++m;
    if (!(m + 1 < g->map_count && same_excitation(g, m) && mu > g->map_friction[m]))
        return table[m];
    low = table[m];
    high = table[m + 1];
    weight = (mu - g->map_friction[m]) / (g->map_friction[m + 1] - g->map_friction[m]);
    for (i = 0; i < g->table_count; ++i)
        blend[i] = low[i] < BS_R(0.0) || high[i] < BS_R(0.0) ? BS_R(-1.0) : low[i] + weight * (high[i] - low[i]);
    return blend;
#else
    (void)mu;
    (void)blend;
    return table[map];
#endif
}

/* The first map of the excitation nearest in frequency to the measured
 * one, if that is its own within the tolerance; else -1. */
static int matching_map(const bs_observer *obs, bs_real frequency, bs_real amplitude)
{
    const bs_observer_gains *g = obs->gains;
    const bs_real tol = obs->options.excitation_tolerance;
    int m, nearest = 0;
    for (m = 1; m < g->map_count; ++m)
        if (bs_fabs(frequency - g->map_frequency[m]) < bs_fabs(frequency - g->map_frequency[nearest]))
            nearest = m;
    if (bs_fabs(frequency - g->map_frequency[nearest]) <= BS_R(0.1) * tol * g->map_frequency[nearest]
        && bs_fabs(amplitude - g->map_accel[nearest]) <= tol * g->map_accel[nearest])
        return nearest;
    return -1;
}

/* 5: whether the measured response h (the lock-in's second stages) falls
 * fast: the first stages' response below FALLING times h. A jump to the low
 * branch shows so: its fall to ~1/40 puts the first stage far below the
 * second within a few tau; in a climb on either branch |H| moves a few
 * percent a second, and the stages differ by about tau times that (a few
 * tenths of a percent). The low branch's rattle near fig6's clamp can fall
 * as fast: the caller counts a fall only from the high branch. */
static int falling(const bs_lockin_basis *basis, const bs_lowpass2 *with_a, const bs_lowpass2 *with_b,
                   complex_real h)
{
    complex_real first;
    bs_lockin_response_of(basis, with_a->stage[0], with_b->stage[0], &first.re, &first.im);
    return first.re * first.re + first.im * first.im < FALLING * FALLING * (h.re * h.re + h.im * h.im);
}

/* 5: the twin's drift since the last update, ds, into drift_lag: its s less
 * s through the lock-in's first and second stage (bs_lowpass2_step over
 * POSITION_EVERY steps, the drift taken as even over them). */
static void follow_drift(bs_observer *obs, bs_real ds)
{
    const bs_real alpha = obs->drift_alpha;
    const bs_real first = (BS_R(1.0) - alpha) * (obs->drift_lag[0] + ds);
    const bs_real second = obs->drift_lag[1] + ds;
    obs->drift_lag[0] = first;
    obs->drift_lag[1] = second - alpha * (second - first);
}

/* 5 and 6: s_error, s_sigma and the reported quantities from the lock-in. */
static void estimate_position(bs_observer *obs, const bs_sim *sim, bs_real dt)
{
    const bs_observer_gains *g = obs->gains;
    const bs_real tau = obs->options.lockin_time;
    bs_observer_estimate *est = &obs->estimate;
    bs_lockin_basis basis;
    complex_real h_m, h_t, h_w, ratio;
    bs_real aa, hm_abs, s_near, s_cross = BS_R(0.0), slope = BS_R(0.0), s_error, sigma_h;
    bs_real var_spread;
    bs_real blend[BLEND_ROOM];
    int mirror, map;

    est->s = bs_sim_position(sim);
    if (bs_fabs(est->s - obs->drift_s) <= DRIFT_JUMP) {
        follow_drift(obs, est->s - obs->drift_s);
        obs->shadow_s += est->s - obs->drift_s; /* 8: the shadow drifts as the twin does */
        if (obs->options.friction_walk > BS_R(0.0))
            obs->own_ds += est->s - obs->drift_s; /* 8, the walk */
    } else {
        obs->shadow_s = est->s; /* a state set from outside: the shadow starts again there */
    }
    obs->drift_s = est->s;
    est->power = bs_lowpass2_mean(&obs->power);
    est->s_sigma = SIGMA_UNKNOWN;
    est->s_error = BS_R(0.0);
    if (!bs_lockin_basis_of(&obs->reference, &basis))
        return; /* no excitation yet: nothing to demodulate against */
    aa = basis.aa;
    h_m = transfer(&basis, &obs->meas_a, &obs->meas_b);
    h_w = transfer(&basis, &obs->defl_a, &obs->defl_b);
    h_t = g->signal == BS_SIGNAL_DEFLECTION ? h_w : transfer(&basis, &obs->twin_a, &obs->twin_b);
    est->frequency = basis.kappa / TWO_PI;
    est->amplitude = bs_sqrt((h_w.re * h_w.re + h_w.im * h_w.im) * BS_R(2.0) * aa);
    hm_abs = bs_sqrt(h_m.re * h_m.re + h_m.im * h_m.im);
    if (h_t.re * h_t.re + h_t.im * h_t.im > BS_R(0.0)) {
        ratio = complex_div(h_m, h_t);
        est->phase_error = angle_of(ratio.im, ratio.re);
    }
    map = matching_map(obs, est->frequency, bs_sqrt(BS_R(2.0) * aa));
    if (obs->options.jump_hold > BS_R(0.0) && est->amplitude > sim->scene->half_thickness
        && falling(&basis, &obs->meas_a, &obs->meas_b, h_m)) {
        const bs_real steps = obs->options.jump_hold / dt; /* finite or +inf: saturated, not cast */
        obs->hold_until = obs->steps + (uint64_t)(steps < HOLD_STEPS_MAX ? steps : HOLD_STEPS_MAX);
    }
    if (map < 0 || obs->steps < obs->hold_until)
        return;
    mirror = est->s > BS_R(0.5);
    s_near = mirror ? BS_R(1.0) - est->s : est->s;
    if (!invert_map(g, branch_at(g, map, h_m.re < BS_R(0.0), sim->k.mu, blend), hm_abs, s_near, &s_cross, &slope)
        || slope == BS_R(0.0))
        return;
    s_error = (mirror ? s_near - s_cross : s_cross - s_near) + obs->drift_lag[1];
    {
        const bs_real alpha = dt * (bs_real)POSITION_EVERY / (BS_R(4.0) * tau);
        bs_lowpass2_step(&obs->s_error_mean, s_error, alpha);
        bs_lowpass2_step(&obs->s_error_sq, s_error * s_error, alpha);
    }
    var_spread = bs_lowpass2_mean(&obs->s_error_sq)
                 - bs_lowpass2_mean(&obs->s_error_mean) * bs_lowpass2_mean(&obs->s_error_mean);
    if (var_spread < BS_R(0.0))
        var_spread = BS_R(0.0);
    sigma_h = g->noise * bs_sqrt(dt / (BS_R(4.0) * tau * aa)) / bs_fabs(slope);
    est->s_error = s_error;
    est->s_sigma = bs_sqrt(sigma_h * sigma_h + var_spread);
    if (!finite(est->s_sigma) || est->s_sigma > SIGMA_UNKNOWN)
        est->s_sigma = SIGMA_UNKNOWN;
}

/* x_C += ds L within the stops, not across s = 1/2. */
static void move_slider(bs_sim *sim, bs_real ds)
{
    const bs_scene *scene = sim->scene;
    const bs_real x = sim->slider[0] + sim->x_c_low;
    const bs_real half = BS_R(0.5) * scene->length;
    bs_real target = x + ds * scene->length;
    if (x <= half && target > half)
        target = half;
    if (x >= half && target < half)
        target = half;
    if (target < scene->stop_min)
        target = scene->stop_min;
    if (target > scene->stop_max)
        target = scene->stop_max;
    add_compensated(&sim->slider[0], &sim->x_c_low, target - x);
}

/* 5: the correction's speed [1/s] for an s error at gain [1/s]: what of
 * the error is beyond position_deadband, within position_rate; 0 within the
 * deadband. */
static bs_real correction_rate(const bs_observer_options *o, bs_real gain, bs_real error)
{
    bs_real rate;
    if (error > o->position_deadband)
        error -= o->position_deadband;
    else if (error < -o->position_deadband)
        error += o->position_deadband;
    else
        return BS_R(0.0);
    rate = gain * error;
    if (rate > o->position_rate)
        rate = o->position_rate;
    if (rate < -o->position_rate)
        rate = -o->position_rate;
    return rate;
}

/* Moves x_C by the correction over interval [s] (the time since the last),
 * and the shadow (8) by its own. */
static void correct_position(bs_observer *obs, bs_sim *sim, bs_real interval)
{
    const bs_observer_options *o = &obs->options;
    bs_real rate;
    if (!o->correct_position || (bs_real)obs->steps * sim->scene->dt < o->settle_time
        || !(obs->estimate.s_sigma < o->sigma_hold))
        return;
    if (o->friction_shadow > BS_R(0.0))
        obs->shadow_s += correction_rate(o, o->friction_shadow, shadow_error(obs)) * interval;
    rate = correction_rate(o, o->position_gain, obs->estimate.s_error);
    if (rate != BS_R(0.0)) {
        move_slider(sim, rate * interval);
        obs->drift_s = bs_sim_position(sim); /* the correction is no drift */
    }
}

/* 8: the measured s's rate, low-passed over CLIMB_TIME, while it is
 * measured on the high branch (climb_s < 0: no last value to difference).
 * Whether it had one, and the rate it read into *rate if so. */
static int follow_climb(bs_observer *obs, bs_real measured, bs_real interval, bs_real *rate)
{
    const int started = obs->climb_s >= BS_R(0.0);
    if (started) {
        *rate = (measured - obs->climb_s) / interval;
        obs->climb_rate += interval / CLIMB_TIME * (*rate - obs->climb_rate);
    }
    obs->climb_s = measured;
    return started;
}

/* 8, the walk: the measured s's speed (rate, as follow_climb read it) and
 * the twin's own, low-passed over CLIMB_TIME from 0 at the climb's start
 * (started 0: both start again alike, so their ratio holds from the first
 * update), and the plant's fastest of this climb. */
static void follow_walk(bs_observer *obs, int started, bs_real rate, bs_real interval)
{
    if (!started) {
        obs->walk_rate = obs->own_rate = obs->walk_peak = BS_R(0.0);
    } else {
        obs->walk_rate += interval / CLIMB_TIME * (rate - obs->walk_rate);
        obs->own_rate += interval / CLIMB_TIME * (obs->own_ds / interval - obs->own_rate);
        if (bs_fabs(obs->walk_rate) > obs->walk_peak)
            obs->walk_peak = bs_fabs(obs->walk_rate);
    }
    obs->own_ds = BS_R(0.0);
}

/* 8, the walk: whether both walk the same way at friction_climb or faster,
 * the plant at CLIMB_PEAK_PART of its fastest in this climb or more. */
static int walking(const bs_observer *obs)
{
    const bs_real v_t = obs->own_rate, v_p = obs->walk_rate, climb = obs->options.friction_climb;
    return v_t * v_p > BS_R(0.0) && bs_fabs(v_t) >= climb && bs_fabs(v_p) >= climb
           && bs_fabs(v_p) >= CLIMB_PEAK_PART * obs->walk_peak;
}

/* 8, the walk: ln(mu_plant / mu^) from the twin's own walking speed v_t and
 * the measured v_p (v ~ mu^-k: ln(v_t / v_p) = k ln(mu_plant / mu^)), the
 * logarithm as 2 (v_t - v_p) / (v_t + v_p): within 2 % of it for speeds
 * within 30 % of each other, and bounded by 2 beyond. */
static bs_real walk_error(const bs_observer *obs)
{
    const bs_real v_t = obs->own_rate, v_p = obs->walk_rate;
    return BS_R(2.0) * (v_t - v_p) / (obs->options.friction_walk * (v_t + v_p));
}

/* 8: whether the excitation's measured frequency holds still: its mean
 * over STEADY_TIME followed over interval [s]. While it moves the slider's
 * walk answers the frequency, not only mu. */
static int steady_excitation(bs_observer *obs, bs_real interval)
{
    const bs_real f = obs->estimate.frequency;
    if (!(obs->frequency_mean > BS_R(0.0)))
        obs->frequency_mean = f;
    obs->frequency_mean += interval / STEADY_TIME * (f - obs->frequency_mean);
    return bs_fabs(f - obs->frequency_mean) <= STEADY_FREQUENCY * obs->frequency_mean;
}

/* 8: mu^ set on the twin, within (1 +- BS_OBSERVER_FRICTION_RANGE) mu_scene. */
static void set_mu(bs_observer *obs, bs_sim *sim, bs_real mu)
{
    const bs_real mu_scene = sim->scene->mu;
    const bs_real low = (BS_R(1.0) - (bs_real)BS_OBSERVER_FRICTION_RANGE) * mu_scene;
    const bs_real high = (BS_R(1.0) + (bs_real)BS_OBSERVER_FRICTION_RANGE) * mu_scene;
    mu = mu < low ? low : mu > high ? high : mu;
    (void)bs_sim_set_contact_laws(sim, mu, sim->k.e_n); /* within the range: accepted */
    obs->estimate.mu = sim->k.mu;
}

/* 8, the walk: mu^ from the two speeds, over interval [s], where
 * estimate_friction's gates have let it through (a separate path, so that
 * the other law's sample costs no more than before the walk). */
static void learn_walk(bs_observer *obs, bs_sim *sim, bs_real interval)
{
    const bs_observer_options *o = &obs->options;
    const bs_real slowing = BS_R(1.0) + obs->friction_learnt / WALK_LEARN_REF;
    bs_real rate = BS_R(0.0);
    const int started = follow_climb(obs, obs->estimate.s + obs->estimate.s_error, interval, &rate);
    follow_walk(obs, started, rate, interval);
    if (!(bs_fabs(obs->climb_rate) >= o->friction_climb) || !walking(obs))
        return;
    obs->friction_persist = walk_error(obs);
    obs->friction_learnt += interval;
    set_mu(obs, sim, sim->k.mu * (BS_R(1.0) + o->friction_gain * obs->friction_persist * interval / slowing));
}

/* 8: mu from the persistent part of the s error (or, with the walk, from
 * the two speeds: learn_walk), over interval [s]. */
static void estimate_friction(bs_observer *obs, bs_sim *sim, bs_real interval)
{
    const bs_observer_options *o = &obs->options;
    const bs_real mu_scene = sim->scene->mu;
    if (!(o->friction_gain > BS_R(0.0)) || !(mu_scene > BS_R(0.0)) || !o->correct_position
        || (bs_real)obs->steps * sim->scene->dt < o->settle_time) {
        obs->climb_s = BS_R(-1.0);
        return;
    }
    /* A ramp of the excitation changes the walk as friction would (fig6_shift
     * of the twin report): no learning while the frequency moves, its mean
     * followed from the settle time on (before, the lock-in's frequency is
     * still far off). On the low branch |H| hardly depends on s, and near
     * the clamp, where the map still resolves it, its s error reads the
     * map's error there, not friction (docs/twin.md, "Friction"): learnt on
     * the high branch only */
    if (!steady_excitation(obs, interval) || !(obs->estimate.s_sigma < o->friction_sigma)
        || !(obs->estimate.amplitude > BS_R(2.0) * o->friction_amplitude * sim->scene->half_thickness)) {
        obs->climb_s = BS_R(-1.0);
        return; /* nothing to learn from: mu^ and what is known of it hold */
    }
    /* ... and there only while the plant climbs: on its plateau the s error
     * the map leaves need not depend on mu, and mu^ would integrate it
     * without end (docs/twin.md, "Friction": where it learns) */
    if (o->friction_walk > BS_R(0.0)) {
        learn_walk(obs, sim, interval);
        return;
    }
    bs_real rate; /* the law reads the low-passed climb_rate alone */
    (void)follow_climb(obs, obs->estimate.s + obs->estimate.s_error, interval, &rate);
    if (!(bs_fabs(obs->climb_rate) >= o->friction_climb))
        return;
    obs->friction_persist += interval / o->friction_time * (shadow_error(obs) - obs->friction_persist);
    obs->friction_learnt += interval;
    set_mu(obs, sim, sim->k.mu - o->friction_gain * mu_scene * friction_drive(obs) * interval);
}

/* The guard of every call that changes the twin: an observer made by
 * bs_observer_init, a sim fit to step, and that observer's own sim. */
static bs_status usable(const bs_observer *obs, const bs_sim *sim)
{
    bs_status status;
    if (!obs)
        return BS_E_NULL;
    if (obs->ready != OBSERVER_READY)
        return BS_E_UNINITIALISED;
    status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    return sim == obs->sim ? BS_OK : BS_E_ARGUMENT;
}

/* obs, as an address the compiler no longer takes for a link-time
 * constant (BS_FORGET): with the observer a static (a firmware's), GCC
 * would read the address of each block the lock-in and the correction move
 * with one vldm or vstm from a literal in flash (a load with wait states)
 * instead of adding its offset to the register that holds obs. */
static bs_observer *in_register(bs_observer *obs)
{
    BS_FORGET(obs);
    return obs;
}

/* One step, with a measurement (measured 1) or without one: the sample of
 * y_k was lost, and the step does all but what needs it (the output
 * injection and the lock-in's products with y). The stages it runs every
 * step (beyond_gate, correction_of, commit_correction, demodulate) are
 * BS_INLINE: left to GCC, whether they are inlined hangs on the size of the
 * firmware around them, and a change of its main loop alone made them
 * calls (tests/qemu/twin_probe.sh on twin-cost-friction-off: the observer
 * step 2424.6 estimated cycles with them static, 2276.1 inlined). */
static bs_status observe(bs_observer *obs, bs_sim *sim, bs_real base_accel, bs_real measurement, int measured)
{
    const int given = measured;
    bs_status status;
    bs_real e;
    int aligned;

    status = usable(obs, sim);
    if (status != BS_OK)
        return status;
    if (!finite(base_accel) || !finite(measurement))
        return BS_E_ARGUMENT; /* refused: nothing changes */
    status = bs_step_measured(sim, base_accel); /* bs_sim_step_measured without its checks: made above */
    if (status != BS_OK)
        return status;

    obs->steps += 1;
    obs->head = obs->head == BS_OBSERVER_MAX_LATENCY ? 0 : obs->head + 1;
    obs->past_deflection[obs->head] = bs_sensor_of(sim);
    obs->past_signal[obs->head] = obs->signal == BS_SIGNAL_DEFLECTION ? obs->past_deflection[obs->head]
                                                                      : twin_signal(sim, obs->signal);
    obs->past_accel[obs->head] = base_accel;
    aligned = obs->head - obs->latency;
    if (aligned < 0)
        aligned += BS_OBSERVER_MAX_LATENCY + 1;

    e = measured ? measurement - obs->past_signal[aligned] : BS_R(0.0);
    if (BS_LIKELY(measured)) { /* a lost sample is rare; an outlier is skipped (7): the step goes on without it */
        corrected_state corrected;
        int outlier = beyond_gate(obs, e);
        if (!outlier && obs->options.correct_beam) {
            correction_of(in_register(obs), sim, e, &corrected);
            outlier = !commit_correction(sim, &corrected);
        }
        if (outlier) {
            obs->estimate.outliers += obs->estimate.outliers < UINT32_MAX;
            obs->last_outlier = obs->steps;
            measured = 0;
        }
    }
    obs->estimate.measurement = given ? measurement : obs->past_signal[aligned];
    obs->estimate.prediction = obs->past_signal[aligned];
    obs->estimate.innovation = e;
    if (!measured)
        measurement = obs->past_signal[aligned]; /* as if it had been predicted exactly */
    demodulate(in_register(obs), obs->past_accel[aligned], measurement, obs->past_signal[aligned],
               obs->past_deflection[aligned], twin_power(sim), measured);
    if (obs->steps % POSITION_EVERY == 0) {
        const bs_real dt = sim->scene->dt;
        estimate_position(obs, sim, dt);
        correct_position(obs, sim, dt * (bs_real)POSITION_EVERY);
        estimate_friction(obs, sim, dt * (bs_real)POSITION_EVERY);
    }
    return BS_OK;
}

bs_status bs_observer_step(bs_observer *obs, bs_sim *sim, bs_real base_accel, bs_real measurement)
{
    return observe(obs, sim, base_accel, measurement, 1);
}

bs_status bs_observer_predict(bs_observer *obs, bs_sim *sim, bs_real base_accel)
{
    return observe(obs, sim, base_accel, BS_R(0.0), 0);
}

bs_status bs_observer_get(const bs_observer *obs, bs_observer_estimate *estimate)
{
    if (!obs || !estimate)
        return BS_E_NULL;
    if (obs->ready != OBSERVER_READY)
        return BS_E_UNINITIALISED;
    /* member by member, as in bs_observer_init: no memcpy in the core */
    estimate->s = bs_sim_position(obs->sim); /* the twin's own, formed here: a division a step saved */
    estimate->s_sigma = obs->estimate.s_sigma;
    estimate->s_error = obs->estimate.s_error;
    estimate->amplitude = obs->estimate.amplitude;
    estimate->power = obs->estimate.power;
    estimate->phase_error = obs->estimate.phase_error;
    estimate->frequency = obs->estimate.frequency;
    estimate->measurement = obs->estimate.measurement;
    estimate->prediction = obs->estimate.prediction;
    estimate->innovation = obs->estimate.innovation;
    estimate->mu = obs->estimate.mu;
    estimate->mu_sigma = mu_sigma_of(obs);
    {
        const bs_real noise_sq = obs->gains->noise * obs->gains->noise;
        const bs_real held = obs->options.lockin_time / obs->sim->scene->dt; /* steps the flag stays */
        estimate->innovation_rms = bs_sqrt(obs->innovation_sq > noise_sq ? obs->innovation_sq : noise_sq);
        estimate->outliers = obs->estimate.outliers;
        estimate->health = obs->last_outlier > 0 && (bs_real)(obs->steps - obs->last_outlier) < held
                               ? BS_OBSERVER_HEALTH_OUTLIERS
                               : 0;
    }
    return BS_OK;
}

bs_status bs_observer_get_friction(const bs_observer *obs, bs_real *mu, bs_real *mu_sigma)
{
    if (!obs || !mu)
        return BS_E_NULL;
    if (obs->ready != OBSERVER_READY)
        return BS_E_UNINITIALISED;
    *mu = obs->estimate.mu;
    if (mu_sigma)
        *mu_sigma = mu_sigma_of(obs);
    return BS_OK;
}

bs_status bs_observer_set_friction(bs_observer *obs, bs_sim *sim, bs_real mu, bs_real mu_sigma)
{
    bs_status status;
    bs_real prior, mu_scene, learnt;
    status = usable(obs, sim);
    if (status != BS_OK)
        return status;
    mu_scene = sim->scene->mu;
    prior = friction_prior(obs);
    if (!finite(mu) || !finite(mu_sigma) || !(mu >= (BS_R(1.0) - (bs_real)BS_OBSERVER_FRICTION_RANGE) * mu_scene)
        || !(mu <= (BS_R(1.0) + (bs_real)BS_OBSERVER_FRICTION_RANGE) * mu_scene) || !(mu_sigma > BS_R(0.0))
        || !(mu_sigma <= prior))
        return BS_E_ARGUMENT;
    learnt = FRICTION_LEARN_REF * (prior * prior / (mu_sigma * mu_sigma) - BS_R(1.0));
    if (!finite(learnt))
        return BS_E_ARGUMENT;
    status = bs_sim_set_contact_laws(sim, mu, sim->k.e_n);
    if (status != BS_OK)
        return status;
    obs->friction_learnt = learnt < BS_R(0.0) ? BS_R(0.0) : learnt;
    obs->friction_persist = BS_R(0.0);
    obs->climb_s = BS_R(-1.0);
    obs->climb_rate = BS_R(0.0);
    obs->estimate.mu = sim->k.mu;
    return BS_OK;
}
