/* cli_map.c - `beamslider map` and `beamslider map-merge` (docs/maps.md):
 * a grid of varied scene fields, each point run K times, on worker
 * processes, resumable, in shards; the merged tables. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"
#include "map_grid.h"
#include "map_pool.h"
#include "map_store.h"
#include "map_table.h"
#include "progress.h"
#include "scene_build.h"
#include "scene_values.h"
#include "summary.h"

static const char map_usage[] =
    "usage: beamslider map SCENE.ini --vary section.key=FROM:TO:STEP|v1,v2,... [--vary ...]\n"
    "                      [--set section.key=value ...] [--repeat K] [--jobs N] [--shard I/N] --out DIR\n"
    "  runs the scene over the grid of the varied fields (the last --vary varies fastest), each\n"
    "  point K times (repeat r from s0 + r 1e-5), on N worker processes (default: the cores),\n"
    "  or only the I-th of N shards (cases c with c % N = I - 1). One row per case in DIR's\n"
    "  result files; the same command again skips the cases done (resume), another map in DIR\n"
    "  is refused. When every case is done, DIR/runs.csv (one row per case) and DIR/map.csv\n"
    "  (one row per grid point: outcome class fractions, spread) are written. JSON summary on\n"
    "  stdout. docs/maps.md says what the columns and outcome classes mean.\n"
    "usage: beamslider map-merge DIR\n"
    "  writes DIR/runs.csv and DIR/map.csv from the result files of every shard (all cases done);\n"
    "  JSON summary on stdout (cases, done, lines ignored, complete)\n";

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

/* Every case's scene must build (a derived check, such as s0 within the
 * clamp stops, can fail for a combination of values): checked before
 * anything is written. The repeats differ only in s0, and the start range
 * is an interval, so the first and last repeat of each point suffice (one
 * when there is one). A build is a modal analysis and a shape fit, some
 * milliseconds: a map of 100 000 points takes minutes here, so it shows its
 * progress (on a terminal, as run does). */
static int check_cases(const map_grid *grid, const scene_file *base)
{
    static scene_file file; /* static: large */
    static bs_scene scene;
    static scene_model model;
    char err[2048], detail[64];
    progress bar;
    long point;
    int status = 0;

    progress_start(&bar, "map: checking the cases' scenes");
    for (point = 0; point < grid->points && status == 0; ++point) {
        int k;
        snprintf(detail, sizeof detail, "%ld/%ld points", point, grid->points);
        progress_update(&bar, (double)point / (double)grid->points, detail);
        for (k = 0; k < (grid->repeat > 1 ? 2 : 1) && status == 0; ++k) {
            const long c = point * grid->repeat + (k ? grid->repeat - 1 : 0);
            if (map_case_scene(grid, base, c, &file, err, sizeof err) != 0
                || scene_build(&file, &scene, &model, err, sizeof err) != 0) {
                progress_end(&bar);
                cli_error("case %ld (grid point %ld, repeat %d) cannot run: %s", c, point,
                          map_case_repeat(grid, c), err);
                status = -1;
            }
        }
    }
    if (status == 0)
        progress_end(&bar);
    return status;
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

/* Reads dir's rows; writes the tables when every case is done. Sets done,
 * torn, invalid, complete of summary. CLI_OK, or after reporting CLI_USAGE
 * (a result file refused: bad input) or CLI_FAILED (the tables not
 * written; cases not done, when report_missing). */
static int merge(const char *dir, const map_grid *grid, summary_map *m, int report_missing)
{
    char err[2048];
    map_found found;

    if (map_found_read(dir, grid, &found, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE; /* a result file refused: bad input */
    }
    m->done_total = found.done;
    m->torn = found.torn;
    m->invalid = found.invalid;
    m->complete = found.done == grid->cases;
    if (found.differing > 0)
        fprintf(stderr, "beamslider: warning: %s: %ld case(s) were run twice with different results "
                "(the first row of each is kept)\n", dir, found.differing);
    if (m->complete && map_tables_write(dir, grid, found.row, err, sizeof err) != 0) {
        cli_error("%s", err);
        map_found_free(&found, grid->cases);
        return CLI_FAILED;
    }
    if (!m->complete && report_missing)
        cli_error("%s: %ld of %ld cases are not done yet (run the map command, or each of its shards, "
                  "again to finish them)", dir, grid->cases - found.done, grid->cases);
    map_found_free(&found, grid->cases);
    return m->complete || !report_missing ? CLI_OK : CLI_FAILED;
}

int cli_map(int argc, char **argv)
{
    static scene_file base; /* static: large */
    map_cli cli;
    map_grid grid;
    map_pool_options pool;
    map_pool_result done;
    summary_map m;
    map_found found;
    unsigned char skip[SCENE_MAX_FIELDS];
    char err[2048];
    char *identity, *command;
    long *pending, c;
    int i, failed = 0;

    if (argc >= 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h"))) {
        fputs(map_usage, stdout);
        return CLI_OK;
    }
    if (parse_options(argc, argv, &cli, &base) != 0)
        return CLI_USAGE;
    map_grid_init(&grid);
    for (i = 0; i < cli.vary_count; ++i)
        if (map_grid_add(&grid, &base, cli.vary[i], err, sizeof err) != 0) {
            cli_error("%s", err);
            map_grid_free(&grid);
            return CLI_USAGE;
        }
    if (map_grid_finish(&grid, cli.repeat, err, sizeof err) != 0) {
        cli_error("%s", err);
        map_grid_free(&grid);
        return CLI_USAGE;
    }
    if (check_cases(&grid, &base) != 0) {
        map_grid_free(&grid);
        return CLI_USAGE;
    }
    command = command_text(argc, argv);
    identity = command ? map_identity_text(&grid, &base, cli.scene_path, command) : NULL;
    free(command);
    if (!identity) {
        cli_error("out of memory");
        map_grid_free(&grid);
        return CLI_FAILED;
    }
    if (writes_over_scene(cli.dir, &base) != 0) {
        free(identity);
        map_grid_free(&grid);
        return CLI_USAGE;
    }
    switch (map_dir_claim(cli.dir, identity, err, sizeof err)) {
    case 0:
        break;
    case 1:
        fprintf(stderr, "beamslider: warning: %s\n", err);
        break;
    default:
        cli_error("%s", err);
        free(identity);
        map_grid_free(&grid);
        return CLI_USAGE;
    }
    free(identity);

    memset(&m, 0, sizeof m);
    m.grid = &grid;
    m.dir = cli.dir;
    m.shard_index = cli.shard_index;
    m.shard_count = cli.shard_count;
    memset(skip, 0, sizeof skip);
    for (i = 0; i < grid.vary_count; ++i)
        skip[grid.vary[i].field] = 1;
    m.fields_hash = scene_values_hash(&base.params, skip);
    if (map_found_read(cli.dir, &grid, &found, err, sizeof err) != 0) {
        cli_error("%s", err);
        map_grid_free(&grid);
        return CLI_FAILED;
    }
    pending = malloc((size_t)grid.cases * sizeof *pending);
    if (!pending) {
        cli_error("out of memory for %ld cases", grid.cases);
        map_found_free(&found, grid.cases);
        map_grid_free(&grid);
        return CLI_FAILED;
    }
    for (c = 0; c < grid.cases; ++c)
        if (map_shard_has(c, cli.shard_index, cli.shard_count)) {
            ++m.shard_cases;
            if (found.row[c])
                ++m.skipped;
            else
                pending[m.run++] = c;
        }
    map_found_free(&found, grid.cases);

    pool.dir = cli.dir;
    pool.grid = &grid;
    pool.base = &base;
    pool.cases = pending;
    pool.count = m.run;
    pool.jobs = cli.jobs < m.run ? cli.jobs : (int)m.run;
    pool.show_progress = 1;
    m.jobs = pool.jobs;
    if (m.run > 0 && map_pool_run(&pool, &done, err, sizeof err) != 0) {
        cli_error("%s", err);
        failed = 1;
    }
    m.wall_s = m.run > 0 ? done.wall_s : 0.0;
    m.run = m.run > 0 ? done.done : 0;
    free(pending);
    if (merge(cli.dir, &grid, &m, 0) != 0)
        failed = 1;
    if (summary_print_map(stdout, &base, &m) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        failed = 1;
    }
    map_grid_free(&grid);
    return failed ? CLI_FAILED : CLI_OK;
}

int cli_map_merge(int argc, char **argv)
{
    map_grid grid;
    summary_map m;
    char err[2048];
    char scene[SCENE_TEXT];
    int status;

    if (argc >= 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h"))) {
        fputs(map_usage, stdout);
        return CLI_OK;
    }
    if (argc != 1 || argv[0][0] == '-') {
        cli_error("usage: beamslider map-merge DIR");
        return CLI_USAGE;
    }
    if (map_identity_read(argv[0], &grid, scene, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    memset(&m, 0, sizeof m);
    m.grid = &grid;
    m.dir = argv[0];
    status = merge(argv[0], &grid, &m, 1);
    if (status == CLI_OK)
        fprintf(stderr, "map-merge: wrote %s/%s and %s/%s: %ld cases (%ld torn and %ld other lines ignored)\n",
                argv[0], MAP_RUNS_TABLE, argv[0], MAP_POINTS_TABLE, grid.cases, m.torn, m.invalid);
    if (summary_print_merge(stdout, scene, &m) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        status = CLI_FAILED;
    }
    map_grid_free(&grid);
    return status;
}
