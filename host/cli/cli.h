/* cli.h - the beamslider command line: one function per subcommand. */
#ifndef CLI_H
#define CLI_H

#include <stdio.h>
#include "scene_ini.h"

/* Exit codes: 0 success, 1 the work failed (run diverged, output not
 * written), 2 bad usage or bad input. */
enum { CLI_OK = 0, CLI_FAILED = 1, CLI_USAGE = 2 };

int cli_modes(int argc, char **argv);
int cli_gen(int argc, char **argv);
int cli_sweep(int argc, char **argv);
int cli_run(int argc, char **argv);
int cli_fields(int argc, char **argv);
int cli_twin(int argc, char **argv);
int cli_twin_plant_command(int argc, char **argv);
int cli_twin_gains_command(int argc, char **argv);
int cli_map(int argc, char **argv);
int cli_map_merge(int argc, char **argv);
int cli_map_plot(int argc, char **argv);

/* Prints "beamslider: error: ..." to stderr. */
void cli_error(const char *format, ...);

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

/* 1 if path names the same existing file as an input of the scene (the
 * file or a base; through links), with that input's path in *input. */
int cli_is_scene_file(const char *path, const scene_file *scene, const char **input);

/* Closes the outputs that are open, without checking them (on a failure). */
void cli_close_outputs(cli_output *outputs, int count);

/* Closes an output opened by cli_open_outputs; -1 after reporting that its own
 * writes failed (write_errno: the errno of the failed write, if known). */
int cli_close_output(const char *path, FILE *file, int write_errno);

#endif
