/* fuzz_files.h - a private temporary folder for the targets that feed their
 * input to a reader as a file (the readers take paths, and open them through
 * host/lib/io/input_file.c, whose checks are part of what is fuzzed).
 *
 * fuzz_folder_make() creates $TMPDIR/bs_fuzz_XXXXXX (or under /tmp) once,
 * and removes it with the files named through fuzz_path() at exit. */
#ifndef FUZZ_FILES_H
#define FUZZ_FILES_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "fuzz_check.h"

#define FUZZ_PATH 512
#define FUZZ_MAX_FILES 16

static char fuzz_folder[64];
static char fuzz_files[FUZZ_MAX_FILES][FUZZ_PATH];
static int fuzz_file_count;

static inline void fuzz_folder_remove(void)
{
    int i;
    for (i = 0; i < fuzz_file_count; ++i)
        unlink(fuzz_files[i]);
    rmdir(fuzz_folder);
}

/* The folder: made on the first call. */
static inline const char *fuzz_folder_make(void)
{
    const char *tmp = getenv("TMPDIR");
    if (fuzz_folder[0])
        return fuzz_folder;
    snprintf(fuzz_folder, sizeof fuzz_folder, "%s/bs_fuzz_XXXXXX", tmp && strlen(tmp) < 40 ? tmp : "/tmp");
    if (!mkdtemp(fuzz_folder))
        fuzz_fail("mkdtemp failed");
    atexit(fuzz_folder_remove);
    return fuzz_folder;
}

/* FOLDER/name, remembered for removal at exit (name: a few fixed names). */
static inline const char *fuzz_path(const char *name)
{
    char path[FUZZ_PATH];
    int i;
    snprintf(path, sizeof path, "%s/%s", fuzz_folder_make(), name);
    for (i = 0; i < fuzz_file_count; ++i)
        if (!strcmp(fuzz_files[i], path))
            return fuzz_files[i];
    if (fuzz_file_count == FUZZ_MAX_FILES)
        fuzz_fail("fuzz_path: too many file names");
    snprintf(fuzz_files[fuzz_file_count], FUZZ_PATH, "%s", path);
    return fuzz_files[fuzz_file_count++];
}

static inline void fuzz_write(const char *path, const uint8_t *data, size_t size)
{
    FILE *out = fopen(path, "wb");
    if (!out || (size && fwrite(data, 1, size, out) != size) || fclose(out) != 0)
        fuzz_fail("cannot write into the temporary folder");
}

/* A copy of FUZZ_CONFIGS/name in the folder (a base a fuzzed scene may name). */
static inline void fuzz_copy_config(const char *name)
{
    static uint8_t text[1 << 16];
    char from[FUZZ_PATH];
    FILE *in;
    size_t size;
    snprintf(from, sizeof from, "%s/%s", FUZZ_CONFIGS, name);
    in = fopen(from, "rb");
    if (!in)
        fuzz_fail("cannot read a scene of FUZZ_CONFIGS");
    size = fread(text, 1, sizeof text, in);
    fclose(in);
    fuzz_write(fuzz_path(name), text, size);
}

/* The offset of the first mark (a line such as "\n#@base\n") in the input,
 * or size: a target that feeds two files splits its input there. */
static inline size_t fuzz_split(const uint8_t *data, size_t size, const char *mark)
{
    const size_t length = strlen(mark);
    size_t i;
    for (i = 0; i + length <= size; ++i)
        if (!memcmp(data + i, mark, length))
            return i;
    return size;
}

/* A message a reader returned with status (0 or -1): terminated, and not
 * empty on a refusal. */
static inline void fuzz_check_message(int status, const char *message, size_t size)
{
    const size_t length = strnlen(message, size);
    if (status != 0 && status != -1)
        fuzz_fail("status neither 0 nor -1");
    if (length == size)
        fuzz_fail("message not terminated");
    if (status == -1 && length == 0)
        fuzz_fail("refused without a message");
}

#endif
