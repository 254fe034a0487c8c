/* input_file.c - opening the files a command reads, and reading their lines
 * (input_file.h; docs/robustness.md, "Files a command reads").
 *
 * The open is O_RDONLY | O_NONBLOCK | O_NOCTTY: a FIFO without a writer
 * opens at once instead of waiting for one, a terminal does not become the
 * controlling one; fstat then refuses everything but a regular file, and a
 * regular file over its kind's bound. Only then is O_NONBLOCK cleared and
 * the descriptor handed to stdio.
 */
#define _POSIX_C_SOURCE 200809L /* open, fstat, fcntl, fdopen, st_mtim, getc_unlocked */

#include "input_file.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The bound of each kind: far above any file of its kind that makes sense
 * (the shipped scenes are under 2 KiB; an hour of a 50 kHz measured stream
 * with four columns is about 10 GB), so that only a file that is not one of
 * its kind (a disk image, /proc, a log that never stops) meets it. */
static const struct {
    const char *name;
    long long max_bytes;
    const char *max_text;
    const char *not_regular_hint; /* appended when the path is not a regular file */
} input_kinds[INPUT_KINDS] = {
    [INPUT_SCENE] = { "scene file", 1LL << 20, "1 MiB", "" },
    [INPUT_RECORD] = { "excitation record", 1LL << 32, "4 GiB", "" },
    [INPUT_MEASURED] = { "measured-signals file", 1LL << 36, "64 GiB",
                         " (a live stream: give --measured - and send it to standard input)" },
    [INPUT_MAP_IDENTITY] = { "map identity", 1LL << 20, "1 MiB", "" },
    [INPUT_MAP_RESULTS] = { "map result file", 1LL << 30, "1 GiB", "" },
    [INPUT_MAP_TABLE] = { "map table", 1LL << 30, "1 GiB", "" },
};

const char *input_kind_name(input_kind kind)
{
    return input_kinds[kind].name;
}

long long input_kind_max_bytes(input_kind kind)
{
    return input_kinds[kind].max_bytes;
}

static const char *file_type(mode_t mode)
{
    if (S_ISDIR(mode))
        return "a folder";
    if (S_ISFIFO(mode))
        return "a FIFO (named pipe)";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a regular file";
}

static void identity_of(const struct stat *info, input_identity *identity)
{
    if (!identity)
        return;
    identity->dev = info->st_dev;
    identity->ino = info->st_ino;
    identity->size = info->st_size;
    identity->mtime_ns = (long long)info->st_mtim.tv_sec * 1000000000LL + (long long)info->st_mtim.tv_nsec;
}

int input_file_open_why(const char *path, input_kind kind, FILE **file, input_identity *identity,
                        const char **verb, char *why, size_t why_size)
{
    struct stat info;
    const int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);

    *file = NULL;
    *verb = "open";
    if (fd < 0) {
        snprintf(why, why_size, "%s", strerror(errno));
        return -1;
    }
    *verb = "read";
    if (fstat(fd, &info) != 0)
        snprintf(why, why_size, "%s", strerror(errno));
    else if (!S_ISREG(info.st_mode))
        snprintf(why, why_size, "%s, not a regular file%s", file_type(info.st_mode),
                 input_kinds[kind].not_regular_hint);
    else if ((long long)info.st_size > input_kinds[kind].max_bytes)
        snprintf(why, why_size, "%lld bytes, more than a %s may have (%lld, %s)", (long long)info.st_size,
                 input_kinds[kind].name, input_kinds[kind].max_bytes, input_kinds[kind].max_text);
    else if (fcntl(fd, F_SETFL, 0) != 0 || !(*file = fdopen(fd, "r")))
        snprintf(why, why_size, "%s", strerror(errno));
    else {
        identity_of(&info, identity);
        return 0;
    }
    close(fd);
    return -1;
}

int input_file_open(const char *path, input_kind kind, FILE **file, input_identity *identity, char *err,
                    size_t err_size)
{
    const char *verb;
    char why[256];
    if (input_file_open_why(path, kind, file, identity, &verb, why, sizeof why) == 0)
        return 0;
    snprintf(err, err_size, "%s: cannot %s %s: %s", path, verb, input_kinds[kind].name, why);
    return -1;
}

int input_file_unchanged(FILE *file, const input_identity *identity)
{
    struct stat info;
    input_identity now;
    if (fstat(fileno(file), &info) != 0)
        return 0;
    identity_of(&info, &now);
    return now.dev == identity->dev && now.ino == identity->ino && now.size == identity->size
           && now.mtime_ns == identity->mtime_ns;
}

void input_lines_start(input_lines *in, FILE *file, const char *path, long long max_bytes)
{
    in->file = file;
    in->path = path;
    in->line = 0;
    in->bytes = 0;
    in->max_bytes = max_bytes;
}

int input_lines_next(input_lines *in, char *text, size_t size, char *err, size_t err_size)
{
    size_t length = 0;
    int c;

    errno = 0;
    c = getc_unlocked(in->file);
    if (c == EOF) {
        if (ferror(in->file)) {
            snprintf(err, err_size, "%s:%ld: cannot read: %s", in->path, in->line + 1,
                     errno ? strerror(errno) : "read error");
            return -1;
        }
        return 0;
    }
    ++in->line;
    for (; c != EOF && c != '\n'; c = getc_unlocked(in->file)) {
        if (in->max_bytes > 0 && ++in->bytes > in->max_bytes) {
            snprintf(err, err_size, "%s:%ld: the file grew past %lld bytes while being read", in->path, in->line,
                     in->max_bytes);
            return -1;
        }
        if (c == '\0') {
            snprintf(err, err_size, "%s:%ld: a NUL byte: not a text file", in->path, in->line);
            return -1;
        }
        if (length + 1 >= size) {
            if (c == '\r') { /* the \r of a full line's \r\n end */
                const int next = getc_unlocked(in->file);
                if (next == '\n' || next == EOF) {
                    in->bytes += next == '\n';
                    text[length] = '\0';
                    return 1;
                }
                ungetc(next, in->file);
            }
            snprintf(err, err_size, "%s:%ld: longer than %lu characters", in->path, in->line,
                     (unsigned long)(size - 1));
            return -1;
        }
        text[length++] = (char)c;
    }
    if (c == EOF && ferror(in->file)) {
        snprintf(err, err_size, "%s:%ld: cannot read: %s", in->path, in->line, errno ? strerror(errno) : "read error");
        return -1;
    }
    if (c == '\n')
        ++in->bytes;
    if (length > 0 && text[length - 1] == '\r')
        --length;
    text[length] = '\0';
    return 1;
}

const char *input_skip_blanks(const char *text)
{
    while (*text == ' ' || *text == '\t')
        ++text;
    return text;
}

void input_trim_end(char *text)
{
    size_t length = strlen(text);
    while (length > 0 && (text[length - 1] == ' ' || text[length - 1] == '\t'))
        --length;
    text[length] = '\0';
}

int input_number(const char *text, const char *unit, double *value)
{
    char *end;
    const char *rest;
    text = input_skip_blanks(text);
    *value = strtod(text, &end);
    if (end == text || !isfinite(*value))
        return -1;
    rest = input_skip_blanks(end);
    if (unit) {
        const size_t n = strlen(unit);
        if (strncmp(rest, unit, n) != 0 || (rest[n] != '\0' && rest[n] != ' ' && rest[n] != '\t'))
            return -1;
        rest = input_skip_blanks(rest + n);
    }
    return *rest == '\0' ? 0 : -1;
}
