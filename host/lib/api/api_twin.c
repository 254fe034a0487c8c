/* api_twin.c - libbeamslider-host: the twin's design and the measured-
 * signals format (host/include/beamslider_host.h), through the twin wing:
 * observer_design, the one reader and the one writer of measured_signals. */
#include "api_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "measured_signals.h"
#include "observer_design.h"
#include "out_c.h"
#include "twin_plant.h"

void bs_host_twin_defaults(bs_host_twin_options *options, double noise)
{
    const observer_design_options d = observer_design_defaults(noise);
    memset(options, 0, sizeof *options);
    options->signal = d.signal;
    options->noise = d.noise;
    options->force_noise = d.force_noise;
    options->accel_noise = d.accel_noise;
    options->latency = 0.0;
}

bs_host_status bs_host_twin_design_(uint32_t observer_tag, size_t gains_size, const bs_host_scene *scene,
                                    const bs_host_twin_options *options, bs_observer_gains *gains,
                                    bs_host_error *error)
{
    observer_design_options o;
    char err[BS_HOST_ERROR_TEXT];
    long latency;

    if (!scene || !options || !gains)
        return api_error(error, BS_HOST_E_NULL, "a NULL scene, options or gains");
    if (observer_tag != BS_OBSERVER_TAG || gains_size != sizeof(bs_observer_gains))
        return api_error(error, BS_HOST_E_BUILD, "this program's bs_observer_gains (BS_OBSERVER_MAPS %u, latency "
                         "%u) is not the library's (%d, %d)", (unsigned)(observer_tag >> 16),
                         (unsigned)(observer_tag & 0xffffu), BS_OBSERVER_MAPS, BS_OBSERVER_MAX_LATENCY);
    latency = twin_latency_steps(options->latency, scene->file.params.dt);
    if (!(options->latency >= 0.0) || latency > BS_OBSERVER_MAX_LATENCY)
        return api_error(error, BS_HOST_E_INPUT, "latency %g s: allowed: 0 to %d steps (%g s)", options->latency,
                         BS_OBSERVER_MAX_LATENCY, BS_OBSERVER_MAX_LATENCY * scene->file.params.dt);
    o = observer_design_defaults(options->noise);
    o.signal = options->signal;
    o.force_noise = options->force_noise;
    o.accel_noise = options->accel_noise;
    o.latency = (int)latency;
    o.map_count = options->map_count;
    memcpy(o.map_frequency, options->map_frequency, sizeof o.map_frequency);
    o.friction_count = options->friction_count;
    memcpy(o.map_friction, options->map_friction, sizeof o.map_friction);
    o.progress = options->progress;
    o.progress_context = options->progress_context;
    if (observer_design(&scene->file, &scene->model, &scene->scene, &o, gains, err, sizeof err) != 0)
        return api_error(error, strstr(err, "stopped") ? BS_HOST_E_FAILED : BS_HOST_E_INPUT, "%s", err);
    return api_ok(error);
}

bs_host_status bs_host_twin_header(FILE *out, const bs_observer_gains *gains, const char *name, const char *comment,
                                   bs_host_error *error)
{
    char why[512];
    if (!out || !gains || !name)
        return api_error(error, BS_HOST_E_NULL, "a NULL file, gains or name");
    if (out_c_identifier_check(name, "name", why, sizeof why) != 0)
        return api_error(error, BS_HOST_E_INPUT, "%s", why);
    if (observer_print_gains(out, gains, name, comment ? comment : "") != 0)
        return api_error(error, BS_HOST_E_FAILED, "the header could not be written (a write error, or a gain that "
                         "is not finite)");
    return api_ok(error);
}

struct bs_host_measured {
    measured_reader reader;
};

static void header_out(const measured_header *h, bs_host_measured_header *out)
{
    out->rate = h->rate;
    out->signal = h->signal == MEASURED_VOLTAGE ? BS_HOST_VOLTAGE : BS_HOST_DEFLECTION;
    out->noise = h->noise;
    out->accel_noise = h->accel_noise;
    out->latency = h->latency;
    out->has_truth = h->has_truth;
}

bs_host_status bs_host_measured_open(const char *path, bs_host_measured **reader, bs_host_measured_header *header,
                                     bs_host_error *error)
{
    char err[BS_HOST_ERROR_TEXT];
    bs_host_measured *m;
    if (reader)
        *reader = NULL;
    if (!path || !reader)
        return api_error(error, BS_HOST_E_NULL, "a NULL path or reader");
    if (!(m = malloc(sizeof *m)))
        return api_error(error, BS_HOST_E_MEMORY, "out of memory for a reader");
    if (measured_open(&m->reader, path, err, sizeof err) != 0) {
        free(m);
        return api_error(error, BS_HOST_E_INPUT, "%s", err);
    }
    if (header)
        header_out(&m->reader.header, header);
    *reader = m;
    return api_ok(error);
}

int bs_host_measured_next(bs_host_measured *reader, bs_host_measured_row *row, bs_host_error *error)
{
    char err[BS_HOST_ERROR_TEXT];
    measured_row r;
    int status;
    if (!reader || !row) {
        api_error(error, BS_HOST_E_NULL, "a NULL reader or row");
        return -1;
    }
    status = measured_next(&reader->reader, &r, err, sizeof err);
    if (status < 0) {
        api_error(error, BS_HOST_E_INPUT, "%s", err);
        return -1;
    }
    api_ok(error);
    if (status > 0) {
        row->t = r.t;
        row->base_accel = r.base_accel;
        row->signal = r.signal;
        row->s_true = r.s_true;
    }
    return status;
}

void bs_host_measured_close(bs_host_measured *reader)
{
    if (!reader)
        return;
    measured_close(&reader->reader);
    free(reader);
}

bs_host_status bs_host_measured_write_header(FILE *out, const bs_host_measured_header *header, const char *plant)
{
    measured_header h;
    if (!out || !header)
        return BS_HOST_E_NULL;
    h.rate = header->rate;
    h.signal = header->signal == BS_HOST_VOLTAGE ? MEASURED_VOLTAGE : MEASURED_DEFLECTION;
    h.noise = header->noise;
    h.accel_noise = header->accel_noise;
    h.latency = header->latency;
    h.has_truth = header->has_truth;
    return measured_write_header(out, &h, plant) == 0 ? BS_HOST_OK : BS_HOST_E_FAILED;
}

bs_host_status bs_host_measured_write_row(FILE *out, const bs_host_measured_row *row, int has_truth)
{
    measured_row r;
    if (!out || !row)
        return BS_HOST_E_NULL;
    r.t = row->t;
    r.base_accel = row->base_accel;
    r.signal = row->signal;
    r.s_true = row->s_true;
    return measured_write_row(out, &r, has_truth) == 0 ? BS_HOST_OK : BS_HOST_E_FAILED;
}
