/* cli_parse.c - option values shared by the subcommands. */
#include "cli.h"

#include <errno.h>
#include <stdlib.h>

int cli_parse_int(const char *option, const char *text, long low, long high, int *value)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(text, &end, 10);
    if (end == text || *end || errno || v < low || v > high) {
        cli_error("%s %s: allowed: an integer in [%ld, %ld]", option, text, low, high);
        return -1;
    }
    *value = (int)v;
    return 0;
}
