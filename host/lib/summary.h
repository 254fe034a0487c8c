/* summary.h - the one-line JSON summaries `run` and `sweep` print on stdout.
 *
 * Written with cJSON (Debian's libcjson-dev), so that every text (a scene
 * name holding a quote, a backslash or a control character, which the file
 * name can) is escaped and the line is valid JSON. Numbers keep the formats
 * the summaries always had (README.md's example line): each is formatted
 * with its printf format and added as a raw value; a number that is not
 * finite (JSON has no NaN) is written as null.
 */
#ifndef SUMMARY_H
#define SUMMARY_H

#include <stdio.h>
#include "beamslider.h"
#include "excitation_file.h"
#include "run.h"
#include "scene_params.h"
#include "sweep.h"

/* Writes the summary of a run of scene (params as read) and a newline to
 * out. record: the recorded excitation the run replayed, NULL for the
 * harmonic one (the scene's, or its schedule). Returns 0, or -1 when it
 * could not be built (out of memory) or written. */
int summary_print_run(FILE *out, const scene_params *params, const bs_scene *scene,
                      const excitation_file *record, const run_result *result);

/* The same for a sweep over options. */
int summary_print_sweep(FILE *out, const scene_params *params, const bs_scene *scene,
                        const sweep_options *options, const sweep_result *result);

#endif
