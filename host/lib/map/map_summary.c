/* map_summary.c - the JSON summaries of map and map-merge (map_summary.h). */
#include "map_summary.h"

#include <stdio.h>
#include "out_json.h"
#include "scene_summary.h"

/* The grid both summaries share: the points of each varied parameter, the
 * points, the repeats and the cases. */
static void print_grid(out_json *s, const summary_map *m)
{
    int v;
    out_json_open(s, "vary");
    for (v = 0; v < m->grid->vary_count; ++v)
        out_json_int(s, m->grid->vary[v].name, m->grid->vary[v].count);
    out_json_close(s);
    out_json_count(s, "points", (unsigned long long)m->grid->points);
    out_json_int(s, "repeat", m->grid->repeat);
    out_json_count(s, "cases", (unsigned long long)m->grid->cases);
}

int summary_print_map(FILE *out, const scene_file *file, const summary_map *m)
{
    out_json s;
    char shard[32];

    out_json_start(&s);
    out_json_text(&s, "scene", file->params.name);
    scene_summary_overrides(&s, file);
    out_json_text(&s, "command", "map");
    out_json_text(&s, "precision", BS_REAL_NAME);
    print_grid(&s, m);
    snprintf(shard, sizeof shard, "%d/%d", m->shard_index, m->shard_count);
    out_json_text(&s, "shard", shard);
    out_json_count(&s, "shard_cases", (unsigned long long)m->shard_cases);
    out_json_count(&s, "skipped", (unsigned long long)m->skipped);
    out_json_count(&s, "run", (unsigned long long)m->run);
    out_json_int(&s, "jobs", m->jobs);
    out_json_count(&s, "done", (unsigned long long)m->done_total);
    out_json_count(&s, "torn_lines", (unsigned long long)m->torn);
    out_json_count(&s, "invalid_lines", (unsigned long long)m->invalid);
    out_json_bool(&s, "complete", m->complete);
    out_json_text(&s, "out", m->dir);
    out_json_number(&s, "wall_s", "%.4g", m->wall_s);
    out_json_number(&s, "cases_per_s", "%.4g", m->wall_s > 0.0 ? (double)m->run / m->wall_s : 0.0);
    snprintf(shard, sizeof shard, "%016llx", m->fields_hash);
    out_json_text(&s, "fields_hash", shard);
    scene_summary_provenance(&s);
    return out_json_finish(&s, out);
}

int summary_print_merge(FILE *out, const char *scene, const summary_map *m)
{
    out_json s;

    out_json_start(&s);
    out_json_text(&s, "scene", scene);
    out_json_text(&s, "command", "map-merge");
    print_grid(&s, m);
    out_json_count(&s, "done", (unsigned long long)m->done_total);
    out_json_count(&s, "torn_lines", (unsigned long long)m->torn);
    out_json_count(&s, "invalid_lines", (unsigned long long)m->invalid);
    out_json_bool(&s, "complete", m->complete);
    out_json_text(&s, "out", m->dir);
    scene_summary_provenance(&s);
    return out_json_finish(&s, out);
}
