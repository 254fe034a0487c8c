/* run.c - drives bs_sim over a run: CSV rows, per-period amplitude, summary.
 *
 * Time is step * dt in double (never accumulated). The amplitude reported is
 * the mean over the last RUN_AMP_PERIODS complete excitation periods of the
 * per-period half peak-to-peak of w(4L/7) (core/src/bs_monitor.c), divided by h.
 * The per-period CSV has one row per completed excitation period: its end
 * time, that amplitude / h, s and the slider displacement over it / L.
 */
#include "run.h"

#include <errno.h>
#include <math.h>
#include "bs_monitor.h"
#include "bs_platform.h"
#include "progress.h"

const char run_csv_header[] = "t,w_sensor,s,z_c,beta,contacts,pgs_iters,pgs_residual\n";
const char run_periods_header[] = "t,amp_h,s,ds\n";

static int write_row(FILE *csv, double t, const bs_sim *sim)
{
    bs_step_report report;
    bs_real slider[3];
    bs_sim_get_report(sim, &report);
    bs_sim_get_state(sim, NULL, NULL, slider, NULL);
    return fprintf(csv, "%.9f,%.9e,%.9f,%.9e,%.9e,%u,%d,%.3e\n", t, (double)bs_sim_sensor(sim),
                   (double)bs_sim_position(sim), (double)slider[1], (double)slider[2], report.active,
                   report.sweeps, (double)report.residual) < 0;
}

static void fail_write(run_result *result)
{
    if (!result->write_failed)
        result->write_errno = errno;
    result->write_failed = 1;
}

int run_scene(const bs_scene *scene, const run_options *options, run_result *result)
{
    static bs_sim sim; /* static: large, and the CLI runs one at a time */
    bs_monitor monitor;
    double amplitudes[RUN_AMP_PERIODS];
    const double dt = options->dt;
    const uint64_t steps = (uint64_t)llround(options->t_end / dt);
    const uint64_t progress_every = 1u << 16;
    const double start = bs_platform_seconds();
    progress bar;
    uint64_t step;
    int i;

    result->status = bs_sim_init(&sim, scene, options->model, (bs_real)options->s0);
    if (result->status == BS_OK)
        result->status = bs_sim_set_solver(&sim, &options->solver);
    result->write_failed = 0;
    result->write_errno = 0;
    result->steps = 0;
    result->t = 0.0;
    result->s_final = result->s_min = options->s0; /* the sim is only readable once init succeeded */
    result->t_s_min = 0.0;
    result->amp_final_h = 0.0;
    result->amp_periods = 0;
    solve_tally_clear(&result->solve);
    result->wall_s = 0.0;
    result->hash = 0;
    if (result->status != BS_OK)
        return -1;
    result->s_final = result->s_min = (double)bs_sim_position(&sim);
    bs_monitor_init(&monitor, &sim);
    if (options->csv && (fputs(run_csv_header, options->csv) < 0 || write_row(options->csv, 0.0, &sim)))
        fail_write(result);
    if (options->periods && fputs(run_periods_header, options->periods) < 0)
        fail_write(result);
    progress_start(&bar, options->model == BS_MODEL_PCS ? "pcs" : "run");

    for (step = 1; step <= steps && !result->write_failed; ++step) {
        bs_step_report report;
        double s;
        result->status = bs_sim_step(&sim);
        if (result->status != BS_OK)
            break;
        result->steps = step;
        bs_sim_get_report(&sim, &report);
        solve_tally_add(&result->solve, &report);
        s = (double)bs_sim_position(&sim);
        if (s < result->s_min) {
            result->s_min = s;
            result->t_s_min = (double)step * dt;
        }
        if (bs_monitor_update(&monitor, &sim)) {
            amplitudes[(monitor.periods - 1) % RUN_AMP_PERIODS] = (double)monitor.amplitude;
            if (options->periods
                && fprintf(options->periods, "%.9f,%.6e,%.9f,%.6e\n", (double)step * dt,
                           (double)monitor.amplitude / (2.0 * (double)scene->half_thickness), s,
                           (double)monitor.transport) < 0)
                fail_write(result);
        }
        if (options->csv && step % (uint64_t)options->every == 0
            && write_row(options->csv, (double)step * dt, &sim))
            fail_write(result);
        if (step % progress_every == 0) {
            char detail[48];
            snprintf(detail, sizeof detail, "t=%.1f/%.1f s s=%.4f", (double)step * dt,
                     (double)steps * dt, s);
            progress_update(&bar, (double)step / (double)steps, detail);
        }
    }
    progress_end(&bar);

    result->t = (double)result->steps * dt;
    result->s_final = (double)bs_sim_position(&sim);
    result->amp_periods = monitor.periods < RUN_AMP_PERIODS ? (int)monitor.periods : RUN_AMP_PERIODS;
    for (i = 0; i < result->amp_periods; ++i)
        result->amp_final_h += amplitudes[i];
    if (result->amp_periods > 0)
        result->amp_final_h /= result->amp_periods * 2.0 * (double)scene->half_thickness;
    result->wall_s = bs_platform_seconds() - start;
    result->hash = bs_sim_hash(&sim);
    if ((options->csv && fflush(options->csv) != 0) || (options->periods && fflush(options->periods) != 0))
        fail_write(result);
    return result->status == BS_OK && !result->write_failed ? 0 : -1;
}
