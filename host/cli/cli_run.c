/* cli_run.c - `beamslider run SCENE [options]`: one simulation, CSV and a
 * one-line JSON summary on stdout. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "run.h"
#include "scene_build.h"
#include "summary.h"

typedef struct run_cli {
    const char *scene_path;
    const char *out_path;
    const char *periods_path;
    long every;
} run_cli;

/* Options that override a scene field: option name -> [section] key. */
static const struct override {
    const char *option, *section, *key;
} overrides[] = {
    { "--model", "run", "model" },
    { "--s0", "run", "s0" },
    { "--t-end", "run", "t_end" },
    { "--dt", "numerics", "dt" },
    { "--pgs-iters", "solver", "max_sweeps" },
    { 0, 0, 0 }
};

static int parse_options(int argc, char **argv, run_cli *cli, scene_file *file)
{
    char err[1024];
    int i;

    if (argc < 1 || argv[0][0] == '-') {
        cli_error("run needs a scene file first: beamslider run SCENE.ini [options]");
        return -1;
    }
    cli->scene_path = argv[0];
    cli->out_path = NULL;
    cli->periods_path = NULL;
    cli->every = 1;
    if (scene_load(cli->scene_path, file, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    for (i = 1; i < argc; i += 2) {
        const char *option = argv[i];
        const struct override *o;
        if (i + 1 >= argc) {
            cli_error("option %s needs a value", option);
            return -1;
        }
        for (o = overrides; o->option && strcmp(o->option, option); ++o)
            ;
        if (o->option) {
            if (scene_set(file, o->section, o->key, argv[i + 1], option, err, sizeof err) != 0) {
                cli_error("%s", err);
                return -1;
            }
        } else if (!strcmp(option, "--out")) {
            cli->out_path = argv[i + 1];
        } else if (!strcmp(option, "--periods")) {
            cli->periods_path = argv[i + 1];
        } else if (!strcmp(option, "--every")) {
            char *end;
            errno = 0;
            cli->every = strtol(argv[i + 1], &end, 10);
            if (*end || errno || cli->every < 1) {
                cli_error("--every %s: allowed: an integer >= 1", argv[i + 1]);
                return -1;
            }
        } else {
            cli_error("unknown option '%s' (see beamslider --help)", option);
            return -1;
        }
    }
    return 0;
}

/* Closes an output; reports and returns -1 if it misses anything: its own
 * write failed, or the run stopped early because another one did. */
static int close_output(const char *path, FILE *file, const run_result *result)
{
    if (!file)
        return 0;
    if (cli_close_output(path, file, result->write_errno) != 0)
        return -1;
    if (result->write_failed) {
        cli_error("%s holds the run only up to t = %.6f s: it stopped at a write error", path, result->t);
        return -1;
    }
    return 0;
}

int cli_run(int argc, char **argv)
{
    static scene_file file;   /* static: large */
    static bs_scene scene;
    static scene_model model;
    run_cli cli;
    run_options options;
    run_result result;
    char err[1024];
    cli_output outputs[2];
    FILE *csv, *periods;
    int failed, status;

    if (parse_options(argc, argv, &cli, &file) != 0)
        return CLI_USAGE;
    if (scene_build(&file, &scene, &model, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    /* outputs are opened only once the input is known to be good */
    outputs[0].option = "--out";
    outputs[0].path = cli.out_path;
    outputs[1].option = "--periods";
    outputs[1].path = cli.periods_path;
    if ((status = cli_open_outputs(outputs, 2, &file)) != CLI_OK)
        return status;
    csv = outputs[0].file;
    periods = outputs[1].file;
    options.model = (bs_model)file.params.model;
    options.s0 = file.params.s0;
    options.t_end = file.params.t_end;
    options.dt = file.params.dt;
    options.solver = scene_solver(&file.params);
    options.every = cli.every;
    options.csv = csv;
    options.periods = periods;
    options.show_progress = 1;
    failed = run_scene(&scene, &options, &result) != 0;
    /* a write error ends the run: then both files are reported incomplete */
    {
        const int csv_lost = close_output(cli.out_path, csv, &result) != 0;
        const int periods_lost = close_output(cli.periods_path, periods, &result) != 0;
        if (csv_lost || periods_lost)
            result.write_failed = failed = 1;
    }
    if (result.status != BS_OK)
        cli_error("%s: stopped at t = %.6f s (step %llu): %s; state and CSV kept up to the last good step",
                  file.params.name, result.t, (unsigned long long)result.steps, bs_status_text(result.status));
    if (summary_print_run(stdout, &file.params, &scene, &result) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        failed = 1;
    }
    return failed ? CLI_FAILED : CLI_OK;
}
