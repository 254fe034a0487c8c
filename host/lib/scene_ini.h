/* scene_ini.h - scene files: INI parsing (libinih) with validation. */
#ifndef SCENE_INI_H
#define SCENE_INI_H

#include <stddef.h>
#include "scene_params.h"

#define SCENE_PATH 512
#define SCENE_MAX_FILES 8
#define SCENE_MAX_FIELDS 40
/* A scene file (and each base) is a regular file of at most this many bytes
 * (1 MiB; the shipped ones are under 2 KiB): a FIFO, a device or a huge file
 * would otherwise be read for ever. */
#define SCENE_MAX_BYTES (1L << 20)

/* A scene as read: the parameters and where each one was set. */
typedef struct scene_file {
    scene_params params;
    char files[SCENE_MAX_FILES][SCENE_PATH]; /* [0]: the file asked for; then bases, options */
    int file_count;
    int set_file[SCENE_MAX_FIELDS];          /* index into files, -1: not set */
    int set_line[SCENE_MAX_FIELDS];
} scene_file;

/* Reads path, after its base file if it names one ([scene] base = FILE,
 * relative to path's folder; the file's own values win). Every field is
 * checked: unknown, duplicate, non-numeric, NaN/inf, out of range, missing.
 * Returns 0, or -1 with "file:line: what is wrong" in err. */
int scene_load(const char *path, scene_file *scene, char *err, size_t err_size);

/* Sets one field from text as if read from a file named origin (used for
 * command-line overrides such as --dt). Same checks; returns 0 or -1. */
int scene_set(scene_file *scene, const char *section, const char *key, const char *value,
              const char *origin, char *err, size_t err_size);

/* "file:line" (or the option name) where [section] key was set, into out. */
const char *scene_where(const scene_file *scene, const char *section, const char *key,
                        char *out, size_t size);

#endif
