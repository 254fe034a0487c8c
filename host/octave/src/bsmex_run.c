/* bsmex_run.c - beamslider_run: one run of a scene, as `beamslider run`
 * (bsmex.h).
 *
 *   r = beamslider_mex('run', SCENE, options...)
 *
 * The run is the host library's bs_host_run, sample for sample the CLI's, so
 * r.summary.hash is the hash `beamslider run` prints for the same scene and
 * overrides. The series are taken every `every` steps from the start (the
 * rows of `run --out --every`); by default every millisecond of simulated
 * time (round(1e-3 / dt) steps), since a row per step of a 60 s run would
 * be 3 million rows. The per-period rows (`run --periods`) come back in
 * r.periods: the library writes them to a stream, read back here.
 */
#include "bsmex.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct run_call {
    bsmex_series series;
} run_call;

static int on_step(void *context, const bs_sim *sim, uint64_t step, double t)
{
    run_call *call = context;
    (void)step;
    bsmex_series_add(&call->series, sim, t);
    return 0;
}

/* Back to the first row of periods, after its header line. */
static void first_row(FILE *periods)
{
    int c;
    rewind(periods);
    while ((c = fgetc(periods)) != EOF && c != '\n')
        ;
}

/* The rows "t,amp_h,s,ds" the run wrote to periods, as fields of a struct. */
static mxArray *read_periods(FILE *periods)
{
    static const char *const names[] = { "t", "amp_h", "s", "ds" };
    mxArray *out = mxCreateStructMatrix(1, 1, 4, (const char **)names);
    double row[4];
    size_t rows = 0, i;
    double *column[4];
    int k;

    first_row(periods);
    while (fscanf(periods, "%lf,%lf,%lf,%lf\n", &row[0], &row[1], &row[2], &row[3]) == 4)
        ++rows;
    for (k = 0; k < 4; ++k) {
        mxArray *a = mxCreateDoubleMatrix((mwSize)rows, 1, mxREAL);
        column[k] = (double *)mxGetData(a);
        mxSetFieldByNumber(out, 0, k, a);
    }
    first_row(periods);
    for (i = 0; i < rows && fscanf(periods, "%lf,%lf,%lf,%lf\n", &row[0], &row[1], &row[2], &row[3]) == 4; ++i)
        for (k = 0; k < 4; ++k)
            column[k][i] = row[k];
    return out;
}

/* Whether the scene has a transducer (then the series have v, p, v_s). */
static int has_transducer(const bs_host_scene *scene, const bs_host_setup *setup)
{
    bs_sim *probe = mxMalloc(sizeof *probe);
    bs_transducer_output t;
    const int present = bs_sim_init(probe, bs_host_scene_core(scene), setup->model, (bs_real)setup->s0) == BS_OK
        && bs_sim_get_transducer(probe, &t) == BS_OK && t.present;
    mxFree(probe);
    return present;
}

static mxArray *number(double x) { return mxCreateDoubleScalar(x); }

/* The overrides as an n x 2 cell {field, value}: a value that reads whole as
 * a number is a number (the JSON summary's "set" object). */
static mxArray *overrides_cell(const bsmex_overrides *overrides)
{
    mxArray *cell = mxCreateCellMatrix((mwSize)overrides->count, 2);
    int i;
    for (i = 0; i < overrides->count; ++i) {
        const char *text = overrides->text[i];
        const char *eq = strchr(text, '=');
        size_t field_len = eq ? (size_t)(eq - text) : strlen(text);
        char *field = mxMalloc(field_len + 1);
        const char *value = eq ? eq + 1 : "";
        char *end;
        const double x = strtod(value, &end);
        memcpy(field, text, field_len);
        field[field_len] = '\0';
        mxSetCell(cell, (mwIndex)i, mxCreateString(field));
        mxSetCell(cell, (mwIndex)(i + overrides->count),
                  *value && !*end ? mxCreateDoubleScalar(x) : mxCreateString(value));
    }
    return cell;
}

/* The figures of `beamslider run`'s JSON summary that the library gives,
 * under the same names. */
static mxArray *summary(const bs_host_scene *scene, const bsmex_overrides *overrides, const bs_host_run_result *r)
{
    bs_host_setup setup;
    bs_host_modes modes;
    char hash[16];
    mxArray *out = mxCreateStructMatrix(1, 1, 0, NULL);

    bs_host_scene_setup(scene, &setup);
    bs_host_scene_modes(scene, &modes);
    bsmex_field(out, "scene", mxCreateString(setup.name));
    bsmex_field(out, "model", mxCreateString(setup.model == BS_MODEL_PCS ? "pcs" : "free"));
    bsmex_field(out, "precision", mxCreateString(BS_REAL_NAME));
    bsmex_field(out, "modes", number(modes.n));
    bsmex_field(out, "dt", number(setup.dt));
    bsmex_field(out, "excitation", mxCreateString(setup.has_schedule ? "schedule" : "harmonic"));
    bsmex_field(out, "status", mxCreateString(bs_status_text(r->status)));
    bsmex_field(out, "t_end", number(r->t));
    bsmex_field(out, "steps", number((double)r->steps));
    bsmex_field(out, "s0", number(setup.s0));
    bsmex_field(out, "s_final", number(r->s_final));
    bsmex_field(out, "s_min", number(r->s_min));
    bsmex_field(out, "t_s_min", number(r->t_s_min));
    bsmex_field(out, "amp_final_h", number(r->amp_final_h));
    bsmex_field(out, "amp_periods", number(r->amp_periods));
    if (r->transducer) {
        bsmex_field(out, "energy_j", number(r->energy));
        bsmex_field(out, "power_mean_w", number(r->power_mean));
        bsmex_field(out, "power_last_w", number(r->power_last));
    }
    bsmex_field(out, "wall_s", number(r->wall_s));
    bsmex_field(out, "steps_per_s", number(r->wall_s > 0.0 ? (double)r->steps / r->wall_s : 0.0));
    bsmex_field(out, "max_pgs_iters", number(r->max_sweeps));
    bsmex_field(out, "unconverged_steps", number((double)r->unconverged_steps));
    bsmex_field(out, "contact_steps", number((double)r->contact_steps));
    bsmex_field(out, "max_systems", number(r->max_systems));
    snprintf(hash, sizeof hash, "%08x", (unsigned)r->hash);
    bsmex_field(out, "hash", mxCreateString(hash));
    bsmex_field(out, "set", overrides_cell(overrides));
    snprintf(hash, sizeof hash, "%08x", (unsigned)bs_scene_hash(bs_host_scene_core(scene)));
    bsmex_field(out, "scene_hash", mxCreateString(hash));
    bsmex_field(out, "version", mxCreateString(bs_version()));
    return out;
}

void bsmex_run(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    bsmex_overrides overrides;
    bs_host_scene *scene;
    bs_host_setup setup;
    bs_host_run_options options;
    bs_host_run_result result;
    bs_host_error error;
    run_call call;
    long every = 0;
    const char *path;
    FILE *periods;
    mxArray *out;

    (void)nlhs;
    if (nin < 1)
        bsmex_fail("beamslider:usage", "usage: r = beamslider_run(SCENE, 'name', value, ...)");
    path = bsmex_text(in[0], "the scene file");
    bsmex_options(nin - 1, in + 1, &overrides, &every, 1);
    scene = bsmex_scene_load(path, &overrides);
    bsmex_hold_scene(scene);
    bs_host_scene_setup(scene, &setup);
    if (every == 0) {
        const double per_ms = floor(1e-3 / setup.dt + 0.5);
        every = per_ms >= 1.0 ? (long)per_ms : 1;
    }
    periods = tmpfile();
    if (!periods)
        bsmex_fail("beamslider:failed", "no temporary file for the per-period rows");
    bsmex_hold_file(periods);
    bs_host_run_defaults(&options);
    options.every = every;
    options.on_step = on_step;
    options.on_step_context = &call;
    options.periods = periods;
    bsmex_series_start(&call.series, (size_t)(setup.steps / (uint64_t)every) + 1, has_transducer(scene, &setup));
    if (bs_host_run(scene, &options, &result, &error) != BS_HOST_OK)
        bsmex_fail_host(&error);
    out = mxCreateStructMatrix(1, 1, 0, NULL);
    bsmex_series_finish(&call.series, out);
    bsmex_field(out, "periods", read_periods(periods));
    bsmex_field(out, "summary", summary(scene, &overrides, &result));
    plhs[0] = out;
}
