/* excitation_file.h - a recorded base acceleration (CSV or WAV) and the mean
 * base acceleration of each step it gives a run (docs/twin.md, "Recorded base
 * acceleration"; the core's input: bs_sim_step_measured, docs/model.md 10).
 *
 * The samples are instantaneous values x_j of the base acceleration at
 * t_j = t0 + j / fs. Between samples the record is the straight line through
 * them; the step [t_B, t_E] gets that line's exact mean over
 * [t_B + latency, t_E + latency]. Nothing is filtered, clamped or cut short:
 * a record that does not cover the run is refused.
 *
 * A record is read streaming, never held: memory stays a few hundred bytes
 * whatever its length or the run's. excitation_file_read reads it once and
 * checks everything a run will take from it (the header, every value, the
 * step count, every step mean finite and within the core's range);
 * excitation_stream then reads it again, as the run goes, for the same step
 * means bit for bit (excitation_means computes both).
 */
#ifndef EXCITATION_FILE_H
#define EXCITATION_FILE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "input_file.h"

#define EXCITATION_G 9.80665 /* standard gravity [m/s^2]: CSV "unit = g" */
/* The range of a record's sample rate [Hz] and of its t0 [s]: wide beyond
 * any accelerometer (a WAV's rate, an integer, always lies in it), and
 * narrow enough that every time and every span in samples stays exact to
 * far below a sample in double. */
#define EXCITATION_RATE_MIN 1e-3
#define EXCITATION_RATE_MAX 1e10
#define EXCITATION_T0_MAX 1e9
/* The most steps a record may give a run: 2^53, counted exactly in a double
 * (as [run] t_end / dt is, host/lib/scene/scene_build.c). */
#define EXCITATION_MAX_STEPS 9007199254740992.0
#define EXCITATION_CSV_LINE 256 /* a CSV line holds at most 255 characters before its end */

/* How to take a record: what the file cannot say itself, and the latency. */
typedef struct excitation_file_options {
    int has_scale;    /* 1: scale was given (required for WAV, refused for CSV) */
    double scale;     /* WAV: m/s^2 per full scale, finite and > 0 */
    int channel;      /* WAV: the channel to read, 1-based; 0: not given (mono only) */
    double latency;   /* the sensor delivers the acceleration of t at t + latency [s], >= 0 */
} excitation_file_options;

/* What a run takes from a record: steps of dt from t = 0, steps of them
 * (0: every whole step the record covers), each mean within +-max_mean. */
typedef struct excitation_run {
    double dt;        /* [s], > 0 */
    uint64_t steps;
    double max_mean;  /* [m/s^2], > 0 (infinity: only finite) */
} excitation_run;

/* A record as checked by excitation_file_read. */
typedef struct excitation_file {
    const char *path;  /* as given to excitation_file_read (not copied) */
    const char *format; /* "csv" or "wav" */
    double rate;       /* fs, samples per second [Hz], in [EXCITATION_RATE_MIN, EXCITATION_RATE_MAX] */
    double t0;         /* time of sample 0 [s] (WAV: 0), |t0| <= EXCITATION_T0_MAX */
    double latency;    /* from the options [s] */
    uint64_t samples;  /* >= 1 */
    uint64_t steps;    /* the run's steps: excitation_run's, or the whole steps covered (>= 1) */
    /* private: how to read it again */
    excitation_file_options options;
    input_identity identity;
} excitation_file;

/* Reads path (a WAV file if it begins with "RIFF", else the CSV format of
 * docs/twin.md) once, without keeping it, and checks it for run (NULL: the
 * file alone; then record->steps is 0). Returns 0,
 * or -1 with a message in err that names the file and what is wrong (CSV:
 * the line; WAV: the chunk or the sample index; a step mean: the step, its
 * time and the samples it reads). */
int excitation_file_read(const char *path, const excitation_file_options *options, const excitation_run *run,
                         excitation_file *record, char *err, size_t err_size);

/* ---- step means from any sequence of samples (members private) */

/* The next sample into *value: 1, 0 at the end, -1 with err filled. */
typedef int (*excitation_sample_fn)(void *source, double *value, char *err, size_t err_size);

typedef struct excitation_means {
    double rate, t0, latency, dt;
    excitation_sample_fn next;
    void *source;
    uint64_t have;       /* samples taken from the source */
    double x[2];         /* the last two: x[have - 2], x[have - 1] */
    int ended;           /* the source has no more */
    uint64_t step;       /* steps whose mean was given */
    uint64_t first, last; /* the samples the last mean read */
} excitation_means;

/* Step means of samples t0 + j / rate taken from next(source), in order,
 * for steps of dt from t = 0 read latency late. */
void excitation_means_start(excitation_means *means, double rate, double t0, double latency, double dt,
                            excitation_sample_fn next, void *source);

/* The mean of the next step into *mean [m/s^2]: 1; 0 when the samples do
 * not cover the step (then no later step either); -1 with the source's err. */
int excitation_means_next(excitation_means *means, double *mean, char *err, size_t err_size);

/* ---- the run's pass (members private) */

/* A record's samples, read in order. */
typedef struct excitation_source {
    const char *path;
    FILE *file;
    int is_wav;
    double rate, t0, latency;
    uint64_t samples;          /* read so far */
    /* CSV */
    input_lines lines;
    char text[EXCITATION_CSV_LINE];
    int pending;               /* pending_value is sample 0, not yet taken */
    double pending_value;
    int columns;               /* values a data line holds: 1, or 2 with the time */
    int has_t0;                /* the header gave t0 */
    double unit;               /* m/s^2 per unit of the values */
    double t_previous;
    long first_line;           /* the line of sample 0 */
    /* WAV */
    unsigned block, bits, channel;
    int is_float;
    uint64_t frames;
    double scale;
} excitation_source;

typedef struct excitation_stream {
    excitation_source source;
    excitation_means means;
    const excitation_file *record;
} excitation_stream;

/* Opens record (checked by excitation_file_read) again for a run of steps
 * of dt. 0, or -1 with err (the file cannot be opened, or has changed since). */
int excitation_stream_open(excitation_stream *stream, const excitation_file *record, double dt, char *err,
                           size_t err_size);

/* The next step's mean [m/s^2]: 0, or -1 with err (the file changed while
 * the run read it). */
int excitation_stream_next(excitation_stream *stream, double *mean, char *err, size_t err_size);

/* The next sample itself [m/s^2] (read instead of the step means, never
 * both from one stream): 1, 0 at the end, -1 with err. */
int excitation_stream_sample(excitation_stream *stream, double *value, char *err, size_t err_size);

void excitation_stream_close(excitation_stream *stream);

#endif
