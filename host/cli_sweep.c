/* cli_sweep.c - `beamslider sweep`: placeholder until the sweep lands. */
#include "cli.h"

int cli_sweep(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("sweep is not implemented yet");
    return CLI_FAILED;
}
