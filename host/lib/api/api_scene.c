/* api_scene.c - libbeamslider-host: scenes, errors, the modal data
 * (host/include/beamslider_host.h). */
#include "api_scene.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "attached.h"
#include "run.h"
#include "scene_values.h"

bs_host_status api_error(bs_host_error *error, bs_host_status status, const char *format, ...)
{
    va_list args;
    if (!error)
        return status;
    error->status = status;
    va_start(args, format);
    vsnprintf(error->text, sizeof error->text, format, args);
    va_end(args);
    return status;
}

bs_host_status api_ok(bs_host_error *error)
{
    if (error) {
        error->status = BS_HOST_OK;
        error->text[0] = '\0';
    }
    return BS_HOST_OK;
}

const char *bs_host_status_text(bs_host_status status)
{
    switch (status) {
    case BS_HOST_OK: return "ok";
    case BS_HOST_E_INPUT: return "bad input";
    case BS_HOST_E_FAILED: return "the work failed";
    case BS_HOST_E_MEMORY: return "out of memory";
    case BS_HOST_E_BUILD: return "program and library built with different configurations (precision, sizes, "
                                 "switches or version)";
    case BS_HOST_E_NULL: return "null pointer";
    }
    return "unknown status";
}

/* Reads (text NULL: the file at path), applies the overrides, builds. */
static bs_host_status load(uint32_t tag, size_t sim_size, size_t scene_size, const char *path, const char *text,
                           const char *const *overrides, int count, bs_host_scene **out, bs_host_error *error)
{
    char err[BS_HOST_ERROR_TEXT];
    bs_host_scene *s;
    int i;

    if (out)
        *out = NULL;
    if (!path || !out || (count > 0 && !overrides))
        return api_error(error, BS_HOST_E_NULL, "a NULL path, scene or overrides");
    if (bs_build_check_(tag, sim_size, scene_size) != BS_OK)
        return api_error(error, BS_HOST_E_BUILD, "this program was compiled against the %s headers of beamslider "
                         "or another build than libbeamslider-host (%s, %s): %s", (tag & 1u) ? "float" : "double",
                         BS_REAL_NAME, bs_version(), bs_status_text(BS_E_BUILD));
    if (!(s = malloc(sizeof *s)))
        return api_error(error, BS_HOST_E_MEMORY, "out of memory for a scene");
    if ((text ? scene_load_text(path, text, &s->file, err, sizeof err) : scene_load(path, &s->file, err, sizeof err))
        != 0) {
        free(s);
        return api_error(error, BS_HOST_E_INPUT, "%s", err);
    }
    for (i = 0; i < count; ++i)
        if (!overrides[i] || scene_set_assignment(&s->file, "--set", overrides[i], err, sizeof err) != 0) {
            free(s);
            return api_error(error, BS_HOST_E_INPUT, "%s", overrides[i] ? err : "override NULL");
        }
    if (scene_build(&s->file, &s->scene, &s->model, err, sizeof err) != 0) {
        free(s);
        return api_error(error, BS_HOST_E_INPUT, "%s", err);
    }
    *out = s;
    return api_ok(error);
}

bs_host_status bs_host_scene_load_(uint32_t tag, size_t sim_size, size_t scene_size, const char *path,
                                   const char *const *overrides, int count, bs_host_scene **scene,
                                   bs_host_error *error)
{
    return load(tag, sim_size, scene_size, path, NULL, overrides, count, scene, error);
}

bs_host_status bs_host_scene_parse_(uint32_t tag, size_t sim_size, size_t scene_size, const char *name,
                                    const char *text, const char *const *overrides, int count,
                                    bs_host_scene **scene, bs_host_error *error)
{
    if (!text) {
        if (scene)
            *scene = NULL;
        return api_error(error, BS_HOST_E_NULL, "a NULL scene text");
    }
    return load(tag, sim_size, scene_size, name, text, overrides, count, scene, error);
}

bs_host_status bs_host_scene_set(bs_host_scene *scene, const char *override, bs_host_error *error)
{
    char err[BS_HOST_ERROR_TEXT];
    bs_host_scene *next;

    if (!scene || !override)
        return api_error(error, BS_HOST_E_NULL, "a NULL scene or override");
    if (!(next = malloc(sizeof *next)))
        return api_error(error, BS_HOST_E_MEMORY, "out of memory for a scene");
    next->file = scene->file;
    if (scene_set_assignment(&next->file, "--set", override, err, sizeof err) != 0
        || scene_build(&next->file, &next->scene, &next->model, err, sizeof err) != 0) {
        free(next);
        return api_error(error, BS_HOST_E_INPUT, "%s", err);
    }
    *scene = *next; /* the scene is replaced whole, or not at all */
    free(next);
    return api_ok(error);
}

void bs_host_scene_free(bs_host_scene *scene)
{
    free(scene);
}

const bs_scene *bs_host_scene_core(const bs_host_scene *scene)
{
    return scene ? &scene->scene : NULL;
}

void bs_host_scene_setup(const bs_host_scene *scene, bs_host_setup *setup)
{
    const scene_params *p = &scene->file.params;
    setup->name = p->name;
    setup->model = (bs_model)p->model;
    setup->s0 = p->s0;
    setup->t_end = p->t_end;
    setup->dt = p->dt;
    setup->steps = run_step_count(p->t_end, p->dt);
    setup->frequency = p->frequency;
    setup->acceleration = p->acceleration;
    setup->has_schedule = p->schedule[strspn(p->schedule, " \t")] != '\0';
    setup->solver = scene_solver(p);
}

bs_host_status bs_host_scene_value(const bs_host_scene *scene, const char *field, char *out, size_t size,
                                   bs_host_error *error)
{
    int i;
    if (!scene || !field || !out)
        return api_error(error, BS_HOST_E_NULL, "a NULL scene, field or text");
    i = scene_field_named(field, strlen(field), NULL, NULL);
    if (i < 0)
        return api_error(error, BS_HOST_E_INPUT, "%s: no such field (section.key; beamslider fields lists every "
                         "field)", field);
    scene_value_text(&scene->file.params, &scene_fields[i], out, size);
    return api_ok(error);
}

void bs_host_scene_modes(const bs_host_scene *scene, bs_host_modes *modes)
{
    const modal_set *m = &scene->model.modes;
    int k;
    memset(modes, 0, sizeof *modes);
    modes->n = m->n;
    for (k = 0; k < m->n; ++k) {
        double phi, slope;
        modal_shape(m, k, 4.0 / 7.0, &phi, &slope);
        modes->frequency[k] = m->omega[k] / (2.0 * 3.14159265358979323846);
        modes->lambda[k] = m->lambda[k];
        modes->gamma[k] = m->gamma[k];
        modes->phi_sensor[k] = phi;
    }
    modes->kappa = scene->model.kappa;
    modes->width = scene->model.width;
    modes->k_axial = m->k_axial_total;
    modes->shape_pieces = scene->model.fit.pieces;
    modes->fit_error_phi = scene->model.fit.error_phi;
    modes->fit_error_slope = scene->model.fit.error_slope;
}

double bs_host_attached_frequency(const bs_host_scene *scene, double s)
{
    return attached_frequency(&scene->model.modes, &scene->file.params, s);
}

double bs_host_attached_position(const bs_host_scene *scene, double frequency)
{
    return attached_position(&scene->model.modes, &scene->file.params, frequency);
}
