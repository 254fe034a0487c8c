/* api_run.c - libbeamslider-host: runs and sweeps of a scene
 * (host/include/beamslider_host.h), through the run wing's run_scene and
 * sweep_run: what `beamslider run` and `sweep` compute, sample for sample. */
#include "api_scene.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "run.h"
#include "run_summary.h"
#include "schedule.h"
#include "sweep.h"

void bs_host_run_defaults(bs_host_run_options *options)
{
    memset(options, 0, sizeof *options);
    options->every = 1;
}

static void copy_result(const run_result *r, bs_host_run_result *out)
{
    memset(out, 0, sizeof *out);
    out->status = r->status;
    out->stopped = r->stopped;
    out->steps = r->steps;
    out->t = r->t;
    out->s_final = r->s_final;
    out->s_min = r->s_min;
    out->t_s_min = r->t_s_min;
    out->amp_final_h = r->amp_final_h;
    out->amp_periods = r->amp_periods;
    out->hash = r->hash;
    out->transducer = r->transducer;
    out->energy = r->energy;
    out->power_mean = r->power_mean;
    out->power_last = r->power_last;
    out->contact_steps = r->solve.contact_steps;
    out->unconverged_steps = r->solve.unconverged_steps;
    out->max_sweeps = r->solve.max_sweeps;
    out->max_systems = r->solve.max_systems;
    out->wall_s = r->wall_s;
}

bs_host_status bs_host_run(const bs_host_scene *scene, const bs_host_run_options *options,
                           bs_host_run_result *result, bs_host_error *error)
{
    const scene_params *p;
    run_options o;
    run_result r;
    schedule excitation;
    char why[256];
    int summary_failed;

    if (!scene || !options || !result)
        return api_error(error, BS_HOST_E_NULL, "a NULL scene, options or result");
    if (options->every < 1)
        return api_error(error, BS_HOST_E_INPUT, "every = %ld: allowed: an integer >= 1", options->every);
    p = &scene->file.params;
    memset(&o, 0, sizeof o);
    o.model = (bs_model)p->model;
    o.s0 = p->s0;
    o.t_end = p->t_end;
    o.dt = p->dt;
    o.solver = scene_solver(p);
    o.every = options->every;
    o.csv = options->csv;
    o.periods = options->periods;
    o.on_step = options->on_step;
    o.on_step_context = options->on_step_context;
    o.progress = options->progress;
    o.progress_context = options->progress_context;
    /* the scene's schedule was checked when it was read */
    o.excitation_schedule = schedule_parse(p->schedule, &excitation, why, sizeof why) == 0 ? &excitation : NULL;
    errno = 0;
    run_scene(&scene->scene, &o, &r);
    copy_result(&r, result);
    if (r.out_of_memory)
        return api_error(error, BS_HOST_E_MEMORY, "out of memory for the simulation");
    /* the summary of a run that stopped too, as `beamslider run` prints it */
    summary_failed = options->summary
                     && summary_print_run(options->summary, &scene->file, &scene->scene, NULL, &r) != 0;
    if (r.write_failed)
        return api_error(error, BS_HOST_E_FAILED, "a write failed: %s; the run stopped at t = %.9g s",
                         r.write_errno ? strerror(r.write_errno) : "write error", r.t);
    if (r.status != BS_OK)
        return api_error(error, BS_HOST_E_FAILED, "%s: stopped at t = %.9g s (step %llu): %s", p->name, r.t,
                         (unsigned long long)r.steps, bs_status_text(r.status));
    if (r.stopped)
        return api_error(error, BS_HOST_E_FAILED, "%s: stopped by on_step at t = %.9g s (step %llu)", p->name, r.t,
                         (unsigned long long)r.steps);
    if (summary_failed)
        return api_error(error, BS_HOST_E_FAILED, "the summary could not be written (out of memory or a write "
                         "error)");
    return api_ok(error);
}

void bs_host_sweep_defaults(bs_host_sweep_options *options)
{
    memset(options, 0, sizeof *options);
    options->from = 0.0;
    options->to = 0.5;
    options->step = 0.005;
    options->hold = 100;
    options->record = 25;
}

int bs_host_sweep_points(const bs_host_sweep_options *options)
{
    return options ? sweep_grid_size(options->from, options->to, options->step) : -1;
}

bs_host_status bs_host_sweep(const bs_host_scene *scene, const bs_host_sweep_options *options, int *points_done,
                             bs_host_error *error)
{
    const int n = bs_host_sweep_points(options);
    sweep_options o;
    sweep_result r;
    int i, summary_failed;

    if (points_done)
        *points_done = 0;
    if (!scene || !options)
        return api_error(error, BS_HOST_E_NULL, "a NULL scene or options");
    if (n < 1)
        return api_error(error, BS_HOST_E_INPUT, "from %g to %g step %g: allowed: 0 <= from < to <= 1 and a step that "
                         "divides to - from into at most %d intervals", options->from, options->to, options->step,
                         SWEEP_MAX_POINTS - 1);
    if (options->hold < 0 || options->record < 1)
        return api_error(error, BS_HOST_E_INPUT, "hold %d, record %d: allowed: hold >= 0 and record >= 1 periods",
                         options->hold, options->record);
    if (options->points && options->point_room < n)
        return api_error(error, BS_HOST_E_INPUT, "room for %d points, the grid has %d", options->point_room, n);
    if (scene->file.params.schedule[strspn(scene->file.params.schedule, " \t")])
        return api_error(error, BS_HOST_E_INPUT, "%s: [excitation] schedule = %s: a sweep runs at the scene's "
                         "constant excitation", scene->file.files[0], scene->file.params.schedule);
    memset(&o, 0, sizeof o);
    o.from = options->from;
    o.to = options->to;
    o.step = options->step;
    o.down = options->down != 0;
    o.hold = options->hold;
    o.record = options->record;
    o.dt = scene->file.params.dt;
    o.solver = scene_solver(&scene->file.params);
    o.csv = options->csv;
    o.trace_index = -1;
    o.progress = options->progress;
    o.progress_context = options->progress_context;
    if (options->points && !(o.points = malloc((size_t)n * sizeof *o.points)))
        return api_error(error, BS_HOST_E_MEMORY, "out of memory for %d points", n);
    sweep_run(&scene->scene, &o, &r);
    summary_failed = options->summary
                     && summary_print_sweep(options->summary, &scene->file, &scene->scene, &o, &r) != 0;
    for (i = 0; o.points && i < r.points_done; ++i) {
        options->points[i].s = o.points[i].s;
        options->points[i].amp_h = o.points[i].amp_h;
        options->points[i].v_mean = o.points[i].v_mean;
    }
    free(o.points);
    if (points_done)
        *points_done = r.points_done;
    if (r.write_failed)
        return api_error(error, BS_HOST_E_FAILED, "a write failed: %s; %d of %d points done",
                         r.write_errno ? strerror(r.write_errno) : "write error", r.points_done, n);
    if (r.status != BS_OK)
        return api_error(error, BS_HOST_E_FAILED, "%s: sweep stopped after %d of %d points: %s",
                         scene->file.params.name, r.points_done, n, bs_status_text(r.status));
    if (summary_failed)
        return api_error(error, BS_HOST_E_FAILED, "the summary could not be written (out of memory or a write "
                         "error)");
    return api_ok(error);
}
