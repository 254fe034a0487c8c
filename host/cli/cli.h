/* cli.h - the beamslider command line: one function per subcommand. */
#ifndef CLI_H
#define CLI_H

#include <stdio.h>

/* Exit codes: 0 success, 1 the work failed (run diverged, output not
 * written), 2 bad usage or bad input. */
enum { CLI_OK = 0, CLI_FAILED = 1, CLI_USAGE = 2 };

int cli_modes(int argc, char **argv);
int cli_gen(int argc, char **argv);
int cli_sweep(int argc, char **argv);
int cli_run(int argc, char **argv);

/* Prints "beamslider: error: ..." to stderr. */
void cli_error(const char *format, ...);

/* Opens PATH for writing (*file = NULL and 0 when PATH is NULL); -1 after
 * reporting a failure. */
int cli_open_output(const char *path, FILE **file);

/* Closes an output opened by cli_open_output; -1 after reporting that its own
 * writes failed (write_errno: the errno of the failed write, if known). */
int cli_close_output(const char *path, FILE *file, int write_errno);

#endif
