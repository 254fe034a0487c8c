/* cli_sweep.c - `beamslider sweep SCENE --dir up|down --out FILE.csv [options]`:
 * the quasi-static PCS sweep of docs/model.md 6 (host/lib/run/sweep.c), one CSV row per
 * grid point and a one-line JSON summary on stdout. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "cli_progress.h"
#include "run_summary.h"
#include "scene_build.h"
#include "sweep.h"

const char cli_sweep_synopsis[] =
    "beamslider sweep SCENE.ini --dir up|down --out FILE.csv [--from 0] [--to 0.5] [--step 0.005]\n"
    "        [--hold 100] [--record 25] [--dt DT] [--pgs-iters K] [--set section.key=value ...]\n"
    "        [--trace FILE.csv --trace-at S [--trace-periods 5]]";
const char cli_sweep_help[] =
    "  quasi-static PCS sweep: amplitude and transport per s~ (docs/model.md 6)\n"
    "  With continuation from rest at the first point: per grid point s~ (up: --from to --to, down: --to to --from)\n"
    "  --hold excitation periods, then --record periods measured. CSV per point: s, amp_h (mean\n"
    "  half peak-to-peak of w(4L/7) / h), v_mean (x_C displacement / (L periods), positive\n"
    "  toward the centre), contact-solve statistics. --trace: per-step rows (beta, beam slope\n"
    "  angle alpha at s~, beta + alpha, contacts) over the first --trace-periods recorded periods\n"
    "  at the grid point S. JSON summary on stdout.\n";

typedef struct sweep_cli {
    const char *scene_path, *out_path, *trace_path;
    int dir;              /* -1 not given, 0 up, 1 down */
    double trace_at;      /* NAN: not given */
} sweep_cli;

/* Options that override a scene field: option name -> [section] key. */
static const struct override {
    const char *option, *section, *key;
} overrides[] = {
    { "--dt", "numerics", "dt" },
    { "--pgs-iters", "solver", "max_sweeps" },
    { 0, 0, 0 }
};

static int parse_real(const char *option, const char *text, double low, double high, double *value)
{
    char *end;
    errno = 0;
    *value = strtod(text, &end);
    if (end == text || *end || errno || !(*value >= low && *value <= high)) {
        cli_error("%s %s: allowed: a number in [%g, %g]", option, text, low, high);
        return -1;
    }
    return 0;
}

static int parse_options(int argc, char **argv, sweep_cli *cli, sweep_options *options, scene_file *file)
{
    char err[1024];
    int i;

    if (argc < 1 || argv[0][0] == '-') {
        cli_error("sweep needs a scene file first: beamslider sweep SCENE.ini --dir up|down --out FILE.csv");
        return -1;
    }
    cli->scene_path = argv[0];
    cli->out_path = cli->trace_path = NULL;
    cli->dir = -1;
    cli->trace_at = (double)NAN;
    options->from = 0.0;
    options->to = 0.5;
    options->step = 0.005;
    options->hold = 100;
    options->record = 25;
    options->trace_periods = -1; /* not given */
    if (scene_load(cli->scene_path, file, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    for (i = 1; i < argc; i += 2) {
        const char *option = argv[i], *value = i + 1 < argc ? argv[i + 1] : NULL;
        const struct override *o;
        int failed = 0;
        if (!value) {
            cli_error("option %s needs a value", option);
            return -1;
        }
        for (o = overrides; o->option && strcmp(o->option, option); ++o)
            ;
        if (o->option || !strcmp(option, "--set")) {
            if (o->option ? scene_set(file, o->section, o->key, value, option, err, sizeof err) != 0
                          : scene_set_assignment(file, option, value, err, sizeof err) != 0) {
                cli_error("%s", err);
                return -1;
            }
        } else if (!strcmp(option, "--from")) {
            failed = parse_real(option, value, 0.0, 1.0, &options->from);
        } else if (!strcmp(option, "--to")) {
            failed = parse_real(option, value, 0.0, 1.0, &options->to);
        } else if (!strcmp(option, "--step")) {
            failed = parse_real(option, value, 1e-9, 1.0, &options->step);
        } else if (!strcmp(option, "--hold")) {
            failed = cli_parse_int(option, value, 0, 1000000, &options->hold);
        } else if (!strcmp(option, "--record")) {
            failed = cli_parse_int(option, value, 1, 1000000, &options->record);
        } else if (!strcmp(option, "--dir")) {
            cli->dir = !strcmp(value, "up") ? 0 : !strcmp(value, "down") ? 1 : -2;
            if (cli->dir == -2) {
                cli_error("--dir %s: allowed: up or down", value);
                return -1;
            }
        } else if (!strcmp(option, "--out")) {
            cli->out_path = value;
        } else if (!strcmp(option, "--trace")) {
            cli->trace_path = value;
        } else if (!strcmp(option, "--trace-at")) {
            failed = parse_real(option, value, 0.0, 1.0, &cli->trace_at);
        } else if (!strcmp(option, "--trace-periods")) {
            failed = cli_parse_int(option, value, 1, 1000000, &options->trace_periods);
        } else {
            cli_error("unknown option '%s' (see beamslider sweep --help)", option);
            return -1;
        }
        if (failed)
            return -1;
    }
    if (cli->dir < 0) {
        cli_error("sweep needs --dir up or --dir down");
        return -1;
    }
    options->down = cli->dir;
    if (!cli->out_path) {
        cli_error("sweep needs --out FILE.csv");
        return -1;
    }
    if (!(options->from < options->to)) {
        cli_error("--from %g --to %g: --from must be below --to (--dir sets the direction)", options->from,
                  options->to);
        return -1;
    }
    if (sweep_grid_size(options->from, options->to, options->step) < 0) {
        cli_error("--step %g: must divide --to - --from = %g into at most %d intervals", options->step,
                  options->to - options->from, SWEEP_MAX_POINTS - 1);
        return -1;
    }
    options->trace_index = -1;
    if (cli->trace_path || !isnan(cli->trace_at)) {
        if (!cli->trace_path || isnan(cli->trace_at)) {
            cli_error("--trace FILE.csv and --trace-at S go together");
            return -1;
        }
        options->trace_index = sweep_grid_index(options, cli->trace_at);
        if (options->trace_index < 0) {
            cli_error("--trace-at %g: not a grid point of --from %g --to %g --step %g", cli->trace_at,
                      options->from, options->to, options->step);
            return -1;
        }
        if (options->trace_periods < 0) /* default: 5 periods, or all recorded ones if fewer */
            options->trace_periods = options->record < 5 ? options->record : 5;
        if (options->trace_periods > options->record) {
            cli_error("--trace-periods %d: allowed: at most --record = %d", options->trace_periods,
                      options->record);
            return -1;
        }
    }
    return 0;
}

/* Closes an output; reports and returns -1 if it misses anything. */
static int close_output(const char *path, FILE *file, const sweep_result *result, int points)
{
    if (!file)
        return 0;
    if (cli_close_output(path, file, result->write_errno) != 0)
        return -1;
    if (result->write_failed) {
        cli_error("%s holds only %d of %d points: the sweep stopped at a write error", path,
                  result->points_done, points);
        return -1;
    }
    return 0;
}

int cli_sweep(int argc, char **argv)
{
    static scene_file file; /* static: large */
    static bs_scene scene;
    static scene_model model;
    sweep_cli cli;
    sweep_options options;
    sweep_result r;
    char err[1024];
    cli_output outputs[2];
    cli_progress bar;
    FILE *csv, *trace;
    int failed, points, status;

    if (parse_options(argc, argv, &cli, &options, &file) != 0)
        return CLI_USAGE;
    if (scene_build(&file, &scene, &model, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    if (file.params.schedule[0]) { /* a sweep holds the excitation at each point */
        cli_error("%s: [excitation] schedule = %s: a sweep runs at the scene's constant excitation; "
                  "use beamslider run for a varying one", file.files[0], file.params.schedule);
        return CLI_USAGE;
    }
    outputs[0].option = "--out";
    outputs[0].path = cli.out_path;
    outputs[1].option = "--trace";
    outputs[1].path = cli.trace_path;
    if ((status = cli_open_outputs(outputs, 2, &file)) != CLI_OK)
        return status;
    csv = outputs[0].file;
    trace = outputs[1].file;
    points = sweep_grid_size(options.from, options.to, options.step);
    options.dt = file.params.dt;
    options.solver = scene_solver(&file.params);
    options.csv = csv;
    options.points = NULL;
    options.trace = trace;
    cli_progress_start(&bar, options.down ? "sweep down" : "sweep up");
    options.progress = cli_progress_hook;
    options.progress_context = &bar;
    failed = sweep_run(&scene, &options, &r) != 0;
    cli_progress_end(&bar);
    {
        const int csv_lost = close_output(cli.out_path, csv, &r, points) != 0;
        const int trace_lost = close_output(cli.trace_path, trace, &r, points) != 0;
        if (csv_lost || trace_lost)
            r.write_failed = failed = 1;
    }
    if (r.status != BS_OK)
        cli_error("%s: sweep stopped after %d of %d points: %s; the CSV holds the complete points",
                  file.params.name, r.points_done, points, bs_status_text(r.status));
    if (summary_print_sweep(stdout, &file, &scene, &options, &r) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        failed = 1;
    }
    return failed ? CLI_FAILED : CLI_OK;
}
