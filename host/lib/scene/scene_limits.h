/* scene_limits.h - inputs too extreme for the numbers derived from them.
 *
 * Each field is checked against its own range when it is read; a value in
 * range can still make a derived quantity (the beam width, a modal
 * frequency, a base displacement) overflow or underflow in double on the
 * host, or in bs_real in the core. scene_limits_check finds that before the
 * quantity is computed, and names the input fields with where they were set
 * and the range each may take with the others as set. The quantities, their
 * inputs and limits are the rows of scene_origins.h.
 */
#ifndef SCENE_LIMITS_H
#define SCENE_LIMITS_H

#include <stddef.h>
#include "scene_ini.h"
#include "scene_origins.h"

/* Checks every derived quantity of file->params the host computes in double
 * or hands to the core in bs_real. Returns 0, or -1 with a message in err
 * that starts with where the field most to blame was set. */
int scene_limits_check(const scene_file *file, char *err, size_t size);

/* The range [low, high] field [section] key may take, the other fields as
 * set, for every derived quantity to stay within its limits (and within the
 * field's own range). Returns 0, or -1 when no value works. */
int scene_limits_range(const scene_file *file, const char *section, const char *key, double *low,
                       double *high);

/* Appends "[section] key = value (where; allowed with the others as set:
 * [low, high] unit)" for each of count inputs, separated by "; ", to out. */
void scene_limits_describe(const scene_file *file, const scene_input *inputs, int count, char *out,
                           size_t size);

/* Of inputs, the one set most specifically (by an option, then in the file
 * asked for, then in its bases in order; the first of equals): the likely
 * culprit when a combination fails a check no single range tells apart. */
int scene_limits_specific(const scene_file *file, const scene_input *inputs, int count);

/* Where the input that lies outside its allowed range was set (when none
 * does, the most specific one: scene_limits_specific), into out. */
const char *scene_limits_blame(const scene_file *file, const scene_input *inputs, int count, char *out,
                               size_t size);

#endif
