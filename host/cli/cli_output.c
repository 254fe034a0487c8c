/* cli_output.c - the output files of run, sweep, twin and twin-plant.
 *
 * Outputs must not clobber each other, the command's inputs (the scene and
 * its bases, a recorded excitation, a measured-signals file) or what
 * standard output carries (the JSON summary), so they are compared as
 * files, not as names:
 * an existing file by device and inode (./x.csv, x.csv, a symbolic or a hard
 * link, /dev/stdout all name one file), a file still to be created by the
 * real path of its folder and its name (a dangling symbolic link by the file
 * it would create). Character devices (a terminal, /dev/null) hold nothing to
 * clobber and may be shared.
 *
 * All or nothing: every output is opened before any is truncated. A new file
 * is created with O_EXCL (so it is known to be ours), an existing one opened
 * without O_TRUNC; if one cannot be opened, the others are closed untouched
 * and the files this call created are removed. Only then are the existing
 * regular files truncated. After opening, the files are compared once more
 * by their descriptors (a file created in between, a link followed).
 */
#define _XOPEN_SOURCE 700 /* POSIX 2008 with realpath: open, fstat, readlink */

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

#define IDENTITY_NAME 4400 /* a resolved folder (PATH_MAX 4096) and a file name */
#define LINK_DEPTH 8       /* dangling symbolic links followed to what they would create */

/* What a path names: an existing file (exists = 1: dev, ino, mode) or one to
 * be created (exists = 0: name, the real path of its folder and its name);
 * known = 0 when neither could be found (the open will fail, or say why). */
typedef struct file_identity {
    int known, exists;
    dev_t dev;
    ino_t ino;
    mode_t mode;
    char name[IDENTITY_NAME];
} file_identity;

static void identify(const char *path, file_identity *id, int depth);

static void identity_of_stat(const struct stat *info, file_identity *id)
{
    id->known = id->exists = 1;
    id->dev = info->st_dev;
    id->ino = info->st_ino;
    id->mode = info->st_mode;
}

/* path does not exist (or is a dangling link): the file open would create. */
static void identify_new(const char *path, file_identity *id, int depth)
{
    char folder[IDENTITY_NAME];
    char target[IDENTITY_NAME];
    char real[IDENTITY_NAME];
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    struct stat info;
    ssize_t length;

    if (lstat(path, &info) == 0 && S_ISLNK(info.st_mode)) {
        length = readlink(path, target, sizeof target - 1);
        if (length <= 0 || depth >= LINK_DEPTH)
            return;
        target[length] = '\0';
        if (target[0] != '/' && slash) { /* relative to the link's folder */
            if (snprintf(folder, sizeof folder, "%.*s/%s", (int)(slash - path), path, target) < (int)sizeof folder)
                identify(folder, id, depth + 1);
        } else {
            identify(target, id, depth + 1);
        }
        return;
    }
    if (!*base || strlen(path) >= sizeof folder)
        return;
    if (!slash)
        strcpy(folder, ".");
    else if (slash == path)
        strcpy(folder, "/");
    else
        snprintf(folder, sizeof folder, "%.*s", (int)(slash - path), path);
    if (strlen(folder) >= 4096 || !realpath(folder, real)) /* realpath writes up to PATH_MAX */
        return;
    if (snprintf(id->name, sizeof id->name, "%s/%s", real, base) >= (int)sizeof id->name)
        return;
    id->known = 1;
}

static void identify(const char *path, file_identity *id, int depth)
{
    struct stat info;
    memset(id, 0, sizeof *id);
    if (stat(path, &info) == 0)
        identity_of_stat(&info, id);
    else if (errno == ENOENT)
        identify_new(path, id, depth);
}

static int same_file(const file_identity *a, const file_identity *b)
{
    if (!a->known || !b->known || a->exists != b->exists)
        return 0;
    if (a->exists)
        return a->dev == b->dev && a->ino == b->ino && !S_ISCHR(a->mode);
    return !strcmp(a->name, b->name);
}

/* 0, or CLI_USAGE after reporting that output i names the same file as
 * another output, the scene or one of its bases, another input, or standard
 * output. */
static int check_overlaps(const cli_output *outputs, const file_identity *ids, int count,
                          const scene_file *scene, const cli_input *inputs, int input_count)
{
    struct stat info;
    file_identity other;
    int i, j;

    for (i = 0; i < count; ++i) {
        if (!outputs[i].path)
            continue;
        for (j = 0; j < i; ++j)
            if (outputs[j].path && same_file(&ids[i], &ids[j])) {
                if (!strcmp(outputs[i].path, outputs[j].path))
                    cli_error("%s and %s both name %s: each needs its own file", outputs[j].option,
                              outputs[i].option, outputs[i].path);
                else
                    cli_error("%s %s and %s %s are the same file: each needs its own file", outputs[j].option,
                              outputs[j].path, outputs[i].option, outputs[i].path);
                return CLI_USAGE;
            }
        for (j = 0; scene && j < scene->file_count; ++j) {
            identify(scene->files[j], &other, 0);
            if (same_file(&ids[i], &other)) {
                cli_error("%s %s is the scene%s file %s: it would be overwritten", outputs[i].option,
                          outputs[i].path, j ? "'s base" : "", scene->files[j]);
                return CLI_USAGE;
            }
        }
        for (j = 0; j < input_count; ++j) {
            if (!inputs[j].path || !strcmp(inputs[j].path, "-"))
                continue;
            identify(inputs[j].path, &other, 0);
            if (other.exists && same_file(&ids[i], &other)) {
                cli_error("%s %s is the %s file %s: it would be overwritten", outputs[i].option, outputs[i].path,
                          inputs[j].option, inputs[j].path);
                return CLI_USAGE;
            }
        }
        memset(&other, 0, sizeof other);
        if (fstat(STDOUT_FILENO, &info) == 0)
            identity_of_stat(&info, &other);
        if (same_file(&ids[i], &other)) {
            cli_error("%s %s is where standard output goes (the JSON summary): each needs its own file",
                      outputs[i].option, outputs[i].path);
            return CLI_USAGE;
        }
    }
    return 0;
}

/* Closes the descriptors of outputs 0 .. count-1 and removes the files this
 * call created. */
static void undo_opens(const cli_output *outputs, const int *fds, const int *created, int count)
{
    int i;
    for (i = 0; i < count; ++i) {
        if (fds[i] < 0)
            continue;
        close(fds[i]);
        if (created[i])
            unlink(outputs[i].path);
    }
}

/* Opens path for writing without truncating it; created = 1 if this call
 * made the file. -1 with errno set when it cannot be opened. */
static int open_untruncated(const char *path, int *created)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOCTTY, 0666);
    *created = fd >= 0;
    if (fd < 0 && errno == EEXIST)
        fd = open(path, O_WRONLY | O_NOCTTY);
    if (fd < 0 && errno == ENOENT) /* a dangling link: creates what it points to */
        fd = open(path, O_WRONLY | O_CREAT | O_NOCTTY, 0666);
    return fd;
}

/* The identities of the opened descriptors into ids. */
static void identify_opened(const int *fds, file_identity *ids, int count)
{
    struct stat info;
    int i;
    for (i = 0; i < count; ++i) {
        memset(&ids[i], 0, sizeof ids[i]);
        if (fds[i] >= 0 && fstat(fds[i], &info) == 0)
            identity_of_stat(&info, &ids[i]);
    }
}

/* Empties the opened files that hold something (regular files only: a
 * device or a /proc file cannot be truncated and has nothing to lose). */
static int truncate_opened(const cli_output *outputs, const int *fds, int count)
{
    struct stat info;
    int i;
    for (i = 0; i < count; ++i)
        if (fds[i] >= 0 && fstat(fds[i], &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0
            && ftruncate(fds[i], 0) != 0) {
            cli_error("cannot empty %s for writing: %s", outputs[i].path, strerror(errno));
            return -1;
        }
    return 0;
}

int cli_is_scene_file(const char *path, const scene_file *scene, const char **input)
{
    file_identity id, other;
    int j;
    identify(path, &id, 0);
    for (j = 0; id.exists && j < scene->file_count; ++j) {
        identify(scene->files[j], &other, 0);
        if (same_file(&id, &other)) {
            *input = scene->files[j];
            return 1;
        }
    }
    return 0;
}

int cli_open_outputs(cli_output *outputs, int count, const scene_file *scene)
{
    return cli_open_outputs_reading(outputs, count, scene, NULL, 0);
}

/* ids[i] of outputs[i] (unknown where it has no path), then check_overlaps. */
static int identify_outputs(const cli_output *outputs, file_identity *ids, int count, const scene_file *scene,
                            const cli_input *inputs, int input_count)
{
    int i;
    if (count > CLI_MAX_OUTPUTS) {
        cli_error("internal: %d outputs, at most %d", count, CLI_MAX_OUTPUTS);
        return CLI_FAILED;
    }
    memset(ids, 0, sizeof(file_identity) * (size_t)count);
    for (i = 0; i < count; ++i)
        if (outputs[i].path)
            identify(outputs[i].path, &ids[i], 0);
    return check_overlaps(outputs, ids, count, scene, inputs, input_count);
}

int cli_check_outputs_reading(const cli_output *outputs, int count, const scene_file *scene, const cli_input *inputs,
                              int input_count)
{
    file_identity ids[CLI_MAX_OUTPUTS];
    return identify_outputs(outputs, ids, count, scene, inputs, input_count);
}

int cli_open_outputs_reading(cli_output *outputs, int count, const scene_file *scene, const cli_input *inputs,
                             int input_count)
{
    file_identity ids[CLI_MAX_OUTPUTS];
    int fds[CLI_MAX_OUTPUTS];
    int created[CLI_MAX_OUTPUTS];
    int i, status;

    for (i = 0; i < count && i < CLI_MAX_OUTPUTS; ++i) {
        outputs[i].file = NULL;
        fds[i] = -1;
        created[i] = 0;
    }
    if ((status = identify_outputs(outputs, ids, count, scene, inputs, input_count)) != 0)
        return status;
    for (i = 0; i < count; ++i) {
        if (!outputs[i].path)
            continue;
        fds[i] = open_untruncated(outputs[i].path, &created[i]);
        if (fds[i] < 0) {
            cli_error("cannot open %s for writing: %s", outputs[i].path, strerror(errno));
            undo_opens(outputs, fds, created, i);
            return CLI_FAILED;
        }
    }
    identify_opened(fds, ids, count);
    if ((status = check_overlaps(outputs, ids, count, scene, inputs, input_count)) != 0
        || truncate_opened(outputs, fds, count) != 0) {
        undo_opens(outputs, fds, created, count);
        return status ? status : CLI_FAILED;
    }
    for (i = 0; i < count; ++i)
        if (fds[i] >= 0 && !(outputs[i].file = fdopen(fds[i], "w"))) {
            cli_error("cannot open %s for writing: %s", outputs[i].path, strerror(errno));
            cli_close_outputs(outputs, i);
            undo_opens(outputs + i, fds + i, created + i, count - i);
            return CLI_FAILED;
        }
    return CLI_OK;
}

void cli_close_outputs(cli_output *outputs, int count)
{
    int i;
    for (i = 0; i < count; ++i)
        if (outputs[i].file) {
            fclose(outputs[i].file);
            outputs[i].file = NULL;
        }
}

int cli_close_output(const char *path, FILE *file, int write_errno)
{
    int own_error;
    if (!file)
        return 0;
    errno = write_errno;
    own_error = ferror(file) != 0;
    own_error |= fclose(file) != 0;
    if (own_error) {
        cli_error("writing %s failed: %s; the file is incomplete", path,
                  errno ? strerror(errno) : "write error");
        return -1;
    }
    return 0;
}
