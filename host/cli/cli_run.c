/* cli_run.c - `beamslider run SCENE [options]`: one simulation, CSV and a
 * one-line JSON summary on stdout. With --excitation FILE the base follows a
 * recorded acceleration instead of the scene's harmonic one (docs/twin.md). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "cli_progress.h"
#include "excitation_file.h"
#include "run.h"
#include "run_summary.h"
#include "scene_build.h"
#include "scene_limits.h"

const char cli_run_synopsis[] =
    "beamslider run SCENE.ini [--model free|pcs] [--s0 S] [--t-end T] [--dt DT] [--pgs-iters K]\n"
    "        [--out FILE.csv] [--every N] [--periods FILE.csv] [--set section.key=value ...]\n"
    "        [--excitation FILE.csv|FILE.wav [--scale A] [--channel C] [--latency S]]";
const char cli_run_help[] =
    "  simulate: CSV rows, one row per excitation period, a JSON summary on stdout\n"
    "  CSV rows every N steps (--out: t, w_sensor, s, z_r, beta, contacts, pgs_iters,\n"
    "  pgs_residual; v, p, v_s with a transducer), one row per excitation period with --periods\n"
    "  (t, amp_h, s, ds), JSON summary on stdout (s_final: s at t_end; README.md).\n"
    "  --model, --s0, --t-end, --dt and --pgs-iters set [run] model, s0, t_end, [numerics] dt and\n"
    "  [solver] max_sweeps; --set any field (beamslider fields lists them). --excitation: the base\n"
    "  follows a recorded acceleration (CSV or WAV; --scale: m/s^2 at full scale, --channel: from\n"
    "  1, --latency: seconds the record lags) for the record's length unless --t-end is given\n"
    "  (docs/twin.md).\n";

typedef struct run_cli {
    const char *scene_path;
    const char *out_path;
    const char *periods_path;
    long every;
    int t_end_given;               /* --t-end: else a record sets the run's length */
    const char *excitation_path;   /* --excitation: NULL for the scene's excitation */
    excitation_file_options record; /* --scale, --channel, --latency */
    const char *record_option;     /* the first of those given, NULL if none */
} run_cli;

/* value as a finite number >= 0, or > 0 if positive; -1 after reporting the
 * option (what: the value's meaning and unit). */
static int parse_amount(const char *option, const char *value, int positive, const char *what, double *out)
{
    char *end;
    *out = strtod(value, &end);
    if (end == value || *end || !isfinite(*out) || *out < 0.0 || (positive && *out == 0.0)) {
        cli_error("%s %s: allowed: a finite number %s 0 (%s)", option, value, positive ? ">" : ">=", what);
        return -1;
    }
    return 0;
}

/* --excitation and the options of how to read the record; 1 if option is
 * none of them, 0 when taken, -1 after reporting a bad value. */
static int parse_record_option(const char *option, const char *value, run_cli *cli)
{
    char *end;
    long channel;

    if (!strcmp(option, "--excitation")) {
        cli->excitation_path = value;
        return 0;
    }
    if (strcmp(option, "--scale") && strcmp(option, "--channel") && strcmp(option, "--latency"))
        return 1;
    if (!cli->record_option)
        cli->record_option = option;
    if (!strcmp(option, "--scale")) {
        cli->record.has_scale = 1;
        return parse_amount(option, value, 1, "m/s^2 at full scale", &cli->record.scale);
    }
    if (!strcmp(option, "--latency"))
        return parse_amount(option, value, 0, "seconds", &cli->record.latency);
    errno = 0;
    channel = strtol(value, &end, 10);
    if (end == value || *end || errno || channel < 1 || channel > 65535) {
        cli_error("%s %s: allowed: an integer in [1, 65535] (1 is the first channel)", option, value);
        return -1;
    }
    cli->record.channel = (int)channel;
    return 0;
}

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
    cli->t_end_given = 0;
    cli->excitation_path = NULL;
    memset(&cli->record, 0, sizeof cli->record);
    cli->record_option = NULL;
    if (scene_load(cli->scene_path, file, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    for (i = 1; i < argc; i += 2) {
        const char *option = argv[i];
        const struct override *o;
        int taken;
        if (i + 1 >= argc) {
            cli_error("option %s needs a value", option);
            return -1;
        }
        for (o = overrides; o->option && strcmp(o->option, option); ++o)
            ;
        if (o->option || !strcmp(option, "--set")) {
            if (o->option ? scene_set(file, o->section, o->key, argv[i + 1], option, err, sizeof err) != 0
                          : scene_set_assignment(file, option, argv[i + 1], err, sizeof err) != 0) {
                cli_error("%s", err);
                return -1;
            }
            if (!strcmp(option, "--t-end") || !strncmp(argv[i + 1], "run.t_end=", 10))
                cli->t_end_given = 1;
        } else if ((taken = parse_record_option(option, argv[i + 1], cli)) <= 0) {
            if (taken < 0)
                return -1;
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
            cli_error("unknown option '%s' (see beamslider run --help)", option);
            return -1;
        }
    }
    if (cli->record_option && !cli->excitation_path) {
        cli_error("%s is about a recorded excitation: give it with --excitation FILE", cli->record_option);
        return -1;
    }
    return 0;
}

/* The recorded excitation of --excitation, read once and checked for the
 * run (its t_end: the record's whole steps unless --t-end was given; every
 * step mean within the range the scene's [excitation] acceleration may take),
 * then opened again for the run to read as it goes. 0, or -1 after reporting
 * why (then nothing is open). */
typedef struct run_record {
    excitation_file file;
    excitation_stream stream;
    char err[1024];       /* why the stream stopped */
} run_record;

static int load_record(const run_cli *cli, const scene_file *file, run_options *options, run_record *record)
{
    excitation_run plan;
    double low;

    if (file->params.schedule[strspn(file->params.schedule, " \t")]) {
        char where[SCENE_PATH + 64];
        cli_error("%s: [excitation] schedule and --excitation both set the excitation: remove one",
                  scene_where(file, "excitation", "schedule", where, sizeof where));
        return -1;
    }
    plan.dt = options->dt;
    plan.steps = cli->t_end_given ? run_step_count(options->t_end, options->dt) : 0;
    if (scene_limits_range(file, "excitation", "acceleration", &low, &plan.max_mean) != 0) {
        cli_error("%s: no base acceleration is within the core's range with this scene", cli->excitation_path);
        return -1;
    }
    if (excitation_file_read(cli->excitation_path, &cli->record, &plan, &record->file, record->err,
                             sizeof record->err) != 0
        || excitation_stream_open(&record->stream, &record->file, options->dt, record->err, sizeof record->err) != 0) {
        cli_error("%s", record->err);
        return -1;
    }
    options->t_end = (double)record->file.steps * options->dt;
    return 0;
}

/* run_options.base_accel of a record: its next step mean. */
static int record_mean(void *source, double *mean)
{
    run_record *record = source;
    return excitation_stream_next(&record->stream, mean, record->err, sizeof record->err);
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
        cli_error("%s holds the run only up to t = %.9g s: it stopped at a write error", path, result->t);
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
    schedule excitation;
    static run_record record; /* static: its line buffer */
    int measured;
    char err[1024];
    cli_output outputs[2];
    cli_input record_input;
    cli_progress bar;
    FILE *csv, *periods;
    int failed, status;

    if (parse_options(argc, argv, &cli, &file) != 0)
        return CLI_USAGE;
    if (scene_build(&file, &scene, &model, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    options.t_end = file.params.t_end;
    options.dt = file.params.dt;
    measured = cli.excitation_path != NULL;
    if (measured && load_record(&cli, &file, &options, &record) != 0)
        return CLI_USAGE;
    /* outputs are opened only once the input is known to be good */
    outputs[0].option = "--out";
    outputs[0].path = cli.out_path;
    outputs[1].option = "--periods";
    outputs[1].path = cli.periods_path;
    record_input.option = "--excitation";
    record_input.path = cli.excitation_path;
    if ((status = cli_open_outputs_reading(outputs, 2, &file, &record_input, 1)) != CLI_OK) {
        if (measured)
            excitation_stream_close(&record.stream);
        return status;
    }
    csv = outputs[0].file;
    periods = outputs[1].file;
    options.model = (bs_model)file.params.model;
    options.s0 = file.params.s0;
    options.solver = scene_solver(&file.params);
    options.every = cli.every;
    options.csv = csv;
    options.periods = periods;
    cli_progress_start(&bar, options.model == BS_MODEL_PCS ? "pcs" : "run");
    options.progress = cli_progress_hook;
    options.progress_context = &bar;
    options.on_step = NULL;
    options.on_step_context = NULL;
    /* the file's schedule was checked when it was read */
    options.excitation_schedule = schedule_parse(file.params.schedule, &excitation, err, sizeof err) == 0
                                      ? &excitation : NULL;
    options.base_accel = measured ? record_mean : NULL;
    options.base_accel_source = &record;
    failed = run_scene(&scene, &options, &result) != 0;
    cli_progress_end(&bar);
    /* a write error ends the run: then both files are reported incomplete */
    {
        const int csv_lost = close_output(cli.out_path, csv, &result) != 0;
        const int periods_lost = close_output(cli.periods_path, periods, &result) != 0;
        if (csv_lost || periods_lost)
            result.write_failed = failed = 1;
    }
    if (result.out_of_memory)
        cli_error("out of memory for the simulation");
    else if (result.input_failed)
        cli_error("%s; state and CSV kept up to t = %.6g s", record.err, result.t);
    else if (result.status != BS_OK)
        cli_error("%s: stopped at t = %.9g s (step %llu): %s; state and CSV kept up to the last good step",
                  file.params.name, result.t, (unsigned long long)result.steps, bs_status_text(result.status));
    if (summary_print_run(stdout, &file, &scene, measured ? &record.file : NULL, &result) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        failed = 1;
    }
    if (measured)
        excitation_stream_close(&record.stream);
    return failed ? CLI_FAILED : CLI_OK;
}
