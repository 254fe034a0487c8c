/* bsmex_state.c - beamslider_sim's state: the uint8 array that holds a sim
 * between calls, and the scene it names (bsmex.h).
 *
 * No pointer crosses a call: the array holds the core's checkpoint
 * (bs_sim_save) and what names the scene (its file's absolute path and the
 * overrides), so it survives unloading the gateway (`clear beamslider_mex`,
 * MATLAB's `clear mex`), can be saved in a .mat file and copied, and two
 * arrays are two independent sims. The checkpoint carries the scene's hash:
 * a scene that is not the one of `init` any more is refused by the restore,
 * not silently taken.
 *
 * Layout (machine byte order, like the checkpoint):
 *   0   8 bytes "BSMXSIM1"
 *   8   u32 checkpoint bytes (BS_CHECKPOINT_SIZE of the build)
 *   12  u32 path bytes, 16 u32 overrides, 20 u32 override bytes
 *   24  u32 sizeof(bs_real), 28 u32 0
 *   32  the checkpoint, then the path, then each override and a NUL
 */
#if !defined(_WIN32)
#define _POSIX_C_SOURCE 200809L /* getcwd */
#include <unistd.h>
#else
#include <direct.h>
#define getcwd _getcwd
#endif
#include "bsmex.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STATE_MAGIC "BSMXSIM1"
#define STATE_HEAD 32

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

void bsmex_state_forget(void)
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

const bs_host_scene *bsmex_state_scene(const char *path, const bsmex_overrides *overrides)
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
    bsmex_state_forget();
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

char *bsmex_absolute_path(const char *path)
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

void bsmex_state_read(const mxArray *array, bsmex_state *state)
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

mxArray *bsmex_state_write(const bs_sim *sim, const char *path, const bsmex_overrides *overrides)
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
