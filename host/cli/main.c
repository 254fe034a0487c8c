/* main.c - beamslider: command dispatch. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "beamslider.h"
#include "bs_revision.h"
#include "cli.h"

static const char usage[] =
    "usage: beamslider COMMAND ...\n"
    "  modes SCENE.ini        modal data: f_k [Hz], gamma_k, phi_k(4/7) per mode\n"
    "  gen SCENE.ini          C header of the scene for a compile-time (embedded) build\n"
    "  sweep SCENE.ini --dir up|down --out FILE.csv [--from 0] [--to 0.5] [--step 0.005]\n"
    "                [--hold 100] [--record 25] [--set section.key=value ...]\n"
    "                         quasi-static PCS sweep: amplitude and transport per s~\n"
    "  run SCENE.ini [--model free|pcs] [--s0 S] [--t-end T] [--dt DT] [--pgs-iters K]\n"
    "                [--out FILE.csv] [--every N] [--periods FILE.csv] [--set section.key=value ...]\n"
    "                         simulate; CSV rows every N steps, one row per excitation\n"
    "                         period with --periods, JSON summary on stdout\n"
    "  twin SCENE.ini --measured FILE.csv|- --out EST.csv [--signal deflection|voltage]\n"
    "                [--latency S] [--noise SIGMA] ...\n"
    "                         the twin corrected from measured signals (beamslider twin --help)\n"
    "  twin-plant SCENE.ini --out FILE.csv [--snr DB] [--freq-scale X] ...\n"
    "                         a measured-signals file from a (perturbed) plant\n"
    "  twin-gains SCENE.ini --noise SIGMA [...]\n"
    "                         the observer's constants as a C header\n"
    "  map SCENE.ini --vary section.key=FROM:TO:STEP|v1,v2,... [--repeat K] [--jobs N]\n"
    "                [--shard I/N] [--set section.key=value ...] --out DIR\n"
    "                         a grid of runs, resumable and sharded (beamslider map --help)\n"
    "  map-merge DIR          the merged tables of a map's shards\n"
    "  map-plot DIR [--x FIELD --y FIELD] [--mark X,Y,LABEL ...]\n"
    "                         heatmaps of a map with gnuplot (beamslider map-plot --help)\n"
    "  fields                 the reference of every scene field (Markdown; docs/fields.md)\n"
    "  --version              version, source revision and precision\n"
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
    if (argc >= 2 && !strcmp(argv[1], "modes"))
        return finish(cli_modes(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "run"))
        return finish(cli_run(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "gen"))
        return finish(cli_gen(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "sweep"))
        return finish(cli_sweep(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "twin"))
        return finish(cli_twin(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "twin-plant"))
        return finish(cli_twin_plant_command(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "twin-gains"))
        return finish(cli_twin_gains_command(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "map"))
        return finish(cli_map(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "map-merge"))
        return finish(cli_map_merge(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "map-plot"))
        return finish(cli_map_plot(argc - 2, argv + 2));
    if (argc >= 2 && !strcmp(argv[1], "fields"))
        return finish(cli_fields(argc - 2, argv + 2));
    if (argc == 2 && !strcmp(argv[1], "--version")) {
        printf("beamslider %s (revision %s), core precision %s\n", bs_version(), BS_REVISION, BS_REAL_NAME);
        return finish(CLI_OK);
    }
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        fputs(usage, stdout);
        return finish(CLI_OK);
    }
    if (argc >= 2)
        cli_error("unknown command '%s'", argv[1]);
    fputs(usage, stderr);
    return CLI_USAGE;
}
