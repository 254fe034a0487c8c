/* api_map.c - libbeamslider-host: a map of a scene (host/include/
 * beamslider_host.h), through the map wing's map_run: `beamslider map`'s
 * work, on worker threads of the calling process. */
#include "api_scene.h"

#include <string.h>
#include "map_run.h"

void bs_host_map_defaults(bs_host_map_options *options)
{
    memset(options, 0, sizeof *options);
    options->repeat = 1;
    options->jobs = 1;
    options->shard_index = options->shard_count = 1;
}

static bs_host_status status_of(int map_status)
{
    return map_status == MAP_DONE ? BS_HOST_OK : map_status == MAP_E_INPUT ? BS_HOST_E_INPUT : BS_HOST_E_FAILED;
}

bs_host_status bs_host_map(const bs_host_scene *scene, const bs_host_map_options *options,
                           bs_host_map_result *result, bs_host_error *error)
{
    char err[BS_HOST_ERROR_TEXT];
    map_run_options o;
    map_grid grid;
    summary_map m;
    int status;

    if (!scene || !options || !result || !options->dir || (options->vary_count > 0 && !options->vary))
        return api_error(error, BS_HOST_E_NULL, "a NULL scene, options, result, folder or vary");
    memset(result, 0, sizeof *result);
    if (options->vary_count < 0 || options->vary_count > MAP_MAX_VARY)
        return api_error(error, BS_HOST_E_INPUT, "%d varied fields: allowed: 0 to %d", options->vary_count,
                         MAP_MAX_VARY);
    if (options->jobs < 1 || options->jobs > 1024)
        return api_error(error, BS_HOST_E_INPUT, "jobs %d: allowed: an integer in [1, 1024]", options->jobs);
    if (options->shard_count < 1 || options->shard_index < 1 || options->shard_index > options->shard_count)
        return api_error(error, BS_HOST_E_INPUT, "shard %d/%d: allowed: 1 <= I <= N", options->shard_index,
                         options->shard_count);
    memset(&o, 0, sizeof o);
    o.dir = options->dir;
    o.vary = options->vary;
    o.vary_count = options->vary_count;
    o.repeat = options->repeat;
    o.jobs = options->jobs;
    o.shard_index = options->shard_index;
    o.shard_count = options->shard_count;
    o.scene_path = scene->file.files[0];
    o.command = "libbeamslider-host bs_host_map";
    o.progress = options->progress;
    o.progress_context = options->progress_context;
    status = map_run_grid(&scene->file, &o, &grid, err, sizeof err);
    if (status != MAP_DONE) {
        map_grid_free(&grid);
        return api_error(error, status_of(status), "%s", err);
    }
    status = map_run_cases(&scene->file, &grid, &o, &m, err, sizeof err, result->warnings, sizeof result->warnings);
    result->points = grid.points;
    result->cases = grid.cases;
    result->shard_cases = m.shard_cases;
    result->skipped = m.skipped;
    result->run = m.run;
    result->done = m.done_total;
    result->complete = m.complete;
    result->jobs = m.jobs;
    result->wall_s = m.wall_s;
    map_grid_free(&grid);
    if (status != MAP_DONE)
        return api_error(error, status_of(status), "%s", err);
    return api_ok(error);
}
