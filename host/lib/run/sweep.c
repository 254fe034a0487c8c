/* sweep.c - quasi-static PCS sweep with continuation (docs/model.md 6).
 *
 * Per grid point s~ (the state carried over from the previous point):
 *   amp_h  = (1 / N_rec) sum over the recorded periods of a_p / h,
 *            a_p = (max w - min w) / 2 of w(4L/7) over period p (bs_monitor)
 *   v_mean = sign * sum over the recorded periods of dx_p / L, / N_rec,
 *            dx_p = x_C(end of p) - x_C(start of p) (bs_monitor's compensated
 *            transport), sign = +1 for s~ <= 1/2 and -1 beyond, so that
 *            positive means toward the beam centre
 * x_C is a free coordinate in the PCS model and drifts without limit over a
 * sweep; only its increments are used. The kinematics use s~.
 */
#include "sweep.h"

#include <errno.h>
#include <math.h>
#include <string.h>
#include "bs_monitor.h"
#include "bs_platform.h"

const char sweep_csv_header[] =
    "s,amp_h,v_mean,mean_sweeps,max_sweeps,unconverged_steps,contact_steps,steps\n";
const char sweep_trace_header[] = "period,t,w_h,beta,alpha,rel_rot,contacts\n";

int sweep_grid_size(double from, double to, double step)
{
    double intervals;
    if (!(from >= 0.0 && from < to && to <= 1.0 && step > 0.0))
        return -1;
    intervals = (to - from) / step;
    if (!(intervals < SWEEP_MAX_POINTS - 1) || fabs(intervals - floor(intervals + 0.5)) > 1e-9 * intervals)
        return -1;
    return (int)floor(intervals + 0.5) + 1;
}

double sweep_grid_s(const sweep_options *options, int index)
{
    const int n = sweep_grid_size(options->from, options->to, options->step);
    /* the last point is `to` itself, not from + (n - 1) step rounded */
    return index == n - 1 ? options->to : options->from + index * options->step;
}

int sweep_grid_index(const sweep_options *options, double s)
{
    const int n = sweep_grid_size(options->from, options->to, options->step);
    const double i = floor((s - options->from) / options->step + 0.5);
    if (n < 0 || !(i >= 0.0 && i < n) || fabs(sweep_grid_s(options, (int)i) - s) > 1e-9 * options->step)
        return -1;
    return (int)i;
}

static void fail_write(sweep_result *result)
{
    if (!result->write_failed)
        result->write_errno = errno;
    result->write_failed = 1;
}

/* One trace row: the slope angle at the prescribed position from the core's
 * own mode shapes (the ones the contact kinematics use). */
static int write_trace_row(FILE *trace, const bs_scene *scene, const bs_sim *sim, double s, double period,
                           double t)
{
    bs_real slider[3], w_slope;
    bs_step_report report;
    double alpha;
    bs_sim_get_state(sim, NULL, NULL, slider, NULL);
    bs_sim_beam_at(sim, (bs_real)s * scene->length, NULL, &w_slope);
    bs_sim_get_report(sim, &report);
    alpha = atan((double)w_slope);
    return fprintf(trace, "%.6f,%.9f,%.6e,%.6e,%.6e,%.6e,%u\n", period, t,
                   (double)bs_sim_sensor(sim) / (2.0 * (double)scene->half_thickness), (double)slider[2],
                   alpha, (double)slider[2] + alpha, report.active) < 0;
}

/* Integrates one grid point: hold + record periods. Returns the status of
 * the first failed step, or BS_OK. */
static bs_status run_point(const bs_scene *scene, bs_sim *sim, bs_monitor *monitor,
                           const sweep_options *options, int traced, sweep_point *point, sweep_result *result)
{
    const double h = 2.0 * (double)scene->half_thickness;
    const int periods = options->hold + options->record;
    double amp_sum = 0.0, transport_sum = 0.0;
    uint64_t trace_steps = 0;
    int done = 0;                        /* completed periods at this point */
    int trace = traced ? 0 : -1;         /* -1 off, 0 waiting for the hold's end, 1 tracing */

    solve_tally_clear(&point->solve);
    point->steps = 0;
    for (;;) {
        if (trace == 1 || (trace == 0 && done == options->hold)) {
            /* the first row is the state at the end of the hold */
            const double period = (done - options->hold) + (double)bs_sim_phase(sim);
            const double t = (double)trace_steps * options->dt;
            trace = 1;
            if (write_trace_row(options->trace, scene, sim, point->s, period, t))
                fail_write(result);
            ++trace_steps;
            if (done - options->hold >= options->trace_periods)
                trace = -1;
        }
        if (done == periods || result->write_failed)
            break;
        {
            bs_step_report report;
            const bs_status status = bs_sim_step(sim);
            if (status != BS_OK)
                return status;
            ++point->steps;
            bs_sim_get_report(sim, &report);
            solve_tally_add(&point->solve, &report);
        }
        if (bs_monitor_update(monitor, sim)) {
            ++done;
            if (done > options->hold) {
                amp_sum += (double)monitor->amplitude;
                transport_sum += (double)monitor->transport;
            }
        }
    }
    point->amp_h = amp_sum / (options->record * h);
    point->v_mean = (point->s <= 0.5 ? 1.0 : -1.0) * transport_sum / options->record;
    result->steps += point->steps;
    solve_tally_merge(&result->solve, &point->solve);
    return BS_OK;
}

int sweep_run(const bs_scene *scene, const sweep_options *options, sweep_result *result)
{
    bs_sim sim; /* automatic: sweeps may run in parallel threads */
    bs_monitor monitor;
    const int n = sweep_grid_size(options->from, options->to, options->step);
    const double start = bs_platform_seconds();
    int i;

    result->status = BS_OK;
    result->write_failed = 0;
    result->write_errno = 0;
    result->points_done = 0;
    result->steps = 0;
    solve_tally_clear(&result->solve);
    result->wall_s = 0.0;
    if (n < 1 || options->hold < 0 || options->record < 1
        || (options->trace && !(options->trace_periods >= 1 && options->trace_periods <= options->record))) {
        result->status = BS_E_ARGUMENT;
        return -1;
    }
    result->status = bs_sim_init(&sim, scene, BS_MODEL_PCS,
                                 (bs_real)sweep_grid_s(options, options->down ? n - 1 : 0));
    if (result->status == BS_OK)
        result->status = bs_sim_set_solver(&sim, &options->solver);
    if (result->status != BS_OK)
        return -1;
    bs_monitor_init(&monitor, &sim);
    if (options->csv && fputs(sweep_csv_header, options->csv) < 0)
        fail_write(result);
    if (options->trace && fputs(sweep_trace_header, options->trace) < 0)
        fail_write(result);

    for (i = 0; i < n && !result->write_failed; ++i) {
        const int index = options->down ? n - 1 - i : i;
        sweep_point point;
        memset(&point, 0, sizeof point); /* callers may compare points bytewise */
        point.s = sweep_grid_s(options, index);
        result->status = bs_sim_set_pcs_position(&sim, (bs_real)point.s);
        if (result->status == BS_OK)
            result->status = run_point(scene, &sim, &monitor, options,
                                       options->trace && index == options->trace_index, &point, result);
        if (result->status != BS_OK)
            break;
        if (result->write_failed)
            break; /* the point is incomplete */
        if (options->points)
            options->points[i] = point;
        if (options->csv
            && fprintf(options->csv, "%.6f,%.6e,%.6e,%.4f,%d,%llu,%llu,%llu\n", point.s, point.amp_h,
                       point.v_mean, solve_tally_mean_sweeps(&point.solve), point.solve.max_sweeps,
                       (unsigned long long)point.solve.unconverged_steps,
                       (unsigned long long)point.solve.contact_steps,
                       (unsigned long long)point.steps) < 0)
            fail_write(result);
        result->points_done = i + 1;
        if (options->progress) {
            char detail[64];
            snprintf(detail, sizeof detail, "s~=%.4f amp=%.3f h (%d/%d)", point.s, point.amp_h, i + 1, n);
            options->progress(options->progress_context, (double)(i + 1) / n, detail);
        }
    }
    result->wall_s = bs_platform_seconds() - start;
    if ((options->csv && fflush(options->csv) != 0) || (options->trace && fflush(options->trace) != 0))
        fail_write(result);
    return result->status == BS_OK && !result->write_failed ? 0 : -1;
}
