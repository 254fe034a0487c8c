/* fuzz_scene.c - libFuzzer target: the INI scene reader and the scene build.
 *
 * Whatever the bytes, scene_load (host/lib/scene/scene_ini.c, libinih underneath) and
 * scene_build (modal analysis, shape fit, bs_scene_check) must not crash,
 * hang, leak or touch memory out of bounds, and must answer 0 or -1 with a
 * message. A scene the host accepts must also be accepted by bs_sim_init and
 * step without crashing (a few steps; stopping with BS_E_UNSTABLE or
 * BS_E_NONFINITE is allowed and must keep the state).
 *
 * The input is written to a scene file in a private temporary folder that
 * also holds copies of configs/mssp2023.ini and fig6.ini (so that
 * `base = mssp2023.ini` reaches the deep checks) and self.ini, which names
 * itself as its base (a cycle).
 * Everything after the first line "#@base" goes to b.ini instead, which the
 * scene can name as `base = b.ini`: two fuzzed files at once.
 *
 * Built by tests/robustness.mk (make fuzz); FUZZ_CONFIGS is the configs folder.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "beamslider.h"
#include "fuzz_check.h"
#include "fuzz_scene_run.h"
#include "scene_build.h"

#ifndef FUZZ_CONFIGS
#define FUZZ_CONFIGS "configs"
#endif


static char folder[64];
static char scene_path[SCENE_PATH];
static char base_path[SCENE_PATH];
static scene_file file;   /* static: large */
static bs_scene scene;
static scene_model model;
static char message[1024];

static void die(const char *what)
{
    fuzz_fail(what);
}

static void write_bytes(const char *path, const uint8_t *data, size_t size)
{
    FILE *out = fopen(path, "wb");
    if (!out || (size && fwrite(data, 1, size, out) != size) || fclose(out) != 0)
        die("cannot write into the temporary folder");
}

static void copy_config(const char *name)
{
    static uint8_t text[1 << 16];
    char from[SCENE_PATH], to[SCENE_PATH];
    FILE *in;
    size_t size;

    snprintf(from, sizeof from, "%s/%s", FUZZ_CONFIGS, name);
    snprintf(to, sizeof to, "%s/%s", folder, name);
    in = fopen(from, "rb");
    if (!in)
        die("cannot read a scene of FUZZ_CONFIGS");
    size = fread(text, 1, sizeof text, in);
    fclose(in);
    write_bytes(to, text, size);
}

static void remove_folder(void)
{
    static const char *const names[] = { "s.ini", "b.ini", "self.ini", "mssp2023.ini", "fig6.ini" };
    char path[SCENE_PATH];
    size_t i;
    for (i = 0; i < sizeof names / sizeof names[0]; ++i) {
        snprintf(path, sizeof path, "%s/%s", folder, names[i]);
        unlink(path);
    }
    rmdir(folder);
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static const char self[] = "[scene]\nbase = self.ini\n";
    char path[SCENE_PATH];
    const char *tmp = getenv("TMPDIR");

    (void)argc;
    (void)argv;
    snprintf(folder, sizeof folder, "%s/bs_fuzz_XXXXXX", tmp && strlen(tmp) < 40 ? tmp : "/tmp");
    if (!mkdtemp(folder))
        die("mkdtemp failed");
    atexit(remove_folder);
    copy_config("mssp2023.ini");
    copy_config("fig6.ini");
    snprintf(path, sizeof path, "%s/self.ini", folder);
    write_bytes(path, (const uint8_t *)self, sizeof self - 1);
    snprintf(scene_path, sizeof scene_path, "%s/s.ini", folder);
    snprintf(base_path, sizeof base_path, "%s/b.ini", folder);
    return 0;
}

/* The first "\n#@base\n" splits the input into the scene and b.ini. */
static size_t split(const uint8_t *data, size_t size)
{
    static const char mark[] = "\n#@base\n";
    const size_t length = sizeof mark - 1;
    size_t i;
    for (i = 0; i + length <= size; ++i)
        if (!memcmp(data + i, mark, length))
            return i;
    return size;
}

static void check_message(int status)
{
    const size_t length = strnlen(message, sizeof message);
    if (status != 0 && status != -1)
        die("status neither 0 nor -1");
    if (length == sizeof message)
        die("message not terminated");
    if (status == -1 && length == 0)
        die("refused without a message");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const size_t cut = split(data, size);
    int status_host;

    write_bytes(scene_path, data, cut);
    if (cut < size)
        write_bytes(base_path, data + cut + 8, size - cut - 8);
    else
        unlink(base_path);

    message[0] = '\0';
    status_host = scene_load(scene_path, &file, message, sizeof message);
    check_message(status_host);
    if (status_host != 0)
        return 0;
    message[0] = '\0';
    status_host = scene_build(&file, &scene, &model, message, sizeof message);
    check_message(status_host);
    if (status_host != 0)
        return 0;

    fuzz_scene_runs(&file, &scene); /* what the host accepts, the core must accept and run */
    return 0;
}
