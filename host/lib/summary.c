/* summary.c - the JSON summaries of run, sweep, map and map-merge (summary.h). */
#include "summary.h"

#include "bs_revision.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "out_json.h"
#include "scene_values.h"

/* The contact-solve figures both summaries end with: sweeps ("pgs_iters")
 * and active-set systems per contact step, most and mean. */
static void add_contact_figures(out_json *s, const solve_tally *solve)
{
    out_json_int(s, "max_pgs_iters", solve->max_sweeps);
    out_json_count(s, "unconverged_steps", solve->unconverged_steps);
    out_json_count(s, "contact_steps", solve->contact_steps);
    out_json_number(s, "mean_pgs_iters", "%.4g", solve_tally_mean_sweeps(solve));
    out_json_int(s, "max_systems", solve->max_systems);
    out_json_number(s, "mean_systems", "%.4g", solve_tally_mean_systems(solve));
}

/* The fields the command line set (--set, --s0, ...) as "section.key":
 * value, numbers as numbers, so that the line says what it is about
 * without the command that made it. */
static void add_overrides(out_json *s, const scene_file *file)
{
    char value[SCENE_TEXT + 32];
    char name[2 * SCENE_NAME];
    int i;

    out_json_open(s, "set");
    for (i = 0; scene_fields[i].key; ++i) {
        const field_spec *f = &scene_fields[i];
        if (file->set_file[i] != SCENE_BY_OPTION)
            continue;
        snprintf(name, sizeof name, "%s.%s", f->section, f->key);
        scene_value_text(&file->params, f, value, sizeof value);
        if (f->kind == FIELD_REAL || f->kind == FIELD_INT)
            out_json_number_text(s, name, value);
        else
            out_json_text(s, name, value);
    }
    out_json_close(s);
}

/* Which scene exactly: the core's hash of the scene it ran (bs_scene_hash)
 * and the host's of every resolved field (scene_values_hash). */
static void add_scene_hashes(out_json *s, const scene_file *file, const bs_scene *scene)
{
    char text[24];
    snprintf(text, sizeof text, "%08x", (unsigned)bs_scene_hash(scene));
    out_json_text(s, "scene_hash", text);
    snprintf(text, sizeof text, "%016llx", (unsigned long long)scene_values_hash(&file->params, NULL));
    out_json_text(s, "fields_hash", text);
}

/* What produced the numbers: the library's version and the source revision
 * (git describe at build time; "unknown" outside a git checkout). */
static void add_provenance(out_json *s)
{
    out_json_text(s, "version", bs_version());
    out_json_text(s, "revision", BS_REVISION);
}

/* Where the base acceleration came from: "harmonic" (the scene's),
 * "schedule" ([excitation] schedule) or "file", with the record's name,
 * format, rate, samples and the latency it was read with. */
static void add_excitation(out_json *s, const scene_params *p, const excitation_file *record)
{
    if (!record) {
        out_json_text(s, "excitation", p->schedule[strspn(p->schedule, " \t")] ? "schedule" : "harmonic");
        return;
    }
    out_json_text(s, "excitation", "file");
    out_json_text(s, "excitation_file", record->path);
    out_json_text(s, "excitation_format", record->format);
    out_json_number(s, "excitation_rate", "%.9g", record->rate);
    out_json_count(s, "excitation_samples", (unsigned long long)record->samples);
    out_json_number(s, "excitation_latency", "%.9g", record->latency);
}

/* What the transducer's load received (only for a scene with one). */
static void add_harvest(out_json *s, const run_result *r)
{
    if (!r->transducer)
        return;
    out_json_number(s, "energy_j", "%.6g", r->energy);
    out_json_number(s, "power_mean_w", "%.6g", r->power_mean);
    out_json_number(s, "power_last_w", "%.6g", r->power_last);
    out_json_number(s, "power_window_s", "%.9g", r->power_window);
}

int summary_print_run(FILE *out, const scene_file *file, const bs_scene *scene, const excitation_file *record,
                      const run_result *r)
{
    const scene_params *p = &file->params;
    out_json s;
    char hash[16];

    out_json_start(&s);
    out_json_text(&s, "scene", p->name);
    out_json_text(&s, "model", p->model == BS_MODEL_PCS ? "pcs" : "free");
    out_json_text(&s, "precision", BS_REAL_NAME);
    out_json_int(&s, "modes", scene->n_modes);
    out_json_number(&s, "dt", "%g", p->dt);
    add_excitation(&s, p, record);
    out_json_text(&s, "status", r->write_failed ? "write error" : bs_status_text(r->status));
    out_json_number(&s, "t_end", "%.9g", r->t);
    out_json_count(&s, "steps", (unsigned long long)r->steps);
    out_json_number(&s, "s0", "%.9g", p->s0);
    out_json_number(&s, "s_final", "%.9g", r->s_final);
    out_json_number(&s, "s_min", "%.9g", r->s_min);
    out_json_number(&s, "t_s_min", "%.6f", r->t_s_min);
    out_json_number(&s, "amp_final_h", "%.6g", r->amp_final_h);
    out_json_int(&s, "amp_periods", r->amp_periods);
    add_harvest(&s, r);
    out_json_number(&s, "wall_s", "%.4g", r->wall_s);
    out_json_number(&s, "steps_per_s", "%.4g", r->wall_s > 0.0 ? (double)r->steps / r->wall_s : 0.0);
    add_contact_figures(&s, &r->solve);
    snprintf(hash, sizeof hash, "%08x", (unsigned)r->hash);
    out_json_text(&s, "hash", hash);
    add_overrides(&s, file);
    add_scene_hashes(&s, file, scene);
    add_provenance(&s);
    return out_json_finish(&s, out);
}

int summary_print_sweep(FILE *out, const scene_file *file, const bs_scene *scene, const sweep_options *o,
                        const sweep_result *r)
{
    const scene_params *p = &file->params;
    out_json s;

    out_json_start(&s);
    out_json_text(&s, "scene", p->name);
    out_json_text(&s, "command", "sweep");
    out_json_text(&s, "dir", o->down ? "down" : "up");
    out_json_text(&s, "precision", BS_REAL_NAME);
    out_json_int(&s, "modes", scene->n_modes);
    out_json_number(&s, "dt", "%g", p->dt);
    out_json_text(&s, "status", r->write_failed ? "write error" : bs_status_text(r->status));
    out_json_number(&s, "from", "%.9g", o->from);
    out_json_number(&s, "to", "%.9g", o->to);
    out_json_number(&s, "step", "%.9g", o->step);
    out_json_int(&s, "hold", o->hold);
    out_json_int(&s, "record", o->record);
    out_json_int(&s, "points", r->points_done);
    out_json_count(&s, "steps", (unsigned long long)r->steps);
    out_json_number(&s, "wall_s", "%.4g", r->wall_s);
    out_json_number(&s, "steps_per_s", "%.4g", r->wall_s > 0.0 ? (double)r->steps / r->wall_s : 0.0);
    add_contact_figures(&s, &r->solve);
    add_overrides(&s, file);
    add_scene_hashes(&s, file, scene);
    add_provenance(&s);
    return out_json_finish(&s, out);
}

int summary_print_map(FILE *out, const scene_file *file, const summary_map *m)
{
    out_json s;
    char shard[32];
    int v;

    out_json_start(&s);
    out_json_text(&s, "scene", file->params.name);
    add_overrides(&s, file);
    out_json_text(&s, "command", "map");
    out_json_text(&s, "precision", BS_REAL_NAME);
    out_json_open(&s, "vary");
    for (v = 0; v < m->grid->vary_count; ++v)
        out_json_int(&s, m->grid->vary[v].name, m->grid->vary[v].count);
    out_json_close(&s);
    out_json_count(&s, "points", (unsigned long long)m->grid->points);
    out_json_int(&s, "repeat", m->grid->repeat);
    out_json_count(&s, "cases", (unsigned long long)m->grid->cases);
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
    add_provenance(&s);
    return out_json_finish(&s, out);
}

int summary_print_merge(FILE *out, const char *scene, const summary_map *m)
{
    out_json s;
    int v;

    out_json_start(&s);
    out_json_text(&s, "scene", scene);
    out_json_text(&s, "command", "map-merge");
    out_json_open(&s, "vary");
    for (v = 0; v < m->grid->vary_count; ++v)
        out_json_int(&s, m->grid->vary[v].name, m->grid->vary[v].count);
    out_json_close(&s);
    out_json_count(&s, "points", (unsigned long long)m->grid->points);
    out_json_int(&s, "repeat", m->grid->repeat);
    out_json_count(&s, "cases", (unsigned long long)m->grid->cases);
    out_json_count(&s, "done", (unsigned long long)m->done_total);
    out_json_count(&s, "torn_lines", (unsigned long long)m->torn);
    out_json_count(&s, "invalid_lines", (unsigned long long)m->invalid);
    out_json_bool(&s, "complete", m->complete);
    out_json_text(&s, "out", m->dir);
    add_provenance(&s);
    return out_json_finish(&s, out);
}
