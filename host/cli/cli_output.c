/* cli_output.c - the optional output files of run and sweep. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"

int cli_open_output(const char *path, FILE **file)
{
    *file = NULL;
    if (!path)
        return 0;
    *file = fopen(path, "w");
    if (!*file) {
        cli_error("cannot open %s for writing: %s", path, strerror(errno));
        return -1;
    }
    return 0;
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
