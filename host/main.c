/* main.c - beamslider: command dispatch. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "beamslider.h"
#include "cli.h"

static const char usage[] =
    "usage: beamslider COMMAND ...\n"
    "  modes SCENE.ini        modal data: f_k [Hz], gamma_k, phi_k(4/7) per mode\n"
    "  gen SCENE.ini          C header of the scene for a compile-time (embedded) build\n"
    "  sweep SCENE.ini --dir up|down --out FILE.csv [--from 0] [--to 0.5] [--step 0.005]\n"
    "                [--hold 100] [--record 25]\n"
    "                         quasi-static PCS sweep: amplitude and transport per s~\n"
    "  run SCENE.ini [--model free|pcs] [--s0 S] [--t-end T] [--dt DT] [--pgs-iters K]\n"
    "                [--out FILE.csv] [--every N] [--periods FILE.csv]\n"
    "                         simulate; CSV rows every N steps, one row per excitation\n"
    "                         period with --periods, JSON summary on stdout\n"
    "core precision: " BS_REAL_NAME "\n";

void cli_error(const char *format, ...)
{
    va_list args;
    fputs("beamslider: error: ", stderr);
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fputc('\n', stderr);
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "modes"))
        return cli_modes(argc - 2, argv + 2);
    if (argc >= 2 && !strcmp(argv[1], "run"))
        return cli_run(argc - 2, argv + 2);
    if (argc >= 2 && !strcmp(argv[1], "gen"))
        return cli_gen(argc - 2, argv + 2);
    if (argc >= 2 && !strcmp(argv[1], "sweep"))
        return cli_sweep(argc - 2, argv + 2);
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        fputs(usage, stdout);
        return CLI_OK;
    }
    if (argc >= 2)
        cli_error("unknown command '%s'", argv[1]);
    fputs(usage, stderr);
    return CLI_USAGE;
}
