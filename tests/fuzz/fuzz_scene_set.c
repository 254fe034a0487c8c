/* fuzz_scene_set.c - libFuzzer target: a scene file with `--set`
 * assignments (host/lib/scene/scene_ini.c scene_set_assignment), then the scene
 * build, as `run`, `map` and `twin` take them.
 *
 * Input: the scene text, then a line "#@set" and the assignments, each
 * ended by a NUL byte (so that an assignment may hold a line break, as an
 * argument can). The scene is written to a file in a private temporary
 * folder that also holds copies of configs/mssp2023.ini and fig6.ini, so
 * that `base = fig6.ini` gives a whole scene to assign into. At most
 * MAX_SETS assignments are applied, with the option name `--set`.
 * The contract checked:
 *   - nothing crashes, hangs, leaks or reads out of bounds;
 *   - scene_load, scene_set_assignment and scene_build answer 0 or -1 with
 *     a message;
 *   - a refused assignment leaves the scene as it was, byte for byte;
 *   - an assignment holding a control character (other than a tab) is
 *     refused, as in a file;
 *   - an accepted one is recorded as set by the option (scene_where names
 *     it);
 *   - a scene the host builds, the core starts and steps (fuzz_scene_run.h).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, strnlen */

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_check.h"
#include "fuzz_files.h"
#include "fuzz_scene_run.h"
#include "scene_build.h"
#include "scene_fields.h"

#define MAX_SETS 16
#define MAX_ASSIGNMENT 1024

static scene_file file, before; /* static: large */
static bs_scene scene;
static scene_model model;

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    fuzz_copy_config("mssp2023.ini");
    fuzz_copy_config("fig6.ini");
    return 0;
}

/* The line that ends the scene: --set assignments follow it. */
static const char set_mark[] = "\n#@set\n";

static int has_control(const char *text)
{
    const unsigned char *c = (const unsigned char *)text;
    for (; *c; ++c)
        if ((*c < 0x20 && *c != '\t') || *c == 0x7f)
            return 1;
    return 0;
}

static void assign(const char *assignment)
{
    char message[1024], section[SCENE_NAME], key[SCENE_NAME], where[SCENE_OPTION + 16];
    const char *equals = strchr(assignment, '=');
    int status, field;

    memcpy(&before, &file, sizeof file);
    message[0] = '\0';
    status = scene_set_assignment(&file, "--set", assignment, message, sizeof message);
    fuzz_check_message(status, message, sizeof message);
    if (status != 0) {
        if (memcmp(&before, &file, sizeof file) != 0)
            fuzz_fail("a refused --set changed the scene");
        return;
    }
    if (has_control(assignment))
        fuzz_fail("scene_set_assignment accepted a control character");
    field = equals ? scene_field_named(assignment, (size_t)(equals - assignment), section, key) : -1;
    if (field < 0)
        fuzz_fail("scene_set_assignment accepted an assignment that names no field");
    if (file.set_file[field] != SCENE_BY_OPTION
        || strncmp(scene_where(&file, section, key, where, sizeof where), "--set ", 6) != 0)
        fuzz_fail("an accepted --set is not recorded as set by the option");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char assignment[MAX_ASSIGNMENT];
    const char *path = fuzz_path("s.ini");
    const size_t cut = fuzz_split(data, size, set_mark);
    char message[1024];
    size_t at = cut + sizeof set_mark - 1;
    int status, sets = 0;

    fuzz_write(path, data, cut);
    message[0] = '\0';
    status = scene_load(path, &file, message, sizeof message);
    fuzz_check_message(status, message, sizeof message);
    if (status != 0)
        return 0;
    while (at < size && sets < MAX_SETS) {
        const uint8_t *nul = memchr(data + at, '\0', size - at);
        const size_t length = nul ? (size_t)(nul - (data + at)) : size - at;
        if (length < sizeof assignment) {
            memcpy(assignment, data + at, length);
            assignment[length] = '\0';
            assign(assignment);
            ++sets;
        }
        at += length + 1;
    }
    message[0] = '\0';
    status = scene_build(&file, &scene, &model, message, sizeof message);
    fuzz_check_message(status, message, sizeof message);
    if (status == 0)
        fuzz_scene_runs(&file, &scene);
    return 0;
}
