/* scene_summary.c - a summary's scene and build (scene_summary.h). */
#include "scene_summary.h"

#include <stdio.h>
#include "scene_values.h"
#include "source_revision.h"

void scene_summary_overrides(out_json *json, const scene_file *file)
{
    char value[SCENE_TEXT + 32];
    char name[2 * SCENE_NAME];
    int i;

    out_json_open(json, "set");
    for (i = 0; scene_fields[i].key; ++i) {
        const field_spec *f = &scene_fields[i];
        if (file->set_file[i] != SCENE_BY_OPTION)
            continue;
        snprintf(name, sizeof name, "%s.%s", f->section, f->key);
        scene_value_text(&file->params, f, value, sizeof value);
        if (f->kind == FIELD_REAL || f->kind == FIELD_INT)
            out_json_number_text(json, name, value);
        else
            out_json_text(json, name, value);
    }
    out_json_close(json);
}

void scene_summary_hashes(out_json *json, const scene_file *file, const bs_scene *scene)
{
    char text[24];
    snprintf(text, sizeof text, "%08x", (unsigned)bs_scene_hash(scene));
    out_json_text(json, "scene_hash", text);
    snprintf(text, sizeof text, "%016llx", (unsigned long long)scene_values_hash(&file->params, NULL));
    out_json_text(json, "fields_hash", text);
}

void scene_summary_provenance(out_json *json)
{
    out_json_text(json, "version", bs_version());
    out_json_text(json, "revision", source_revision());
}
