/* run.c - drives bs_sim over a run: CSV rows, per-period amplitude, summary.
 *
 * Time is step * dt in double (never accumulated). The amplitude reported is
 * the mean over the last RUN_AMP_PERIODS complete excitation periods of the
 * per-period half peak-to-peak of w(4L/7) (core/src/bs_monitor.c), divided by h.
 * The per-period CSV has one row per completed excitation period: its end
 * time, that amplitude / h, s and the slider displacement over it / L.
 *
 * The base is driven by the harmonic excitation (bs_sim_step; a schedule
 * changes its frequency and amplitude) or by given step means of a measured
 * one (bs_sim_step_measured; docs/twin.md). With a transducer, the rows add
 * v, p, V_s and the result the energy into the load, and the mean power over
 * the run and over its last RUN_POWER_WINDOW seconds: a window in time, not
 * in excitation periods, because a recorded excitation has no period.
 */
#include "run.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bs_monitor.h"
#include "bs_platform.h"

const char run_csv_header[] = "t,w_sensor,s,z_r,beta,contacts,pgs_iters,pgs_residual\n";
const char run_transducer_columns[] = ",v,p,v_s";
const char run_periods_header[] = "t,amp_h,s,ds\n";

static int write_header(FILE *csv, int transducer)
{
    if (!transducer)
        return fputs(run_csv_header, csv) < 0;
    /* the header's line without its '\n', then the columns */
    return fprintf(csv, "%.*s%s\n", (int)strlen(run_csv_header) - 1, run_csv_header,
                   run_transducer_columns) < 0;
}

static int write_row(FILE *csv, double t, const bs_sim *sim)
{
    bs_step_report report;
    bs_transducer_output out;
    bs_real slider[3];
    bs_sim_get_report(sim, &report);
    bs_sim_get_state(sim, NULL, NULL, slider, NULL);
    bs_sim_get_transducer(sim, &out);
    if (fprintf(csv, "%.9f,%.9e,%.9f,%.9e,%.9e,%u,%d,%.3e", t, (double)bs_sim_sensor(sim),
                (double)bs_sim_position(sim), (double)slider[1], (double)slider[2], report.active,
                report.sweeps, (double)report.residual) < 0)
        return 1;
    if (out.present && fprintf(csv, ",%.9e,%.9e,%.9e", (double)out.voltage, (double)out.power,
                               (double)out.storage_voltage) < 0)
        return 1;
    return fputc('\n', csv) == EOF;
}

/* Energy into the transducer's load since the start [J] (0 without one). */
static double load_energy(const bs_sim *sim)
{
    bs_transducer_output out;
    bs_sim_get_transducer(sim, &out);
    return (double)out.energy;
}

/* Takes step number step under the run's excitation: the measured step mean
 * (*input_failed set if it cannot be read), or the harmonic one, with a
 * schedule's frequency and amplitude at the step's midpoint handed to the sim
 * when they change (*frequency, *amplitude: the values it has). */
static bs_status advance(bs_sim *sim, const run_options *options, uint64_t step, double *frequency,
                         double *amplitude, int *input_failed)
{
    const schedule *plan = options->excitation_schedule;
    if (options->base_accel) {
        double mean;
        if (options->base_accel(options->base_accel_source, &mean) != 0) {
            *input_failed = 1;
            return BS_E_ARGUMENT;
        }
        return bs_sim_step_measured(sim, (bs_real)mean);
    }
    return run_step_harmonic(sim, plan, options->dt, step, frequency, amplitude);
}

bs_status run_step_harmonic(bs_sim *sim, const schedule *plan, double dt, uint64_t step, double *frequency,
                            double *amplitude)
{
    if (plan && plan->points > 0) {
        double f, a;
        schedule_at(plan, ((double)step - 0.5) * dt, &f, &a);
        if (f != *frequency || a != *amplitude) {
            const bs_status status = bs_sim_set_excitation(sim, (bs_real)f, (bs_real)a);
            if (status != BS_OK)
                return status;
            *frequency = f;
            *amplitude = a;
        }
    }
    return bs_sim_step(sim);
}

uint64_t run_step_count(double t_end, double dt)
{
    const double steps = t_end / dt;
    if (!(steps < 9007199254740992.0)) /* 2^53, and NaN */
        return (uint64_t)1 << 53;
    return steps > 0.0 ? (uint64_t)llround(steps) : 0;
}

static void fail_write(run_result *result)
{
    if (!result->write_failed)
        result->write_errno = errno;
    result->write_failed = 1;
}

int run_scene(const bs_scene *scene, const run_options *options, run_result *result)
{
    bs_sim *sim = malloc(sizeof *sim); /* large: on the heap, one per call (runs may share a process) */
    bs_monitor monitor;
    double amplitudes[RUN_AMP_PERIODS];
    const double dt = options->dt;
    const uint64_t steps = run_step_count(options->t_end, dt);
    const uint64_t window_steps = run_step_count(RUN_POWER_WINDOW, dt);
    const uint64_t window_start = steps > window_steps ? steps - window_steps : 0;
    const uint64_t progress_every = 1u << 16;
    const double start = bs_platform_seconds();
    bs_transducer_output transducer;
    uint64_t step;
    double energy_window_start = 0.0; /* [J] at step window_start */
    double frequency = -1.0, amplitude = -1.0; /* the schedule's, as the sim has them (advance) */
    int i;

    result->status = sim ? bs_sim_init(sim, scene, options->model, (bs_real)options->s0) : BS_E_NULL;
    if (result->status == BS_OK)
        result->status = bs_sim_set_solver(sim, &options->solver);
    result->out_of_memory = !sim;
    result->write_failed = 0;
    result->write_errno = 0;
    result->input_failed = 0;
    result->stopped = 0;
    result->steps = 0;
    result->t = 0.0;
    result->s_final = result->s_min = options->s0; /* the sim is only readable once init succeeded */
    result->t_s_min = 0.0;
    result->amp_final_h = 0.0;
    result->amp_periods = 0;
    solve_tally_clear(&result->solve);
    result->wall_s = 0.0;
    result->hash = 0;
    result->transducer = 0;
    result->energy = result->power_mean = result->power_window = 0.0;
    result->power_last = (double)NAN;
    if (result->status != BS_OK) {
        free(sim);
        return -1;
    }
    result->s_final = result->s_min = (double)bs_sim_position(sim);
    bs_sim_get_transducer(sim, &transducer);
    result->transducer = transducer.present;
    bs_monitor_init(&monitor, sim);
    if (options->csv
        && (write_header(options->csv, transducer.present) || write_row(options->csv, 0.0, sim)))
        fail_write(result);
    if (options->periods && fputs(run_periods_header, options->periods) < 0)
        fail_write(result);
    if (options->on_step && options->on_step(options->on_step_context, sim, 0, 0.0) != 0)
        result->stopped = 1;

    for (step = 1; step <= steps && !result->write_failed && !result->stopped; ++step) {
        bs_step_report report;
        double s;
        result->status = advance(sim, options, step, &frequency, &amplitude, &result->input_failed);
        if (result->status != BS_OK)
            break;
        result->steps = step;
        if (step == window_start)
            energy_window_start = load_energy(sim);
        bs_sim_get_report(sim, &report);
        solve_tally_add(&result->solve, &report);
        s = (double)bs_sim_position(sim);
        if (s < result->s_min) {
            result->s_min = s;
            result->t_s_min = (double)step * dt;
        }
        if (bs_monitor_update(&monitor, sim)) {
            amplitudes[(monitor.periods - 1) % RUN_AMP_PERIODS] = (double)monitor.amplitude;
            if (options->periods
                && fprintf(options->periods, "%.9f,%.6e,%.9f,%.6e\n", (double)step * dt,
                           (double)monitor.amplitude / (2.0 * (double)scene->half_thickness), s,
                           (double)monitor.transport) < 0)
                fail_write(result);
        }
        if (options->every > 0 && step % (uint64_t)options->every == 0) {
            if (options->csv && write_row(options->csv, (double)step * dt, sim))
                fail_write(result);
            if (options->on_step && options->on_step(options->on_step_context, sim, step, (double)step * dt) != 0)
                result->stopped = 1;
        }
        if (options->progress && step % progress_every == 0) {
            char detail[48];
            snprintf(detail, sizeof detail, "t=%.1f/%.1f s s=%.4f", (double)step * dt,
                     (double)steps * dt, s);
            options->progress(options->progress_context, (double)step / (double)steps, detail);
        }
    }

    result->t = (double)result->steps * dt;
    result->s_final = (double)bs_sim_position(sim);
    result->amp_periods = monitor.periods < RUN_AMP_PERIODS ? (int)monitor.periods : RUN_AMP_PERIODS;
    for (i = 0; i < result->amp_periods; ++i)
        result->amp_final_h += amplitudes[i];
    if (result->amp_periods > 0)
        result->amp_final_h /= result->amp_periods * 2.0 * (double)scene->half_thickness;
    if (result->transducer) {
        result->energy = load_energy(sim);
        result->power_mean = result->steps > 0 ? result->energy / result->t : 0.0;
        result->power_window = (double)(steps - window_start) * dt;
        if (result->steps == steps && steps > 0)
            result->power_last = (result->energy - energy_window_start) / result->power_window;
    }
    result->wall_s = bs_platform_seconds() - start;
    result->hash = bs_sim_hash(sim);
    if ((options->csv && fflush(options->csv) != 0) || (options->periods && fflush(options->periods) != 0))
        fail_write(result);
    free(sim);
    return result->status == BS_OK && !result->write_failed && !result->stopped ? 0 : -1;
}
