/* cli_error.c - the CLI's one error printer: every message a subcommand
 * reports goes to stderr as "beamslider: error: ..." through here, so no
 * subcommand calls back into the dispatcher (main.c). */
#include <stdarg.h>
#include <stdio.h>
#include "cli.h"

void cli_error(const char *format, ...)
{
    va_list args;
    fputs("beamslider: error: ", stderr);
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fputc('\n', stderr);
}
