/* twin_run.h - the twin on a measured stream (docs/twin.md, "Observer"):
 * the scene's sim corrected by the observer (core/include/bs_observer.h)
 * from each row of a measured-signals file (measured_signals.h), its
 * estimates written as CSV and scored against the stream's truth.
 * `beamslider twin`.
 */
#ifndef TWIN_RUN_H
#define TWIN_RUN_H

#include <stdint.h>
#include <stdio.h>
#include "bs_observer.h"
#include "measured_signals.h"
#include "scene_build.h"

/* The stream the twin reads, opened: the header read (its rate checked
 * against the scene's dt) and, for a file, every row checked in a first
 * pass before anything is written (its signal's sum of squares kept: the
 * default noise). Standard input ("-") is read once: its rows are checked
 * as the twin reads them. */
typedef struct twin_stream {
    measured_reader reader;
    int is_stdin;
    double y_sq;            /* sum of signal^2 over the rows (a file's first pass) */
} twin_stream;

/* Opens path ("-": standard input) for a scene of step dt. 0, or -1 with
 * err (nothing left open). */
int twin_stream_open(twin_stream *stream, const char *path, double dt, char *err, size_t err_size);
void twin_stream_close(twin_stream *stream);

/* How the twin runs and is scored. */
typedef struct twin_run_options {
    bs_observer_options observer;  /* bs_observer_defaults(), changed */
    long every;                    /* an estimate row every this many rows, >= 1 */
    double score_after;            /* [s] rows from this time on are scored ... */
    double tolerance;              /* ... within this distance of s_true */
    double mu, e_n;                /* the twin's contact laws (bs_sim_set_contact_laws); NAN: the scene's */
} twin_run_options;

/* What the run counted, for its summary. */
typedef struct twin_tally {
    uint64_t rows, scored, within;
    double innovation_sq, error_sq;
    double s_true;                 /* the last row's (NAN without truth) */
    double t_last;                 /* the last row's time [s] */
    int has_truth;                 /* the stream has s_true */
    double elapsed;                /* wall time [s] */
    bs_observer_estimate last;
} twin_tally;

/* The estimates' CSV header line. */
extern const char twin_estimates_header[];

/* Runs the twin (scene built from file, gains designed for it) over the
 * stream's rows, an estimate row to out every options->every rows. 0; -1
 * with err: the twin stopped (a core status), a write failed, or
 * (*bad_input set) a row of standard input is malformed (the estimates up
 * to it are written). */
int twin_run(const scene_file *file, const bs_scene *scene, const bs_observer_gains *gains,
             const twin_run_options *options, twin_stream *stream, FILE *out, twin_tally *tally, int *bad_input,
             char *err, size_t err_size);

/* Why nothing was scored, when nothing was (the summary's within and
 * rms_s_error are then null): "the stream has no s_true column" or "the
 * stream ends at t = 2 s, before --score-after 5 s". 1 with the reason in
 * out, 0 when rows were scored. */
int twin_unscored_reason(const twin_tally *tally, const twin_run_options *options, char *out, size_t size);

/* The twin's one-line JSON summary (out_json.h): scene, signal, rows,
 * noise, latency, corrections, innovation, outliers, health, the final
 * estimate against the truth, the score (scored: the rows scored; within
 * and rms_s_error null when none was) and the wall time. 0 or -1. */
int twin_print_summary(FILE *out, const scene_file *file, const bs_observer_gains *gains,
                       const twin_run_options *options, const twin_tally *tally, double noise);

#endif
