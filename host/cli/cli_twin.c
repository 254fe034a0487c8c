/* cli_twin.c - the digital twin's commands (docs/twin.md, "Observer"):
 *
 *   beamslider twin-plant SCENE --out FILE.csv [...]   a test stream from a plant
 *   beamslider twin SCENE --measured FILE.csv --out EST.csv [...]   the twin on it
 *   beamslider twin-gains SCENE [...]                   the observer's constants as a C header
 *
 * Options, files and messages only: the plant, the stream's reader and
 * writer, the design and the run are the twin wing's (host/lib/twin/). The
 * measured-signals file (written by twin-plant, or by any plant) has one
 * grammar, one reader and one writer, host/lib/twin/measured_signals.h;
 * `twin --measured -` reads it from standard input, once, as it comes.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bs_observer.h"
#include "cli.h"
#include "cli_progress.h"
#include "observer_design.h"
#include "out_c.h"
#include "out_json.h"
#include "scene_build.h"
#include "twin_plant.h"
#include "twin_run.h"

#define MAX_SETS 16

const char cli_twin_synopsis[] =
    "beamslider twin SCENE.ini --measured FILE.csv|- --out EST.csv [--signal deflection|voltage]\n"
    "        [--latency S] [--noise SIGMA] [--accel-noise SIGMA] [--force-noise N] [--s0 S] [--t-end T]\n"
    "        [--every N] [--open-loop] [--no-position] [--lockin TAU] [--position-gain G]\n"
    "        [--position-rate R] [--deadband D] [--outlier-gate K] [--score-after T] [--tolerance D]\n"
    "        [--map-frequencies F,F,...] [--map-frictions MU,MU,...] [--friction MU] [--restitution E]\n"
    "        [--estimate-friction K] [--friction-time T] [--friction-deadband D] [--friction-sigma S]\n"
    "        [--friction-amplitude A] [--friction-climb R] [--friction-shadow G] [--friction-walk K]\n"
    "        [--jump-hold T] [--set section.key=value ...]";
const char cli_twin_help[] =
    "  the twin corrected from measured signals (docs/twin.md, \"Observer\")\n"
    "  Runs the scene on the measured base acceleration, corrected from the measured signal; EST.csv every N steps: t,\n"
    "  s_hat, s_sigma, amplitude, power, y, y_hat, s_true (if the file has it), phase_error,\n"
    "  s_error, outliers (measurements skipped so far: beyond --outlier-gate K times the\n"
    "  innovation's RMS, default 6, or a correction that would throw the slider off), health (1:\n"
    "  one within the last lock-in time), mu, mu_sigma, energy (the twin's into the load since its start [J]:\n"
    "  its difference over an interval is the twin's mean power there; power lags by about twice the\n"
    "  lock-in time). JSON summary on stdout: within is the fraction of the\n"
    "  rows from --score-after T (default 5 s) on whose s_hat is within --tolerance D (default\n"
    "  0.005) of s_true; null, said why on stderr, when no row was scored (a stream without\n"
    "  s_true, or one that ends before T).\n"
    "  --measured -: a live stream on standard input, read once to its end (give --noise).\n"
    "  --friction MU, --restitution E: the twin's contact laws, set on the running twin (the maps keep the\n"
    "  scene's, or with --map-frictions MU,MU,... [ascending] are made at each and follow the twin's mu);\n"
    "  --estimate-friction K: mu estimated from the persistent s error at gain K [1/s]\n"
    "  (docs/twin.md, \"Friction\"); mu, mu_sigma are then its estimate. With it: --friction-time T\n"
    "  (default 0.5 s) the persistent error's low-pass, --friction-deadband D (default 0.001) what of it\n"
    "  moves nothing; it learns while s_sigma is below --friction-sigma S (default 0.002) and the\n"
    "  amplitude above --friction-amplitude A beam thicknesses (default 0.5: the high branch), and\n"
    "  only while the measured s moves at --friction-climb R [1/s] or faster (default 0.001: the climb)\n"
    "  and the excitation's frequency holds still (within 0.1 % of its mean over 1 s: not in a ramp).\n"
    "  --friction-shadow G: the estimate reads the s error of a shadow of the slider corrected at G [1/s]\n"
    "  instead of the twin's (default 0: the twin's; docs/twin.md, \"The shadow\").\n"
    "  --friction-walk K: mu follows the twin's own walking speed against the measured one, taking the\n"
    "  speed as mu^-K; --estimate-friction is then the law's rate [1/s] (default 0: the s error;\n"
    "  docs/twin.md, \"The walk\").\n"
    "  --jump-hold T: no s correction for T seconds after the measured response starts falling fast (a jump\n"
    "  to the low branch; default 0: none; docs/twin.md, \"Jump hold\").\n";

const char cli_twin_plant_synopsis[] =
    "beamslider twin-plant SCENE.ini --out FILE.csv [--signal deflection|voltage] [--snr DB]\n"
    "        [--accel-snr DB] [--bits B] [--seed N] [--latency S] [--freq-scale X] [--s0 S] [--t-end T]\n"
    "        [--set section.key=value ...]";
const char cli_twin_plant_help[] =
    "  a measured-signals file from a (perturbed) plant (docs/twin.md)\n"
    "  The scene as the plant, its modal frequencies times --freq-scale, signals with white noise SNR dB below their RMS and B-bit\n"
    "  quantisation over +-2x their largest value, the signal --latency late (docs/twin.md).\n"
    "  JSON summary on stdout.\n";

const char cli_twin_gains_synopsis[] =
    "beamslider twin-gains SCENE.ini --noise SIGMA [--signal deflection|voltage] [--latency S]\n"
    "        [--accel-noise SIGMA] [--force-noise N] [--map-frequencies F,F,...] [--map-frictions MU,MU,...]\n"
    "        [--name NAME] [--set section.key=value ...]";
const char cli_twin_gains_help[] =
    "  the observer's constants (bs_observer_gains) as a C header on stdout\n"
    "  Response maps at --map-frequencies [Hz, ascending], else at the scene's excitation or across its schedule;\n"
    "  each at every one of --map-frictions [mu, ascending], else at the scene's mu.\n";

/* The options of the three commands (each uses some). */
typedef struct twin_cli {
    const char *scene_path, *out_path, *measured_path, *name;
    const char *sets[MAX_SETS];
    int set_count;
    int map_count;              /* --map-frequencies (0: from the scene) */
    double map_frequency[BS_OBSERVER_MAPS];
    int friction_count;         /* --map-frictions (0: the scene's mu) */
    double map_friction[BS_OBSERVER_MAPS];
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
    double mu, e_n, friction_gain; /* NAN: the scene's; 0: no estimate */
    double friction_time, friction_deadband, friction_sigma, friction_amplitude, friction_climb, friction_shadow;
    double friction_walk;
    double jump_hold;
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
    c->mu = c->e_n = NAN;
    c->friction_gain = BS_OBSERVER_DEFAULT_FRICTION_GAIN;
    c->friction_time = BS_OBSERVER_DEFAULT_FRICTION_TIME;
    c->friction_deadband = BS_OBSERVER_DEFAULT_FRICTION_DEADBAND;
    c->friction_sigma = BS_OBSERVER_DEFAULT_FRICTION_SIGMA;
    c->friction_amplitude = BS_OBSERVER_DEFAULT_FRICTION_AMPLITUDE;
    c->friction_climb = BS_OBSERVER_DEFAULT_FRICTION_CLIMB;
    c->friction_shadow = BS_OBSERVER_DEFAULT_FRICTION_SHADOW;
    c->friction_walk = BS_OBSERVER_DEFAULT_FRICTION_WALK;
    c->jump_hold = BS_OBSERVER_DEFAULT_JUMP_HOLD;
}

/* --map-frequencies F,F,... or --map-frictions MU,MU,...: 1 to
 * BS_OBSERVER_MAPS numbers, above low (or at it, with low_allowed),
 * ascending. Returns 0, or -1 after reporting what is wrong. */
static int parse_ascending(const char *option, const char *value, const char *item, const char *what, double low,
                           int low_allowed, double *list, int *count)
{
    const char *p = value;
    *count = 0;
    for (;;) {
        char *end;
        const double f = strtod(p, &end);
        if (*count == BS_OBSERVER_MAPS || end == p || (*end != ',' && *end != '\0') || !isfinite(f)
            || !(f > low || (low_allowed && f == low)) || (*count > 0 && !(f > list[*count - 1]))) {
            cli_error("%s %s: %s %d: allowed: 1 to %d %s, %s %g, ascending, separated by commas", option, value,
                      item, *count + 1, BS_OBSERVER_MAPS, what, low_allowed ? ">=" : ">", low);
            return -1;
        }
        list[(*count)++] = f;
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
    } else if (!strcmp(option, "--map-frequencies"))
        return parse_ascending(option, value, "frequency", "frequencies [Hz]", 0.0, 0, c->map_frequency,
                               &c->map_count);
    else if (!strcmp(option, "--map-frictions"))
        return parse_ascending(option, value, "mu", "friction coefficients", 0.0, 1, c->map_friction,
                               &c->friction_count);
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
    else if (!strcmp(option, "--friction")) return parse_number(option, value, 0.0, 10.0, &c->mu);
    else if (!strcmp(option, "--restitution")) return parse_number(option, value, 0.0, 1.0, &c->e_n);
    else if (!strcmp(option, "--estimate-friction")) return parse_number(option, value, 0.0, 1e3, &c->friction_gain);
    else if (!strcmp(option, "--friction-time")) return parse_number(option, value, 1e-3, 1e3, &c->friction_time);
    else if (!strcmp(option, "--friction-deadband")) return parse_number(option, value, 0.0, 1.0, &c->friction_deadband);
    else if (!strcmp(option, "--friction-sigma")) return parse_number(option, value, 1e-6, 1.0, &c->friction_sigma);
    else if (!strcmp(option, "--friction-amplitude")) return parse_number(option, value, 0.0, 100.0, &c->friction_amplitude);
    else if (!strcmp(option, "--friction-climb")) return parse_number(option, value, 0.0, 1.0, &c->friction_climb);
    else if (!strcmp(option, "--friction-shadow")) return parse_number(option, value, 0.0, 1e3, &c->friction_shadow);
    else if (!strcmp(option, "--friction-walk")) return parse_number(option, value, 0.0, 1e3, &c->friction_walk);
    else if (!strcmp(option, "--jump-hold")) return parse_number(option, value, 0.0, 1e3, &c->jump_hold);
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
    for (i = 0; i < c->set_count; ++i) /* checked as a file line is (host/lib/scene/scene_ini.h) */
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
    if (scene_build(file, scene, model, err, sizeof err) != 0
        || twin_plant_scale_frequencies(model, scene, c->freq_scale, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    return 0;
}

/* A scene as the three commands read it: large, on the heap. */
typedef struct twin_scene {
    scene_file file;
    bs_scene scene;
    scene_model model;
    bs_observer_gains gains;
} twin_scene;

static twin_scene *new_scene(void)
{
    twin_scene *t = malloc(sizeof *t);
    if (!t)
        cli_error("out of memory");
    return t;
}

/* ---- twin-plant ---- */

static int twin_plant(twin_scene *t, twin_cli *c)
{
    twin_plant_options plant;
    twin_plant_result result;
    cli_output output;
    char err[1024];
    int status, write_failed;

    plant.signal = c->signal < 0 ? BS_SIGNAL_DEFLECTION : c->signal;
    plant.latency = twin_latency_steps(c->latency, t->file.params.dt);
    plant.snr = c->snr;
    plant.accel_snr = c->accel_snr;
    plant.bits = c->bits;
    plant.seed = c->seed;
    plant.freq_scale = c->freq_scale;
    if (twin_plant_check(&t->file, &t->scene, &plant, err, sizeof err) != 0) {
        if (plant.latency > BS_OBSERVER_MAX_LATENCY)
            cli_error("--latency %g: at most %d steps (%g s)", c->latency, BS_OBSERVER_MAX_LATENCY,
                      BS_OBSERVER_MAX_LATENCY * t->file.params.dt);
        else
            cli_error("%s", err);
        return CLI_USAGE;
    }
    if (!c->out_path) {
        cli_error("twin-plant needs --out FILE.csv");
        return CLI_USAGE;
    }
    if (twin_plant_measure(&t->file, &t->scene, &plant, &result, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_FAILED;
    }
    output.option = "--out";
    output.path = c->out_path;
    if ((status = cli_open_outputs(&output, 1, &t->file)) != CLI_OK)
        return status;
    if (twin_plant_write(&t->file, &t->scene, &plant, &result, output.file, &write_failed, err, sizeof err) != 0) {
        const int write_errno = errno;
        if (!write_failed)
            cli_error("%s", err);
        cli_close_output(c->out_path, output.file, write_failed ? write_errno : 0);
        return CLI_FAILED;
    }
    if (cli_close_output(c->out_path, output.file, 0) != 0)
        return CLI_FAILED;
    {
        out_json j;
        out_json_start(&j);
        out_json_text(&j, "plant", t->file.params.name);
        out_json_count(&j, "steps", (unsigned long long)result.steps);
        out_json_number(&j, "signal_rms", "%.6g", result.signal_rms);
        out_json_number(&j, "noise", "%.6g", result.noise);
        out_json_number(&j, "accel_rms", "%.6g", result.accel_rms);
        out_json_number(&j, "accel_noise", "%.6g", result.accel_noise);
        if (out_json_finish(&j, stdout) != 0) {
            cli_error("cannot write the summary (out of memory?)");
            return CLI_FAILED;
        }
    }
    return CLI_OK;
}

/* ---- twin-gains and twin ---- */

static int design(const twin_cli *c, twin_scene *t, int signal, double noise, double accel_noise)
{
    observer_design_options o = observer_design_defaults(noise);
    cli_progress bar;
    char err[1024];
    int failed;
    const long latency = twin_latency_steps(c->latency, t->file.params.dt);
    o.signal = signal;
    o.force_noise = c->force_noise;
    o.accel_noise = isnan(accel_noise) ? 0.0 : accel_noise;
    o.map_count = c->map_count;
    memcpy(o.map_frequency, c->map_frequency, sizeof o.map_frequency);
    o.friction_count = c->friction_count;
    memcpy(o.map_friction, c->map_friction, sizeof o.map_friction);
    if (latency > BS_OBSERVER_MAX_LATENCY) {
        cli_error("--latency %g: at most %d steps (%g s)", c->latency, BS_OBSERVER_MAX_LATENCY,
                  BS_OBSERVER_MAX_LATENCY * t->file.params.dt);
        return -1;
    }
    o.latency = (int)latency;
    cli_progress_start(&bar, "observer design (response maps)");
    o.progress = cli_progress_hook;
    o.progress_context = &bar;
    failed = observer_design(&t->file, &t->model, &t->scene, &o, &t->gains, err, sizeof err) != 0;
    cli_progress_end(&bar);
    if (failed) {
        cli_error("%s", err);
        return -1;
    }
    return 0;
}

static int twin_gains(twin_scene *t, twin_cli *c)
{
    char comment[1024];
    if (isnan(c->noise)) {
        cli_error("twin-gains needs --noise SIGMA (the signal's noise standard deviation)");
        return CLI_USAGE;
    }
    if (c->signal < 0)
        c->signal = BS_SIGNAL_DEFLECTION;
    if (design(c, t, c->signal, c->noise, c->accel_noise) != 0)
        return CLI_USAGE;
    snprintf(comment, sizeof comment, "%s: signal %s, noise %g, accel noise %g, force noise %g N/sqrt(Hz), latency %d steps",
             t->file.params.name, c->signal ? "voltage" : "deflection", c->noise,
             isnan(c->accel_noise) ? 0.0 : c->accel_noise, c->force_noise, t->gains.latency);
    return observer_print_gains(stdout, &t->gains, c->name, comment) == 0 ? CLI_OK : CLI_FAILED;
}

static twin_run_options run_options(const twin_cli *c)
{
    twin_run_options o;
    o.observer = bs_observer_defaults();
    o.observer.correct_beam = !c->open_loop;
    o.observer.correct_position = !c->open_loop && !c->no_position;
    o.observer.lockin_time = (bs_real)c->lockin;
    o.observer.position_gain = (bs_real)c->position_gain;
    o.observer.position_rate = (bs_real)c->position_rate;
    o.observer.position_deadband = (bs_real)c->position_deadband;
    o.observer.outlier_gate = (bs_real)c->outlier_gate;
    o.every = c->every;
    o.score_after = c->score_after;
    o.tolerance = c->tolerance;
    o.observer.friction_gain = (bs_real)c->friction_gain;
    o.observer.friction_time = (bs_real)c->friction_time;
    o.observer.friction_deadband = (bs_real)c->friction_deadband;
    o.observer.friction_sigma = (bs_real)c->friction_sigma;
    o.observer.friction_amplitude = (bs_real)c->friction_amplitude;
    o.observer.friction_climb = (bs_real)c->friction_climb;
    o.observer.friction_shadow = (bs_real)c->friction_shadow;
    o.observer.friction_walk = (bs_real)c->friction_walk;
    o.observer.jump_hold = (bs_real)c->jump_hold;
    o.mu = c->mu;
    o.e_n = c->e_n;
    return o;
}

static int twin(twin_scene *t, twin_cli *c)
{
    const twin_run_options options = run_options(c);
    twin_stream m;
    twin_tally tally;
    cli_output output;
    cli_input measured_input;
    const measured_header *header;
    char err[1024];
    double noise;
    int status, failed, bad_input = 0;

    if (!c->measured_path || !c->out_path) {
        cli_error("twin needs --measured FILE.csv and --out EST.csv");
        return CLI_USAGE;
    }
    if (twin_stream_open(&m, c->measured_path, t->file.params.dt, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    header = &m.reader.header;
    if (c->signal >= 0 && c->signal != header->signal) {
        cli_error("--signal %s contradicts %s's signal = %s", c->signal ? "voltage" : "deflection", m.reader.path,
                  measured_signal_name(header->signal));
        twin_stream_close(&m);
        return CLI_USAGE;
    }
    c->signal = header->signal == MEASURED_VOLTAGE ? BS_SIGNAL_VOLTAGE : BS_SIGNAL_DEFLECTION;
    /* the noise: stated, else the file's, else 40 dB below the signal's RMS
     * (a file's first pass measured it; standard input cannot be measured
     * in advance) */
    if (isnan(c->noise) && isnan(header->noise) && m.is_stdin) {
        cli_error("--measured -: standard input is read once, so the twin cannot measure the signal's RMS "
                  "first: give --noise SIGMA or a '# noise = ...' header line");
        twin_stream_close(&m);
        return CLI_USAGE;
    }
    noise = !isnan(c->noise) ? c->noise : !isnan(header->noise) ? header->noise
                                                               : 0.01 * sqrt(m.y_sq / (double)m.reader.rows);
    output.option = "--out";
    output.path = c->out_path;
    measured_input.option = "--measured";
    measured_input.path = c->measured_path;
    /* an --out that is an input is refused before the response maps (seconds of work) */
    if ((status = cli_check_outputs_reading(&output, 1, &t->file, &measured_input, 1)) != CLI_OK
        || design(c, t, c->signal, noise, !isnan(c->accel_noise) ? c->accel_noise : header->accel_noise) != 0) {
        twin_stream_close(&m);
        return status != CLI_OK ? status : CLI_USAGE;
    }
    if ((status = cli_open_outputs_reading(&output, 1, &t->file, &measured_input, 1)) != CLI_OK) {
        twin_stream_close(&m);
        return status;
    }
    failed = twin_run(&t->file, &t->scene, &t->gains, &options, &m, output.file, &tally, &bad_input, err,
                      sizeof err) != 0;
    twin_stream_close(&m);
    if (failed)
        cli_error("%s", err);
    if (cli_close_output(c->out_path, output.file, 0) != 0)
        failed = 1;
    if (!failed && twin_unscored_reason(&tally, &options, err, sizeof err))
        fprintf(stderr, "beamslider: note: no row was scored (within and rms_s_error are null): %s\n", err);
    if (twin_print_summary(stdout, &t->file, &t->gains, &options, &tally, noise) != 0) {
        cli_error("cannot write the summary (out of memory?)");
        failed = 1;
    }
    return bad_input ? CLI_USAGE : failed ? CLI_FAILED : CLI_OK;
}

/* ---- the three commands ---- */

/* Parses the command's options, reads its scene and runs body. */
static int twin_command(int argc, char **argv, const char *command, int (*body)(twin_scene *, twin_cli *))
{
    twin_cli c;
    twin_scene *t;
    int status;
    if (parse_options(argc, argv, command, &c) != 0)
        return CLI_USAGE;
    if (!(t = new_scene()))
        return CLI_FAILED;
    status = load_scene(&c, &t->file, &t->scene, &t->model) != 0 ? CLI_USAGE : body(t, &c);
    free(t);
    return status;
}

int cli_twin(int argc, char **argv)
{
    return twin_command(argc, argv, "twin", twin);
}

int cli_twin_plant(int argc, char **argv)
{
    return twin_command(argc, argv, "twin-plant", twin_plant);
}

int cli_twin_gains(int argc, char **argv)
{
    return twin_command(argc, argv, "twin-gains", twin_gains);
}
