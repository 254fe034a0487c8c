/* cli.h - the beamslider command line: a thin client of the host library
 * (host/lib/): it parses options, opens the files a command writes, prints
 * what went wrong and chooses the exit status. The commands are one table,
 * main.c's commands[]: (name, handler, usage).
 *
 * Adding a command (the checklist, as git's builtin.h has one):
 *   1. host/cli/cli_NAME.c: int cli_NAME(int argc, char **argv), given the
 *      arguments after the command's name; and its usage texts
 *      cli_NAME_synopsis (every option, as "beamslider NAME SCENE.ini
 *      [--opt X] ...") and cli_NAME_help (what it does, indented by two);
 *   2. declare the three below;
 *   3. a row of commands[] in main.c (its place there is its place in
 *      `beamslider --help`); `beamslider NAME --help` then prints its usage;
 *   4. the work itself in a wing of host/lib (never here), its messages
 *      returned as text; report them with cli_error, exit with CLI_*;
 *   5. a check in tests/check_cli.sh and a line in README.md's command list.
 */
#ifndef CLI_H
#define CLI_H

#include <stdio.h>
#include "scene_ini.h"

/* Exit codes: 0 success, 1 the work failed (run diverged, output not
 * written), 2 bad usage or bad input. */
enum { CLI_OK = 0, CLI_FAILED = 1, CLI_USAGE = 2 };

/* The commands: handler, synopsis, help (see the checklist above). */
#define CLI_COMMAND(name)                   \
    int cli_##name(int argc, char **argv); \
    extern const char cli_##name##_synopsis[]; \
    extern const char cli_##name##_help[];
CLI_COMMAND(modes)
CLI_COMMAND(gen)
CLI_COMMAND(sweep)
CLI_COMMAND(run)
CLI_COMMAND(fields)
CLI_COMMAND(twin)
CLI_COMMAND(twin_plant)
CLI_COMMAND(twin_gains)
CLI_COMMAND(map)
CLI_COMMAND(map_merge)
CLI_COMMAND(map_plot)
#undef CLI_COMMAND

/* Prints "beamslider: error: ..." to stderr (cli_error.c). */
#if defined(__GNUC__)
void cli_error(const char *format, ...) __attribute__((format(printf, 1, 2)));
#else
void cli_error(const char *format, ...);
#endif

/* An integer option value in [low, high] (low, high within int) into
 * *value. Returns 0, or -1 after reporting "OPTION TEXT: allowed: ...". */
int cli_parse_int(const char *option, const char *text, long low, long high, int *value);

/* One output file of a command: the option that names it and its path
 * (NULL: not asked for); file is set by cli_open_outputs. */
typedef struct cli_output {
    const char *option;
    const char *path;
    FILE *file;
} cli_output;

#define CLI_MAX_OUTPUTS 4

/* A file a command reads besides its scene: the option that names it and
 * its path (NULL or "-": none, or standard input). */
typedef struct cli_input {
    const char *option;
    const char *path;
} cli_input;

/* Opens every output asked for, or none (cli_output.c says how). Returns
 * CLI_OK; CLI_USAGE after reporting that two outputs are one file, or that
 * an output is one of the command's inputs (the scene file, one of its
 * bases, one of inputs: compared as files, through links) or where standard
 * output goes; CLI_FAILED after reporting an output that cannot be opened
 * (then no file was truncated, and none was left behind). */
int cli_open_outputs_reading(cli_output *outputs, int count, const scene_file *scene, const cli_input *inputs,
                             int input_count);

/* The same for a command that reads nothing but its scene. */
int cli_open_outputs(cli_output *outputs, int count, const scene_file *scene);

/* The checks of cli_open_outputs_reading alone, nothing opened or
 * truncated: for a command that refuses such outputs before long work (twin,
 * before its response maps); it opens them with cli_open_outputs_reading
 * after, which checks again. The same returns, CLI_FAILED only for more
 * than CLI_MAX_OUTPUTS outputs. */
int cli_check_outputs_reading(const cli_output *outputs, int count, const scene_file *scene, const cli_input *inputs,
                              int input_count);

/* 1 if path names the same existing file as an input of the scene (the
 * file or a base; through links), with that input's path in *input. */
int cli_is_scene_file(const char *path, const scene_file *scene, const char **input);

/* Closes the outputs that are open, without checking them (on a failure). */
void cli_close_outputs(cli_output *outputs, int count);

/* Closes an output opened by cli_open_outputs; -1 after reporting that its own
 * writes failed (write_errno: the errno of the failed write, if known). */
int cli_close_output(const char *path, FILE *file, int write_errno);

#endif
