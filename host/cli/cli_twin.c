/* cli_twin.c - the digital twin's observer on recorded signals (docs/twin.md,
 * "Observer"):
 *
 *   beamslider twin-plant SCENE --out FILE.csv [...]   a test stream from a plant
 *   beamslider twin SCENE --measured FILE.csv --out EST.csv [...]   the twin on it
 *   beamslider twin-gains SCENE [...]                   the observer's constants as a C header
 *
 * The measured-signals file (written by twin-plant, or by any plant) has one
 * grammar and one reader, host/lib/measured_signals.h; `twin --measured -`
 * reads it from standard input, once, as it comes.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bs_observer.h"
#include "bs_platform.h"
#include "cli.h"
#include "measured_signals.h"
#include "observer_design.h"
#include "out_c.h"
#include "out_json.h"
#include "out_text.h"
#include "progress.h"
#include "run.h"
#include "scene_build.h"
#include "schedule.h"

#define MAX_SETS 16

static const char twin_usage[] =
    "usage: beamslider twin SCENE.ini --measured FILE.csv|- --out EST.csv [--signal deflection|voltage]\n"
    "                       [--latency S] [--noise SIGMA] [--accel-noise SIGMA] [--force-noise N]\n"
    "                       [--s0 S] [--every N] [--open-loop] [--no-position] [--lockin TAU]\n"
    "                       [--position-gain G] [--position-rate R] [--deadband D] [--outlier-gate K]\n"
    "                       [--score-after T] [--tolerance D]\n"
    "                       [--map-frequencies F,F,...] [--set SECTION.KEY=VALUE]...\n"
    "  runs the scene as a twin on the measured base acceleration, corrected from the measured\n"
    "  signal (docs/twin.md, \"Observer\"); EST.csv every N steps: t, s_hat, s_sigma, amplitude,\n"
    "  power, y, y_hat, s_true (if the file has it), phase_error, s_error, outliers (measurements\n"
    "  skipped so far: beyond --outlier-gate K times the innovation's RMS, default 6, or a\n"
    "  correction that would throw the slider off), health (1: one within the last lock-in\n"
    "  time). JSON summary on stdout.\n"
    "  --measured -: a live stream on standard input, read once to its end (give --noise).\n"
    "usage: beamslider twin-plant SCENE.ini --out FILE.csv [--signal deflection|voltage] [--snr DB]\n"
    "                       [--accel-snr DB] [--bits B] [--seed N] [--latency S] [--freq-scale X]\n"
    "                       [--s0 S] [--t-end T] [--set SECTION.KEY=VALUE]...\n"
    "  a test stream: the scene (perturbed) as the plant, signals with white noise SNR dB below\n"
    "  their RMS and B-bit quantisation over +-2x their largest value, the signal --latency late.\n"
    "usage: beamslider twin-gains SCENE.ini --noise SIGMA [--signal deflection|voltage] [--latency S]\n"
    "                       [--accel-noise SIGMA] [--force-noise N] [--map-frequencies F,F,...]\n"
    "                       [--name NAME] [--set ...]\n"
    "  the observer's constants (bs_observer_gains) as a C header on stdout. Response maps at\n"
    "  --map-frequencies [Hz, ascending], else at the scene's excitation or across its schedule.\n";

/* The options of the three commands (each uses some). */
typedef struct twin_cli {
    const char *scene_path, *out_path, *measured_path, *name;
    const char *sets[MAX_SETS];
    int set_count;
    int map_count;              /* --map-frequencies (0: from the scene) */
    double map_frequency[BS_OBSERVER_MAPS];
    int signal;                 /* -1: not given */
    double latency;             /* [s] */
    double noise, accel_noise;  /* NAN: not given */
    double force_noise;
    double s0, t_end;           /* NAN: the scene's */
    double snr, accel_snr;      /* [dB]; INFINITY: no noise; accel_snr NAN: as snr */
    int bits;
    unsigned long seed;
    double freq_scale;
    long every;
    int open_loop, no_position;
    double lockin, position_gain, position_rate, position_deadband, outlier_gate;
    double score_after, tolerance;
} twin_cli;

/* ---- options ---- */

static int parse_number(const char *option, const char *text, double low, double high, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    if (*end || errno || !(*out >= low && *out <= high)) {
        cli_error("%s %s: allowed: a number in [%g, %g]", option, text, low, high);
        return -1;
    }
    return 0;
}

static int parse_signal(const char *text, int *signal)
{
    if (!strcmp(text, "deflection"))
        *signal = BS_SIGNAL_DEFLECTION;
    else if (!strcmp(text, "voltage"))
        *signal = BS_SIGNAL_VOLTAGE;
    else
        return -1;
    return 0;
}

static void cli_defaults(twin_cli *c)
{
    memset(c, 0, sizeof *c);
    c->signal = -1;
    c->noise = c->accel_noise = NAN;
    c->force_noise = OBSERVER_DEFAULT_FORCE_NOISE;
    c->s0 = c->t_end = NAN;
    c->snr = INFINITY;
    c->accel_snr = NAN;
    c->bits = 0;
    c->seed = 1;
    c->freq_scale = 1.0;
    c->every = 50;
    c->lockin = BS_OBSERVER_DEFAULT_LOCKIN_TIME;
    c->position_gain = BS_OBSERVER_DEFAULT_POSITION_GAIN;
    c->position_rate = BS_OBSERVER_DEFAULT_POSITION_RATE;
    c->position_deadband = BS_OBSERVER_DEFAULT_POSITION_DEADBAND;
    c->outlier_gate = BS_OBSERVER_DEFAULT_OUTLIER_GATE;
    c->score_after = 5.0;
    c->tolerance = 0.005;
    c->name = "bs_observer_gains_scene";
}

/* --map-frequencies F,F,...: 1 to BS_OBSERVER_MAPS frequencies [Hz], > 0,
 * ascending. Returns 0, or -1 after reporting what is wrong. */
static int parse_map_frequencies(twin_cli *c, const char *value)
{
    const char *p = value;
    c->map_count = 0;
    for (;;) {
        char *end;
        const double f = strtod(p, &end);
        if (c->map_count == BS_OBSERVER_MAPS || end == p || (*end != ',' && *end != '\0') || !isfinite(f)
            || !(f > 0.0) || (c->map_count > 0 && !(f > c->map_frequency[c->map_count - 1]))) {
            cli_error("--map-frequencies %s: frequency %d: allowed: 1 to %d frequencies [Hz], > 0, ascending, "
                      "separated by commas", value, c->map_count + 1, BS_OBSERVER_MAPS);
            return -1;
        }
        c->map_frequency[c->map_count++] = f;
        if (*end == '\0')
            return 0;
        p = end + 1;
    }
}

/* One option with a value; returns 0, 1 if it is not an option of this
 * table, -1 after reporting a bad value. */
static int parse_valued(twin_cli *c, const char *option, const char *value)
{
    double x;
    if (!strcmp(option, "--out")) c->out_path = value;
    else if (!strcmp(option, "--measured")) c->measured_path = value;
    else if (!strcmp(option, "--name")) {
        char err[512];
        if (out_c_identifier_check(value, option, err, sizeof err) != 0) {
            cli_error("%s", err);
            return -1;
        }
        c->name = value;
    }
    else if (!strcmp(option, "--signal")) {
        if (parse_signal(value, &c->signal) != 0) {
            cli_error("--signal %s: allowed: deflection, voltage", value);
            return -1;
        }
    } else if (!strcmp(option, "--set")) {
        if (c->set_count == MAX_SETS || !strchr(value, '.') || !strchr(value, '=')) {
            cli_error("--set %s: allowed: SECTION.KEY=VALUE, at most %d times", value, MAX_SETS);
            return -1;
        }
        c->sets[c->set_count++] = value;
    } else if (!strcmp(option, "--map-frequencies")) return parse_map_frequencies(c, value);
    else if (!strcmp(option, "--latency")) return parse_number(option, value, 0.0, 1.0, &c->latency);
    else if (!strcmp(option, "--noise")) return parse_number(option, value, 1e-300, HUGE_VAL, &c->noise);
    else if (!strcmp(option, "--accel-noise")) return parse_number(option, value, 0.0, HUGE_VAL, &c->accel_noise);
    else if (!strcmp(option, "--force-noise")) return parse_number(option, value, 0.0, HUGE_VAL, &c->force_noise);
    else if (!strcmp(option, "--s0")) return parse_number(option, value, 0.0, 1.0, &c->s0);
    else if (!strcmp(option, "--t-end")) return parse_number(option, value, 1e-300, HUGE_VAL, &c->t_end);
    else if (!strcmp(option, "--snr")) return parse_number(option, value, -HUGE_VAL, HUGE_VAL, &c->snr);
    else if (!strcmp(option, "--accel-snr")) return parse_number(option, value, -HUGE_VAL, HUGE_VAL, &c->accel_snr);
    else if (!strcmp(option, "--freq-scale")) return parse_number(option, value, 0.5, 2.0, &c->freq_scale);
    else if (!strcmp(option, "--lockin")) return parse_number(option, value, 1e-3, 100.0, &c->lockin);
    else if (!strcmp(option, "--position-gain")) return parse_number(option, value, 0.0, 1e3, &c->position_gain);
    else if (!strcmp(option, "--position-rate")) return parse_number(option, value, 0.0, 1e3, &c->position_rate);
    else if (!strcmp(option, "--deadband")) return parse_number(option, value, 0.0, 1.0, &c->position_deadband);
    else if (!strcmp(option, "--outlier-gate")) return parse_number(option, value, 1.5, 1e6, &c->outlier_gate);
    else if (!strcmp(option, "--score-after")) return parse_number(option, value, 0.0, HUGE_VAL, &c->score_after);
    else if (!strcmp(option, "--tolerance")) return parse_number(option, value, 0.0, 1.0, &c->tolerance);
    else if (!strcmp(option, "--bits") || !strcmp(option, "--every") || !strcmp(option, "--seed")) {
        if (parse_number(option, value, !strcmp(option, "--every") ? 1.0 : 0.0,
                         !strcmp(option, "--bits") ? 24.0 : 4e9, &x) != 0 || x != floor(x)) {
            if (x != floor(x))
                cli_error("%s %s: allowed: an integer", option, value);
            return -1;
        }
        if (!strcmp(option, "--bits")) c->bits = (int)x;
        else if (!strcmp(option, "--every")) c->every = (long)x;
        else c->seed = (unsigned long)x;
    } else return 1;
    return 0;
}

static int parse_options(int argc, char **argv, const char *command, twin_cli *c)
{
    int i;
    cli_defaults(c);
    if (argc < 1 || argv[0][0] == '-') {
        cli_error("%s needs a scene file first (see beamslider %s --help)", command, command);
        return -1;
    }
    c->scene_path = argv[0];
    for (i = 1; i < argc; ++i) {
        int status;
        if (!strcmp(argv[i], "--open-loop")) { c->open_loop = 1; continue; }
        if (!strcmp(argv[i], "--no-position")) { c->no_position = 1; continue; }
        if (i + 1 >= argc) {
            cli_error("option %s needs a value (or is unknown: see beamslider %s --help)", argv[i], command);
            return -1;
        }
        status = parse_valued(c, argv[i], argv[i + 1]);
        if (status < 0)
            return -1;
        if (status > 0) {
            cli_error("unknown option '%s' (see beamslider %s --help)", argv[i], command);
            return -1;
        }
        ++i;
    }
    return 0;
}

/* ---- the scene: file, --set, --s0, --t-end, then --freq-scale on the built modal data ---- */

static int load_scene(const twin_cli *c, scene_file *file, bs_scene *scene, scene_model *model)
{
    char err[1024];
    int i;
    if (scene_load(c->scene_path, file, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    for (i = 0; i < c->set_count; ++i) /* checked as a file line is (host/lib/scene_ini.h) */
        if (scene_set_assignment(file, "--set", c->sets[i], err, sizeof err) != 0) {
            cli_error("%s", err);
            return -1;
        }
    if (!isnan(c->s0)) {
        snprintf(err, sizeof err, "%.17g", c->s0);
        if (scene_set(file, "run", "s0", err, "--s0", err + 512, 512) != 0) {
            cli_error("%s", err + 512);
            return -1;
        }
    }
    if (!isnan(c->t_end)) {
        snprintf(err, sizeof err, "%.17g", c->t_end);
        if (scene_set(file, "run", "t_end", err, "--t-end", err + 512, 512) != 0) {
            cli_error("%s", err + 512);
            return -1;
        }
    }
    if (scene_build(file, scene, model, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    if (c->freq_scale != 1.0) { /* every modal frequency times X, damping ratio kept */
        scene_data *d = &model->data;
        int k;
        for (k = 0; k < d->n_modes; ++k) {
            d->omega_sq[k] *= c->freq_scale * c->freq_scale;
            d->damping[k] *= c->freq_scale;
            if (d->implicit)
                d->mode_gain[k] = 1.0 / (1.0 + d->theta * d->dt * d->damping[k]
                                         + d->theta * d->theta * d->dt * d->dt * d->omega_sq[k]);
        }
        scene_data_round(d, scene);
        if (bs_scene_check(scene, NULL) != BS_OK) {
            cli_error("--freq-scale %g: the scene is no longer valid (explicit limit omega_max dt < 2?)",
                      c->freq_scale);
            return -1;
        }
    }
    return 0;
}

/* --latency in steps; beyond BS_OBSERVER_MAX_LATENCY (refused by the
 * callers) the quotient is not converted: it may exceed a long. */
static long latency_steps(const twin_cli *c, double dt)
{
    const double steps = c->latency / dt;
    return steps < BS_OBSERVER_MAX_LATENCY + 1.0 ? lround(steps) : BS_OBSERVER_MAX_LATENCY + 1;
}

/* ---- twin-plant ---- */

/* xorshift64* and Box-Muller: reproducible white Gaussian noise. */
static double uniform(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return ((double)((*state * UINT64_C(2685821657736338717)) >> 11) + 0.5) / 9007199254740992.0;
}

static double gaussian(uint64_t *state)
{
    const double u1 = uniform(state), u2 = uniform(state);
    return sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
}

static double quantise(double x, double full_scale, int bits)
{
    double lsb;
    if (bits <= 0 || !(full_scale > 0.0))
        return x;
    lsb = 2.0 * full_scale / ldexp(1.0, bits);
    x = floor(x / lsb + 0.5) * lsb;
    return fmax(-full_scale, fmin(full_scale - lsb, x));
}

static double plant_signal(const bs_sim *sim, int signal)
{
    if (signal == BS_SIGNAL_VOLTAGE) {
        bs_transducer_output out;
        bs_sim_get_transducer(sim, &out);
        return (double)out.voltage;
    }
    return (double)bs_sim_sensor(sim);
}

/* Statistics of one clean run: RMS and largest magnitude of a and the signal. */
typedef struct plant_stats {
    double a_sq, y_sq, a_max, y_max;
    uint64_t steps;
} plant_stats;

static int plant_pass(const bs_scene *scene, const scene_file *file, const twin_cli *c, uint64_t steps,
                      plant_stats *stats, FILE *out, double y_noise, double a_noise)
{
    static bs_sim sim;
    static double delay[BS_OBSERVER_MAX_LATENCY + 1];
    const long d = latency_steps(c, file->params.dt);
    uint64_t k, rng = 0x9e3779b97f4a7c15u ^ (uint64_t)c->seed * 0xbf58476d1ce4e5b9u;
    bs_status status = bs_sim_init(&sim, scene, BS_MODEL_FREE, (bs_real)file->params.s0);
    schedule plan; /* the scene's [excitation] schedule, stepped as `run` steps it */
    double frequency = -1.0, amplitude = -1.0;
    char why[256];
    int i;

    if (schedule_parse(file->params.schedule, &plan, why, sizeof why) != 0) { /* checked when read */
        cli_error("plant: [excitation] schedule: %s", why);
        return -1;
    }
    if (status != BS_OK) {
        cli_error("plant: %s", bs_status_text(status));
        return -1;
    }
    bs_sim_set_solver(&sim, &(bs_solver_options){ file->params.solver_max_sweeps, (bs_real)file->params.solver_tol_rel,
                                                   (bs_real)file->params.solver_tol_abs, file->params.solver_residual });
    for (i = 0; i <= BS_OBSERVER_MAX_LATENCY; ++i)
        delay[i] = plant_signal(&sim, c->signal);
    if (!out)
        memset(stats, 0, sizeof *stats);
    for (k = 1; k <= steps; ++k) {
        double a, y;
        status = run_step_harmonic(&sim, &plan, file->params.dt, k, &frequency, &amplitude);
        if (status != BS_OK) {
            cli_error("plant: stopped at step %llu: %s", (unsigned long long)k, bs_status_text(status));
            return -1;
        }
        a = (double)bs_sim_base_acceleration(&sim);
        delay[k % (BS_OBSERVER_MAX_LATENCY + 1)] = plant_signal(&sim, c->signal);
        y = delay[(k + (uint64_t)(BS_OBSERVER_MAX_LATENCY + 1) - (uint64_t)d) % (BS_OBSERVER_MAX_LATENCY + 1)];
        if (!out) {
            stats->a_sq += a * a;
            stats->y_sq += y * y;
            stats->a_max = fmax(stats->a_max, fabs(a));
            stats->y_max = fmax(stats->y_max, fabs(y));
            continue;
        }
        a = quantise(a + a_noise * gaussian(&rng), 2.0 * stats->a_max, c->bits);
        y = quantise(y + y_noise * gaussian(&rng), 2.0 * stats->y_max, c->bits);
        if (fprintf(out, "%.12g,%.9g,%.9g,%.9g\n", (double)k * file->params.dt, a, y, /* t to 1e-12: long runs */
                    (double)bs_sim_position(&sim)) < 0)
            return -1;
    }
    stats->steps = steps;
    return 0;
}

static int cli_twin_plant(int argc, char **argv)
{
    static scene_file file;
    static bs_scene scene;
    static scene_model model;
    twin_cli c;
    plant_stats stats;
    cli_output output;
    char plant[SCENE_TEXT];
    double y_noise, a_noise, a_snr;
    uint64_t steps;
    int status, failed;

    if (parse_options(argc, argv, "twin-plant", &c) != 0 || load_scene(&c, &file, &scene, &model) != 0)
        return CLI_USAGE;
    if (c.signal < 0)
        c.signal = BS_SIGNAL_DEFLECTION;
    if (c.signal == BS_SIGNAL_VOLTAGE && scene.load != BS_LOAD_RESISTOR) {
        cli_error("--signal voltage needs [transducer] load = resistor (e.g. --set transducer.load=resistor)");
        return CLI_USAGE;
    }
    if (latency_steps(&c, file.params.dt) > BS_OBSERVER_MAX_LATENCY) {
        cli_error("--latency %g: at most %d steps (%g s)", c.latency, BS_OBSERVER_MAX_LATENCY,
                  BS_OBSERVER_MAX_LATENCY * file.params.dt);
        return CLI_USAGE;
    }
    if (!c.out_path) {
        cli_error("twin-plant needs --out FILE.csv");
        return CLI_USAGE;
    }
    steps = run_step_count(file.params.t_end, file.params.dt); /* the scene's check bounds it */
    if (plant_pass(&scene, &file, &c, steps, &stats, NULL, 0.0, 0.0) != 0)
        return CLI_FAILED;
    a_snr = isnan(c.accel_snr) ? c.snr : c.accel_snr;
    y_noise = isinf(c.snr) ? 0.0 : sqrt(stats.y_sq / (double)steps) * pow(10.0, -c.snr / 20.0);
    a_noise = isinf(a_snr) ? 0.0 : sqrt(stats.a_sq / (double)steps) * pow(10.0, -a_snr / 20.0);
    output.option = "--out";
    output.path = c.out_path;
    snprintf(plant, sizeof plant, "%s", file.params.name);
    out_text_one_line(plant); /* a line break in the name would forge header lines */
    if ((status = cli_open_outputs(&output, 1, &file)) != CLI_OK)
        return status;
    /* exactly the grammar of host/lib/measured_signals.h */
    failed = fprintf(output.file,
                     "# beamslider measured signals (docs/twin.md, \"Observer\")\n"
                     "# plant = %s, s0 %.6g, freq_scale %.6g, snr %g dB, accel_snr %g dB, bits %d, seed %lu\n"
                     "# sample_rate = %.12g Hz\n# signal = %s\n# signal_unit = %s\n# base_accel_unit = m/s^2\n"
                     "# latency = %.9g s\n# noise = %.9g %s\n# accel_noise = %.9g m/s^2\n"
                     "t,base_accel,signal,s_true\n",
                     plant, file.params.s0, c.freq_scale, c.snr, a_snr, c.bits, c.seed,
                     1.0 / file.params.dt, c.signal == BS_SIGNAL_VOLTAGE ? "voltage" : "deflection",
                     c.signal == BS_SIGNAL_VOLTAGE ? "V" : "m", (double)latency_steps(&c, file.params.dt) * file.params.dt,
                     fmax(y_noise, 1e-30), c.signal == BS_SIGNAL_VOLTAGE ? "V" : "m", a_noise) < 0;
    failed = failed || plant_pass(&scene, &file, &c, steps, &stats, output.file, y_noise, a_noise) != 0;
    if (cli_close_output(c.out_path, output.file, failed ? errno : 0) != 0 || failed)
        return CLI_FAILED;
    {
        out_json j;
        out_json_start(&j);
        out_json_text(&j, "plant", file.params.name);
        out_json_count(&j, "steps", (unsigned long long)steps);
        out_json_number(&j, "signal_rms", "%.6g", sqrt(stats.y_sq / (double)steps));
        out_json_number(&j, "noise", "%.6g", y_noise);
        out_json_number(&j, "accel_rms", "%.6g", sqrt(stats.a_sq / (double)steps));
        out_json_number(&j, "accel_noise", "%.6g", a_noise);
        if (out_json_finish(&j, stdout) != 0) {
            cli_error("cannot write the summary (out of memory?)");
            return CLI_FAILED;
        }
    }
    return CLI_OK;
}

/* ---- the measured-signals file (host/lib/measured_signals.h: the one reader) ---- */

/* What the twin takes from the file before it runs. */
typedef struct measured_file {
    measured_reader reader;
    int is_stdin;          /* --measured -: read once, as it comes */
    double y_sq;           /* sum of signal^2 over the rows (a file's first pass) */
} measured_file;

/* Opens --measured: the header (its rate must be 1/dt of the scene) and, for
 * a file, every row checked in a first pass before anything is written.
 * Standard input is read once: the rows are checked as the twin reads them.
 * 0, or -1 after reporting (nothing left open). */
static int open_measured(measured_file *m, const char *path, double dt)
{
    measured_reader *r = &m->reader;
    measured_row row;
    char err[1024];
    int status;

    memset(m, 0, sizeof *m);
    m->is_stdin = !strcmp(path, "-");
    if (measured_open(r, path, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    if (!(fabs(r->header.rate * dt - 1.0) <= 1e-9)) {
        cli_error("%s: sample_rate = %g Hz, but the scene's dt = %g s needs %.10g Hz (resample the record)", r->path,
                  r->header.rate, dt, 1.0 / dt);
        measured_close(r);
        return -1;
    }
    if (m->is_stdin)
        return 0;
    while ((status = measured_next(r, &row, err, sizeof err)) > 0)
        m->y_sq += row.signal * row.signal;
    if (status < 0 || measured_rewind(r, err, sizeof err) != 0) {
        cli_error("%s", err);
        measured_close(r);
        return -1;
    }
    return 0;
}

/* ---- twin-gains and twin ---- */

/* The design's progress bar (on a terminal only, like run's). */
static void design_progress(void *context, double fraction)
{
    progress_update((progress *)context, fraction, NULL);
}

static int design(const twin_cli *c, const scene_file *file, const scene_model *model, const bs_scene *scene,
                  int signal, double noise,
                  double accel_noise, bs_observer_gains *gains)
{
    observer_design_options o = observer_design_defaults(noise);
    progress bar;
    char err[1024];
    int failed;
    o.signal = signal;
    o.force_noise = c->force_noise;
    o.accel_noise = isnan(accel_noise) ? 0.0 : accel_noise;
    o.latency = (int)latency_steps(c, file->params.dt);
    o.map_count = c->map_count;
    memcpy(o.map_frequency, c->map_frequency, sizeof o.map_frequency);
    if (o.latency > BS_OBSERVER_MAX_LATENCY) {
        cli_error("--latency %g: at most %d steps (%g s)", c->latency, BS_OBSERVER_MAX_LATENCY,
                  BS_OBSERVER_MAX_LATENCY * file->params.dt);
        return -1;
    }
    progress_start(&bar, "observer design (response maps)");
    o.progress = design_progress;
    o.progress_context = &bar;
    failed = observer_design(file, model, scene, &o, gains, err, sizeof err) != 0;
    progress_end(&bar);
    if (failed) {
        cli_error("%s", err);
        return -1;
    }
    return 0;
}

static int cli_twin_gains(int argc, char **argv)
{
    static scene_file file;
    static bs_scene scene;
    static scene_model model;
    static bs_observer_gains gains;
    char comment[1024];
    twin_cli c;
    if (parse_options(argc, argv, "twin-gains", &c) != 0 || load_scene(&c, &file, &scene, &model) != 0)
        return CLI_USAGE;
    if (isnan(c.noise)) {
        cli_error("twin-gains needs --noise SIGMA (the signal's noise standard deviation)");
        return CLI_USAGE;
    }
    if (c.signal < 0)
        c.signal = BS_SIGNAL_DEFLECTION;
    if (design(&c, &file, &model, &scene, c.signal, c.noise, c.accel_noise, &gains) != 0)
        return CLI_USAGE;
    snprintf(comment, sizeof comment, "%s: signal %s, noise %g, accel noise %g, force noise %g N/sqrt(Hz), latency %d steps",
             file.params.name, c.signal ? "voltage" : "deflection", c.noise, isnan(c.accel_noise) ? 0.0 : c.accel_noise,
             c.force_noise, gains.latency);
    return observer_print_gains(stdout, &gains, c.name, comment) == 0 ? CLI_OK : CLI_FAILED;
}

/* What the twin run counts for its summary. */
typedef struct twin_tally {
    uint64_t rows, scored, within;
    double innovation_sq, error_sq, s_true, elapsed;
    bs_observer_estimate last;
} twin_tally;

static int write_estimate(FILE *out, double t, const bs_observer_estimate *e, double s_true)
{
    return fprintf(out, "%.9g,%.9g,%.4g,%.6g,%.6g,%.6g,%.6g,%.9g,%.5g,%.5g,%lu,%d\n", t, (double)e->s,
                   (double)e->s_sigma, (double)e->amplitude, (double)e->power, (double)e->measurement,
                   (double)e->prediction, s_true, (double)e->phase_error, (double)e->s_error,
                   (unsigned long)e->outliers, e->health) < 0;
}

static int run_twin(const twin_cli *c, const bs_scene *scene, const scene_file *file, const bs_observer_gains *gains,
                    measured_file *m, FILE *out, twin_tally *tally, int *bad_input)
{
    static bs_sim sim;
    static bs_observer obs;
    bs_observer_options options = bs_observer_defaults();
    measured_row sample;
    char err[1024];
    double t, a, y, s_true;
    int row;
    bs_status status = bs_sim_init(&sim, scene, BS_MODEL_FREE, (bs_real)file->params.s0);

    if (status == BS_OK)
        status = bs_sim_set_solver(&sim, &(bs_solver_options){ file->params.solver_max_sweeps,
                                                                (bs_real)file->params.solver_tol_rel,
                                                                (bs_real)file->params.solver_tol_abs,
                                                                file->params.solver_residual });
    options.correct_beam = !c->open_loop;
    options.correct_position = !c->open_loop && !c->no_position;
    options.lockin_time = (bs_real)c->lockin;
    options.position_gain = (bs_real)c->position_gain;
    options.position_rate = (bs_real)c->position_rate;
    options.position_deadband = (bs_real)c->position_deadband;
    options.outlier_gate = (bs_real)c->outlier_gate;
    if (status == BS_OK)
        status = bs_observer_init(&obs, &sim, gains, &options);
    if (status != BS_OK) {
        cli_error("twin: %s", bs_status_text(status));
        return -1;
    }
    memset(tally, 0, sizeof *tally);
    tally->s_true = NAN;
    if (fprintf(out, "t,s_hat,s_sigma,amplitude,power,y,y_hat,s_true,phase_error,s_error,outliers,health\n") < 0)
        return -1;
    while ((row = measured_next(&m->reader, &sample, err, sizeof err)) > 0) {
        t = sample.t;
        a = sample.base_accel;
        y = sample.signal;
        s_true = sample.s_true;
        status = bs_observer_step(&obs, &sim, (bs_real)a, (bs_real)y);
        if (status != BS_OK) {
            cli_error("%s:%ld: the twin stopped: %s", m->reader.path, m->reader.lines.line, bs_status_text(status));
            return -1;
        }
        tally->rows += 1;
        bs_observer_get(&obs, &tally->last);
        tally->innovation_sq += (double)tally->last.innovation * (double)tally->last.innovation;
        tally->s_true = s_true;
        if (!isnan(s_true) && t >= c->score_after) {
            const double error = (double)tally->last.s - s_true;
            tally->scored += 1;
            tally->within += fabs(error) <= c->tolerance;
            tally->error_sq += error * error;
        }
        if (tally->rows % (uint64_t)c->every == 0 && write_estimate(out, t, &tally->last, s_true) != 0)
            return -1;
    }
    if (row < 0) { /* a file's rows were checked before: a bad row of standard input */
        cli_error("%s%s", err, m->is_stdin ? " (the estimates up to it are written)" : "");
        *bad_input = 1;
        return -1;
    }
    return 0;
}

/* The summary through the JSON writer (out_json.h: NaN as null, such as
 * s_true without truth in the file, or within when nothing was scored). */
static int print_summary(const twin_cli *c, const scene_file *file, const bs_observer_gains *gains,
                         const twin_tally *tally, double noise)
{
    const int scored = tally->scored > 0;
    out_json j;
    out_json_start(&j);
    out_json_text(&j, "scene", file->params.name);
    out_json_text(&j, "signal", c->signal ? "voltage" : "deflection");
    out_json_count(&j, "rows", (unsigned long long)tally->rows);
    out_json_number(&j, "noise", "%.6g", noise);
    out_json_int(&j, "latency_steps", gains->latency);
    out_json_int(&j, "beam_correction", !c->open_loop);
    out_json_int(&j, "position_correction", !c->open_loop && !c->no_position);
    out_json_number(&j, "rms_innovation", "%.6g", tally->rows ? sqrt(tally->innovation_sq / (double)tally->rows) : 0.0);
    out_json_number(&j, "outlier_gate", "%g", c->outlier_gate);
    out_json_count(&j, "outliers", (unsigned long long)tally->last.outliers);
    out_json_int(&j, "health", tally->last.health);
    out_json_number(&j, "s_final", "%.6f", (double)tally->last.s);
    out_json_number(&j, "s_sigma_final", "%.4g", (double)tally->last.s_sigma);
    out_json_number(&j, "s_true_final", "%.6f", tally->s_true);
    out_json_number(&j, "score_after", "%g", c->score_after);
    out_json_number(&j, "tolerance", "%g", c->tolerance);
    out_json_number(&j, "within", "%.4f", scored ? (double)tally->within / (double)tally->scored : (double)NAN);
    out_json_number(&j, "rms_s_error", "%.6g", scored ? sqrt(tally->error_sq / (double)tally->scored) : (double)NAN);
    out_json_number(&j, "wall_s", "%.3f", tally->elapsed);
    return out_json_finish(&j, stdout);
}

static int cli_twin_run(int argc, char **argv)
{
    static scene_file file;
    static bs_scene scene;
    static scene_model model;
    static bs_observer_gains gains;
    twin_cli c;
    measured_file m;
    twin_tally tally;
    cli_output output;
    cli_input measured_input;
    const measured_header *header;
    double noise, start;
    int status, failed, bad_input = 0;

    if (parse_options(argc, argv, "twin", &c) != 0 || load_scene(&c, &file, &scene, &model) != 0)
        return CLI_USAGE;
    if (!c.measured_path || !c.out_path) {
        cli_error("twin needs --measured FILE.csv and --out EST.csv");
        return CLI_USAGE;
    }
    if (open_measured(&m, c.measured_path, file.params.dt) != 0)
        return CLI_USAGE;
    header = &m.reader.header;
    if (c.signal >= 0 && c.signal != header->signal) {
        cli_error("--signal %s contradicts %s's signal = %s", c.signal ? "voltage" : "deflection", m.reader.path,
                  measured_signal_name(header->signal));
        measured_close(&m.reader);
        return CLI_USAGE;
    }
    c.signal = header->signal == MEASURED_VOLTAGE ? BS_SIGNAL_VOLTAGE : BS_SIGNAL_DEFLECTION;
    /* the noise: stated, else the file's, else 40 dB below the signal's RMS
     * (a file's first pass measured it; standard input cannot be measured
     * in advance) */
    if (isnan(c.noise) && isnan(header->noise) && m.is_stdin) {
        cli_error("--measured -: standard input is read once, so the twin cannot measure the signal's RMS "
                  "first: give --noise SIGMA or a '# noise = ...' header line");
        measured_close(&m.reader);
        return CLI_USAGE;
    }
    noise = !isnan(c.noise) ? c.noise : !isnan(header->noise) ? header->noise
                                                              : 0.01 * sqrt(m.y_sq / (double)m.reader.rows);
    if (design(&c, &file, &model, &scene, c.signal, noise,
               !isnan(c.accel_noise) ? c.accel_noise : header->accel_noise, &gains) != 0) {
        measured_close(&m.reader);
        return CLI_USAGE;
    }
    output.option = "--out";
    output.path = c.out_path;
    measured_input.option = "--measured";
    measured_input.path = c.measured_path;
    if ((status = cli_open_outputs_reading(&output, 1, &file, &measured_input, 1)) != CLI_OK) {
        measured_close(&m.reader);
        return status;
    }
    start = bs_platform_seconds();
    failed = run_twin(&c, &scene, &file, &gains, &m, output.file, &tally, &bad_input) != 0;
    tally.elapsed = bs_platform_seconds() - start;
    measured_close(&m.reader);
    if (cli_close_output(c.out_path, output.file, 0) != 0)
        failed = 1;
    if (print_summary(&c, &file, &gains, &tally, noise) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        failed = 1;
    }
    return bad_input ? CLI_USAGE : failed ? CLI_FAILED : CLI_OK;
}

static int wants_help(int argc, char **argv)
{
    if (argc >= 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h"))) {
        fputs(twin_usage, stdout);
        return 1;
    }
    return 0;
}

int cli_twin(int argc, char **argv)
{
    return wants_help(argc, argv) ? CLI_OK : cli_twin_run(argc, argv);
}

int cli_twin_plant_command(int argc, char **argv)
{
    return wants_help(argc, argv) ? CLI_OK : cli_twin_plant(argc, argv);
}

int cli_twin_gains_command(int argc, char **argv)
{
    return wants_help(argc, argv) ? CLI_OK : cli_twin_gains(argc, argv);
}
