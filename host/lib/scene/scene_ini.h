/* scene_ini.h - scene files: INI parsing (libinih) with validation. */
#ifndef SCENE_INI_H
#define SCENE_INI_H

#include <stddef.h>
#include "scene_params.h"

#define SCENE_PATH 512
#define SCENE_MAX_FILES 8
/* The number of fields of the table (scene_fields.h): one per X. */
#define SCENE_COUNT_FIELD(kind, section, key, member, where, low, high, low_open, high_open, default_text, \
                          unit, meaning, choices) +1
enum { SCENE_MAX_FIELDS = 0 SCENE_FIELDS(SCENE_COUNT_FIELD) };
/* A scene file (and each base) is a regular file of at most this many bytes
 * (1 MiB; the shipped ones are under 2 KiB): a FIFO, a device or a huge file
 * would otherwise be read for ever. The bound of INPUT_SCENE (input_file.h). */
#define SCENE_MAX_BYTES (1L << 20)

#define SCENE_OPTION 192 /* "--set section.key=value" with a value of most texts */
#define SCENE_NAME 32    /* a section's or a key's name, with its NUL */
#define SCENE_NOT_SET (-1)   /* set_file: the field was not set (default or missing) */
#define SCENE_BY_OPTION (-2) /* set_file: set by a command-line option (set_option) */

/* A scene as read: the parameters and where each one was set. Files and
 * options are recorded apart, so that options never use up the
 * SCENE_MAX_FILES slots of the base chain. */
typedef struct scene_file {
    scene_params params;
    char files[SCENE_MAX_FILES][SCENE_PATH]; /* [0]: the file asked for; then its bases */
    int file_count;
    int set_file[SCENE_MAX_FIELDS];          /* index into files, SCENE_NOT_SET or SCENE_BY_OPTION */
    int set_line[SCENE_MAX_FIELDS];
    char set_option[SCENE_MAX_FIELDS][SCENE_OPTION]; /* the option, when SCENE_BY_OPTION */
} scene_file;

/* Reads path, after its base file if it names one ([scene] base = FILE,
 * relative to path's folder; the file's own values win). Every field is
 * checked: unknown, duplicate, non-numeric, NaN/inf, out of range, missing.
 * Returns 0, or -1 with "file:line: what is wrong" in err. */
int scene_load(const char *path, scene_file *scene, char *err, size_t err_size);

/* Reads text as the scene file named name (messages say "name:line: ...";
 * a [scene] base is found relative to name's folder, or the working folder
 * when name has none; the default [scene] name is name's). Checked as
 * scene_load checks a file. Returns 0, or -1 with the message in err. */
int scene_load_text(const char *name, const char *text, scene_file *scene, char *err, size_t err_size);

/* Sets one field from text given by the command-line option origin (such as
 * --dt; shorter than SCENE_OPTION). Same checks as in a file; messages name
 * the option. Any number of options may be set, the last value of a field
 * wins. Returns 0 or -1. */
int scene_set(scene_file *scene, const char *section, const char *key, const char *value,
              const char *origin, char *err, size_t err_size);

/* Sets one field from assignment "section.key=value", given by the
 * command-line option (--set): checked exactly as a file line is, and
 * reported alike with "OPTION section.key=value" in place of "file:line"
 * ("--set numerics.dt=abc: [numerics] dt = abc: not a number; allowed: ...").
 * An unknown field or an assignment without section.key= is refused. The
 * field's place (scene_where) is the option and the assignment. Returns 0
 * or -1. */
int scene_set_assignment(scene_file *scene, const char *option, const char *assignment, char *err,
                         size_t err_size);

/* The index into scene_fields of the field named "section.key" (the first
 * length characters of name), -1 if there is none; its section and key are
 * copied to section and key (SCENE_NAME characters each) unless NULL. */
int scene_field_named(const char *name, size_t length, char *section, char *key);

/* "file:line" (or the option name) where [section] key was set, into out. */
const char *scene_where(const scene_file *scene, const char *section, const char *key,
                        char *out, size_t size);

#endif
