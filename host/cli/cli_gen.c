/* cli_gen.c - `beamslider gen SCENE.ini > configs/NAME.h`: a compile-time
 * scene for an embedded build (host/lib/scene/scene_header.c writes it). */
#include <stdio.h>
#include <stdlib.h>
#include "cli.h"
#include "scene_header.h"

const char cli_gen_synopsis[] = "beamslider gen SCENE.ini";
const char cli_gen_help[] =
    "  the scene as a C header for a compile-time (embedded) build, on stdout\n"
    "  (docs/porting.md section 2; make configs writes configs/*.h with it)\n";

int cli_gen(int argc, char **argv)
{
    typedef struct gen_scene {
        scene_file file;
        bs_scene scene;
        scene_model model;
    } gen_scene;
    gen_scene *g;
    char err[1024];
    char *header;
    int status;

    if (argc != 1) {
        cli_error("gen takes exactly one scene file");
        return CLI_USAGE;
    }
    if (!(g = malloc(sizeof *g))) {
        cli_error("out of memory");
        return CLI_FAILED;
    }
    if (scene_read(argv[0], &g->file, &g->scene, &g->model, err, sizeof err) != 0) {
        cli_error("%s", err);
        free(g);
        return CLI_USAGE;
    }
    status = scene_header(&g->file, &g->model, argv[0], &header, err, sizeof err);
    free(g);
    if (status != 0) {
        cli_error("%s", err);
        return status == -2 ? CLI_USAGE : CLI_FAILED;
    }
    fputs(header, stdout);
    free(header);
    return fflush(stdout) == 0 && !ferror(stdout) ? CLI_OK : CLI_FAILED;
}
