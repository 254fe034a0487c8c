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
#include "fuzz_files.h"
#include "fuzz_scene_run.h"
#include "scene_build.h"


static const char base_mark[] = "\n#@base\n";
static scene_file file;   /* static: large */
static bs_scene scene;
static scene_model model;
static char message[1024];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static const char self[] = "[scene]\nbase = self.ini\n";
    (void)argc;
    (void)argv;
    fuzz_copy_config("mssp2023.ini");
    fuzz_copy_config("fig6.ini");
    fuzz_write(fuzz_path("self.ini"), (const uint8_t *)self, sizeof self - 1);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const size_t cut = fuzz_split(data, size, base_mark);
    const size_t mark = sizeof base_mark - 1;
    const char *scene_path = fuzz_path("s.ini");
    int status_host;

    fuzz_write(scene_path, data, cut);
    if (cut < size)
        fuzz_write(fuzz_path("b.ini"), data + cut + mark, size - cut - mark);
    else
        unlink(fuzz_path("b.ini"));

    message[0] = '\0';
    status_host = scene_load(scene_path, &file, message, sizeof message);
    fuzz_check_message(status_host, message, sizeof message);
    if (status_host != 0)
        return 0;
    message[0] = '\0';
    status_host = scene_build(&file, &scene, &model, message, sizeof message);
    fuzz_check_message(status_host, message, sizeof message);
    if (status_host != 0)
        return 0;

    fuzz_scene_runs(&file, &scene); /* what the host accepts, the core must accept and run */
    return 0;
}
