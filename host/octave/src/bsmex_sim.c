/* bsmex_sim.c - beamslider_sim: a simulator stepped from MATLAB or Octave,
 * its whole state a uint8 array between calls (bsmex.h; the array:
 * bsmex_state.c).
 *
 *   st = beamslider_mex('sim', 'init', SCENE, options...)
 *   [st, out] = beamslider_mex('sim', 'step', st, n [, every])
 *   [st, out] = beamslider_mex('sim', 'step_measured', st, accel [, every])
 *   st = beamslider_mex('sim', 'excite', st, frequency, amplitude)
 *   info = beamslider_mex('sim', 'info', st)
 *   [w, slope] = beamslider_mex('sim', 'beam', st, x)
 *
 * Each call takes the scene the state names (bsmex_state_scene: loaded, or
 * cached), initialises a sim, restores the checkpoint, works and saves it
 * into a new array; the input array is never changed. The solver settings
 * are the scene's [solver], set at every call (a checkpoint holds no solver
 * options).
 */
#include "bsmex.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A sim started on the scene as its file says (model, s0, [solver]). */
static bs_sim *sim_start(const bs_host_scene *scene, bs_host_setup *setup)
{
    bs_sim *sim = mxMalloc(sizeof *sim);
    bs_status status;
    bs_host_scene_setup(scene, setup);
    status = bs_sim_init(sim, bs_host_scene_core(scene), setup->model, (bs_real)setup->s0);
    if (status == BS_OK)
        status = bs_sim_set_solver(sim, &setup->solver);
    if (status != BS_OK)
        bsmex_fail("beamslider:input", "%s: the sim cannot start: %s", setup->name, bs_status_text(status));
    return sim;
}

/* The sim a state holds: its scene, started, the checkpoint restored. */
static bs_sim *sim_open(const bsmex_state *state, bs_host_setup *setup)
{
    const bs_host_scene *scene = bsmex_state_scene(state->path, &state->overrides);
    bs_sim *sim = sim_start(scene, setup);
    const bs_status status = bs_sim_restore(sim, state->checkpoint, BS_CHECKPOINT_SIZE);
    if (status == BS_E_CHECKPOINT_SCENE)
        bsmex_fail("beamslider:state", "st: its checkpoint was made on another scene than the one %s and its "
                   "overrides give now (was the file changed since 'init'?): %s", state->path, bs_status_text(status));
    if (status != BS_OK)
        bsmex_fail("beamslider:state", "st: its checkpoint is refused: %s", bs_status_text(status));
    return sim;
}

/* ---- the commands ---------------------------------------------------------------- */

static void sim_init(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    bsmex_overrides overrides;
    const bs_host_scene *scene;
    bs_host_setup setup;
    const char *path;
    bs_sim *sim;

    (void)nlhs;
    if (nin < 1)
        bsmex_fail("beamslider:usage", "usage: st = beamslider_sim('init', SCENE, 'name', value, ...)");
    path = bsmex_absolute_path(bsmex_text(in[0], "the scene file"));
    bsmex_options(nin - 1, in + 1, &overrides, NULL, 0);
    scene = bsmex_state_scene(path, &overrides);
    bs_host_scene_setup(scene, &setup);
    if (setup.has_schedule)
        bsmex_fail("beamslider:input", "%s: [excitation] schedule: beamslider_sim steps at one harmonic excitation "
                   "(change it between steps with 'excite'); beamslider_run runs a schedule", path);
    sim = sim_start(scene, &setup);
    plhs[0] = bsmex_state_write(sim, path, &overrides);
}

/* 'step' (measured NULL) or 'step_measured' (measured: the mean base
 * acceleration of each of the steps; NULL only when there are none). */
static void sim_advance(int nlhs, mxArray *plhs[], const mxArray *st, uint64_t steps, const double *measured,
                        uint64_t every)
{
    bsmex_state state;
    bs_host_setup setup;
    bsmex_series series;
    bs_sim *sim;
    const int want_series = nlhs > 1;
    uint64_t k;

    bsmex_state_read(st, &state);
    sim = sim_open(&state, &setup);
    if (want_series) {
        bs_transducer_output t;
        bs_sim_get_transducer(sim, &t);
        bsmex_series_start(&series, (size_t)(steps / every), t.present);
    }
    for (k = 1; k <= steps; ++k) {
        const bs_status status = measured ? bs_sim_step_measured(sim, (bs_real)measured[k - 1]) : bs_sim_step(sim);
        if (status != BS_OK)
            bsmex_fail("beamslider:failed", "%s: step %.0f of this call failed (at t = %.9g s): %s", setup.name,
                       (double)k, (double)bs_sim_steps(sim) * setup.dt, bs_status_text(status));
        if (want_series && k % every == 0)
            bsmex_series_add(&series, sim, (double)bs_sim_steps(sim) * setup.dt);
    }
    plhs[0] = bsmex_state_write(sim, state.path, &state.overrides);
    if (want_series) {
        plhs[1] = mxCreateStructMatrix(1, 1, 0, NULL);
        bsmex_series_finish(&series, plhs[1]);
    }
}

static uint64_t every_argument(int nin, const mxArray *in[], int at)
{
    return nin > at ? bsmex_count(in[at], "every", 1, 1000000000) : 1;
}

static void sim_step(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    if (nin < 2 || nin > 3)
        bsmex_fail("beamslider:usage", "usage: [st, out] = beamslider_sim('step', st, n [, every])");
    sim_advance(nlhs, plhs, in[0], bsmex_count(in[1], "n", 0, (uint64_t)1 << 53), NULL, every_argument(nin, in, 2));
}

static void sim_step_measured(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    const double *accel;
    size_t n, i;
    if (nin < 2 || nin > 3)
        bsmex_fail("beamslider:usage", "usage: [st, out] = beamslider_sim('step_measured', st, accel [, every])");
    if (!mxIsDouble(in[1]) || mxIsComplex(in[1]) || mxIsSparse(in[1]))
        bsmex_fail("beamslider:usage", "accel: expected a real double array (m/s^2, one value a step)");
    accel = (const double *)mxGetData(in[1]);
    n = mxGetNumberOfElements(in[1]);
    for (i = 0; i < n; ++i)
        if (!isfinite(accel[i]))
            bsmex_fail("beamslider:usage", "accel(%lu) = %g: expected a finite base acceleration [m/s^2]",
                       (unsigned long)i + 1, accel[i]);
    sim_advance(nlhs, plhs, in[0], (uint64_t)n, accel, every_argument(nin, in, 2));
}

static void sim_excite(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    bsmex_state state;
    bs_host_setup setup;
    bs_sim *sim;
    double frequency, amplitude;
    (void)nlhs;
    if (nin != 3)
        bsmex_fail("beamslider:usage", "usage: st = beamslider_sim('excite', st, frequency, amplitude)");
    bsmex_state_read(in[0], &state);
    frequency = bsmex_number(in[1], "frequency");
    amplitude = bsmex_number(in[2], "amplitude");
    sim = sim_open(&state, &setup);
    if (bs_sim_set_excitation(sim, (bs_real)frequency, (bs_real)amplitude) != BS_OK)
        bsmex_fail("beamslider:input", "frequency = %g Hz, amplitude = %g m/s^2: allowed: frequency * dt in (0, 1/2) "
                   "(dt = %g s: below %g Hz) and amplitude >= 0", frequency, amplitude, setup.dt, 0.5 / setup.dt);
    plhs[0] = bsmex_state_write(sim, state.path, &state.overrides);
}

static void sim_info(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    bsmex_state state;
    bs_host_setup setup;
    bs_sim *sim;
    bs_real frequency, amplitude, slider[3], mu, e_n;
    char hash[16];
    mxArray *out, *set;
    int i;

    (void)nlhs;
    if (nin != 1)
        bsmex_fail("beamslider:usage", "usage: info = beamslider_sim('info', st)");
    bsmex_state_read(in[0], &state);
    sim = sim_open(&state, &setup);
    bs_sim_get_excitation(sim, &frequency, &amplitude);
    bs_sim_get_contact_laws(sim, &mu, &e_n);
    bs_sim_get_state(sim, NULL, NULL, slider, NULL);
    out = mxCreateStructMatrix(1, 1, 0, NULL);
    bsmex_field(out, "scene", mxCreateString(state.path));
    set = mxCreateCellMatrix((mwSize)state.overrides.count, 1);
    for (i = 0; i < state.overrides.count; ++i)
        mxSetCell(set, (mwIndex)i, mxCreateString(state.overrides.text[i]));
    bsmex_field(out, "set", set);
    bsmex_field(out, "name", mxCreateString(setup.name));
    bsmex_field(out, "model", mxCreateString(setup.model == BS_MODEL_PCS ? "pcs" : "free"));
    bsmex_field(out, "precision", mxCreateString(BS_REAL_NAME));
    bsmex_field(out, "dt", mxCreateDoubleScalar(setup.dt));
    bsmex_field(out, "steps", mxCreateDoubleScalar((double)bs_sim_steps(sim)));
    bsmex_field(out, "t", mxCreateDoubleScalar((double)bs_sim_steps(sim) * setup.dt));
    bsmex_field(out, "s", mxCreateDoubleScalar((double)bs_sim_position(sim)));
    bsmex_field(out, "w_sensor", mxCreateDoubleScalar((double)bs_sim_sensor(sim)));
    bsmex_field(out, "z_r", mxCreateDoubleScalar((double)slider[1]));
    bsmex_field(out, "beta", mxCreateDoubleScalar((double)slider[2]));
    bsmex_field(out, "phase", mxCreateDoubleScalar((double)bs_sim_phase(sim)));
    bsmex_field(out, "frequency", mxCreateDoubleScalar((double)frequency));
    bsmex_field(out, "amplitude", mxCreateDoubleScalar((double)amplitude));
    bsmex_field(out, "mu", mxCreateDoubleScalar((double)mu));
    bsmex_field(out, "e_n", mxCreateDoubleScalar((double)e_n));
    snprintf(hash, sizeof hash, "%08x", (unsigned)bs_sim_hash(sim));
    bsmex_field(out, "hash", mxCreateString(hash));
    plhs[0] = out;
}

static void sim_beam(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    bsmex_state state;
    bs_host_setup setup;
    bs_sim *sim;
    const double *x;
    double *w, *slope;
    size_t n, i;

    if (nin != 2 || !mxIsDouble(in[1]) || mxIsComplex(in[1]) || mxIsSparse(in[1]))
        bsmex_fail("beamslider:usage", "usage: [w, slope] = beamslider_sim('beam', st, x) (x: positions [m], "
                   "a real double array)");
    bsmex_state_read(in[0], &state);
    sim = sim_open(&state, &setup);
    x = (const double *)mxGetData(in[1]);
    n = mxGetNumberOfElements(in[1]);
    plhs[0] = mxCreateDoubleMatrix((mwSize)mxGetM(in[1]), (mwSize)mxGetN(in[1]), mxREAL);
    w = (double *)mxGetData(plhs[0]);
    slope = mxMalloc(n ? n * sizeof *slope : 1);
    for (i = 0; i < n; ++i) {
        bs_real wi, si;
        if (bs_sim_beam_at(sim, (bs_real)x[i], &wi, &si) != BS_OK)
            bsmex_fail("beamslider:usage", "x(%lu) = %g: expected a finite position [m]", (unsigned long)i + 1, x[i]);
        w[i] = (double)wi;
        slope[i] = (double)si;
    }
    if (nlhs > 1) {
        plhs[1] = mxCreateDoubleMatrix((mwSize)mxGetM(in[1]), (mwSize)mxGetN(in[1]), mxREAL);
        if (n)
            memcpy(mxGetData(plhs[1]), slope, n * sizeof *slope);
    }
}

/* The subcommands of 'sim', one table. */
static const struct sim_command {
    const char *name;
    void (*run)(int nlhs, mxArray *plhs[], int nin, const mxArray *in[]);
    int max_outputs;
} sim_commands[] = {
    { "init", sim_init, 1 },
    { "step", sim_step, 2 },
    { "step_measured", sim_step_measured, 2 },
    { "excite", sim_excite, 1 },
    { "info", sim_info, 1 },
    { "beam", sim_beam, 2 },
};

void bsmex_sim(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    const char *name;
    size_t k;
    if (nin < 1)
        bsmex_fail("beamslider:usage", "usage: beamslider_sim(COMMAND, ...): COMMAND 'init', 'step', "
                                       "'step_measured', 'excite', 'info' or 'beam'");
    name = bsmex_text(in[0], "the command");
    for (k = 0; k < sizeof sim_commands / sizeof sim_commands[0]; ++k)
        if (strcmp(name, sim_commands[k].name) == 0) {
            if (nlhs > sim_commands[k].max_outputs)
                bsmex_fail("beamslider:usage", "beamslider_sim('%s', ...) gives at most %d outputs", name,
                           sim_commands[k].max_outputs);
            sim_commands[k].run(nlhs, plhs, nin - 1, in + 1);
            return;
        }
    bsmex_fail("beamslider:usage", "unknown command '%s'; allowed: 'init', 'step', 'step_measured', 'excite', "
               "'info', 'beam'", name);
}
