/* twin_run.c - the twin on a measured stream (twin_run.h). */
#include "twin_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bs_platform.h"
#include "out_json.h"

const char twin_estimates_header[] =
    "t,s_hat,s_sigma,amplitude,power,y,y_hat,s_true,phase_error,s_error,outliers,health,mu,mu_sigma,energy\n";

int twin_stream_open(twin_stream *m, const char *path, double dt, char *err, size_t err_size)
{
    measured_reader *r = &m->reader;
    measured_row row;
    int status;

    memset(m, 0, sizeof *m);
    m->is_stdin = !strcmp(path, "-");
    if (measured_open(r, path, err, err_size) != 0)
        return -1;
    if (!(fabs(r->header.rate * dt - 1.0) <= 1e-9)) {
        snprintf(err, err_size, "%s: sample_rate = %g Hz, but the scene's dt = %g s needs %.10g Hz (resample the "
                 "record)", r->path, r->header.rate, dt, 1.0 / dt);
        measured_close(r);
        return -1;
    }
    if (m->is_stdin)
        return 0;
    while ((status = measured_next(r, &row, err, err_size)) > 0)
        m->y_sq += row.signal * row.signal;
    if (status < 0 || measured_rewind(r, err, err_size) != 0) {
        measured_close(r);
        return -1;
    }
    return 0;
}

void twin_stream_close(twin_stream *m)
{
    measured_close(&m->reader);
}

/* A row of the estimates. energy: the twin's energy into the load since its
 * start (0 without a transducer), whose difference over an interval is the
 * twin's mean power there exactly; power is the observer's running mean,
 * a low-pass over the lock-in time that lags the twin by about twice it. */
static int write_estimate(FILE *out, double t, const bs_observer_estimate *e, double s_true, const bs_sim *twin)
{
    bs_transducer_output transducer;
    bs_sim_get_transducer(twin, &transducer);
    return fprintf(out, "%.9g,%.9g,%.4g,%.6g,%.6g,%.6g,%.6g,%.9g,%.5g,%.5g,%lu,%d,%.6g,%.4g,%.12g\n", t, (double)e->s,
                   (double)e->s_sigma, (double)e->amplitude, (double)e->power, (double)e->measurement,
                   (double)e->prediction, s_true, (double)e->phase_error, (double)e->s_error,
                   (unsigned long)e->outliers, e->health, (double)e->mu, (double)e->mu_sigma,
                   (double)transducer.energy) < 0;
}

/* The twin's sim and observer: large, on the heap, one per run. */
typedef struct twin_state {
    bs_sim sim;
    bs_observer obs;
} twin_state;

/* The rows of the stream through the observer. */
static int observe(const twin_run_options *o, twin_state *w, twin_stream *m, FILE *out, twin_tally *tally,
                   int *bad_input, char *err, size_t err_size)
{
    measured_row sample;
    int row;

    if (fputs(twin_estimates_header, out) < 0) {
        snprintf(err, err_size, "cannot write the estimates");
        return -1;
    }
    while ((row = measured_next(&m->reader, &sample, err, err_size)) > 0) {
        const bs_status status = bs_observer_step(&w->obs, &w->sim, (bs_real)sample.base_accel,
                                                  (bs_real)sample.signal);
        if (status != BS_OK) {
            snprintf(err, err_size, "%s:%ld: the twin stopped: %s", m->reader.path, m->reader.lines.line,
                     bs_status_text(status));
            return -1;
        }
        tally->rows += 1;
        tally->t_last = sample.t;
        bs_observer_get(&w->obs, &tally->last);
        tally->innovation_sq += (double)tally->last.innovation * (double)tally->last.innovation;
        tally->s_true = sample.s_true;
        if (!isnan(sample.s_true) && sample.t >= o->score_after) {
            const double error = (double)tally->last.s - sample.s_true;
            tally->scored += 1;
            tally->within += fabs(error) <= o->tolerance;
            tally->error_sq += error * error;
        }
        if (tally->rows % (uint64_t)o->every == 0
            && write_estimate(out, sample.t, &tally->last, sample.s_true, &w->sim) != 0) {
            snprintf(err, err_size, "cannot write the estimates");
            return -1;
        }
    }
    if (row < 0) { /* a file's rows were checked before: a bad row of standard input */
        if (m->is_stdin) {
            size_t used = strlen(err);
            snprintf(err + used, err_size - used, " (the estimates up to it are written)");
        }
        *bad_input = 1;
        return -1;
    }
    return 0;
}

int twin_run(const scene_file *file, const bs_scene *scene, const bs_observer_gains *gains,
             const twin_run_options *o, twin_stream *m, FILE *out, twin_tally *tally, int *bad_input, char *err,
             size_t err_size)
{
    twin_state *w = malloc(sizeof *w);
    const bs_solver_options solver = scene_solver(&file->params);
    const double start = bs_platform_seconds();
    bs_status status;
    int failed;

    *bad_input = 0;
    memset(tally, 0, sizeof *tally);
    tally->s_true = NAN;
    tally->has_truth = m->reader.header.has_truth;
    if (!w) {
        snprintf(err, err_size, "twin: out of memory");
        return -1;
    }
    status = bs_sim_init(&w->sim, scene, BS_MODEL_FREE, (bs_real)file->params.s0);
    if (status == BS_OK)
        status = bs_sim_set_solver(&w->sim, &solver);
    if (status == BS_OK && !(isnan(o->mu) && isnan(o->e_n))) {
        bs_real mu, e_n;
        bs_sim_get_contact_laws(&w->sim, &mu, &e_n);
        status = bs_sim_set_contact_laws(&w->sim, isnan(o->mu) ? mu : (bs_real)o->mu,
                                         isnan(o->e_n) ? e_n : (bs_real)o->e_n);
    }
    if (status == BS_OK)
        status = bs_observer_init(&w->obs, &w->sim, gains, &o->observer);
    if (status != BS_OK) {
        snprintf(err, err_size, "twin: %s", bs_status_text(status));
        free(w);
        return -1;
    }
    failed = observe(o, w, m, out, tally, bad_input, err, err_size);
    tally->elapsed = bs_platform_seconds() - start;
    free(w);
    return failed;
}

int twin_unscored_reason(const twin_tally *tally, const twin_run_options *o, char *out, size_t size)
{
    if (tally->scored > 0)
        return 0;
    if (tally->rows == 0)
        snprintf(out, size, "the stream has no rows");
    else if (!tally->has_truth)
        snprintf(out, size, "the stream has no s_true column");
    else
        snprintf(out, size, "the stream ends at t = %g s, before --score-after %g s", tally->t_last, o->score_after);
    return 1;
}

/* The mu the first excitation's maps were made at, "0.15,0.2,0.25"
 * (the maps follow the twin's mu when there are several). */
static const char *map_frictions(const bs_observer_gains *gains, char *text, size_t size)
{
    size_t used = 0;
    int m;
    text[0] = '\0';
    for (m = 0; m < gains->map_count && (m == 0 || gains->map_frequency[m] == gains->map_frequency[0]); ++m) {
        const int n = snprintf(text + used, size - used, "%s%g", m ? "," : "", (double)gains->map_friction[m]);
        if (n < 0 || (size_t)n >= size - used)
            break;
        used += (size_t)n;
    }
    return text;
}

int twin_print_summary(FILE *out, const scene_file *file, const bs_observer_gains *gains, const twin_run_options *o,
                       const twin_tally *tally, double noise)
{
    const int scored = tally->scored > 0;
    char frictions[32 * BS_OBSERVER_MAPS];
    out_json j;
    out_json_start(&j);
    out_json_text(&j, "scene", file->params.name);
    out_json_text(&j, "signal", gains->signal == BS_SIGNAL_VOLTAGE ? "voltage" : "deflection");
    out_json_count(&j, "rows", (unsigned long long)tally->rows);
    out_json_number(&j, "noise", "%.6g", noise);
    out_json_int(&j, "latency_steps", gains->latency);
    out_json_int(&j, "maps", gains->map_count);
    out_json_text(&j, "map_frictions", map_frictions(gains, frictions, sizeof frictions));
    out_json_int(&j, "beam_correction", o->observer.correct_beam);
    out_json_int(&j, "position_correction", o->observer.correct_position);
    out_json_number(&j, "rms_innovation", "%.6g", tally->rows ? sqrt(tally->innovation_sq / (double)tally->rows) : 0.0);
    out_json_number(&j, "outlier_gate", "%g", (double)o->observer.outlier_gate);
    out_json_count(&j, "outliers", (unsigned long long)tally->last.outliers);
    out_json_int(&j, "health", tally->last.health);
    out_json_number(&j, "s_final", "%.6f", (double)tally->last.s);
    out_json_number(&j, "s_sigma_final", "%.4g", (double)tally->last.s_sigma);
    out_json_number(&j, "s_true_final", "%.6f", tally->s_true);
    out_json_number(&j, "score_after", "%g", o->score_after);
    out_json_number(&j, "tolerance", "%g", o->tolerance);
    out_json_count(&j, "scored", (unsigned long long)tally->scored);
    out_json_number(&j, "within", "%.4f", scored ? (double)tally->within / (double)tally->scored : (double)NAN);
    out_json_number(&j, "rms_s_error", "%.6g", scored ? sqrt(tally->error_sq / (double)tally->scored) : (double)NAN);
    out_json_number(&j, "friction_gain", "%g", (double)o->observer.friction_gain);
    out_json_number(&j, "friction_time", "%g", (double)o->observer.friction_time);
    out_json_number(&j, "friction_deadband", "%g", (double)o->observer.friction_deadband);
    out_json_number(&j, "friction_sigma", "%g", (double)o->observer.friction_sigma);
    out_json_number(&j, "friction_amplitude", "%g", (double)o->observer.friction_amplitude);
    out_json_number(&j, "friction_climb", "%g", (double)o->observer.friction_climb);
    out_json_number(&j, "friction_shadow", "%g", (double)o->observer.friction_shadow);
    out_json_number(&j, "friction_walk", "%g", (double)o->observer.friction_walk);
    out_json_number(&j, "jump_hold", "%g", (double)o->observer.jump_hold);
    out_json_number(&j, "mu_final", "%.6g", (double)tally->last.mu);
    out_json_number(&j, "mu_sigma_final", "%.4g", (double)tally->last.mu_sigma);
    out_json_number(&j, "wall_s", "%.3f", tally->elapsed);
    return out_json_finish(&j, out);
}
