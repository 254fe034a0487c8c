/* cli_map_plot.c - `beamslider map-plot DIR`: heatmaps of a map's merged
 * table (DIR/map.csv) over two of its varied fields, drawn by gnuplot
 * (Debian's gnuplot-nox; docs/maps.md section 5). The options, and running
 * gnuplot: what is drawn is the map wing's (host/lib/map/map_plot.h).
 *
 * Writes PREFIX.dat (the grid, one line per point, NaN where a class or a
 * number is missing) and PREFIX.gp (the gnuplot script, kept so that a
 * figure can be restyled by hand), then runs gnuplot on it: PREFIX_outcome,
 * _agreement, _s_settled, _s_spread, _amp_h and, when the scene has a
 * transducer, _power (.png). Cells are grid indices, so that a list of
 * values as uneven as 1,2,5,10 still gives equal cells; the tics name the
 * values. Fields varied beyond the two plotted are fixed with --at.
 *
 * The folder is input: its identity (map_identity_read) and map.csv
 * (map_table_point_parse) are checked line by line before anything is
 * written, and every text in the script (the scene's name, --title, the
 * values, the labels of --mark, the paths) goes through the gnuplot writer
 * (out_gnuplot.h): single-quoted strings, which gnuplot never substitutes.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "cli.h"
#include "map_grid.h"
#include "map_plot.h"
#include "map_store.h"
#include "out_gnuplot.h"

const char cli_map_plot_synopsis[] =
    "beamslider map-plot DIR [--x FIELD] [--y FIELD] [--at FIELD=VALUE ...] [--mark X,Y,LABEL ...]\n"
    "        [--title TEXT] [--out PREFIX]";
const char cli_map_plot_help[] =
    "  heatmaps of a map with gnuplot (docs/maps.md section 5)\n"
    "  Of DIR/map.csv (beamslider map, then map-merge for shards) over two varied fields (default: the first two --vary of the map): outcome class (the class\n"
    "  most starts ended in), agreement (the fraction that did), final position s_final (mean\n"
    "  and spread over the starts), settled amplitude amp_h and, with a transducer, power.\n"
    "  --at fixes every other varied field; --mark draws a labelled point at field values\n"
    "  X,Y; --title starts each title (default: the scene's name). PNGs PREFIX_outcome.png,\n"
    "  ... (default PREFIX: DIR/plot); needs gnuplot (Debian: gnuplot-nox).\n";

#define MAX_MARKS MAP_PLOT_MARKS

typedef struct plot_cli {
    const char *dir, *x, *y, *prefix, *title;
    const char *at[MAP_MAX_VARY];
    int at_count;
    const char *mark[MAX_MARKS];
    int mark_count;
} plot_cli;

static int parse_options(int argc, char **argv, plot_cli *cli)
{
    int i;
    memset(cli, 0, sizeof *cli);
    if (argc < 1 || argv[0][0] == '-') {
        cli_error("map-plot needs the map's folder first: beamslider map-plot DIR (beamslider map-plot --help)");
        return -1;
    }
    cli->dir = argv[0];
    for (i = 1; i < argc; i += 2) {
        const char *option = argv[i], *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (!value) {
            cli_error("option %s needs a value", option);
            return -1;
        }
        if (!strcmp(option, "--x"))
            cli->x = value;
        else if (!strcmp(option, "--y"))
            cli->y = value;
        else if (!strcmp(option, "--out"))
            cli->prefix = value;
        else if (!strcmp(option, "--title"))
            cli->title = value;
        else if (!strcmp(option, "--at") && cli->at_count < MAP_MAX_VARY)
            cli->at[cli->at_count++] = value;
        else if (!strcmp(option, "--mark") && cli->mark_count < MAX_MARKS)
            cli->mark[cli->mark_count++] = value;
        else {
            cli_error("unknown option '%s', or too many of it (beamslider map-plot --help)", option);
            return -1;
        }
    }
    return 0;
}

static int vary_named(const map_grid *grid, const char *name)
{
    int v;
    for (v = 0; v < grid->vary_count; ++v)
        if (!strcmp(grid->vary[v].name, name))
            return v;
    return -1;
}

/* The gnuplot on PATH, into found; 0, or -1 if there is none. */
static int find_gnuplot(char *found, size_t size)
{
    const char *path = getenv("PATH");
    const char *at = path && *path ? path : "/usr/bin:/bin";
    while (*at) {
        const size_t n = strcspn(at, ":");
        snprintf(found, size, "%.*s%sgnuplot", (int)n, at, n ? "/" : "./");
        if (access(found, X_OK) == 0)
            return 0;
        at += n + (at[n] == ':');
    }
    return -1;
}

/* Runs program (gnuplot) on script. 0; -1 after reporting why: it could not
 * be started (the child tells the exec's errno through a pipe that a
 * successful exec closes), or it failed (its messages went to stderr). */
static int run_gnuplot(const char *program, const char *script)
{
    char argument[4400];
    int status, report[2], why = 0;
    pid_t pid;

    /* a script named -x.gp would be read as an option */
    snprintf(argument, sizeof argument, "%s%s", script[0] == '/' ? "" : "./", script);
    if (pipe(report) != 0) {
        cli_error("cannot start gnuplot: %s", strerror(errno));
        return -1;
    }
    if (fcntl(report[1], F_SETFD, FD_CLOEXEC) != 0) {
        cli_error("cannot start gnuplot: %s", strerror(errno));
        close(report[0]);
        close(report[1]);
        return -1;
    }
    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid == 0) {
        close(report[0]);
        execl(program, "gnuplot", argument, (char *)NULL);
        why = errno;
        _exit(write(report[1], &why, sizeof why) == (ssize_t)sizeof why ? 127 : 126);
    }
    close(report[1]);
    if (pid < 0) {
        cli_error("cannot start gnuplot: %s", strerror(errno));
        close(report[0]);
        return -1;
    }
    if (read(report[0], &why, sizeof why) != (ssize_t)sizeof why)
        why = 0;
    close(report[0]);
    if (waitpid(pid, &status, 0) != pid) {
        cli_error("gnuplot %s: cannot wait for it: %s", argument, strerror(errno));
        return -1;
    }
    if (why) {
        cli_error("cannot run %s: %s", program, strerror(why));
        return -1;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        cli_error("gnuplot %s failed (%s %d; its messages are above)", argument,
                  WIFEXITED(status) ? "exit status" : "signal",
                  WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
        return -1;
    }
    return 0;
}

int cli_map_plot(int argc, char **argv)
{
    plot_cli cli;
    map_grid grid;
    map_plot plot;
    char err[4800], scene[SCENE_TEXT], prefix[4200], path[4300], gnuplot[4200];
    int vx, vy, v, k, status = CLI_USAGE;
    size_t n_cells, c;

    if (parse_options(argc, argv, &cli) != 0)
        return CLI_USAGE;
    if (strlen(cli.prefix ? cli.prefix : cli.dir) > 4000) {
        cli_error("%s: too long a name for the pictures; name them with --out PREFIX",
                  cli.prefix ? "--out" : cli.dir);
        return CLI_USAGE;
    }
    if (cli.prefix)
        snprintf(prefix, sizeof prefix, "%s", cli.prefix);
    else
        snprintf(prefix, sizeof prefix, "%s/plot", cli.dir);
    if (!out_gnuplot_path_ok(prefix)) {
        cli_error("%s: the pictures' names would hold a control character (a line break?); %s",
                  cli.prefix ? "--out" : cli.dir, cli.prefix ? "choose another PREFIX" : "name them with --out PREFIX");
        return CLI_USAGE;
    }
    if (map_identity_read(cli.dir, &grid, scene, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    memset(&plot, 0, sizeof plot);
    plot.grid = &grid;
    plot.scene = cli.title ? cli.title : scene;
    vx = cli.x ? vary_named(&grid, cli.x) : 0;
    vy = cli.y ? vary_named(&grid, cli.y) : 1;
    if (grid.vary_count < 2 || vx < 0 || vy < 0 || vx == vy || vy >= grid.vary_count) {
        cli_error("map-plot draws over two different varied fields of the map (--x, --y); %s varies %d", cli.dir,
                  grid.vary_count);
        goto done;
    }
    plot.vx = vx;
    plot.vy = vy;
    for (v = 0; v < grid.vary_count; ++v)
        plot.at_index[v] = -1;
    for (k = 0; k < cli.at_count; ++k) {
        const char *equals = strchr(cli.at[k], '=');
        char name[MAP_FIELD];
        snprintf(name, sizeof name, "%.*s", equals ? (int)(equals - cli.at[k]) : 0, cli.at[k]);
        v = vary_named(&grid, name);
        if (!equals || v < 0 || v == vx || v == vy) {
            cli_error("--at %s: expected FIELD=VALUE of a varied field other than --x and --y", cli.at[k]);
            goto done;
        }
        for (plot.at_index[v] = 0; plot.at_index[v] < grid.vary[v].count; ++plot.at_index[v])
            if (!strcmp(grid.vary[v].values[plot.at_index[v]], equals + 1))
                break;
        if (plot.at_index[v] == grid.vary[v].count) {
            cli_error("--at %s: %s is not one of the map's values of %s", cli.at[k], equals + 1, name);
            goto done;
        }
    }
    for (v = 0; v < grid.vary_count; ++v)
        if (v != vx && v != vy && plot.at_index[v] < 0) {
            if (grid.vary[v].count > 1) {
                cli_error("%s is varied too: fix it with --at %s=VALUE", grid.vary[v].name, grid.vary[v].name);
                goto done;
            }
            plot.at_index[v] = 0;
        }
    for (k = 0; k < cli.mark_count; ++k) { /* checked before anything is read or written */
        char x[64], y[64];
        if (sscanf(cli.mark[k], "%63[^,],%63[^,],%159[^\n]", x, y, plot.mark_label[k]) != 3
            || (plot.mark_x[k] = map_plot_position(&grid.vary[vx], x)) < 0
            || (plot.mark_y[k] = map_plot_position(&grid.vary[vy], y)) < 0) {
            cli_error("--mark %s: expected X,Y,LABEL with X and Y within the map's values of %s and %s",
                      cli.mark[k], grid.vary[vx].name, grid.vary[vy].name);
            goto done;
        }
    }
    plot.mark_count = cli.mark_count;
    /* the grid's points bound the two counts (MAP_MAX_CASES): no overflow */
    n_cells = (size_t)grid.vary[vx].count * (size_t)grid.vary[vy].count;
    plot.cells = malloc(n_cells * MAP_PLOT_FIGURES * sizeof *plot.cells);
    if (!plot.cells) {
        cli_error("out of memory for %lu cells", (unsigned long)n_cells);
        status = CLI_FAILED;
        goto done;
    }
    for (c = 0; c < n_cells * MAP_PLOT_FIGURES; ++c)
        plot.cells[c] = (double)NAN;
    if (map_plot_read(cli.dir, &plot, err, sizeof err) != 0) {
        cli_error("%s", err);
        goto done; /* CLI_USAGE: the folder is bad input */
    }
    status = CLI_FAILED; /* from here on, what fails is the work */
    if (find_gnuplot(gnuplot, sizeof gnuplot) != 0) {
        cli_error("gnuplot is not installed (no gnuplot on PATH; Debian: apt-get install gnuplot-nox): "
                  "no picture drawn, nothing written");
        goto done;
    }
    if (map_plot_write(prefix, cli.dir, &plot, err, sizeof err) != 0) {
        cli_error("%s", err);
        goto done;
    }
    snprintf(path, sizeof path, "%s.gp", prefix);
    if (run_gnuplot(gnuplot, path) != 0)
        goto done;
    fprintf(stderr, "map-plot: wrote %s_{outcome,agreement,s_settled%s,amp_h%s}.png\n", prefix,
            plot.has[MAP_PLOT_SPREAD] ? ",s_spread" : "", plot.has[MAP_PLOT_POWER] ? ",power" : "");
    status = CLI_OK;
done:
    free(plot.cells);
    map_grid_free(&grid);
    return status;
}
