/* api_scene.h - what a bs_host_scene holds (host/include/beamslider_host.h
 * keeps it opaque), and the error helper of the api wing. */
#ifndef API_SCENE_H
#define API_SCENE_H

#include "beamslider_host.h"
#include "scene_build.h"

struct bs_host_scene {
    scene_file file;     /* as read, with the overrides and where each field was set */
    bs_scene scene;      /* built from it */
    scene_model model;   /* the modal data on the way */
};

/* Sets error (NULL: nothing) to status and the printf text; returns status. */
#if defined(__GNUC__)
bs_host_status api_error(bs_host_error *error, bs_host_status status, const char *format, ...)
    __attribute__((format(printf, 3, 4)));
#else
bs_host_status api_error(bs_host_error *error, bs_host_status status, const char *format, ...);
#endif

/* BS_HOST_OK into error (text empty); returns BS_HOST_OK. */
bs_host_status api_ok(bs_host_error *error);

#endif
