/* cli_map.c - `beamslider map` and `beamslider map-merge` (docs/maps.md):
 * a grid of varied scene fields, each point run K times, on worker
 * threads, resumable, in shards; the merged tables. The options and the
 * messages: the work is the map wing's (host/lib/map/map_run.h). */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"
#include "cli_progress.h"
#include "map_run.h"
#include "map_store.h"
#include "map_summary.h"
#include "map_table.h"

const char cli_map_synopsis[] =
    "beamslider map SCENE.ini --vary section.key=FROM:TO:STEP|v1,v2,... [--vary ...]\n"
    "        [--set section.key=value ...] [--repeat K] [--jobs N] [--shard I/N] --out DIR";
const char cli_map_help[] =
    "  a grid of runs, resumable and sharded (docs/maps.md)\n"
    "  Runs the scene over the grid of the varied fields (the last --vary varies fastest), each point K times (repeat r from\n"
    "  s0 + r 1e-5), on N worker threads (default: the cores), or only the I-th of N shards\n"
    "  (cases c with c % N = I - 1). One row per case in DIR's result files (DIR and the folders\n"
    "  above it are made); the same command again skips the cases done (resume), another map in\n"
    "  DIR is refused. When every case is done, DIR/runs.csv (one row per case) and DIR/map.csv\n"
    "  (one row per grid point: outcome class fractions, spread) are written. JSON summary on\n"
    "  stdout. docs/maps.md says what the columns and outcome classes mean.\n";

const char cli_map_merge_synopsis[] = "beamslider map-merge DIR";
const char cli_map_merge_help[] =
    "  the merged tables of a map's shards\n"
    "  Writes DIR/runs.csv and DIR/map.csv from the result\n"
    "  files of every shard (all cases done); JSON summary on stdout (cases, done, lines ignored,\n"
    "  complete)\n";

typedef struct map_cli {
    const char *scene_path, *dir;
    const char *vary[MAP_MAX_VARY + 1];
    int vary_count;
    int repeat, jobs;
    int shard_index, shard_count;
} map_cli;

static int online_cores(void)
{
    const long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n >= 1 && n <= 1024 ? (int)n : 1;
}

static int parse_options(int argc, char **argv, map_cli *cli, scene_file *file)
{
    char err[2048];
    int i;

    memset(cli, 0, sizeof *cli);
    cli->repeat = 1;
    cli->jobs = online_cores();
    cli->shard_index = cli->shard_count = 1;
    if (argc < 1 || argv[0][0] == '-') {
        cli_error("map needs a scene file first: beamslider map SCENE.ini --vary ... --out DIR "
                  "(beamslider map --help)");
        return -1;
    }
    cli->scene_path = argv[0];
    if (scene_load(cli->scene_path, file, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    for (i = 1; i < argc; i += 2) {
        const char *option = argv[i], *value = i + 1 < argc ? argv[i + 1] : NULL;
        int failed = 0;
        if (!value) {
            cli_error("option %s needs a value", option);
            return -1;
        }
        if (!strcmp(option, "--set")) {
            if (scene_set_assignment(file, option, value, err, sizeof err) != 0) {
                cli_error("%s", err);
                return -1;
            }
        } else if (!strcmp(option, "--vary")) {
            if (cli->vary_count >= MAP_MAX_VARY) {
                cli_error("--vary %s: at most %d fields can be varied", value, MAP_MAX_VARY);
                return -1;
            }
            cli->vary[cli->vary_count++] = value;
        } else if (!strcmp(option, "--repeat")) {
            failed = cli_parse_int(option, value, 1, MAP_MAX_REPEAT, &cli->repeat);
        } else if (!strcmp(option, "--jobs")) {
            failed = cli_parse_int(option, value, 1, 1024, &cli->jobs);
        } else if (!strcmp(option, "--shard")) {
            if (map_shard_parse(value, &cli->shard_index, &cli->shard_count, err, sizeof err) != 0) {
                cli_error("%s", err);
                return -1;
            }
        } else if (!strcmp(option, "--out")) {
            cli->dir = value;
        } else {
            cli_error("unknown option '%s' (beamslider map --help)", option);
            return -1;
        }
        if (failed)
            return -1;
    }
    if (!cli->dir) {
        cli_error("map needs --out DIR (the folder of the map's results)");
        return -1;
    }
    return 0;
}

/* The command line as one text (for the identity's info line). */
static char *command_text(int argc, char **argv)
{
    size_t length = strlen("beamslider map") + 1;
    char *text;
    int i;
    for (i = 0; i < argc; ++i)
        length += strlen(argv[i]) + 1;
    text = malloc(length);
    if (!text)
        return NULL;
    strcpy(text, "beamslider map");
    for (i = 0; i < argc; ++i) {
        strcat(text, " ");
        strcat(text, argv[i]);
    }
    return text;
}

/* The tables the map writes into dir must not be the scene or a base (a
 * scene named map.csv in its own --out folder would be replaced): 0, or -1
 * after reporting. */
static int writes_over_scene(const char *dir, const scene_file *scene)
{
    static const char *const tables[] = { MAP_RUNS_TABLE, MAP_POINTS_TABLE, MAP_IDENTITY_FILE };
    char path[4200];
    const char *input;
    size_t i;
    for (i = 0; i < sizeof tables / sizeof tables[0]; ++i) {
        snprintf(path, sizeof path, "%s/%s", dir, tables[i]);
        if (cli_is_scene_file(path, scene, &input)) {
            cli_error("--out %s: %s is the scene file %s: it would be replaced", dir, path, input);
            return -1;
        }
    }
    return 0;
}

/* Prints each line of warnings as a warning. */
static void print_warnings(const char *warnings)
{
    while (*warnings) {
        const size_t n = strcspn(warnings, "\n");
        fprintf(stderr, "beamslider: warning: %.*s\n", (int)n, warnings);
        warnings += n + (warnings[n] == '\n');
    }
}

static int exit_status(int map_status)
{
    return map_status == MAP_DONE ? CLI_OK : map_status == MAP_E_INPUT ? CLI_USAGE : CLI_FAILED;
}

int cli_map(int argc, char **argv)
{
    scene_file *base = malloc(sizeof *base); /* large: on the heap */
    map_cli cli;
    map_grid grid;
    map_run_options options;
    summary_map m;
    cli_progress bar;
    char err[4096], warnings[4096];
    char *command = NULL;
    int status;

    if (!base) {
        cli_error("out of memory");
        return CLI_FAILED;
    }
    if (parse_options(argc, argv, &cli, base) != 0) {
        free(base);
        return CLI_USAGE;
    }
    memset(&options, 0, sizeof options);
    options.dir = cli.dir;
    options.vary = cli.vary;
    options.vary_count = cli.vary_count;
    options.repeat = cli.repeat;
    options.jobs = cli.jobs;
    options.shard_index = cli.shard_index;
    options.shard_count = cli.shard_count;
    options.scene_path = cli.scene_path;
    cli_progress_start(&bar, "map: checking the cases' scenes");
    options.progress = cli_progress_hook;
    options.progress_context = &bar;
    status = map_run_grid(base, &options, &grid, err, sizeof err);
    cli_progress_end(&bar);
    if (status == MAP_DONE && !(command = command_text(argc, argv))) {
        snprintf(err, sizeof err, "out of memory");
        status = MAP_E_FAILED;
    }
    if (status != MAP_DONE) {
        cli_error("%s", err);
        map_grid_free(&grid);
        free(base);
        return exit_status(status);
    }
    if (writes_over_scene(cli.dir, base) != 0) {
        free(command);
        map_grid_free(&grid);
        free(base);
        return CLI_USAGE;
    }
    options.command = command;
    cli_progress_start(&bar, "map");
    status = map_run_cases(base, &grid, &options, &m, err, sizeof err, warnings, sizeof warnings);
    cli_progress_end(&bar);
    free(command);
    print_warnings(warnings);
    if (status == MAP_E_INPUT) { /* refused before any case was run: no summary */
        cli_error("%s", err);
        map_grid_free(&grid);
        free(base);
        return CLI_USAGE;
    }
    if (status != MAP_DONE)
        cli_error("%s", err);
    if (summary_print_map(stdout, base, &m) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        status = MAP_E_FAILED;
    }
    map_grid_free(&grid);
    free(base);
    return status == MAP_DONE ? CLI_OK : CLI_FAILED;
}

int cli_map_merge(int argc, char **argv)
{
    map_grid grid;
    summary_map m;
    char err[2048], warnings[2048] = "";
    char scene[SCENE_TEXT];
    int status;

    if (argc != 1 || argv[0][0] == '-') {
        cli_error("usage: %s", cli_map_merge_synopsis);
        return CLI_USAGE;
    }
    if (map_identity_read(argv[0], &grid, scene, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    memset(&m, 0, sizeof m);
    m.grid = &grid;
    m.dir = argv[0];
    status = map_run_merge(argv[0], &grid, &m, 1, err, sizeof err, warnings, sizeof warnings);
    print_warnings(warnings);
    if (status != MAP_DONE)
        cli_error("%s", err);
    else
        fprintf(stderr, "map-merge: wrote %s/%s and %s/%s: %ld cases (%ld torn and %ld other lines ignored)\n",
                argv[0], MAP_RUNS_TABLE, argv[0], MAP_POINTS_TABLE, grid.cases, m.torn, m.invalid);
    status = exit_status(status);
    if (summary_print_merge(stdout, scene, &m) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        status = CLI_FAILED;
    }
    map_grid_free(&grid);
    return status;
}
