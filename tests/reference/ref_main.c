/* ref_main.c - bs-reference: the double-precision reference model of
 * docs/model.md on the command line (the oracle for core/).
 *
 *   bs-reference run SCENE.ini [--t-end T] [--dt DT] [--substeps K] [--model free|pcs]
 *                [--s0 S] [--out FILE.csv] [--every N] [--periods FILE.csv]
 *                [--solver enum|pgs] [--pgs-tol X] [--exhaustive] [--compliance EPS]
 *                [--base-accel FILE]
 *   bs-reference modes SCENE.ini
 *
 * --compliance is a diagnostic outside docs/model.md (G_ii (1 + EPS)), to
 * reproduce a regularised contact solve; the default 0 is the model.
 * --base-accel FILE replays a measured base acceleration (docs/model.md 10):
 * the mean over each outer step, one value per line in m/s^2 ('#' comments),
 * held for the step's K substeps, at least round(t_end / dt) values; it
 * replaces the scene's [excitation].
 *
 * Exit status: 0 ok, 1 the run failed (solve, non-finite state, write), 2 bad usage or input. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ref_replay.h"
#include "ref_run.h"
#include "scene_ini.h"

#define EXIT_WORK 1
#define EXIT_USAGE 2

static void usage(void)
{
    fprintf(stderr, "usage: bs-reference run SCENE.ini [--t-end T] [--dt DT] [--substeps K] [--model free|pcs]\n"
                    "                    [--s0 S] [--out FILE.csv] [--every N] [--periods FILE.csv]\n"
                    "                    [--solver enum|pgs] [--pgs-tol X] [--exhaustive] [--compliance EPS]\n"
                    "                    [--base-accel FILE]\n"
                    "       bs-reference modes SCENE.ini\n");
}

static int parse_long(const char *text, long low, long *out)
{
    char *end;
    errno = 0;
    *out = strtol(text, &end, 10);
    return *end || end == text || errno || *out < low ? -1 : 0;
}

static int load(const char *path, scene_file *file)
{
    char err[1024];
    if (scene_load(path, file, err, sizeof err) != 0) {
        fprintf(stderr, "bs-reference: %s\n", err);
        return -1;
    }
    return 0;
}

static int cmd_modes(int argc, char **argv)
{
    static scene_file file;
    static ref_scene scene;
    char err[256];
    int k;

    if (argc != 1) {
        usage();
        return EXIT_USAGE;
    }
    if (load(argv[0], &file) != 0)
        return EXIT_USAGE;
    if (ref_scene_init(&scene, &file.params, 1, err, sizeof err) != 0) {
        fprintf(stderr, "bs-reference: %s\n", err);
        return EXIT_USAGE;
    }
    printf("# %s: N = %d, b = %.6Lg m, EI = %.6Lg N m^2, kappa = k_r L/EI = %.6Lg, k_ax = %.6Lg N/m\n",
           file.params.name, scene.n_modes, scene.modes.width, scene.modes.ei, scene.modes.kappa,
           scene.modes.k_ax);
    printf("k,lambda,f_hz,gamma,phi_4_7\n");
    for (k = 0; k < scene.n_modes; ++k)
        printf("%d,%.15Lg,%.9g,%.9g,%.9g\n", k + 1, scene.modes.lambda[k],
               scene.modes.omega[k] / (2.0 * (double)REF_PI), scene.modes.gamma[k], scene.sensor_phi[k]);
    return 0;
}

typedef struct run_cli {
    const char *out_path, *periods_path;
    const char *base_accel_path;  /* NULL: the scene's excitation */
    long every, substeps;
} run_cli;

static int parse_run(int argc, char **argv, scene_file *file, run_cli *cli, ref_step_options *step)
{
    static const struct {
        const char *option, *section, *key;
    } overrides[] = { { "--model", "run", "model" }, { "--s0", "run", "s0" }, { "--t-end", "run", "t_end" },
                      { "--dt", "numerics", "dt" }, { 0, 0, 0 } };
    char err[1024];
    int i;

    if (argc < 1 || argv[0][0] == '-') {
        usage();
        return -1;
    }
    if (load(argv[0], file) != 0)
        return -1;
    cli->out_path = cli->periods_path = cli->base_accel_path = NULL;
    cli->every = 1;
    cli->substeps = 1;
    ref_step_default_options(step);
    for (i = 1; i < argc; i += 2) {
        const char *option = argv[i], *value = i + 1 < argc ? argv[i + 1] : NULL;
        int o;
        if (!strcmp(option, "--exhaustive")) {
            step->exhaustive = 1;
            --i;
            continue;
        }
        if (!value) {
            fprintf(stderr, "bs-reference: option %s needs a value\n", option);
            return -1;
        }
        for (o = 0; overrides[o].option && strcmp(overrides[o].option, option); ++o)
            ;
        if (overrides[o].option) {
            if (scene_set(file, overrides[o].section, overrides[o].key, value, option, err, sizeof err) != 0) {
                fprintf(stderr, "bs-reference: %s\n", err);
                return -1;
            }
        } else if (!strcmp(option, "--out")) {
            cli->out_path = value;
        } else if (!strcmp(option, "--periods")) {
            cli->periods_path = value;
        } else if (!strcmp(option, "--base-accel")) {
            cli->base_accel_path = value;
        } else if (!strcmp(option, "--every")) {
            if (parse_long(value, 1, &cli->every) != 0) {
                fprintf(stderr, "bs-reference: --every %s: allowed: an integer >= 1\n", value);
                return -1;
            }
        } else if (!strcmp(option, "--substeps")) {
            if (parse_long(value, 1, &cli->substeps) != 0 || cli->substeps > 1000000L) {
                fprintf(stderr, "bs-reference: --substeps %s: allowed: an integer in [1, 1e6]\n", value);
                return -1;
            }
        } else if (!strcmp(option, "--solver")) {
            if (!strcmp(value, "enum"))
                step->solver = REF_SOLVER_ENUM;
            else if (!strcmp(value, "pgs"))
                step->solver = REF_SOLVER_PGS;
            else {
                fprintf(stderr, "bs-reference: --solver %s: allowed: enum, pgs\n", value);
                return -1;
            }
        } else if (!strcmp(option, "--compliance")) {
            char *end;
            step->compliance = strtod(value, &end);
            if (*end || !(step->compliance >= 0.0 && step->compliance < 1.0)) {
                fprintf(stderr, "bs-reference: --compliance %s: allowed: a number in [0, 1)\n", value);
                return -1;
            }
        } else if (!strcmp(option, "--pgs-tol")) {
            char *end;
            step->pgs_tol_rel = strtod(value, &end);
            if (*end || !(step->pgs_tol_rel > 0.0)) {
                fprintf(stderr, "bs-reference: --pgs-tol %s: allowed: a number > 0\n", value);
                return -1;
            }
        } else {
            fprintf(stderr, "bs-reference: unknown option '%s'\n", option);
            usage();
            return -1;
        }
    }
    return 0;
}

static int open_output(const char *path, FILE **f)
{
    *f = NULL;
    if (!path)
        return 0;
    *f = fopen(path, "w");
    if (!*f) {
        fprintf(stderr, "bs-reference: cannot open %s for writing: %s\n", path, strerror(errno));
        return -1;
    }
    return 0;
}

static const char *excitation_name(const ref_scene *scene, const run_cli *cli)
{
    return cli->base_accel_path ? "replay" : scene->schedule_points ? "schedule" : "harmonic";
}

static void print_summary(const scene_file *file, const ref_scene *scene, const run_cli *cli,
                          const ref_step_options *step, const ref_run_result *r)
{
    printf("{\"program\":\"bs-reference\",\"scene\":\"%s\",\"model\":\"%s\",\"precision\":\"double\","
           "\"solver\":\"%s\",\"compliance\":%g,\"modes\":%d,\"dt\":%g,\"substeps\":%d,\"excitation\":\"%s\","
           "\"load\":\"%s\",\"status\":\"%s\",\"t_end\":%.9g,"
           "\"steps\":%llu,\"s0\":%.9g,\"s_final\":%.9g,\"s_min\":%.9g,\"t_s_min\":%.6f,"
           "\"amp_final_h\":%.6g,\"amp_periods\":%d,\"periods\":%llu,\"wall_s\":%.4g,\"steps_per_s\":%.4g,"
           "\"max_iters\":%ld,\"mean_iters\":%.4g,\"contact_steps\":%llu,\"exhaustive_steps\":%llu,"
           "\"ambiguous_steps\":%llu,\"unconverged_steps\":%llu,\"max_residual_rel\":%.3g",
           file->params.name, scene->model == REF_MODEL_PCS ? "pcs" : "free",
           step->solver == REF_SOLVER_PGS ? "pgs" : "enum", step->compliance, scene->n_modes, scene->dt, scene->substeps,
           excitation_name(scene, cli), ref_scene_load_name(scene->load),
           r->failed ? "failed" : r->write_failed ? "write error" : "ok", r->t, (unsigned long long)r->steps,
           file->params.s0, r->s_final, r->s_min, r->t_s_min, r->amp_final_h, r->amp_periods,
           (unsigned long long)r->periods, r->wall_s, r->wall_s > 0.0 ? (double)r->steps / r->wall_s : 0.0,
           r->max_iters, r->contact_steps ? (double)r->total_iters / (double)r->contact_steps : 0.0,
           (unsigned long long)r->contact_steps, (unsigned long long)r->exhaustive_steps,
           (unsigned long long)r->ambiguous_steps, (unsigned long long)r->unconverged_steps, r->max_residual_rel);
    if (scene->load != REF_LOAD_NONE)
        /* harvested: the energy into the load (R_l, or R_s behind the bridge); docs/model.md 11 */
        printf(",\"energy_load_j\":%.9g,\"mean_power_w\":%.9g,\"v_final\":%.9g,\"v_max\":%.9g,"
               "\"v_s_final\":%.9g,\"energy_storage_j\":%.9g,\"bridge_steps\":%llu",
               r->load_energy, r->t > 0.0 ? r->load_energy / r->t : 0.0, r->voltage_final, r->voltage_max,
               r->storage_voltage_final,
               scene->load == REF_LOAD_RECTIFIER
                   ? 0.5 * scene->storage_capacitance * r->storage_voltage_final * r->storage_voltage_final
                   : 0.0,
               (unsigned long long)r->bridge_steps);
    printf("}\n");
}

/* --base-accel: the file's values, at least one per outer step of the run. */
static int load_base_accel(const run_cli *cli, const ref_scene *scene, double t_end, ref_run_options *options)
{
    char err[1024];
    double *values;
    uint64_t count, steps;
    unsigned long lines;

    options->base_accel = NULL;
    options->base_accel_count = 0;
    if (!cli->base_accel_path)
        return 0;
    if (ref_replay_read(cli->base_accel_path, &values, &count, &lines, err, sizeof err) != 0) {
        fprintf(stderr, "bs-reference: %s\n", err);
        return -1;
    }
    steps = (uint64_t)llround(t_end / scene->dt);
    if (count < steps) {
        fprintf(stderr,
                "bs-reference: --base-accel %s:%lu: the file ends after %llu values; the run needs %llu, one per "
                "step of dt = %.9g s for t_end = %.9g s\n",
                cli->base_accel_path, lines, (unsigned long long)count, (unsigned long long)steps, scene->dt, t_end);
        free(values);
        return -1;
    }
    options->base_accel = values;
    options->base_accel_count = count;
    return 0;
}

static int cmd_run(int argc, char **argv)
{
    static scene_file file;
    static ref_scene scene;
    ref_run_options options;
    ref_run_result result;
    run_cli cli;
    char err[256];
    int status, bad_close = 0;

    if (parse_run(argc, argv, &file, &cli, &options.step) != 0)
        return EXIT_USAGE;
    if (ref_scene_init(&scene, &file.params, (int)cli.substeps, err, sizeof err) != 0) {
        fprintf(stderr, "bs-reference: %s\n", err);
        return EXIT_USAGE;
    }
    options.t_end = file.params.t_end;
    options.every = cli.every;
    if (load_base_accel(&cli, &scene, options.t_end, &options) != 0)
        return EXIT_USAGE;
    if (open_output(cli.out_path, &options.csv) != 0) {
        free((void *)options.base_accel);
        return EXIT_WORK;
    }
    if (open_output(cli.periods_path, &options.periods) != 0) {
        if (options.csv)
            fclose(options.csv);
        free((void *)options.base_accel);
        return EXIT_WORK;
    }
    status = ref_run(&scene, &options, &result);
    free((void *)options.base_accel);
    if (options.csv && fclose(options.csv) != 0)
        bad_close = 1;
    if (options.periods && fclose(options.periods) != 0)
        bad_close = 1;
    if (bad_close)
        result.write_failed = 1;
    print_summary(&file, &scene, &cli, &options.step, &result);
    if (result.write_failed)
        fprintf(stderr, "bs-reference: writing an output failed; it is incomplete\n");
    if (result.failed)
        fprintf(stderr, "bs-reference: the run stopped at t = %.6f s: a step failed\n", result.t);
    return status != 0 || bad_close ? EXIT_WORK : 0;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "run"))
        return cmd_run(argc - 2, argv + 2);
    if (argc >= 2 && !strcmp(argv[1], "modes"))
        return cmd_modes(argc - 2, argv + 2);
    usage();
    return EXIT_USAGE;
}
