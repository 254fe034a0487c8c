/* cli_map_plot.c - `beamslider map-plot DIR`: heatmaps of a map's merged
 * table (DIR/map.csv) over two of its varied fields, drawn by gnuplot
 * (Debian's gnuplot-nox; docs/maps.md section 5).
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
#include "input_file.h"
#include "map_grid.h"
#include "map_store.h"
#include "map_table.h"
#include "out_gnuplot.h"
#include "outcome.h"

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

#define MAX_MARKS 16

/* One value per cell and figure. */
enum { FIG_OUTCOME, FIG_AGREEMENT, FIG_S, FIG_SPREAD, FIG_AMP, FIG_POWER, FIG_WINDOW, FIGURES };

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

/* The grid position of value text of field v: an index, fractional between
 * two numeric values; -1 if outside. */
static double position_of(const map_vary *vary, const char *text)
{
    char *end;
    const double x = strtod(text, &end);
    int k;
    for (k = 0; k < vary->count; ++k)
        if (!strcmp(vary->values[k], text))
            return k;
    if (*end || end == text)
        return -1.0;
    for (k = 0; k + 1 < vary->count; ++k) {
        const double a = strtod(vary->values[k], NULL), b = strtod(vary->values[k + 1], NULL);
        if ((x - a) * (x - b) <= 0.0 && a != b)
            return k + (x - a) / (b - a);
    }
    return -1.0;
}

/* A field name with its unit, for an axis. */
static void axis_label(const map_vary *vary, char *out, size_t size)
{
    const char *unit = vary->field >= 0 ? scene_fields[vary->field].unit : "";
    snprintf(out, size, *unit ? "%s [%s]" : "%s%s", vary->name, unit);
}

/* gnuplot tics naming at most 13 of the values. */
static void write_tics(FILE *gp, const char *axis, const map_vary *vary)
{
    const int every = (vary->count + 12) / 13;
    int k;
    fprintf(gp, "set %stics (", axis);
    for (k = 0; k < vary->count; k += every) {
        fputs(k ? ", " : "", gp);
        out_gnuplot_string(gp, vary->values[k]);
        fprintf(gp, " %d", k);
    }
    fprintf(gp, ")\n");
}

/* Reads map.csv into cells[(iy * nx + ix) * FIGURES + figure] for the rows
 * at the --at values. The table must be whole: its header, one row per
 * grid point in order, each as map-merge writes it, and nothing after.
 * 0, or -1 after reporting the file and line. */
static int read_table(const char *dir, const map_grid *grid, int vx, int vy, const int *at_index, double *cells)
{
    char path[4200], line[4096], header[MAP_POINTS_HEADER], why[256];
    long number = 0, point = 0;
    FILE *in;
    int failed = 0;

    snprintf(path, sizeof path, "%s/%s", dir, MAP_POINTS_TABLE);
    {
        char err[4600];
        const char *verb;
        if (input_file_open_why(path, INPUT_MAP_TABLE, &in, NULL, &verb, err, sizeof err) != 0) {
            if (!strcmp(verb, "open"))
                cli_error("%s: %s (all cases done? beamslider map-merge %s writes it)", path, err, dir);
            else
                cli_error("%s: cannot read %s: %s", path, input_kind_name(INPUT_MAP_TABLE), err);
            return -1;
        }
    }
    map_table_points_header(grid, header, sizeof header);
    while (!failed && fgets(line, sizeof line, in)) {
        const size_t length = strlen(line);
        map_point_figures figures;
        long cell;
        int v, skip = 0;
        ++number;
        if (length == 0 || line[length - 1] != '\n') {
            snprintf(why, sizeof why, length + 1 == sizeof line ? "line too long" : "the last line is cut short");
            failed = 1;
            break;
        }
        line[length - 1] = '\0';
        if (number == 1) {
            if (strcmp(line, header)) {
                snprintf(why, sizeof why, "not the header of this map's table (%.60s...)", header);
                failed = 1;
            }
            continue;
        }
        if (point >= grid->points) {
            snprintf(why, sizeof why, "more rows than the map's %ld grid points", grid->points);
            failed = 1;
            break;
        }
        if (map_table_point_parse(grid, point, line, &figures, why, sizeof why) != 0) {
            failed = 1;
            break;
        }
        ++point;
        for (v = 0; v < grid->vary_count; ++v)
            skip |= at_index[v] >= 0 && map_point_value(grid, figures.point, v) != at_index[v];
        if (skip)
            continue;
        cell = (long)map_point_value(grid, figures.point, vy) * grid->vary[vx].count
               + map_point_value(grid, figures.point, vx);
        cells[cell * FIGURES + FIG_OUTCOME] = figures.outcome;
        cells[cell * FIGURES + FIG_AGREEMENT] = figures.agreement;
        cells[cell * FIGURES + FIG_S] = figures.s_settled_mean;
        cells[cell * FIGURES + FIG_SPREAD] = figures.s_settled_sd;
        cells[cell * FIGURES + FIG_AMP] = figures.amp_h_mean;
        cells[cell * FIGURES + FIG_POWER] = figures.power_w_mean;
        cells[cell * FIGURES + FIG_WINDOW] = figures.window_s;
    }
    if (!failed && ferror(in)) {
        cli_error("%s: %s", path, strerror(errno));
        fclose(in);
        return -1;
    }
    if (!failed && point < grid->points) {
        snprintf(why, sizeof why, "%ld of the map's %ld grid points have no row (cut short?)", grid->points - point,
                 grid->points);
        failed = 1;
        number = 0;
    }
    fclose(in);
    if (failed) {
        if (number > 0)
            cli_error("%s:%ld: %s; not a table as map-merge writes it (run beamslider map-merge %s again)", path,
                      number, why, dir);
        else
            cli_error("%s: %s; not a table as map-merge writes it (run beamslider map-merge %s again)", path, why,
                      dir);
        return -1;
    }
    return 0;
}

/* The settled window the plotted runs had, for the titles: "last 10 s",
 * "last 2 s" (a map of 2 s runs), "last 2 to 10 s" when the runs differ
 * (a varied t_end); "settled window" when no run completed. */
static void window_text(const double *cells, size_t n_cells, char *out, size_t size)
{
    double low = HUGE_VAL, high = -HUGE_VAL;
    size_t c;
    for (c = 0; c < n_cells; ++c) {
        const double w = cells[c * FIGURES + FIG_WINDOW];
        if (isfinite(w)) {
            low = fmin(low, w);
            high = fmax(high, w);
        }
    }
    if (!(low <= high))
        snprintf(out, size, "settled window");
    else if (low == high)
        snprintf(out, size, "last %.3g s", low);
    else
        snprintf(out, size, "last %.3g to %.3g s", low, high);
}

static void write_figure(FILE *gp, const char *prefix, const char *name, const char *title, int column,
                         const char *scene, int repeat, int marks)
{
    char text[4400];
    fprintf(gp, "set output ");
    snprintf(text, sizeof text, "%s_%s.png", prefix, name);
    out_gnuplot_path(gp, text);
    fprintf(gp, "\nset title "); /* two lines: the map, the figure */
    out_gnuplot_string(gp, scene);
    fprintf(gp, " . \"\\n\" . ");
    snprintf(text, sizeof text, "%s (%d start%s per point)", title, repeat, repeat > 1 ? "s" : "");
    out_gnuplot_string(gp, text);
    fprintf(gp, "\nplot grid using 1:2:%d with image notitle", column);
    if (marks)
        fprintf(gp, ", \\\n     marks using 1:2 with points pt 7 ps 1.3 lc rgb 'white' notitle, \\\n"
                    "     marks using 1:2 with points pt 6 ps 1.3 lc rgb 'black' notitle");
    fputc('\n', gp);
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

/* Writes the script to path: every text through the gnuplot writer. 0, or -1. */
static int write_script(const char *path, const plot_cli *cli, const map_grid *grid, int vx, int vy,
                        const char *prefix, const char *scene, const int *has, const double *mark_x,
                        const double *mark_y, char mark_label[][160], const char *window)
{
    char text[4400], label[160];
    FILE *out = fopen(path, "w");
    int k, failed;

    if (!out)
        return -1;
    snprintf(text, sizeof text, "written by beamslider map-plot %s (docs/maps.md); run: gnuplot %s", cli->dir, path);
    out_gnuplot_comment(out, text);
    fprintf(out, "set terminal pngcairo size 1000,700 font 'sans,11' noenhanced\n");
    fprintf(out, "grid = ");
    snprintf(text, sizeof text, "%s.dat", prefix);
    out_gnuplot_path(out, text);
    fprintf(out, "\nmarks = ");
    snprintf(text, sizeof text, "%s_marks.dat", prefix);
    out_gnuplot_path(out, text);
    fprintf(out, "\nset datafile missing 'NaN'\nset xrange [-0.5:%d.5]\nset yrange [-0.5:%d.5]\n",
            grid->vary[vx].count - 1, grid->vary[vy].count - 1);
    write_tics(out, "x", &grid->vary[vx]);
    write_tics(out, "y", &grid->vary[vy]);
    axis_label(&grid->vary[vx], label, sizeof label);
    fprintf(out, "set xlabel ");
    out_gnuplot_string(out, label);
    axis_label(&grid->vary[vy], label, sizeof label);
    fprintf(out, "\nset ylabel ");
    out_gnuplot_string(out, label);
    fprintf(out, "\nset tics out nomirror\nset rmargin 24\n");
    for (k = 0; k < cli->mark_count; ++k) {
        fprintf(out, "set label %d ", k + 1);
        out_gnuplot_string(out, mark_label[k]);
        fprintf(out, " at %.6g,%.6g left offset 0.9,0.5 tc rgb 'black' font ',10' front\n", mark_x[k], mark_y[k]);
    }
    fprintf(out, "set palette maxcolors %d\nset palette defined (", OUTCOME_CLASSES);
    for (k = 0; k < OUTCOME_CLASSES; ++k)
        fprintf(out, "%s%d '%s'", k ? ", " : "", k, outcome_colour((outcome_class)k));
    fprintf(out, ")\nset cbrange [-0.5:%d.5]\nset cbtics (", OUTCOME_CLASSES - 1);
    for (k = 0; k < OUTCOME_CLASSES; ++k) {
        fprintf(out, "%s", k ? ", " : "");
        out_gnuplot_string(out, outcome_label((outcome_class)k));
        fprintf(out, " %d", k);
    }
    fprintf(out, ")\n");
    write_figure(out, prefix, "outcome", "outcome class: the class most starts ended in", 3, scene, grid->repeat, cli->mark_count > 0);
    fprintf(out, "set palette maxcolors 0\nset palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21908d', "
                 "0.75 '#5dc863', 1 '#fde725')\nset cbtics auto\n");
    fprintf(out, "set cbrange [0:1]\nset cblabel 'fraction of the starts'\n");
    write_figure(out, prefix, "agreement", "agreement: the fraction of the starts in that class", 4, scene,
                 grid->repeat, cli->mark_count > 0);
    fprintf(out, "set cbrange [*:*]\nset cblabel 's = x_C / L'\n");
    snprintf(text, sizeof text, "settled position s_settled: mean s over the %s, mean of the starts", window);
    write_figure(out, prefix, "s_settled", text, 5, scene, grid->repeat, cli->mark_count > 0);
    fprintf(out, "set cblabel 'standard deviation of s_settled'\n");
    if (has[FIG_SPREAD]) {
        snprintf(text, sizeof text, "spread of s_settled (the %s): standard deviation over the starts", window);
        write_figure(out, prefix, "s_spread", text, 6, scene, grid->repeat, cli->mark_count > 0);
    }
    fprintf(out, "set cblabel 'w(4L/7) / h'\n");
    snprintf(text, sizeof text, "settled amplitude amp_h: the %s, mean of the starts", window);
    write_figure(out, prefix, "amp_h", text, 7, scene, grid->repeat, cli->mark_count > 0);
    if (has[FIG_POWER]) {
        fprintf(out, "set cblabel 'W'\n");
        snprintf(text, sizeof text, "harvested power: the %s, mean of the starts", window);
        write_figure(out, prefix, "power", text, 8, scene, grid->repeat, cli->mark_count > 0);
    }
    failed = ferror(out) != 0;
    failed |= fclose(out) != 0;
    return failed ? -1 : 0;
}

/* Writes the grid's cells (one line per cell, a blank line per row of y:
 * gnuplot's image format) to path, and sets has[figure] when a figure has
 * a value. 0, or -1. */
static int write_grid(const char *path, const map_grid *grid, int vx, int vy, const double *cells, int *has)
{
    FILE *out = fopen(path, "w");
    int ix, iy, k, failed;
    if (!out)
        return -1;
    fprintf(out, "# ix iy outcome agreement s_settled_mean s_settled_sd amp_h_mean power_w_mean window_s\n");
    for (iy = 0; iy < grid->vary[vy].count; ++iy) {
        for (ix = 0; ix < grid->vary[vx].count; ++ix) {
            const double *cell = cells + ((size_t)iy * (size_t)grid->vary[vx].count + (size_t)ix) * FIGURES;
            fprintf(out, "%d %d", ix, iy);
            for (k = 0; k < FIGURES; ++k) {
                fprintf(out, isfinite(cell[k]) ? " %.9g" : " NaN", cell[k]);
                has[k] |= isfinite(cell[k]) != 0;
            }
            fputc('\n', out);
        }
        fputc('\n', out);
    }
    failed = ferror(out) != 0;
    failed |= fclose(out) != 0;
    return failed ? -1 : 0;
}

/* The --mark points in grid positions (their labels are in the script). 0, or -1. */
static int write_marks(const char *path, const double *mark_x, const double *mark_y, int count)
{
    FILE *out = fopen(path, "w");
    int k, failed;
    if (!out)
        return -1;
    fprintf(out, "# x y: the --mark points in grid positions\n");
    for (k = 0; k < count; ++k)
        fprintf(out, "%.6g %.6g\n", mark_x[k], mark_y[k]);
    failed = ferror(out) != 0;
    failed |= fclose(out) != 0;
    return failed ? -1 : 0;
}

int cli_map_plot(int argc, char **argv)
{
    plot_cli cli;
    map_grid grid;
    char err[2048], scene[SCENE_TEXT], prefix[4200], path[4300], gnuplot[4200], window[64];
    int at_index[MAP_MAX_VARY];
    double mark_x[MAX_MARKS], mark_y[MAX_MARKS];
    char mark_label[MAX_MARKS][160];
    double *cells = NULL;
    int has[FIGURES] = { 0 }; /* figures with a value to draw (a spread needs two starts) */
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
    if (cli.title)
        snprintf(scene, sizeof scene, "%s", cli.title);
    vx = cli.x ? vary_named(&grid, cli.x) : 0;
    vy = cli.y ? vary_named(&grid, cli.y) : 1;
    if (grid.vary_count < 2 || vx < 0 || vy < 0 || vx == vy || vy >= grid.vary_count) {
        cli_error("map-plot draws over two different varied fields of the map (--x, --y); %s varies %d", cli.dir,
                  grid.vary_count);
        goto done;
    }
    for (v = 0; v < grid.vary_count; ++v)
        at_index[v] = -1;
    for (k = 0; k < cli.at_count; ++k) {
        const char *equals = strchr(cli.at[k], '=');
        char name[MAP_FIELD];
        snprintf(name, sizeof name, "%.*s", equals ? (int)(equals - cli.at[k]) : 0, cli.at[k]);
        v = vary_named(&grid, name);
        if (!equals || v < 0 || v == vx || v == vy) {
            cli_error("--at %s: expected FIELD=VALUE of a varied field other than --x and --y", cli.at[k]);
            goto done;
        }
        for (at_index[v] = 0; at_index[v] < grid.vary[v].count; ++at_index[v])
            if (!strcmp(grid.vary[v].values[at_index[v]], equals + 1))
                break;
        if (at_index[v] == grid.vary[v].count) {
            cli_error("--at %s: %s is not one of the map's values of %s", cli.at[k], equals + 1, name);
            goto done;
        }
    }
    for (v = 0; v < grid.vary_count; ++v)
        if (v != vx && v != vy && at_index[v] < 0) {
            if (grid.vary[v].count > 1) {
                cli_error("%s is varied too: fix it with --at %s=VALUE", grid.vary[v].name, grid.vary[v].name);
                goto done;
            }
            at_index[v] = 0;
        }
    for (k = 0; k < cli.mark_count; ++k) { /* checked before anything is read or written */
        char x[64], y[64];
        if (sscanf(cli.mark[k], "%63[^,],%63[^,],%159[^\n]", x, y, mark_label[k]) != 3
            || (mark_x[k] = position_of(&grid.vary[vx], x)) < 0 || (mark_y[k] = position_of(&grid.vary[vy], y)) < 0) {
            cli_error("--mark %s: expected X,Y,LABEL with X and Y within the map's values of %s and %s",
                      cli.mark[k], grid.vary[vx].name, grid.vary[vy].name);
            goto done;
        }
    }
    /* the grid's points bound the two counts (MAP_MAX_CASES): no overflow */
    n_cells = (size_t)grid.vary[vx].count * (size_t)grid.vary[vy].count;
    cells = malloc(n_cells * FIGURES * sizeof *cells);
    if (!cells) {
        cli_error("out of memory for %lu cells", (unsigned long)n_cells);
        status = CLI_FAILED;
        goto done;
    }
    for (c = 0; c < n_cells * FIGURES; ++c)
        cells[c] = (double)NAN;
    if (read_table(cli.dir, &grid, vx, vy, at_index, cells) != 0)
        goto done; /* CLI_USAGE: the folder is bad input */
    status = CLI_FAILED; /* from here on, what fails is the work */
    if (find_gnuplot(gnuplot, sizeof gnuplot) != 0) {
        cli_error("gnuplot is not installed (no gnuplot on PATH; Debian: apt-get install gnuplot-nox): "
                  "no picture drawn, nothing written");
        goto done;
    }
    snprintf(path, sizeof path, "%s.dat", prefix);
    if (write_grid(path, &grid, vx, vy, cells, has) != 0) {
        cli_error("cannot write %s: %s", path, strerror(errno));
        goto done;
    }
    snprintf(path, sizeof path, "%s_marks.dat", prefix);
    if (write_marks(path, mark_x, mark_y, cli.mark_count) != 0) {
        cli_error("cannot write %s: %s", path, strerror(errno));
        goto done;
    }
    snprintf(path, sizeof path, "%s.gp", prefix);
    window_text(cells, n_cells, window, sizeof window);
    if (write_script(path, &cli, &grid, vx, vy, prefix, scene, has, mark_x, mark_y, mark_label, window) != 0) {
        cli_error("cannot write %s: %s", path, strerror(errno));
        goto done;
    }
    if (run_gnuplot(gnuplot, path) != 0)
        goto done;
    fprintf(stderr, "map-plot: wrote %s_{outcome,agreement,s_settled%s,amp_h%s}.png\n", prefix,
            has[FIG_SPREAD] ? ",s_spread" : "", has[FIG_POWER] ? ",power" : "");
    status = CLI_OK;
done:
    free(cells);
    map_grid_free(&grid);
    return status;
}
