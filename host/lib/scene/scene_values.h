/* scene_values.h - a resolved scene's field values as text, and their hash.
 *
 * The map command (docs/maps.md) and the JSON summaries need to say exactly
 * which scene produced a number: every field of the table (scene_fields.h)
 * as canonical text, and one hash over all of them.
 */
#ifndef SCENE_VALUES_H
#define SCENE_VALUES_H

#include <stddef.h>
#include <stdint.h>
#include "scene_params.h"

/* The canonical text of a number: the shortest %g text (1 to 17
 * significant digits) that reads back as exactly value ("0.3", "124",
 * "2e-05"). size: at least 32. */
void scene_number_text(double value, char *out, size_t size);

/* The canonical text of field f's value in params: a REAL as
 * scene_number_text, an INT in decimal, a CHOICE by its name, a TEXT as it
 * is. Read back through the scene reader, it gives the same value. */
void scene_value_text(const scene_params *params, const field_spec *f, char *out, size_t size);

/* FNV-1a (64 bits) over "section.key=value\n" of every field in the table's
 * order, values as scene_value_text, except the fields that change no
 * result ([scene] name and description) and those with skip[i] set (skip may
 * be NULL; the map leaves out the fields it varies). Two scenes with the
 * same hash run alike, bit for bit, in one build. */
uint64_t scene_values_hash(const scene_params *params, const unsigned char *skip);

/* 1 if field f changes no result (it only names or describes the scene). */
int scene_value_is_label(const field_spec *f);

#endif
