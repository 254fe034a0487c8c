/* _shim.c - the C side of the Python package (_shim.h says what and why).
 * Included by each precision's extension module, which cffi generates, and
 * compiled there with the headers of that precision's build (build_ffi.py).
 * Python.h, included first, asks for POSIX 2008 (open_memstream). */

#include "_shim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint32_t bspy_build_tag(void)
{
    return BS_BUILD_TAG;
}

int bspy_real_is_float(void)
{
    return BS_REAL_FLOAT;
}

int bspy_build_check(void)
{
    return bs_build_check();
}

int bspy_scene_load(const char *path, const char *text, const char *const *overrides, int count,
                    bs_host_scene **scene, bs_host_error *error)
{
    if (text)
        return bs_host_scene_parse(path, text, overrides, count, scene, error);
    return bs_host_scene_load(path, overrides, count, scene, error);
}

int bspy_sim_init(bs_sim *sim, const bs_host_scene *scene, int model, double s0)
{
    bs_host_setup setup;
    bs_status status;
    if (!scene)
        return BS_E_NULL;
    bs_host_scene_setup(scene, &setup);
    status = bs_sim_init(sim, bs_host_scene_core(scene), (bs_model)model, (bs_real)s0);
    return status != BS_OK ? status : bs_sim_set_solver(sim, &setup.solver);
}

/* One row of rows' columns from the sim's state at time t. */
static void put_row(bspy_rows *rows, const bs_sim *sim, double t)
{
    const uint64_t i = rows->rows;
    if (i >= rows->room)
        return;
    if (rows->t)
        rows->t[i] = t;
    if (rows->s)
        rows->s[i] = (double)bs_sim_position(sim);
    if (rows->w_sensor)
        rows->w_sensor[i] = (double)bs_sim_sensor(sim);
    if (rows->z_r || rows->beta) {
        bs_real slider[3];
        bs_sim_get_state(sim, NULL, NULL, slider, NULL);
        if (rows->z_r)
            rows->z_r[i] = (double)slider[1];
        if (rows->beta)
            rows->beta[i] = (double)slider[2];
    }
    if (rows->contacts || rows->sweeps || rows->residual) {
        bs_step_report report;
        bs_sim_get_report(sim, &report);
        if (rows->contacts)
            rows->contacts[i] = report.active;
        if (rows->sweeps)
            rows->sweeps[i] = report.sweeps;
        if (rows->residual)
            rows->residual[i] = (double)report.residual;
    }
    if (rows->v || rows->p || rows->v_s) {
        bs_transducer_output out;
        bs_sim_get_transducer(sim, &out);
        if (rows->v)
            rows->v[i] = (double)out.voltage;
        if (rows->p)
            rows->p[i] = (double)out.power;
        if (rows->v_s)
            rows->v_s[i] = (double)out.storage_voltage;
    }
    rows->rows = i + 1;
}

/* The stepping loops count down to the next row rather than take a
 * remainder each step (a division costs a tenth of a step). */
int bspy_sim_steps(bs_sim *sim, uint64_t n, double dt, long every, bspy_rows *rows, uint64_t *done)
{
    uint64_t i;
    long until_row = every;
    *done = 0;
    if (every < 1)
        return BS_E_ARGUMENT;
    for (i = 0; i < n; ++i) {
        const bs_status status = bs_sim_step(sim);
        if (status != BS_OK)
            return status;
        *done = i + 1;
        if (--until_row == 0) {
            until_row = every;
            if (rows)
                put_row(rows, sim, (double)bs_sim_steps(sim) * dt);
        }
    }
    return BS_OK;
}

int bspy_sim_steps_measured(bs_sim *sim, const double *accel, uint64_t n, double dt, long every, bspy_rows *rows,
                            uint64_t *done)
{
    uint64_t i;
    long until_row = every;
    *done = 0;
    if (every < 1 || (n > 0 && !accel))
        return BS_E_ARGUMENT;
    for (i = 0; i < n; ++i) {
        const bs_status status = bs_sim_step_measured(sim, (bs_real)accel[i]);
        if (status != BS_OK)
            return status;
        *done = i + 1;
        if (--until_row == 0) {
            until_row = every;
            if (rows)
                put_row(rows, sim, (double)bs_sim_steps(sim) * dt);
        }
    }
    return BS_OK;
}

int bspy_observer_init(bs_observer *obs, const bs_sim *sim, const bs_observer_gains *gains,
                       const bs_observer_options *options)
{
    return bs_observer_init(obs, sim, gains, options);
}

static void put_estimate(bspy_estimates *out, const bs_observer *obs, double t)
{
    const uint64_t i = out->rows;
    bs_observer_estimate e;
    if (i >= out->room || bs_observer_get(obs, &e) != BS_OK)
        return;
    if (out->t)
        out->t[i] = t;
    if (out->s)
        out->s[i] = (double)e.s;
    if (out->s_sigma)
        out->s_sigma[i] = (double)e.s_sigma;
    if (out->s_error)
        out->s_error[i] = (double)e.s_error;
    if (out->amplitude)
        out->amplitude[i] = (double)e.amplitude;
    if (out->power)
        out->power[i] = (double)e.power;
    if (out->phase_error)
        out->phase_error[i] = (double)e.phase_error;
    if (out->frequency)
        out->frequency[i] = (double)e.frequency;
    if (out->innovation)
        out->innovation[i] = (double)e.innovation;
    if (out->outliers)
        out->outliers[i] = e.outliers;
    if (out->health)
        out->health[i] = e.health;
    out->rows = i + 1;
}

int bspy_observer_steps(bs_observer *obs, bs_sim *sim, const double *accel, const double *measurement, uint64_t n,
                        double dt, long every, bspy_estimates *out, uint64_t *done)
{
    uint64_t i;
    long until_row = every;
    *done = 0;
    if (every < 1 || (n > 0 && (!accel || !measurement)))
        return BS_E_ARGUMENT;
    for (i = 0; i < n; ++i) {
        const bs_status status = isnan(measurement[i])
                                     ? bs_observer_predict(obs, sim, (bs_real)accel[i])
                                     : bs_observer_step(obs, sim, (bs_real)accel[i], (bs_real)measurement[i]);
        if (status != BS_OK)
            return status;
        *done = i + 1;
        if (--until_row == 0) {
            until_row = every;
            if (out)
                put_estimate(out, obs, (double)bs_sim_steps(sim) * dt);
        }
    }
    return BS_OK;
}

int bspy_twin_design(const bs_host_scene *scene, const bs_host_twin_options *options, bs_observer_gains *gains,
                     bs_host_error *error)
{
    return bs_host_twin_design(scene, options, gains, error);
}

/* ---- runs and sweeps: the host library with rows and a summary -------------- */

typedef struct run_context {
    bspy_rows *rows;
    int *stop;
} run_context;

static int on_step(void *context, const bs_sim *sim, uint64_t step, double t)
{
    run_context *c = context;
    (void)step;
    if (c->rows)
        put_row(c->rows, sim, t);
    return c->stop ? *c->stop : 0;
}

/* A memory stream for a summary; NULL when none can be had. */
static FILE *summary_stream(char **text, size_t *size)
{
    *text = NULL;
    *size = 0;
    return open_memstream(text, size);
}

/* Closes the stream (which sets *text: open_memstream updates it at
 * fflush and fclose only), its text into *summary (NULL if it is empty). */
static void summary_take(FILE *stream, char **text, char **summary)
{
    fclose(stream);
    if (*text && !(*text)[0]) {
        free(*text);
        *text = NULL;
    }
    *summary = *text;
}

int bspy_run(const bs_host_scene *scene, long every, bspy_rows *rows, bs_host_progress progress, void *context,
             int *stop, bs_host_run_result *result, char **summary, bs_host_error *error)
{
    bs_host_run_options options;
    run_context c;
    bs_host_status status;
    char *text;
    size_t size;
    FILE *stream = summary_stream(&text, &size);

    *summary = NULL;
    if (!stream) {
        memset(result, 0, sizeof *result);
        snprintf(error->text, sizeof error->text, "out of memory for the run's summary");
        return error->status = BS_HOST_E_MEMORY;
    }
    c.rows = rows;
    c.stop = stop;
    bs_host_run_defaults(&options);
    options.every = every;
    options.on_step = on_step;
    options.on_step_context = &c;
    options.progress = progress;
    options.progress_context = context;
    options.summary = stream;
    status = bs_host_run(scene, &options, result, error);
    summary_take(stream, &text, summary);
    return status;
}

int bspy_sweep(const bs_host_scene *scene, double from, double to, double step, int down, int hold, int record,
               bs_host_sweep_point *points, int room, bs_host_progress progress, void *context, int *done,
               char **summary, bs_host_error *error)
{
    bs_host_sweep_options options;
    bs_host_status status;
    char *text;
    size_t size;
    FILE *stream = summary_stream(&text, &size);

    *summary = NULL;
    *done = 0;
    if (!stream) {
        snprintf(error->text, sizeof error->text, "out of memory for the sweep's summary");
        return error->status = BS_HOST_E_MEMORY;
    }
    bs_host_sweep_defaults(&options);
    options.from = from;
    options.to = to;
    options.step = step;
    options.down = down;
    options.hold = hold;
    options.record = record;
    options.points = points;
    options.point_room = room;
    options.progress = progress;
    options.progress_context = context;
    options.summary = stream;
    status = bs_host_sweep(scene, &options, done, error);
    summary_take(stream, &text, summary);
    return status;
}

int bspy_sweep_points(double from, double to, double step)
{
    bs_host_sweep_options options;
    bs_host_sweep_defaults(&options);
    options.from = from;
    options.to = to;
    options.step = step;
    return bs_host_sweep_points(&options);
}

/* ---- measured signals --------------------------------------------------------- */

int bspy_measured_read(const char *path, bs_host_measured_header *header, double **rows, uint64_t *count,
                       bs_host_error *error)
{
    bs_host_measured *reader;
    bs_host_measured_row row;
    bs_host_status status;
    uint64_t room = 0, n = 0;
    double *all = NULL;
    int more;

    *rows = NULL;
    *count = 0;
    status = bs_host_measured_open(path, &reader, header, error);
    if (status != BS_HOST_OK)
        return status;
    while ((more = bs_host_measured_next(reader, &row, error)) == 1) {
        if (n == room) {
            const uint64_t grown = room ? 2 * room : 4096;
            double *next = realloc(all, (size_t)grown * 4 * sizeof *all);
            if (!next) {
                free(all);
                bs_host_measured_close(reader);
                snprintf(error->text, sizeof error->text, "%s: out of memory after %llu rows", path,
                         (unsigned long long)n);
                return error->status = BS_HOST_E_MEMORY;
            }
            all = next;
            room = grown;
        }
        all[4 * n] = row.t;
        all[4 * n + 1] = row.base_accel;
        all[4 * n + 2] = row.signal;
        all[4 * n + 3] = row.s_true;
        ++n;
    }
    bs_host_measured_close(reader);
    if (more < 0) {
        free(all);
        return error->status;
    }
    *rows = all;
    *count = n;
    error->status = BS_HOST_OK;
    error->text[0] = '\0';
    return BS_HOST_OK;
}

void bspy_free(void *memory)
{
    free(memory);
}
