/* twin_plant.h - a test stream for the twin: the scene as the plant (its
 * modal frequencies perhaps scaled, the "wrong model" a twin must cope
 * with), its base acceleration and signal with white noise and quantisation,
 * the signal late by a latency, written as a measured-signals file
 * (measured_signals.h, the one writer). `beamslider twin-plant`.
 *
 * Two passes over the same run: the first measures the RMS and the largest
 * magnitude of both signals (the noise is set SNR dB below the RMS, the
 * quantiser's full scale to twice the largest value), the second writes the
 * rows. The plant steps the scene's [excitation] schedule through run's own
 * function (run_step_harmonic), so that its w(4L/7) is `run`'s at every step.
 */
#ifndef TWIN_PLANT_H
#define TWIN_PLANT_H

#include <stdint.h>
#include <stdio.h>
#include "scene_build.h"

typedef struct twin_plant_options {
    int signal;               /* BS_SIGNAL_DEFLECTION or BS_SIGNAL_VOLTAGE (resistor load only) */
    long latency;             /* the signal's delay [steps], 0 .. BS_OBSERVER_MAX_LATENCY */
    double snr, accel_snr;    /* [dB] below each signal's RMS; INFINITY: no noise */
    int bits;                 /* quantisation over +-2x the largest value; 0: none */
    unsigned long seed;       /* of the noise (xorshift64*, Box-Muller) */
    double freq_scale;        /* the plant's modal frequencies were scaled by this (for the header) */
} twin_plant_options;

typedef struct twin_plant_result {
    uint64_t steps;
    double signal_rms, accel_rms;   /* of the clean signals */
    double signal_max, accel_max;   /* their largest magnitudes (the quantiser's full scale is twice) */
    double noise, accel_noise;      /* the noise standard deviations added */
} twin_plant_result;

/* Every modal frequency of model's data times scale (damping ratios kept,
 * the implicit step's gains again), rounded into scene: the perturbed plant.
 * 0, or -1 with err when the scene is then no longer one the core takes. */
int twin_plant_scale_frequencies(scene_model *model, bs_scene *scene, double scale, char *err, size_t err_size);

/* The latency of seconds at dt in whole steps; beyond
 * BS_OBSERVER_MAX_LATENCY (which callers refuse) the quotient is not
 * converted: it may exceed a long. */
long twin_latency_steps(double seconds, double dt);

/* Checks the options against the scene: 0, or -1 with err (a voltage
 * signal without a resistor load, a latency beyond BS_OBSERVER_MAX_LATENCY
 * steps). */
int twin_plant_check(const scene_file *file, const bs_scene *scene, const twin_plant_options *options, char *err,
                     size_t err_size);

/* The first pass: runs the plant over the scene's t_end and measures the
 * clean signals into result (the noise follows from them). 0, or -1 with
 * err when the plant's run stopped. Nothing is written: a caller opens its
 * output only after this succeeded. */
int twin_plant_measure(const scene_file *file, const bs_scene *scene, const twin_plant_options *options,
                       twin_plant_result *result, char *err, size_t err_size);

/* The second pass: the same run again, the stream written to out (header
 * and rows) with result's noise. 0; -1 with err when the run stopped or a
 * write failed (*write_failed set). */
int twin_plant_write(const scene_file *file, const bs_scene *scene, const twin_plant_options *options,
                     const twin_plant_result *result, FILE *out, int *write_failed, char *err, size_t err_size);

#endif
