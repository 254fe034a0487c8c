/* run_summary.c - the JSON summaries of run and sweep (run_summary.h). */
#include "run_summary.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "out_json.h"
#include "scene_summary.h"

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
    scene_summary_overrides(&s, file);
    scene_summary_hashes(&s, file, scene);
    scene_summary_provenance(&s);
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
    scene_summary_overrides(&s, file);
    scene_summary_hashes(&s, file, scene);
    scene_summary_provenance(&s);
    return out_json_finish(&s, out);
}
