/* excitation_file.h - a recorded base acceleration (CSV or WAV) and the mean
 * base acceleration of each step it gives a run (docs/twin.md, "Recorded base
 * acceleration"; the core's input: bs_sim_step_measured, docs/model.md 10).
 *
 * The samples are instantaneous values x_j of the base acceleration at
 * t_j = t0 + j / fs. Between samples the record is the straight line through
 * them; the step [t_B, t_E] gets that line's exact mean over
 * [t_B + latency, t_E + latency]. Nothing is filtered, clamped or cut short:
 * a record that does not cover the run is refused.
 */
#ifndef EXCITATION_FILE_H
#define EXCITATION_FILE_H

#include <stddef.h>
#include <stdint.h>

#define EXCITATION_G 9.80665 /* standard gravity [m/s^2]: CSV "unit = g" */

/* How to take a record: what the file cannot say itself, and the latency. */
typedef struct excitation_file_options {
    int has_scale;    /* 1: scale was given (required for WAV, refused for CSV) */
    double scale;     /* WAV: m/s^2 per full scale, finite and > 0 */
    int channel;      /* WAV: the channel to read, 1-based; 0: not given (mono only) */
    double latency;   /* the sensor delivers the acceleration of t at t + latency [s], >= 0 */
} excitation_file_options;

/* A record as read. */
typedef struct excitation_file {
    const char *path;  /* as given to excitation_file_read (not copied) */
    const char *format; /* "csv" or "wav" */
    double rate;       /* fs, samples per second [Hz], > 0 */
    double t0;         /* time of sample 0 [s] (WAV: 0) */
    double latency;    /* from the options [s] */
    size_t samples;    /* >= 1 */
    double *accel;     /* samples [m/s^2] (malloc'd; excitation_file_free) */
} excitation_file;

/* Reads path: a WAV file if it begins with "RIFF", else the CSV format of
 * docs/twin.md. Returns 0, or -1 with a message in err that names the file
 * and what is wrong (CSV: the line; WAV: the chunk or the sample index);
 * then record holds nothing to free. */
int excitation_file_read(const char *path, const excitation_file_options *options, excitation_file *record,
                         char *err, size_t err_size);

void excitation_file_free(excitation_file *record);

/* The whole steps of dt the record covers from t = 0 (0: not one). */
uint64_t excitation_file_steps(const excitation_file *record, double dt);

/* The mean base acceleration of steps 1 .. steps into means[0 .. steps - 1]
 * [m/s^2]. Returns 0, or -1 with both durations in err when the record does
 * not cover [latency, steps dt + latency]. */
int excitation_file_means(const excitation_file *record, double dt, uint64_t steps, double *means, char *err,
                          size_t err_size);

#endif
