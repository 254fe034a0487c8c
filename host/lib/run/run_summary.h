/* run_summary.h - the one-line JSON summaries `run` and `sweep` print on
 * stdout, written by the one JSON writer (out_json.h: every text escaped and
 * UTF-8, numbers in the formats the summaries always had (README.md's
 * example line), a number that is not finite as null).
 */
#ifndef RUN_SUMMARY_H
#define RUN_SUMMARY_H

#include <stdio.h>
#include "beamslider.h"
#include "excitation_file.h"
#include "run.h"
#include "scene_ini.h"
#include "sweep.h"

/* Writes the summary of a run of scene (file: the scene as read, with the
 * command line's overrides) and a newline to out. It echoes the scene's
 * name, every field the command line set ("set": {"section.key": value}),
 * the hashes of the core scene and of every resolved field ("scene_hash",
 * "fields_hash"), the version and the source revision. record: the recorded
 * excitation the run replayed, NULL for the harmonic one (the scene's, or
 * its schedule). Returns 0, or -1 when it could not be built (out of
 * memory) or written. */
int summary_print_run(FILE *out, const scene_file *file, const bs_scene *scene,
                      const excitation_file *record, const run_result *result);

/* The same for a sweep over options. */
int summary_print_sweep(FILE *out, const scene_file *file, const bs_scene *scene,
                        const sweep_options *options, const sweep_result *result);

#endif
