/* bsmex_sim.c - beamslider_sim: a simulator stepped from MATLAB or Octave,
 * its whole state a uint8 array between calls (bsmex.h).
 *
 *   st = beamslider_mex('sim', 'init', SCENE, options...)
 *   [st, out] = beamslider_mex('sim', 'step', st, n [, every])
 *   [st, out] = beamslider_mex('sim', 'step_measured', st, accel [, every])
 *   st = beamslider_mex('sim', 'excite', st, frequency, amplitude)
 *   info = beamslider_mex('sim', 'info', st)
 *   [w, slope] = beamslider_mex('sim', 'beam', st, x)
 *
 * No pointer crosses a call: the state array holds the core's checkpoint
 * (bs_sim_save) and what names the scene (its file's absolute path and the
 * overrides), so it survives unloading the gateway (`clear beamslider_mex`,
 * MATLAB's `clear mex`), can be saved in a .mat file and
 * copied, and two arrays are two independent sims. Each call loads the scene
 * (or finds it in a one-scene cache, below), initialises a sim, restores the
 * checkpoint, steps and saves it into a new array; the input array is never
 * changed. The checkpoint
 * carries the scene's hash: a scene file edited since `init` is refused by
 * the restore, not silently taken. The solver settings are the scene's
 * [solver], set at every call (a checkpoint holds no solver options).
 *
 * Layout of the state (machine byte order, like the checkpoint):
 *   0   8 bytes "BSMXSIM1"
 *   8   u32 checkpoint bytes (BS_CHECKPOINT_SIZE of the build)
 *   12  u32 path bytes, 16 u32 overrides, 20 u32 override bytes
 *   24  u32 sizeof(bs_real), 28 u32 0
 *   32  the checkpoint, then the path, then each override and a NUL
 */
#if !defined(_WIN32)
#define _POSIX_C_SOURCE 200809L
#include <unistd.h>
#else
#include <direct.h>
#define getcwd _getcwd
#endif
#include "bsmex.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STATE_MAGIC "BSMXSIM1"
#define STATE_HEAD 32

/* A state array read: pointers into it, and its scene's overrides. */
typedef struct sim_state {
    const unsigned char *checkpoint;
    const char *path;                   /* mxMalloc'd, NUL-terminated */
    bsmex_overrides overrides;          /* texts mxMalloc'd */
} sim_state;

/* ---- the one-scene cache --------------------------------------------------------- */

/* Loading a scene costs about 10 ms (the modal precomputation), a hundred
 * times a short step call: the last scene is kept, keyed by its path and
 * overrides and checked against the bytes of its file at every call, so an
 * edited scene file is read again. (A base file it names is not checked:
 * `clear beamslider_mex` after editing one.) */
#define SCENE_FILE_MAX (1 << 20)

static bs_host_scene *cached_scene;
static char *cached_key;                /* malloc'd: path, NUL, overrides with NULs, then the file's bytes */
static size_t cached_name_size, cached_key_size; /* of the path and overrides; of all */

void bsmex_sim_forget(void)
{
    bs_host_scene_free(cached_scene);
    free(cached_key);
    cached_scene = NULL;
    cached_key = NULL;
    cached_name_size = cached_key_size = 0;
}

/* The key of a scene: its path and overrides, each with its NUL (*name_size
 * bytes), then the contents of its file when with_file (a file that cannot
 * be read adds nothing). with_file only for a path the library has read as
 * a regular file (it refuses a FIFO, which fread would wait on). */
static char *scene_key(const char *path, const bsmex_overrides *overrides, int with_file, size_t *name_size,
                       size_t *size)
{
    FILE *file = with_file ? fopen(path, "rb") : NULL;
    long file_size = 0;
    size_t at;
    char *key;
    int i;

    if (file && (fseek(file, 0, SEEK_END) != 0 || (file_size = ftell(file)) < 0 || file_size > SCENE_FILE_MAX
                 || fseek(file, 0, SEEK_SET) != 0))
        file_size = 0;
    *name_size = strlen(path) + 1;
    for (i = 0; i < overrides->count; ++i)
        *name_size += strlen(overrides->text[i]) + 1;
    key = mxMalloc(*name_size + (size_t)file_size + 1);
    memcpy(key, path, strlen(path) + 1);
    at = strlen(path) + 1;
    for (i = 0; i < overrides->count; ++i) {
        memcpy(key + at, overrides->text[i], strlen(overrides->text[i]) + 1);
        at += strlen(overrides->text[i]) + 1;
    }
    *size = at + (file ? fread(key + at, 1, (size_t)file_size, file) : 0);
    if (file)
        fclose(file);
    return key;
}

/* The scene of path and overrides: the cached one while its file says the
 * same, or loaded (and cached). */
static const bs_host_scene *scene_get(const char *path, const bsmex_overrides *overrides)
{
    const int known = cached_scene != NULL;
    size_t name_size, size;
    char *key = scene_key(path, overrides, 0, &name_size, &size);
    bs_host_scene *scene;
    char *kept;

    if (known && name_size == cached_name_size && memcmp(key, cached_key, name_size) == 0) {
        key = scene_key(path, overrides, 1, &name_size, &size);
        if (size == cached_key_size && memcmp(key, cached_key, size) == 0)
            return cached_scene;
    }
    bsmex_sim_forget();
    scene = bsmex_scene_load(path, overrides);
    key = scene_key(path, overrides, 1, &name_size, &size);
    kept = malloc(size);
    if (!kept) {
        bs_host_scene_free(scene);
        bsmex_fail("beamslider:memory", "out of memory for the scene cache");
    }
    memcpy(kept, key, size);
    cached_scene = scene;
    cached_key = kept;
    cached_name_size = name_size;
    cached_key_size = size;
    return cached_scene;
}

/* ---- the state array ------------------------------------------------------------- */

static uint32_t get_u32(const unsigned char *at)
{
    uint32_t x;
    memcpy(&x, at, 4);
    return x;
}

static void put_u32(unsigned char *at, uint32_t x) { memcpy(at, &x, 4); }

/* path made absolute against the working folder, so that a later call from
 * another folder finds the same file (mxMalloc'd). */
static char *absolute_path(const char *path)
{
    char folder[4096];
    char *out;
    size_t size;
    int absolute = path[0] == '/';
#ifdef _WIN32
    absolute = absolute || path[0] == '\\' || (path[0] && path[1] == ':');
#endif
    if (absolute || !getcwd(folder, sizeof folder))
        folder[0] = '\0';
    size = strlen(folder) + strlen(path) + 2;
    out = mxMalloc(size);
    snprintf(out, size, "%s%s%s", folder, folder[0] ? "/" : "", path);
    return out;
}

static void bad_state(const char *why)
{
    bsmex_fail("beamslider:state", "st: not a beamslider_sim state of this build: %s (make one with "
                                   "beamslider_sim('init', ...))", why);
}

static void state_read(const mxArray *array, sim_state *state)
{
    const unsigned char *bytes;
    size_t size, path_bytes, override_bytes, at;
    uint32_t count;
    char *texts;
    int i;

    if (!array || !mxIsUint8(array))
        bad_state("expected a uint8 array");
    bytes = (const unsigned char *)mxGetData(array);
    size = mxGetNumberOfElements(array);
    if (size < STATE_HEAD || memcmp(bytes, STATE_MAGIC, 8) != 0)
        bad_state("no state mark");
    if (get_u32(bytes + 8) != BS_CHECKPOINT_SIZE || get_u32(bytes + 24) != sizeof(bs_real))
        bsmex_fail("beamslider:state", "st: a state of another build (precision %s, %u-byte checkpoint; this "
                   "gateway: %s, %u)", get_u32(bytes + 24) == 4 ? "float" : "double", (unsigned)get_u32(bytes + 8),
                   BS_REAL_NAME, (unsigned)BS_CHECKPOINT_SIZE);
    path_bytes = get_u32(bytes + 12);
    count = get_u32(bytes + 16);
    override_bytes = get_u32(bytes + 20);
    if (count > BSMEX_MAX_OVERRIDES || size != STATE_HEAD + BS_CHECKPOINT_SIZE + path_bytes + override_bytes)
        bad_state("its lengths do not add up");
    state->checkpoint = bytes + STATE_HEAD;
    texts = mxMalloc(path_bytes + 1 + override_bytes + 1);
    memcpy(texts, bytes + STATE_HEAD + BS_CHECKPOINT_SIZE, path_bytes + override_bytes);
    texts[path_bytes + override_bytes] = '\0';
    /* the path, then the overrides: move the overrides one on to end the path */
    memmove(texts + path_bytes + 1, texts + path_bytes, override_bytes);
    texts[path_bytes] = '\0';
    texts[path_bytes + 1 + override_bytes] = '\0';
    if (strlen(texts) != path_bytes)
        bad_state("a NUL in its path");
    state->path = texts;
    state->overrides.count = (int)count;
    at = path_bytes + 1;
    for (i = 0; i < (int)count; ++i) {
        if (at >= path_bytes + 1 + override_bytes)
            bad_state("fewer overrides than it says");
        state->overrides.text[i] = texts + at;
        at += strlen(texts + at) + 1;
    }
    if (at != path_bytes + 1 + override_bytes)
        bad_state("more override bytes than overrides");
}

/* A new state array: sim's checkpoint, the path and overrides of state. */
static mxArray *state_write(const bs_sim *sim, const char *path, const bsmex_overrides *overrides)
{
    size_t override_bytes = 0, at;
    const size_t path_bytes = strlen(path);
    unsigned char *bytes;
    mxArray *array;
    int i;

    for (i = 0; i < overrides->count; ++i)
        override_bytes += strlen(overrides->text[i]) + 1;
    array = mxCreateNumericMatrix((mwSize)(STATE_HEAD + BS_CHECKPOINT_SIZE + path_bytes + override_bytes), 1,
                                  mxUINT8_CLASS, mxREAL);
    bytes = (unsigned char *)mxGetData(array);
    memcpy(bytes, STATE_MAGIC, 8);
    put_u32(bytes + 8, (uint32_t)BS_CHECKPOINT_SIZE);
    put_u32(bytes + 12, (uint32_t)path_bytes);
    put_u32(bytes + 16, (uint32_t)overrides->count);
    put_u32(bytes + 20, (uint32_t)override_bytes);
    put_u32(bytes + 24, (uint32_t)sizeof(bs_real));
    put_u32(bytes + 28, 0);
    if (bs_sim_save(sim, bytes + STATE_HEAD, BS_CHECKPOINT_SIZE) != BS_OK)
        bsmex_fail("beamslider:failed", "the sim could not be saved");
    at = STATE_HEAD + BS_CHECKPOINT_SIZE;
    memcpy(bytes + at, path, path_bytes);
    at += path_bytes;
    for (i = 0; i < overrides->count; ++i) {
        memcpy(bytes + at, overrides->text[i], strlen(overrides->text[i]) + 1);
        at += strlen(overrides->text[i]) + 1;
    }
    return array;
}

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
static bs_sim *sim_open(const sim_state *state, bs_host_setup *setup)
{
    const bs_host_scene *scene = scene_get(state->path, &state->overrides);
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
    path = absolute_path(bsmex_text(in[0], "the scene file"));
    bsmex_options(nin - 1, in + 1, &overrides, NULL, 0);
    scene = scene_get(path, &overrides);
    bs_host_scene_setup(scene, &setup);
    if (setup.has_schedule)
        bsmex_fail("beamslider:input", "%s: [excitation] schedule: beamslider_sim steps at one harmonic excitation "
                   "(change it between steps with 'excite'); beamslider_run runs a schedule", path);
    sim = sim_start(scene, &setup);
    plhs[0] = state_write(sim, path, &overrides);
}

/* 'step' (measured NULL) or 'step_measured' (measured: the mean base
 * acceleration of each of the steps; NULL only when there are none). */
static void sim_advance(int nlhs, mxArray *plhs[], const mxArray *st, uint64_t steps, const double *measured,
                        uint64_t every)
{
    sim_state state;
    bs_host_setup setup;
    bsmex_series series;
    bs_sim *sim;
    const int want_series = nlhs > 1;
    uint64_t k;

    state_read(st, &state);
    sim = sim_open(&state, &setup);
    if (want_series) {
        bs_transducer_output t;
        bs_sim_get_transducer(sim, &t);
        bsmex_series_start(&series, (size_t)(steps / every), t.present);
    }
    for (k = 1; k <= steps; ++k) {
        const bs_status status = measured ? bs_sim_step_measured(sim, (bs_real)measured[k - 1]) : bs_sim_step(sim);
        if (status != BS_OK)
            bsmex_fail("beamslider:failed", "%s: step %.0f of this call (t = %.9g s) failed: %s", setup.name,
                       (double)k, (double)bs_sim_time(sim), bs_status_text(status));
        if (want_series && k % every == 0)
            bsmex_series_add(&series, sim, (double)bs_sim_steps(sim) * setup.dt);
    }
    plhs[0] = state_write(sim, state.path, &state.overrides);
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
    sim_state state;
    bs_host_setup setup;
    bs_sim *sim;
    double frequency, amplitude;
    (void)nlhs;
    if (nin != 3)
        bsmex_fail("beamslider:usage", "usage: st = beamslider_sim('excite', st, frequency, amplitude)");
    state_read(in[0], &state);
    frequency = bsmex_number(in[1], "frequency");
    amplitude = bsmex_number(in[2], "amplitude");
    sim = sim_open(&state, &setup);
    if (bs_sim_set_excitation(sim, (bs_real)frequency, (bs_real)amplitude) != BS_OK)
        bsmex_fail("beamslider:input", "frequency = %g Hz, amplitude = %g m/s^2: allowed: frequency * dt in (0, 1/2) "
                   "(dt = %g s: below %g Hz) and amplitude >= 0", frequency, amplitude, setup.dt, 0.5 / setup.dt);
    plhs[0] = state_write(sim, state.path, &state.overrides);
}

static void sim_info(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    sim_state state;
    bs_host_setup setup;
    bs_sim *sim;
    bs_real frequency, amplitude, slider[3], mu, e_n;
    char hash[16];
    mxArray *out, *set;
    int i;

    (void)nlhs;
    if (nin != 1)
        bsmex_fail("beamslider:usage", "usage: info = beamslider_sim('info', st)");
    state_read(in[0], &state);
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
    sim_state state;
    bs_host_setup setup;
    bs_sim *sim;
    const double *x;
    double *w, *slope;
    size_t n, i;

    if (nin != 2 || !mxIsDouble(in[1]) || mxIsComplex(in[1]) || mxIsSparse(in[1]))
        bsmex_fail("beamslider:usage", "usage: [w, slope] = beamslider_sim('beam', st, x) (x: positions [m], "
                   "a real double array)");
    state_read(in[0], &state);
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
