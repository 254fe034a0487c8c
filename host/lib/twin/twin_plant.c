/* twin_plant.c - the twin's test plant (twin_plant.h). */
#include "twin_plant.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bs_observer.h"
#include "measured_signals.h"
#include "run.h"
#include "schedule.h"

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

int twin_plant_scale_frequencies(scene_model *model, bs_scene *scene, double scale, char *err, size_t err_size)
{
    scene_data *d = &model->data;
    int k;
    if (scale == 1.0)
        return 0;
    for (k = 0; k < d->n_modes; ++k) {
        d->omega_sq[k] *= scale * scale;
        d->damping[k] *= scale;
        if (d->implicit)
            d->mode_gain[k] = 1.0 / (1.0 + d->theta * d->dt * d->damping[k]
                                     + d->theta * d->theta * d->dt * d->dt * d->omega_sq[k]);
    }
    scene_data_round(d, scene);
    if (bs_scene_check(scene, NULL) != BS_OK) {
        snprintf(err, err_size, "--freq-scale %g: the scene is no longer valid (explicit limit omega_max dt < 2?)",
                 scale);
        return -1;
    }
    return 0;
}

long twin_latency_steps(double seconds, double dt)
{
    const double steps = seconds / dt;
    return steps < BS_OBSERVER_MAX_LATENCY + 1.0 ? lround(steps) : BS_OBSERVER_MAX_LATENCY + 1;
}

int twin_plant_check(const scene_file *file, const bs_scene *scene, const twin_plant_options *o, char *err,
                     size_t err_size)
{
    if (o->signal == BS_SIGNAL_VOLTAGE && scene->load != BS_LOAD_RESISTOR) {
        snprintf(err, err_size,
                 "--signal voltage needs [transducer] load = resistor (e.g. --set transducer.load=resistor)");
        return -1;
    }
    if (o->latency < 0 || o->latency > BS_OBSERVER_MAX_LATENCY) {
        snprintf(err, err_size, "--latency: at most %d steps (%g s)", BS_OBSERVER_MAX_LATENCY,
                 BS_OBSERVER_MAX_LATENCY * file->params.dt);
        return -1;
    }
    return 0;
}

/* Statistics of one clean run: sums of squares and largest magnitudes. */
typedef struct plant_stats {
    double a_sq, y_sq, a_max, y_max;
} plant_stats;

/* One pass over the run: with out NULL the clean signals' statistics into
 * stats, else the noisy, quantised rows to out. 0, or -1 with err (the run
 * stopped), or -2 (a write failed). */
static int plant_pass(const scene_file *file, const bs_scene *scene, const twin_plant_options *o, uint64_t steps,
                      plant_stats *stats, FILE *out, double y_noise, double a_noise, char *err, size_t err_size)
{
    bs_sim *sim = malloc(sizeof *sim);                              /* large: on the heap */
    double *delay = malloc((BS_OBSERVER_MAX_LATENCY + 1) * sizeof *delay); /* the signal's past */
    const double dt = file->params.dt;
    uint64_t k, rng = 0x9e3779b97f4a7c15u ^ (uint64_t)o->seed * 0xbf58476d1ce4e5b9u;
    schedule plan; /* the scene's [excitation] schedule, stepped as `run` steps it */
    double frequency = -1.0, amplitude = -1.0;
    bs_solver_options solver = scene_solver(&file->params);
    bs_status status;
    char why[256];
    int i, failed = 0;

    if (!sim || !delay) {
        snprintf(err, err_size, "plant: out of memory");
        failed = -1;
        goto done;
    }
    if (schedule_parse(file->params.schedule, &plan, why, sizeof why) != 0) { /* checked when read */
        snprintf(err, err_size, "plant: [excitation] schedule: %s", why);
        failed = -1;
        goto done;
    }
    status = bs_sim_init(sim, scene, BS_MODEL_FREE, (bs_real)file->params.s0);
    if (status == BS_OK)
        status = bs_sim_set_solver(sim, &solver);
    if (status != BS_OK) {
        snprintf(err, err_size, "plant: %s", bs_status_text(status));
        failed = -1;
        goto done;
    }
    for (i = 0; i <= BS_OBSERVER_MAX_LATENCY; ++i)
        delay[i] = plant_signal(sim, o->signal);
    if (!out)
        memset(stats, 0, sizeof *stats);
    for (k = 1; k <= steps; ++k) {
        measured_row row;
        double a, y;
        status = run_step_harmonic(sim, &plan, dt, k, &frequency, &amplitude);
        if (status != BS_OK) {
            snprintf(err, err_size, "plant: stopped at step %llu: %s", (unsigned long long)k, bs_status_text(status));
            failed = -1;
            break;
        }
        a = (double)bs_sim_base_acceleration(sim);
        delay[k % (BS_OBSERVER_MAX_LATENCY + 1)] = plant_signal(sim, o->signal);
        y = delay[(k + (uint64_t)(BS_OBSERVER_MAX_LATENCY + 1) - (uint64_t)o->latency) % (BS_OBSERVER_MAX_LATENCY + 1)];
        if (!out) {
            stats->a_sq += a * a;
            stats->y_sq += y * y;
            stats->a_max = fmax(stats->a_max, fabs(a));
            stats->y_max = fmax(stats->y_max, fabs(y));
            continue;
        }
        row.t = (double)k * dt;
        row.base_accel = quantise(a + a_noise * gaussian(&rng), 2.0 * stats->a_max, o->bits);
        row.signal = quantise(y + y_noise * gaussian(&rng), 2.0 * stats->y_max, o->bits);
        row.s_true = (double)bs_sim_position(sim);
        if (measured_write_row(out, &row, 1) != 0) {
            failed = -2;
            break;
        }
    }
done:
    free(sim);
    free(delay);
    return failed;
}

int twin_plant_measure(const scene_file *file, const bs_scene *scene, const twin_plant_options *o,
                       twin_plant_result *result, char *err, size_t err_size)
{
    const uint64_t steps = run_step_count(file->params.t_end, file->params.dt); /* the scene's check bounds it */
    const double a_snr = isnan(o->accel_snr) ? o->snr : o->accel_snr;
    plant_stats stats;

    memset(result, 0, sizeof *result);
    if (plant_pass(file, scene, o, steps, &stats, NULL, 0.0, 0.0, err, err_size) != 0)
        return -1;
    result->steps = steps;
    result->signal_rms = sqrt(stats.y_sq / (double)steps);
    result->accel_rms = sqrt(stats.a_sq / (double)steps);
    result->signal_max = stats.y_max;
    result->accel_max = stats.a_max;
    result->noise = isinf(o->snr) ? 0.0 : result->signal_rms * pow(10.0, -o->snr / 20.0);
    result->accel_noise = isinf(a_snr) ? 0.0 : result->accel_rms * pow(10.0, -a_snr / 20.0);
    return 0;
}

int twin_plant_write(const scene_file *file, const bs_scene *scene, const twin_plant_options *o,
                     const twin_plant_result *result, FILE *out, int *write_failed, char *err, size_t err_size)
{
    const double dt = file->params.dt;
    const double a_snr = isnan(o->accel_snr) ? o->snr : o->accel_snr;
    measured_header header;
    plant_stats stats;
    char plant[SCENE_TEXT + 160];
    int status;

    *write_failed = 0;
    memset(&stats, 0, sizeof stats);
    stats.y_max = result->signal_max;
    stats.a_max = result->accel_max;
    header.rate = 1.0 / dt;
    header.signal = o->signal == BS_SIGNAL_VOLTAGE ? MEASURED_VOLTAGE : MEASURED_DEFLECTION;
    header.latency = (double)o->latency * dt;
    header.noise = fmax(result->noise, 1e-30); /* the format's noise is > 0 */
    header.accel_noise = result->accel_noise;
    header.has_truth = 1;
    snprintf(plant, sizeof plant, "%s, s0 %.6g, freq_scale %.6g, snr %g dB, accel_snr %g dB, bits %d, seed %lu",
             file->params.name, file->params.s0, o->freq_scale, o->snr, a_snr, o->bits, o->seed);
    if (measured_write_header(out, &header, plant) != 0) {
        *write_failed = 1;
        snprintf(err, err_size, "cannot write the stream");
        return -1;
    }
    status = plant_pass(file, scene, o, result->steps, &stats, out, result->noise, result->accel_noise, err,
                        err_size);
    if (status == -2) {
        *write_failed = 1;
        snprintf(err, err_size, "cannot write the stream");
    }
    return status == 0 ? 0 : -1;
}
