/* scene_header.h - a scene as a C header for a compile-time (embedded)
 * build of the core (docs/porting.md section 2; `beamslider gen`,
 * `make configs`): its run and solver settings, the sizes and switches of a
 * core compiled against it, and the scene as `static const bs_scene
 * bs_compiled_scene` (scene_header.c says how). */
#ifndef SCENE_HEADER_H
#define SCENE_HEADER_H

#include <stddef.h>
#include "scene_build.h"

/* The header of the scene read into file and built into model (its data
 * refitted at the float and at the double tolerance), naming source as the
 * file it came from, as a malloc'd text in *out (free it). 0; -1 with err
 * (a value that is not finite: no header; out of memory); -2 with err (the
 * scene's shapes need more pieces than a build may have: bad input). */
int scene_header(const scene_file *file, const scene_model *model, const char *source, char **out, char *err,
                 size_t err_size);

#endif
