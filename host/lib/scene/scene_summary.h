/* scene_summary.h - what every JSON summary says about its scene and its
 * build: the fields the command line set, the hashes of the scene, the
 * version and the source revision. The summaries of the wings (run_summary.h,
 * map_summary.h) add these through the one JSON writer (out_json.h). */
#ifndef SCENE_SUMMARY_H
#define SCENE_SUMMARY_H

#include "beamslider.h"
#include "out_json.h"
#include "scene_ini.h"

/* "set": {"section.key": value} of every field set by an option (--set,
 * --s0, ...), numbers as numbers: the line says what it is about without
 * the command that made it. */
void scene_summary_overrides(out_json *json, const scene_file *file);

/* "scene_hash" (the core's bs_scene_hash of scene) and "fields_hash" (the
 * host's scene_values_hash of every resolved field). */
void scene_summary_hashes(out_json *json, const scene_file *file, const bs_scene *scene);

/* "version" (the library's) and "revision" (git describe at build time;
 * "unknown" outside a git checkout). */
void scene_summary_provenance(out_json *json);

#endif
