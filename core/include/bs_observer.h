/* bs_observer.h - the digital twin's observer: a bs_sim corrected from
 * measurements of the real harvester (docs/twin.md, "Observer";
 * docs/model.md 10).
 *
 * Per step the caller gives the mean base acceleration a_k [m/s^2] (what
 * drives the twin, bs_sim_step_measured) and one beam signal y_k: the
 * deflection w(4L/7) [m] of a laser or strain gauge, or the transducer's
 * patch voltage v [V]. The observer steps the twin and then
 *
 *   1. corrects its beam state by output injection, q += L_q e, u += L_u e
 *      (v += L_v e), e = y_k - y^ with y^ the twin's own signal delayed by
 *      the stated latency, and carries the slider along; the gains L are
 *      steady-state Kalman gains of the beam with the slider attached at the
 *      twin's s, designed on the host (host/lib/observer_design.c);
 *   2. corrects the slider position s = x_C / L, which nobody measures, from
 *      how the beam responds: the measured signal is demodulated against a_k
 *      (a lock-in), and the response magnitude |H| is located on a map of
 *      the scene's own response against s (host-made, both branches; at
 *      the twin's mu where maps at several mu were made); a slow,
 *      rate-limited integral action moves x_C toward it;
 *   3. optionally (friction_gain > 0) estimates the plant's Coulomb friction
 *      from the persistent part of that s error on the high branch and sets
 *      it on the twin (bs_sim_set_contact_laws; docs/twin.md, "Friction").
 *
 * Like bs_sim, a bs_observer is a caller-owned struct of compile-time size
 * (`static bs_observer obs;`) whose members are private; read it through
 * bs_observer_get. It holds a pointer to its gains, which must outlive it
 * and not change under it: it keeps the gains of the schedule's interval the
 * slider is in (bs_observer_init again after changing them).
 */
#ifndef BS_OBSERVER_H
#define BS_OBSERVER_H

#include "beamslider.h"
#include "bs_lockin_layout.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Longest latency of the beam signal behind the base acceleration [steps]. */
#ifndef BS_OBSERVER_MAX_LATENCY
#define BS_OBSERVER_MAX_LATENCY 256
#endif

/* Points of the gain schedule (the Kalman gains against s). */
#define BS_OBSERVER_GAINS 24

/* Points of the response map (the first-harmonic response against s). */
#define BS_OBSERVER_TABLE 48

/* Room for response maps, one per excitation (frequency, amplitude) and
 * friction coefficient: an ambient frequency that moves is followed map to
 * map, and maps of one excitation made at several mu are interpolated at the
 * twin's mu (which the friction estimate moves). The default holds eight
 * excitations at three mu each. A firmware whose excitation keeps one
 * frequency and whose maps do not follow mu saves 2 x 48 values per map with
 * -DBS_OBSERVER_MAPS=1 (core and application compiled with the same value,
 * as for BS_OBSERVER_MAX_LATENCY; gains printed by `beamslider twin-gains`
 * refuse to compile with fewer than they carry). */
#ifndef BS_OBSERVER_MAPS
#define BS_OBSERVER_MAPS 24
#endif

/* What the measured beam signal is. */
typedef enum bs_observer_signal {
    BS_SIGNAL_DEFLECTION = 0, /* w(4L/7) [m], no base motion (bs_sim_sensor) */
    BS_SIGNAL_VOLTAGE = 1     /* patch voltage v [V] (bs_sim_get_transducer; resistor load) */
} bs_observer_signal;

/* The observer's constants, designed on the host for one scene, signal chain
 * and noise (host/lib/observer_design.c; `beamslider twin-gains` prints them
 * as a C header). */
typedef struct bs_observer_gains {
    int n_modes;                        /* the scene's mode count */
    int signal;                         /* bs_observer_signal */
    int latency;                        /* the signal lags a_k by this many steps, 0 .. BS_OBSERVER_MAX_LATENCY */
    bs_real noise;                      /* measurement noise standard deviation [m or V], > 0 */
    int gain_count;                     /* points of the gain schedule, 2 .. BS_OBSERVER_GAINS */
    bs_real gain_s[BS_OBSERVER_GAINS];  /* s, ascending, within the clamp stops / L */
    bs_real gain_q[BS_OBSERVER_GAINS][BS_MAX_MODES]; /* L_q = Phi^latency K at gain_s: modal
                                                        displacement per unit of e */
    bs_real gain_u[BS_OBSERVER_GAINS][BS_MAX_MODES]; /* L_u: modal velocity per unit of e */
    bs_real gain_v[BS_OBSERVER_GAINS];  /* L_v: patch voltage per unit of e (0 without a transducer) */
    int map_count;                      /* response maps, 1 .. BS_OBSERVER_MAPS */
    bs_real map_frequency[BS_OBSERVER_MAPS]; /* the excitation map m was made at: f_ex [Hz], ascending
                                               (equal for maps of one excitation at several mu) */
    bs_real map_accel[BS_OBSERVER_MAPS];     /* and its amplitude a [m/s^2] */
    bs_real map_friction[BS_OBSERVER_MAPS];  /* and the Coulomb friction mu it was made at, >= 0.
                                               Maps of one excitation (equal frequency and
                                               amplitude), in ascending mu, are interpolated
                                               linearly at the twin's mu; beyond the first or
                                               last the nearest is used alone */
    int table_count;                    /* points of each response map, 2 .. BS_OBSERVER_TABLE */
    bs_real table_s[BS_OBSERVER_TABLE]; /* s, ascending, within [stop_min / L, 1/2] */
    bs_real table_stiff[BS_OBSERVER_MAPS][BS_OBSERVER_TABLE]; /* map m: |H| [signal unit per m/s^2]
                                               of the branch below its resonance (Re H < 0: the
                                               low-amplitude branch near the clamp and the
                                               hardened high branch), from a PCS sweep from the
                                               clamp toward the centre */
    bs_real table_soft[BS_OBSERVER_MAPS][BS_OBSERVER_TABLE]; /* |H| of the branch above it (Re H > 0:
                                               the low-amplitude branch toward the centre), from a
                                               PCS sweep from the centre toward the clamp; in
                                               either, a negative value: no such branch at that s */
} bs_observer_gains;

/* Run-time settings (bs_observer_defaults). */
typedef struct bs_observer_options {
    int correct_beam;        /* 1: output injection on the beam state; 0: none (open loop) */
    int correct_position;    /* 1: the s correction; 0: none */
    bs_real lockin_time;     /* time constant of each of the lock-in's two low-pass stages [s], > 0 */
    bs_real position_gain;   /* part of the estimated s error corrected per second [1/s], >= 0 */
    bs_real position_rate;   /* largest correction speed |ds/dt| [1/s], >= 0 */
    bs_real position_deadband; /* s errors up to this are left to the twin's own dynamics [1], >= 0:
                                  the response map's uncertainty (a model off by 3 % in frequency
                                  moves it by ~0.01) */
    bs_real sigma_hold;      /* no s correction while s_sigma exceeds this [1], > 0 */
    bs_real excitation_tolerance; /* a map is used only while the measured excitation is within
                                     this relative distance of its own (frequency: a tenth of
                                     it; the map nearest in frequency), > 0 */
    bs_real settle_time;     /* no s correction during the first settle_time [s] (the lock-in
                                filling), >= 0 */
    bs_real outlier_gate;    /* a measurement whose innovation exceeds outlier_gate times the
                                innovation's running RMS is skipped as an outlier (counted;
                                the step goes on as without a measurement), > 1 */
    bs_real friction_gain;   /* the friction estimate (docs/twin.md, "Friction"): relative change
                                of mu per second per unit of persistent s error beyond
                                friction_deadband [1/s], >= 0; 0: mu is not estimated (the sim's
                                stays as set) */
    bs_real friction_time;   /* time constant of the persistent part of the s error [s], > 0 */
    bs_real friction_deadband; /* persistent s errors up to this leave mu alone [1], >= 0 */
    bs_real friction_sigma;  /* mu is learnt only while s_sigma is below this (where s is
                                measured: the high branch, and near the clamp the low one) [1],
                                > 0 */
    bs_real friction_amplitude; /* ... and the twin's w(4L/7) amplitude above this many beam
                                   thicknesses h (the high branch; the low branch stays below
                                   h/4) [1], >= 0 */
    bs_real friction_climb;  /* ... and while the measured s moves at least this fast (the plant
                                climbing the high branch; its rate low-passed over 1 s) [1/s],
                                >= 0 */
    bs_real friction_shadow; /* 0: the estimate reads the twin's s error; > 0: that of a shadow
                                of the twin's slider, which moves with the twin's own drift and
                                is corrected at this gain (with position_deadband and
                                position_rate), so that a strong position_gain, which keeps the
                                twin on the plant, does not take away the lag the estimate reads
                                (docs/twin.md, "The shadow") [1/s], >= 0 */
    bs_real friction_walk;   /* 0: mu follows the persistent s error; > 0: the exponent k of the
                                slider's walking speed in mu on the high branch (v ~ mu^-k),
                                and mu follows the twin's own walking speed against the
                                measured one, at friction_gain [1/s] (docs/twin.md, "The
                                walk") [1], >= 0 */
    bs_real jump_hold;       /* no s correction (and so no friction learning) for this long after
                                the measured response starts falling fast from the high branch
                                (the twin's amplitude above h/2; a jump to the low branch under
                                way: the lock-in holds the old branch's response for ~10
                                lockin_time) [s], >= 0; 0: none */
} bs_observer_options;

/* Defaults (tuned on fig6, docs/twin.md): both corrections, lock-in 0.1 s,
 * gain 1 /s, rate 0.05 /s, deadband 0.004, hold above s_sigma 0.02,
 * excitation within 10 % (frequency 1 %), settle 0.5 s, outliers beyond
 * 6 times the innovation's RMS; no hold after a fall (jump_hold 0). */
#define BS_OBSERVER_DEFAULT_LOCKIN_TIME 0.1
#define BS_OBSERVER_DEFAULT_POSITION_GAIN 1.0
#define BS_OBSERVER_DEFAULT_EXCITATION_TOLERANCE 0.1
#define BS_OBSERVER_DEFAULT_POSITION_RATE 0.05
#define BS_OBSERVER_DEFAULT_POSITION_DEADBAND 0.004
#define BS_OBSERVER_DEFAULT_SIGMA_HOLD 0.02
#define BS_OBSERVER_DEFAULT_SETTLE_TIME 0.5
#define BS_OBSERVER_DEFAULT_OUTLIER_GATE 6.0
#define BS_OBSERVER_DEFAULT_FRICTION_GAIN 0.0
#define BS_OBSERVER_DEFAULT_FRICTION_TIME 0.5
#define BS_OBSERVER_DEFAULT_FRICTION_DEADBAND 0.001
#define BS_OBSERVER_DEFAULT_FRICTION_SIGMA 0.002
#define BS_OBSERVER_DEFAULT_FRICTION_AMPLITUDE 0.5
#define BS_OBSERVER_DEFAULT_FRICTION_CLIMB 0.001
#define BS_OBSERVER_DEFAULT_FRICTION_SHADOW 0.0
#define BS_OBSERVER_DEFAULT_FRICTION_WALK 0.0
#define BS_OBSERVER_DEFAULT_JUMP_HOLD 0.0
/* The friction estimate stays within [1 - range, 1 + range] times the
 * scene's mu (twice the +-25 % a plant is drawn with in the twin report). */
#define BS_OBSERVER_FRICTION_RANGE 0.5

/* bs_observer_estimate.health: bits. */
#define BS_OBSERVER_HEALTH_OUTLIERS 1 /* a measurement was skipped as an outlier within the last
                                         lockin_time (or its correction would have broken the
                                         sim's state: a slider off the beam, a value not finite) */

/* What the observer knows after a step (bs_observer_get). */
typedef struct bs_observer_estimate {
    bs_real s;              /* the twin's slider position x_C / L */
    bs_real s_sigma;        /* standard deviation of s [1]: large where the response is tiny */
    bs_real s_error;        /* the latest estimate of s_plant - s_twin, before rate limits */
    bs_real amplitude;      /* first-harmonic amplitude of the twin's w(4L/7) [m] */
    bs_real power;          /* mean power into the transducer's load [W] (0 without one) */
    bs_real phase_error;    /* arg(H_measured / H_twin) at the excitation [rad] */
    bs_real frequency;      /* the excitation frequency found in a_k [Hz] (0 before it is known) */
    bs_real measurement;    /* y_k as given */
    bs_real prediction;     /* y^_k, the twin's signal it was compared with */
    bs_real innovation;     /* e = y_k - y^_k */
    bs_real innovation_rms; /* the running RMS of e the outlier gate compares with */
    uint32_t outliers;      /* measurements skipped as outliers since bs_observer_init */
    int health;             /* 0, or BS_OBSERVER_HEALTH_* bits */
    bs_real mu;             /* the twin's Coulomb friction: the estimate mu^ while friction_gain > 0 */
    bs_real mu_sigma;       /* standard deviation of mu^ (docs/twin.md, "Friction"); 0 when mu is
                               not estimated */
} bs_observer_estimate;

/* PRIVATE members (core/src/bs_observer.c). */
typedef struct bs_observer {
    uint32_t ready;
    const bs_sim *sim;                                /* the twin it was initialised with */
    const bs_observer_gains *gains;
    bs_observer_options options;
    uint64_t steps;
    int head;                                         /* ring index of the newest entry */
    /* what every sample reads of the gains and the scene, copied at init:
     * a controller keeps those in flash, where each read costs wait states */
    int latency, signal;                              /* the gains' */
    int gain_last;                                    /* the gain schedule's last index */
    bs_real noise_sq;                                 /* the gains' noise, squared */
    bs_real com_offset;                               /* the scene's */
    bs_lockin_reference reference;                    /* the aligned a_k and its quadrature */
    bs_lowpass2 meas_a, meas_b;                       /* <y a>, <y b> */
    bs_lowpass2 twin_a, twin_b;                       /* <y^ a>, <y^ b> (unused when y is w: defl_a, defl_b) */
    bs_lowpass2 defl_a, defl_b;                       /* <w a>, <w b>: the twin's w(4L/7) */
    bs_real innovation_sq;                            /* running mean of e^2, each clipped at the gate */
    uint64_t last_outlier;                            /* step of the last outlier (0: none) */
    uint64_t hold_until;                              /* no s correction before this step (jump_hold) */
    int gain_interval;                                /* the gain schedule's interval of the last step
                                                         (-1: none yet) */
    bs_real gain_s_from, gain_s_to, gain_s_width;     /* its start, end and width in s (its start
                                                         as the end of an end interval: gains_at) */
    bs_real gain_from[2 * BS_MAX_MODES + 1];          /* L_q, L_u, L_v at its start, */
    bs_real gain_change[2 * BS_MAX_MODES + 1];        /* and their change over it */
    bs_shape_cache shape;                             /* the mode shapes expanded about the slider */
    bs_lowpass2 power;                                /* <p> */
    bs_lowpass2 s_error_mean, s_error_sq;             /* of the raw s error */
    bs_real drift_alpha;                              /* the lock-in's alpha over POSITION_EVERY steps */
    bs_real drift_s;                                  /* the twin's s after the last position update */
    bs_real drift_lag[2];                             /* its own drift less that through one and two
                                                         of the lock-in's stages (5) */
    bs_real friction_persist;                         /* the s error low-passed over friction_time
                                                         (the walk: its last ln(mu_plant / mu^)) */
    bs_real friction_learnt;                          /* time spent learning mu [s] */
    bs_real climb_s;                                  /* the measured s at the last update on the
                                                         high branch (-1: none) (8) */
    bs_real climb_rate;                               /* its rate, low-passed over 1 s [1/s] */
    bs_real shadow_s;                                 /* the shadow's s, read with friction_shadow > 0 (8) */
    bs_real own_ds;                                   /* the twin's own drift since the last
                                                         friction update (8) */
    bs_real walk_rate, own_rate;                      /* the measured s's rate and the twin's own,
                                                         low-passed over 1 s from 0 at the climb's
                                                         start (8, the walk) [1/s] */
    bs_real walk_peak;                                /* the largest abs(walk_rate) of this climb */
    bs_real frequency_mean;                           /* the measured excitation's frequency,
                                                         low-passed over 1 s (0: none yet) (8) [Hz] */
    bs_observer_estimate estimate;
    /* the delay lines last: what a sample reads stays within short offsets
     * (a Cortex-M's VLDR reaches 1020 bytes) */
    bs_real past_signal[BS_OBSERVER_MAX_LATENCY + 1]; /* the twin's signal, newest at head */
    bs_real past_accel[BS_OBSERVER_MAX_LATENCY + 1];  /* a_k, aligned with it */
    bs_real past_deflection[BS_OBSERVER_MAX_LATENCY + 1]; /* the twin's w(4L/7), aligned with it */
} bs_observer;

/* The default options. */
bs_observer_options bs_observer_defaults(void);

/* The observer's table sizes as this translation unit sees them: with the
 * core's build tag and the sizes of bs_observer and bs_observer_gains they
 * go to the library through bs_observer_init (the zlib inflateInit_ pattern,
 * as bs_sim_init does), so a firmware compiled with another
 * BS_OBSERVER_MAPS or BS_OBSERVER_MAX_LATENCY than its core is refused with
 * BS_E_BUILD instead of reading its gains out of place. */
#define BS_OBSERVER_TAG (((uint32_t)(BS_OBSERVER_MAPS) << 16) | ((uint32_t)(BS_OBSERVER_MAX_LATENCY) & 0xffffu))

/* Starts observing the twin sim (initialised, free model, the scene the
 * gains were designed for: its mode count, and a transducer with a resistor
 * load for BS_SIGNAL_VOLTAGE); options NULL: the defaults. The sim's state
 * is the initial estimate (start it on the known side of the beam: s and
 * 1 - s respond alike). Returns BS_OK, BS_E_NULL, BS_E_BUILD (this program
 * and the library built with another precision, switches, BS_OBSERVER_MAPS
 * or BS_OBSERVER_MAX_LATENCY: nothing is written), BS_E_UNINITIALISED (sim)
 * or BS_E_ARGUMENT (gains or options out of range, a PCS sim, gains of
 * another scene); after another error the observer is not initialised. */
#define bs_observer_init(obs, sim, gains, options)                                                  \
    bs_observer_init_(BS_BUILD_TAG, BS_OBSERVER_TAG, sizeof(bs_observer), sizeof(bs_observer_gains), \
                      (obs), (sim), (gains), (options))
bs_status bs_observer_init_(uint32_t tag, uint32_t observer_tag, size_t observer_size, size_t gains_size,
                            bs_observer *obs, const bs_sim *sim, const bs_observer_gains *gains,
                            const bs_observer_options *options);

/* One step: advances sim by bs_sim_step_measured(sim, base_accel), then
 * corrects it with the measurement y_k (units of gains->signal). sim must
 * be the sim the observer was initialised with. A base_accel or
 * measurement that is not finite, or another sim, is refused with
 * BS_E_ARGUMENT and nothing changes; a failed twin step returns its status
 * (the sim keeps its last good state, the observer is unchanged).
 * Outliers (docs/twin.md, "Outliers"): a measurement whose innovation is
 * beyond options.outlier_gate times its running RMS, or whose correction
 * would leave the sim in a state bs_sim_set_state refuses (the slider off
 * the beam, a value not finite), is skipped: the step goes on as
 * bs_observer_predict's, the estimate counts it (outliers) and flags it
 * (health), and BS_OK is returned. Returns BS_OK, BS_E_NULL,
 * BS_E_UNINITIALISED, BS_E_ARGUMENT or a status of bs_sim_step. */
bs_status bs_observer_step(bs_observer *obs, bs_sim *sim, bs_real base_accel, bs_real measurement);

/* One step without a measurement: the sample of y_k was lost (a FIFO
 * overrun, a sensor error). Advances sim by bs_sim_step_measured(sim,
 * base_accel), base_accel the caller's best value for the step (e.g.
 * interpolated between the samples either side of a gap), and the delay
 * line with it, so that the next measurement meets the twin's prediction of
 * its own time. No beam correction (the twin runs open loop for the step);
 * the lock-in's products with y hold, while its reference (an integral of
 * a over time) and the twin's own products go on, and so does the s
 * correction from them. The estimate's innovation is 0 and its measurement
 * the prediction. A base_accel that is not finite is refused with
 * BS_E_ARGUMENT and nothing changes, and so is another sim than the
 * observer's; a failed twin step returns its status (nothing changes).
 * Returns BS_OK, BS_E_NULL, BS_E_UNINITIALISED, BS_E_ARGUMENT or a status
 * of bs_sim_step. */
bs_status bs_observer_predict(bs_observer *obs, bs_sim *sim, bs_real base_accel);

/* Copies the latest estimate into *estimate. Returns BS_OK, BS_E_NULL or
 * BS_E_UNINITIALISED. */
bs_status bs_observer_get(const bs_observer *obs, bs_observer_estimate *estimate);

/* The friction estimate mu^ [1] and its standard deviation (mu_sigma may be
 * NULL). mu^ is the twin sim's friction (bs_sim_get_contact_laws): a
 * checkpoint of the sim (bs_sim_save) holds it, and bs_sim_restore checks
 * it. Returns BS_OK, BS_E_NULL or BS_E_UNINITIALISED. */
bs_status bs_observer_get_friction(const bs_observer *obs, bs_real *mu, bs_real *mu_sigma);

/* Resumes the friction estimate where a saved one left off (after
 * bs_sim_restore and bs_observer_init): mu^ within [1 - range, 1 + range]
 * times the scene's mu (BS_OBSERVER_FRICTION_RANGE), and mu_sigma in
 * (0, the prior's] (the prior: uniform over that range) are checked; mu^
 * goes to the sim (bs_sim_set_contact_laws, e_N kept) and the learning time
 * that mu_sigma stands for to the observer. Returns BS_OK, BS_E_NULL,
 * BS_E_UNINITIALISED or BS_E_ARGUMENT (another sim, a value out of range:
 * nothing changes). */
bs_status bs_observer_set_friction(bs_observer *obs, bs_sim *sim, bs_real mu, bs_real mu_sigma);

#ifdef __cplusplus
}
#endif

#endif
