/* scene_values.c - field values as canonical text and their hash
 * (scene_values.h). */
#include "scene_values.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void scene_number_text(double value, char *out, size_t size)
{
    int digits, exponent;
    /* the fewest digits that read back exactly: 0.1 stays "0.1", not
     * "0.10000000000000001"; 17 always do */
    for (digits = 1; digits < 17; ++digits) {
        snprintf(out, size, "%.*g", digits, value);
        if (strtod(out, NULL) == value)
            break;
    }
    /* %g writes 110 with 2 digits as 1.1e+02: whole numbers up to 17
     * digits are written out */
    exponent = value != 0.0 && isfinite(value) ? (int)floor(log10(fabs(value))) : 0;
    if (exponent >= digits && exponent < 17)
        digits = exponent + 1;
    snprintf(out, size, "%.*g", digits, value);
}

void scene_value_text(const scene_params *params, const field_spec *f, char *out, size_t size)
{
    const char *where = (const char *)params + f->offset;

    switch (f->kind) {
    case FIELD_REAL:
        scene_number_text(*(const double *)where, out, size);
        break;
    case FIELD_INT:
        snprintf(out, size, "%d", *(const int *)where);
        break;
    case FIELD_CHOICE: {
        const int index = *(const int *)where;
        int count;
        for (count = 0; f->choices[count]; ++count)
            ;
        snprintf(out, size, "%s", index >= 0 && index < count ? f->choices[index] : "?");
        break;
    }
    case FIELD_TEXT:
        snprintf(out, size, "%s", where);
        break;
    }
}

int scene_value_is_label(const field_spec *f)
{
    return !strcmp(f->section, "scene") && (!strcmp(f->key, "name") || !strcmp(f->key, "description"));
}

static uint64_t fnv1a(uint64_t hash, const char *text)
{
    for (; *text; ++text) {
        hash ^= (unsigned char)*text;
        hash *= 0x100000001b3u;
    }
    return hash;
}

uint64_t scene_values_hash(const scene_params *params, const unsigned char *skip)
{
    uint64_t hash = 0xcbf29ce484222325u;
    char value[SCENE_TEXT + 32];
    int i;

    for (i = 0; scene_fields[i].key; ++i) {
        const field_spec *f = &scene_fields[i];
        if (scene_value_is_label(f) || (skip && skip[i]))
            continue;
        scene_value_text(params, f, value, sizeof value);
        hash = fnv1a(hash, f->section);
        hash = fnv1a(hash, ".");
        hash = fnv1a(hash, f->key);
        hash = fnv1a(hash, "=");
        hash = fnv1a(hash, value);
        hash = fnv1a(hash, "\n");
    }
    return hash;
}
