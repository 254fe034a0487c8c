/* bsmex_main.c - the entry of the MEX gateway beamslider_mex (bsmex.h).
 *
 *   beamslider_mex('run', SCENE, options...)      beamslider_run.m
 *   beamslider_mex('sim', COMMAND, ...)           beamslider_sim.m
 *   beamslider_mex('version')                     the library's version and precision
 *
 * The .m files beside it carry the help text users read; this file only
 * dispatches through one table.
 */
#include "bsmex.h"

#include <string.h>

/* What the call holds (bsmex_hold_*): a few of each at most. */
#define HOLD_ROOM 4
static bs_host_scene *held_scenes[HOLD_ROOM];
static FILE *held_files[HOLD_ROOM];

void bsmex_hold_scene(bs_host_scene *scene)
{
    int i;
    for (i = 0; i < HOLD_ROOM; ++i)
        if (!held_scenes[i]) {
            held_scenes[i] = scene;
            return;
        }
    bs_host_scene_free(scene);
    bsmex_fail("beamslider:memory", "more than %d scenes held by one call", HOLD_ROOM);
}

void bsmex_hold_file(FILE *file)
{
    int i;
    for (i = 0; i < HOLD_ROOM; ++i)
        if (!held_files[i]) {
            held_files[i] = file;
            return;
        }
    fclose(file);
    bsmex_fail("beamslider:memory", "more than %d files held by one call", HOLD_ROOM);
}

void bsmex_release(void)
{
    int i;
    for (i = 0; i < HOLD_ROOM; ++i) {
        bs_host_scene_free(held_scenes[i]);
        held_scenes[i] = NULL;
        if (held_files[i])
            fclose(held_files[i]);
        held_files[i] = NULL;
    }
}

/* When the gateway is unloaded (`clear beamslider_mex`, `clear functions`,
 * MATLAB's `clear mex`) and when the program ends. */
static void at_exit(void)
{
    bsmex_release();
    bsmex_state_forget();
}

static void version(int nlhs, mxArray *plhs[], int nin, const mxArray *in[])
{
    static const char *const names[] = { "version", "precision", "checkpoint_bytes" };
    mxArray *out = mxCreateStructMatrix(1, 1, 3, (const char **)names);
    (void)nlhs;
    (void)in;
    if (nin != 0)
        bsmex_fail("beamslider:usage", "usage: v = beamslider_mex('version')");
    mxSetFieldByNumber(out, 0, 0, mxCreateString(bs_version()));
    mxSetFieldByNumber(out, 0, 1, mxCreateString(BS_REAL_NAME));
    mxSetFieldByNumber(out, 0, 2, mxCreateDoubleScalar((double)BS_CHECKPOINT_SIZE));
    plhs[0] = out;
}

static const struct command {
    const char *name;
    void (*run)(int nlhs, mxArray *plhs[], int nin, const mxArray *in[]);
} commands[] = {
    { "run", bsmex_run },
    { "sim", bsmex_sim },
    { "version", version },
};

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static int registered;
    const char *name;
    size_t k;
    if (!registered) {
        mexAtExit(at_exit);
        registered = 1;
    }
    bsmex_release(); /* what a call that raised an error left */
    if (nrhs < 1)
        bsmex_fail("beamslider:usage", "usage: beamslider_mex('run' | 'sim' | 'version', ...); call "
                                       "beamslider_run or beamslider_sim");
    if (bs_build_check() != BS_OK)
        bsmex_fail("beamslider:build", "beamslider_mex was compiled against the headers of another build than "
                                       "the library it links (precision, switches, version)");
    name = bsmex_text(prhs[0], "the command");
    for (k = 0; k < sizeof commands / sizeof commands[0]; ++k)
        if (strcmp(name, commands[k].name) == 0) {
            commands[k].run(nlhs, plhs, nrhs - 1, prhs + 1);
            bsmex_release();
            return;
        }
    bsmex_fail("beamslider:usage", "unknown command '%s'; allowed: 'run', 'sim', 'version'", name);
}
