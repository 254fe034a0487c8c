/* ref_run.c - drives the reference step over a run: CSV rows, per-period
 * rows (ref_monitor.c) and the summary. Outer step n covers substeps
 * nK+1..(n+1)K; its row reports the largest iteration count and residual of
 * its substeps and the contacts of the last one as a bit mask (bits 0-3:
 * corners P1..P4, as `beamslider run` writes them; bits 4, 5: end stops).
 * With a transducer (docs/model.md 11) the row adds v, the mean power into
 * the load over the outer step (its energy / dt) and V_s. A replayed base
 * acceleration (docs/model.md 10) gives one value per outer step, held for
 * its K substeps. */
#define _POSIX_C_SOURCE 199309L
#include "ref_run.h"

#include <math.h>
#include <time.h>
#include "ref_monitor.h"

const char ref_run_csv_header[] = "t,w_sensor,s,z_r,beta,contacts,pgs_iters,pgs_residual\n";
const char ref_run_csv_header_transducer[] = "t,w_sensor,s,z_r,beta,contacts,pgs_iters,pgs_residual,v,p,v_s\n";
const char ref_run_periods_header[] = "t,amp_h,s,ds\n";

static double seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int write_row(FILE *csv, double t, const ref_scene *scene, const ref_state *state, unsigned active,
                     long iters, double residual, double power)
{
    if (fprintf(csv, "%.9f,%.9e,%.9f,%.9e,%.9e,%u,%ld,%.3e", t, ref_scene_sensor(scene, state->q),
                state->q[scene->i_x] / scene->length, state->q[scene->i_z], state->q[scene->i_beta], active, iters,
                residual) < 0)
        return 1;
    if (scene->load != REF_LOAD_NONE
        && fprintf(csv, ",%.9e,%.9e,%.9e", state->voltage, power, state->storage_voltage) < 0)
        return 1;
    return fputc('\n', csv) == EOF;
}

static void count_step(const ref_step_report *report, ref_run_result *r)
{
    if (report->solved) {
        r->unconverged_steps += (uint64_t)!report->converged;
        if (report->residual_rel > r->max_residual_rel)
            r->max_residual_rel = report->residual_rel;
    }
    if (report->bridge_charge > 0.0)
        ++r->bridge_steps;
    if (!report->active)
        return;
    ++r->contact_steps;
    r->total_iters += (uint64_t)report->iterations;
    r->exhaustive_steps += (uint64_t)report->exhaustive;
    r->ambiguous_steps += (uint64_t)report->ambiguous;
    if (report->iterations > r->max_iters)
        r->max_iters = report->iterations;
}

int ref_run(const ref_scene *scene, const ref_run_options *options, ref_run_result *r)
{
    static ref_state state;
    ref_monitor monitor;
    double amplitudes[REF_AMP_PERIODS];
    const uint64_t steps = (uint64_t)llround(options->t_end / scene->dt);
    const double start = seconds();
    uint64_t n;
    int i;

    ref_state_init(scene, &state);
    r->failed = r->write_failed = 0;
    r->steps = 0;
    r->t = 0.0;
    r->s_final = r->s_min = state.q[scene->i_x] / scene->length;
    r->t_s_min = 0.0;
    r->amp_final_h = 0.0;
    r->amp_periods = 0;
    r->periods = 0;
    r->contact_steps = r->total_iters = 0;
    r->max_iters = 0;
    r->exhaustive_steps = r->ambiguous_steps = r->unconverged_steps = 0;
    r->max_residual_rel = 0.0;
    r->load_energy = r->voltage_final = r->voltage_max = r->storage_voltage_final = 0.0;
    r->bridge_steps = 0;
    r->wall_s = 0.0;
    if (options->base_accel && options->base_accel_count < steps) {
        r->failed = 1;
        return -1;
    }
    ref_monitor_init(&monitor, scene->dt, scene->frequency, ref_scene_sensor(scene, state.q), state.q[scene->i_x]);
    if (options->csv
        && (fputs(scene->load != REF_LOAD_NONE ? ref_run_csv_header_transducer : ref_run_csv_header, options->csv) < 0
            || write_row(options->csv, 0.0, scene, &state, 0, 0, 0.0, 0.0)))
        r->write_failed = 1;
    if (options->periods && fputs(ref_run_periods_header, options->periods) < 0)
        r->write_failed = 1;

    for (n = 1; n <= steps && !r->write_failed && !r->failed; ++n) {
        const double t = (double)((long double)n * (long double)scene->dt);
        const double energy_before = state.load_energy;
        long iters = 0;
        double residual = 0.0, s;
        unsigned active = 0;
        int k;
        for (k = 0; k < scene->substeps; ++k) {
            ref_step_report report;
            const int status = options->base_accel
                                   ? ref_step_with_accel(scene, &options->step, options->base_accel[n - 1], &state, &report)
                                   : ref_step(scene, &options->step, &state, &report);
            if (status != 0)
                r->failed = 1;
            active = report.mask;
            count_step(&report, r);
            if (report.iterations > iters)
                iters = report.iterations;
            if (report.residual > residual)
                residual = report.residual;
        }
        r->steps = n;
        s = state.q[scene->i_x] / scene->length;
        if (s < r->s_min) {
            r->s_min = s;
            r->t_s_min = t;
        }
        if (ref_monitor_update(&monitor, n, ref_scene_sensor(scene, state.q), state.q[scene->i_x])) {
            amplitudes[r->periods % REF_AMP_PERIODS] = monitor.amplitude;
            ++r->periods;
            if (options->periods
                && fprintf(options->periods, "%.9f,%.6e,%.9f,%.6e\n", t,
                           monitor.amplitude / (2.0 * scene->half_thickness), s,
                           monitor.transport / scene->length) < 0)
                r->write_failed = 1;
        }
        if (fabs(state.voltage) > r->voltage_max)
            r->voltage_max = fabs(state.voltage);
        if (options->csv && n % (uint64_t)options->every == 0
            && write_row(options->csv, t, scene, &state, active, iters, residual,
                         (state.load_energy - energy_before) / scene->dt))
            r->write_failed = 1;
    }
    r->t = (double)((long double)r->steps * (long double)scene->dt);
    r->s_final = state.q[scene->i_x] / scene->length;
    r->load_energy = state.load_energy;
    r->voltage_final = state.voltage;
    r->storage_voltage_final = state.storage_voltage;
    r->amp_periods = r->periods < REF_AMP_PERIODS ? (int)r->periods : REF_AMP_PERIODS;
    for (i = 0; i < r->amp_periods; ++i)
        r->amp_final_h += amplitudes[i];
    if (r->amp_periods > 0)
        r->amp_final_h /= (double)r->amp_periods * 2.0 * scene->half_thickness;
    r->wall_s = seconds() - start;
    if ((options->csv && fflush(options->csv) != 0) || (options->periods && fflush(options->periods) != 0))
        r->write_failed = 1;
    return r->failed || r->write_failed ? -1 : 0;
}
