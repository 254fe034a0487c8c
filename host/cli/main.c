/* main.c - beamslider: the table of commands and the dispatch through it.
 * host/cli/cli.h has the checklist for adding a command. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "beamslider.h"
#include "cli.h"
#include "source_revision.h"

typedef struct cli_command {
    const char *name;
    int (*run)(int argc, char **argv); /* the arguments after the name */
    const char *synopsis;              /* every option: "beamslider run SCENE.ini [--model free|pcs] ..." */
    const char *help;                  /* what it does, lines indented by two */
} cli_command;

/* The commands, in the order `beamslider --help` lists them. */
static const cli_command commands[] = {
    { "modes", cli_modes, cli_modes_synopsis, cli_modes_help },
    { "gen", cli_gen, cli_gen_synopsis, cli_gen_help },
    { "sweep", cli_sweep, cli_sweep_synopsis, cli_sweep_help },
    { "run", cli_run, cli_run_synopsis, cli_run_help },
    { "twin", cli_twin, cli_twin_synopsis, cli_twin_help },
    { "twin-plant", cli_twin_plant, cli_twin_plant_synopsis, cli_twin_plant_help },
    { "twin-gains", cli_twin_gains, cli_twin_gains_synopsis, cli_twin_gains_help },
    { "map", cli_map, cli_map_synopsis, cli_map_help },
    { "map-merge", cli_map_merge, cli_map_merge_synopsis, cli_map_merge_help },
    { "map-plot", cli_map_plot, cli_map_plot_synopsis, cli_map_plot_help },
    { "fields", cli_fields, cli_fields_synopsis, cli_fields_help },
};
#define COMMANDS (sizeof commands / sizeof commands[0])

static int is_help(const char *argument)
{
    return !strcmp(argument, "--help") || !strcmp(argument, "-h");
}

/* `beamslider --help`: every command's synopsis, so every option, and the
 * first line of what it does. */
static void print_usage(FILE *out)
{
    size_t i;
    fputs("usage: beamslider COMMAND ...   (beamslider COMMAND --help: the command's help)\n", out);
    for (i = 0; i < COMMANDS; ++i) {
        const char *help = commands[i].help;
        fprintf(out, "  %s\n  %.*s\n", commands[i].synopsis, (int)strcspn(help, "\n"), help);
    }
    fputs("  beamslider --version\n    version, source revision and precision\n"
          "  beamslider --help\n    this text\n", out);
    fputs("core precision: " BS_REAL_NAME "\n", out);
}

/* Standard output carries what a command produces (the JSON summary, the
 * modal table, the generated header): if writing it failed (> /dev/full, a
 * full disk), say so and do not exit 0. */
static int finish(int status)
{
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        cli_error("writing standard output failed: %s", errno ? strerror(errno) : "write error");
        return status == CLI_USAGE ? CLI_USAGE : CLI_FAILED;
    }
    return status;
}

int main(int argc, char **argv)
{
    size_t i;

    if (argc >= 2) {
        for (i = 0; i < COMMANDS; ++i)
            if (!strcmp(argv[1], commands[i].name)) {
                if (argc >= 3 && is_help(argv[2])) {
                    printf("usage: %s\n%s", commands[i].synopsis, commands[i].help);
                    return finish(CLI_OK);
                }
                return finish(commands[i].run(argc - 2, argv + 2));
            }
        if (argc == 2 && !strcmp(argv[1], "--version")) {
            printf("beamslider %s (revision %s), core precision %s\n", bs_version(), source_revision(), BS_REAL_NAME);
            return finish(CLI_OK);
        }
        if (is_help(argv[1])) {
            print_usage(stdout);
            return finish(CLI_OK);
        }
        cli_error("unknown command '%s'", argv[1]);
    }
    print_usage(stderr);
    return CLI_USAGE;
}
