/* summary.c - the JSON summaries of run and sweep (summary.h). */
#include "summary.h"

#include <cjson/cJSON.h>
#include "bs_revision.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "scene_values.h"

/* A summary being built; failed: some part could not be added. */
typedef struct summary {
    cJSON *root;
    int failed;
} summary;

static void add_text(summary *s, const char *key, const char *text)
{
    if (!cJSON_AddStringToObject(s->root, key, text))
        s->failed = 1;
}

/* value as format prints it (a %f of 1e300 is 300 digits long). */
static void add_number(summary *s, const char *key, const char *format, double value)
{
    char text[400];
    if (!isfinite(value)) {
        if (!cJSON_AddNullToObject(s->root, key))
            s->failed = 1;
        return;
    }
    snprintf(text, sizeof text, format, value);
    if (!cJSON_AddRawToObject(s->root, key, text))
        s->failed = 1;
}

static void add_int(summary *s, const char *key, long long value)
{
    char text[32];
    snprintf(text, sizeof text, "%lld", value);
    if (!cJSON_AddRawToObject(s->root, key, text))
        s->failed = 1;
}

static void add_count(summary *s, const char *key, unsigned long long value)
{
    char text[32];
    snprintf(text, sizeof text, "%llu", value);
    if (!cJSON_AddRawToObject(s->root, key, text))
        s->failed = 1;
}

/* The contact-solve figures both summaries end with: sweeps ("pgs_iters")
 * and active-set systems per contact step, most and mean. */
static void add_contact_figures(summary *s, const solve_tally *solve)
{
    add_int(s, "max_pgs_iters", solve->max_sweeps);
    add_count(s, "unconverged_steps", solve->unconverged_steps);
    add_count(s, "contact_steps", solve->contact_steps);
    add_number(s, "mean_pgs_iters", "%.4g", solve_tally_mean_sweeps(solve));
    add_int(s, "max_systems", solve->max_systems);
    add_number(s, "mean_systems", "%.4g", solve_tally_mean_systems(solve));
}

/* The fields the command line set (--set, --s0, ...) as "section.key":
 * value, numbers as numbers, so that the line says what it is about
 * without the command that made it. */
static void add_overrides(summary *s, const scene_file *file)
{
    cJSON *set = cJSON_AddObjectToObject(s->root, "set");
    char value[SCENE_TEXT + 32];
    char name[2 * SCENE_NAME];
    int i;

    if (!set) {
        s->failed = 1;
        return;
    }
    for (i = 0; scene_fields[i].key; ++i) {
        const field_spec *f = &scene_fields[i];
        if (file->set_file[i] != SCENE_BY_OPTION)
            continue;
        snprintf(name, sizeof name, "%s.%s", f->section, f->key);
        scene_value_text(&file->params, f, value, sizeof value);
        if (!(f->kind == FIELD_REAL || f->kind == FIELD_INT ? cJSON_AddRawToObject(set, name, value)
                                                             : cJSON_AddStringToObject(set, name, value)))
            s->failed = 1;
    }
}

/* Which scene exactly: the core's hash of the scene it ran (bs_scene_hash)
 * and the host's of every resolved field (scene_values_hash). */
static void add_scene_hashes(summary *s, const scene_file *file, const bs_scene *scene)
{
    char text[24];
    snprintf(text, sizeof text, "%08x", (unsigned)bs_scene_hash(scene));
    add_text(s, "scene_hash", text);
    snprintf(text, sizeof text, "%016llx", (unsigned long long)scene_values_hash(&file->params, NULL));
    add_text(s, "fields_hash", text);
}

/* What produced the numbers: the library's version and the source revision
 * (git describe at build time; "unknown" outside a git checkout). */
static void add_provenance(summary *s)
{
    add_text(s, "version", bs_version());
    add_text(s, "revision", BS_REVISION);
}

/* Prints the summary as one line and frees it; 0 or -1. */
static int finish(summary *s, FILE *out)
{
    char *line = s->failed ? NULL : cJSON_PrintUnformatted(s->root);
    int status = -1;

    if (line) {
        status = fputs(line, out) >= 0 && fputc('\n', out) == '\n' ? 0 : -1;
        cJSON_free(line);
    }
    cJSON_Delete(s->root);
    return status;
}

/* Where the base acceleration came from: "harmonic" (the scene's),
 * "schedule" ([excitation] schedule) or "file", with the record's name,
 * format, rate, samples and the latency it was read with. */
static void add_excitation(summary *s, const scene_params *p, const excitation_file *record)
{
    if (!record) {
        add_text(s, "excitation", p->schedule[strspn(p->schedule, " \t")] ? "schedule" : "harmonic");
        return;
    }
    add_text(s, "excitation", "file");
    add_text(s, "excitation_file", record->path);
    add_text(s, "excitation_format", record->format);
    add_number(s, "excitation_rate", "%.9g", record->rate);
    add_count(s, "excitation_samples", (unsigned long long)record->samples);
    add_number(s, "excitation_latency", "%.9g", record->latency);
}

/* What the transducer's load received (only for a scene with one). */
static void add_harvest(summary *s, const run_result *r)
{
    if (!r->transducer)
        return;
    add_number(s, "energy_j", "%.6g", r->energy);
    add_number(s, "power_mean_w", "%.6g", r->power_mean);
    add_number(s, "power_last_w", "%.6g", r->power_last);
    add_number(s, "power_window_s", "%.9g", r->power_window);
}

int summary_print_run(FILE *out, const scene_file *file, const bs_scene *scene, const excitation_file *record,
                      const run_result *r)
{
    const scene_params *p = &file->params;
    summary s;
    char hash[16];

    s.root = cJSON_CreateObject();
    s.failed = s.root == NULL;
    add_text(&s, "scene", p->name);
    add_text(&s, "model", p->model == BS_MODEL_PCS ? "pcs" : "free");
    add_text(&s, "precision", BS_REAL_NAME);
    add_int(&s, "modes", scene->n_modes);
    add_number(&s, "dt", "%g", p->dt);
    add_excitation(&s, p, record);
    add_text(&s, "status", r->write_failed ? "write error" : bs_status_text(r->status));
    add_number(&s, "t_end", "%.9g", r->t);
    add_count(&s, "steps", (unsigned long long)r->steps);
    add_number(&s, "s0", "%.9g", p->s0);
    add_number(&s, "s_final", "%.9g", r->s_final);
    add_number(&s, "s_min", "%.9g", r->s_min);
    add_number(&s, "t_s_min", "%.6f", r->t_s_min);
    add_number(&s, "amp_final_h", "%.6g", r->amp_final_h);
    add_int(&s, "amp_periods", r->amp_periods);
    add_harvest(&s, r);
    add_number(&s, "wall_s", "%.4g", r->wall_s);
    add_number(&s, "steps_per_s", "%.4g", r->wall_s > 0.0 ? (double)r->steps / r->wall_s : 0.0);
    add_contact_figures(&s, &r->solve);
    snprintf(hash, sizeof hash, "%08x", (unsigned)r->hash);
    add_text(&s, "hash", hash);
    add_overrides(&s, file);
    add_scene_hashes(&s, file, scene);
    add_provenance(&s);
    return finish(&s, out);
}

int summary_print_sweep(FILE *out, const scene_file *file, const bs_scene *scene, const sweep_options *o,
                        const sweep_result *r)
{
    const scene_params *p = &file->params;
    summary s;

    s.root = cJSON_CreateObject();
    s.failed = s.root == NULL;
    add_text(&s, "scene", p->name);
    add_text(&s, "command", "sweep");
    add_text(&s, "dir", o->down ? "down" : "up");
    add_text(&s, "precision", BS_REAL_NAME);
    add_int(&s, "modes", scene->n_modes);
    add_number(&s, "dt", "%g", p->dt);
    add_text(&s, "status", r->write_failed ? "write error" : bs_status_text(r->status));
    add_number(&s, "from", "%.9g", o->from);
    add_number(&s, "to", "%.9g", o->to);
    add_number(&s, "step", "%.9g", o->step);
    add_int(&s, "hold", o->hold);
    add_int(&s, "record", o->record);
    add_int(&s, "points", r->points_done);
    add_count(&s, "steps", (unsigned long long)r->steps);
    add_number(&s, "wall_s", "%.4g", r->wall_s);
    add_number(&s, "steps_per_s", "%.4g", r->wall_s > 0.0 ? (double)r->steps / r->wall_s : 0.0);
    add_contact_figures(&s, &r->solve);
    add_overrides(&s, file);
    add_scene_hashes(&s, file, scene);
    add_provenance(&s);
    return finish(&s, out);
}

int summary_print_map(FILE *out, const scene_file *file, const summary_map *m)
{
    summary s;
    cJSON *vary;
    char shard[32];
    int v;

    s.root = cJSON_CreateObject();
    s.failed = s.root == NULL;
    add_text(&s, "scene", file->params.name);
    add_overrides(&s, file);
    add_text(&s, "command", "map");
    add_text(&s, "precision", BS_REAL_NAME);
    vary = s.failed ? NULL : cJSON_AddObjectToObject(s.root, "vary");
    if (!vary)
        s.failed = 1;
    for (v = 0; vary && v < m->grid->vary_count; ++v) {
        char count[16];
        snprintf(count, sizeof count, "%d", m->grid->vary[v].count);
        if (!cJSON_AddRawToObject(vary, m->grid->vary[v].name, count))
            s.failed = 1;
    }
    add_count(&s, "points", (unsigned long long)m->grid->points);
    add_int(&s, "repeat", m->grid->repeat);
    add_count(&s, "cases", (unsigned long long)m->grid->cases);
    snprintf(shard, sizeof shard, "%d/%d", m->shard_index, m->shard_count);
    add_text(&s, "shard", shard);
    add_count(&s, "shard_cases", (unsigned long long)m->shard_cases);
    add_count(&s, "skipped", (unsigned long long)m->skipped);
    add_count(&s, "run", (unsigned long long)m->run);
    add_int(&s, "jobs", m->jobs);
    add_count(&s, "done", (unsigned long long)m->done_total);
    add_count(&s, "torn_lines", (unsigned long long)m->torn);
    add_count(&s, "invalid_lines", (unsigned long long)m->invalid);
    if (!s.failed && !cJSON_AddBoolToObject(s.root, "complete", m->complete))
        s.failed = 1;
    add_text(&s, "out", m->dir);
    add_number(&s, "wall_s", "%.4g", m->wall_s);
    add_number(&s, "cases_per_s", "%.4g", m->wall_s > 0.0 ? (double)m->run / m->wall_s : 0.0);
    snprintf(shard, sizeof shard, "%016llx", m->fields_hash);
    add_text(&s, "fields_hash", shard);
    add_provenance(&s);
    return finish(&s, out);
}
