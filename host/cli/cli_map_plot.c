/* cli_map_plot.c - `beamslider map-plot DIR`: heatmaps of a map's merged
 * table (DIR/map.csv) over two of its varied fields, drawn by gnuplot
 * (Debian's gnuplot-nox; docs/maps.md section 5).
 *
 * Writes PREFIX.dat (the grid, one line per point, NaN where a class or a
 * number is missing) and PREFIX.gp (the gnuplot script, kept so that a
 * figure can be restyled by hand), then runs gnuplot on it: PREFIX_outcome,
 * _agreement, _s_final, _s_spread, _amp_h and, when the scene has a
 * transducer, _power (.png). Cells are grid indices, so that a list of
 * values as uneven as 1,2,5,10 still gives equal cells; the tics name the
 * values. Fields varied beyond the two plotted are fixed with --at.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "cli.h"
#include "map_grid.h"
#include "map_store.h"
#include "map_table.h"
#include "outcome.h"

static const char plot_usage[] =
    "usage: beamslider map-plot DIR [--x FIELD] [--y FIELD] [--at FIELD=VALUE ...]\n"
    "                           [--mark X,Y,LABEL ...] [--title TEXT] [--out PREFIX]\n"
    "  heatmaps of DIR/map.csv (beamslider map, then map-merge for shards) over two varied\n"
    "  fields (default: the first two --vary of the map): outcome class (the class most\n"
    "  starts ended in), agreement (the fraction that did), final position s_final (mean\n"
    "  and spread over the starts), settled amplitude amp_h and, with a transducer, power.\n"
    "  --at fixes every other varied field; --mark draws a labelled point at field values\n"
    "  X,Y; --title starts each title (default: the scene's name). PNGs PREFIX_outcome.png,\n"
    "  ... (default PREFIX: DIR/plot); needs gnuplot (Debian: gnuplot-nox).\n";

#define MAX_MARKS 16

/* One value per cell and figure. */
enum { FIG_OUTCOME, FIG_AGREEMENT, FIG_S, FIG_SPREAD, FIG_AMP, FIG_POWER, FIGURES };
static const char *const figure_column[FIGURES] = { "outcome", "agreement", "s_final_mean", "s_final_sd",
                                                    "amp_h_mean", "power_w_mean" };

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
    for (k = 0; k < vary->count; k += every)
        fprintf(gp, "%s\"%s\" %d", k ? ", " : "", vary->values[k], k);
    fprintf(gp, ")\n");
}

/* The column indices of map.csv's header line for the figures. */
static int find_columns(const char *header, int *index)
{
    int f, column;
    for (f = 0; f < FIGURES; ++f) {
        const char *at = header;
        index[f] = -1;
        for (column = 0; at; ++column) {
            const size_t n = strcspn(at, ",\n");
            if (n == strlen(figure_column[f]) && !strncmp(at, figure_column[f], n))
                index[f] = column;
            at = at[n] == ',' ? at + n + 1 : NULL;
        }
        if (index[f] < 0)
            return -1;
    }
    return 0;
}

/* Reads map.csv into cells[(iy * nx + ix) * FIGURES + figure] for the rows
 * at the --at values; 0 or -1 after reporting. */
static int read_table(const char *dir, const map_grid *grid, int vx, int vy, const int *at_index, double *cells)
{
    char path[4200];
    char *line = NULL;
    size_t capacity = 0;
    int index[FIGURES];
    FILE *in;
    int ok = 0;

    snprintf(path, sizeof path, "%s/%s", dir, MAP_POINTS_TABLE);
    in = fopen(path, "r");
    if (!in) {
        cli_error("%s: %s (all cases done? beamslider map-merge %s writes it)", path, strerror(errno), dir);
        return -1;
    }
    if (getline(&line, &capacity, in) <= 0 || find_columns(line, index) != 0) {
        cli_error("%s: not a map table (no header with %s)", path, figure_column[0]);
        goto done;
    }
    while (getline(&line, &capacity, in) > 0) {
        const long point = strtol(line, NULL, 10);
        long cell;
        int v, f, skip = 0;
        if (point < 0 || point >= grid->points)
            continue;
        for (v = 0; v < grid->vary_count; ++v)
            skip |= at_index[v] >= 0 && map_point_value(grid, point, v) != at_index[v];
        if (skip)
            continue;
        cell = (long)map_point_value(grid, point, vy) * grid->vary[vx].count + map_point_value(grid, point, vx);
        for (f = 0; f < FIGURES; ++f) {
            const char *at = line;
            int c;
            for (c = 0; c < index[f] && at; ++c)
                at = strchr(at, ',') ? strchr(at, ',') + 1 : NULL;
            if (!at)
                continue;
            if (f == FIG_OUTCOME) {
                char name[32];
                snprintf(name, sizeof name, "%.*s", (int)strcspn(at, ",\n"), at);
                cells[cell * FIGURES + f] = outcome_from_name(name) >= 0 ? outcome_from_name(name) : (double)NAN;
            } else {
                cells[cell * FIGURES + f] = strtod(at, NULL);
            }
        }
    }
    ok = 1;
done:
    free(line);
    fclose(in);
    return ok ? 0 : -1;
}

/* A text inside a gnuplot double-quoted string. */
static void quoted(FILE *gp, const char *text)
{
    fputc('"', gp);
    for (; *text; ++text) {
        if (*text == '"' || *text == '\\')
            fputc('\\', gp);
        fputc(*text, gp);
    }
    fputc('"', gp);
}

static void write_figure(FILE *gp, const char *prefix, const char *name, const char *title, int column,
                         const char *scene, int repeat, int marks)
{
    char text[4400];
    fprintf(gp, "set output ");
    snprintf(text, sizeof text, "%s_%s.png", prefix, name);
    quoted(gp, text);
    fprintf(gp, "\nset title "); /* two lines: the map, the figure */
    quoted(gp, scene);
    fprintf(gp, " . \"\\n\" . ");
    snprintf(text, sizeof text, "%s (%d start%s per point)", title, repeat, repeat > 1 ? "s" : "");
    quoted(gp, text);
    fprintf(gp, "\nplot grid using 1:2:%d with image notitle", column);
    if (marks)
        fprintf(gp, ", \\\n     marks using 1:2 with points pt 7 ps 1.3 lc rgb 'white' notitle, \\\n"
                    "     marks using 1:2 with points pt 6 ps 1.3 lc rgb 'black' notitle, \\\n"
                    "     marks using 1:2:3 with labels left offset 0.9,0.5 tc rgb 'black' font ',10' notitle");
    fputc('\n', gp);
}

static int run_gnuplot(const char *script)
{
    int status;
    const pid_t pid = fork();
    if (pid == 0) {
        execlp("gnuplot", "gnuplot", script, (char *)NULL);
        fprintf(stderr, "beamslider: error: cannot run gnuplot: %s (Debian: apt-get install gnuplot-nox)\n",
                strerror(errno));
        _exit(127);
    }
    if (pid < 0 || waitpid(pid, &status, 0) != pid)
        return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

int cli_map_plot(int argc, char **argv)
{
    static const char *const class_colour[OUTCOME_CLASSES] = { "#2ca02c", "#1f77b4", "#ff7f0e", "#b0b0b0",
                                                               "#8c564b", "#d62728", "#e377c2" };
    plot_cli cli;
    map_grid grid;
    char err[2048], scene[SCENE_TEXT], prefix[4200], path[4300], label[160];
    int at_index[MAP_MAX_VARY];
    double mark_x[MAX_MARKS], mark_y[MAX_MARKS];
    char mark_label[MAX_MARKS][160];
    double *cells = NULL;
    int has[FIGURES] = { 0 }; /* figures with a value to draw (a spread needs two starts) */
    int vx, vy, v, k, ix, iy, status = CLI_USAGE;
    FILE *out;

    if (argc >= 1 && (!strcmp(argv[0], "--help") || !strcmp(argv[0], "-h"))) {
        fputs(plot_usage, stdout);
        return CLI_OK;
    }
    if (parse_options(argc, argv, &cli) != 0)
        return CLI_USAGE;
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
    cells = malloc((size_t)grid.vary[vx].count * (size_t)grid.vary[vy].count * FIGURES * sizeof *cells);
    if (!cells) {
        cli_error("out of memory");
        goto done;
    }
    for (k = 0; k < grid.vary[vx].count * grid.vary[vy].count * FIGURES; ++k)
        cells[k] = (double)NAN;
    if (read_table(cli.dir, &grid, vx, vy, at_index, cells) != 0) {
        status = CLI_FAILED;
        goto done;
    }
    for (k = 0; k < cli.mark_count; ++k) { /* checked before anything is written */
        char x[64], y[64];
        if (sscanf(cli.mark[k], "%63[^,],%63[^,],%159[^\n]", x, y, mark_label[k]) != 3
            || (mark_x[k] = position_of(&grid.vary[vx], x)) < 0 || (mark_y[k] = position_of(&grid.vary[vy], y)) < 0) {
            cli_error("--mark %s: expected X,Y,LABEL with X and Y within the map's values of %s and %s",
                      cli.mark[k], grid.vary[vx].name, grid.vary[vy].name);
            goto done;
        }
    }
    snprintf(prefix, sizeof prefix, "%s", cli.prefix ? cli.prefix : "");
    if (!cli.prefix)
        snprintf(prefix, sizeof prefix, "%s/plot", cli.dir);

    /* the grid */
    snprintf(path, sizeof path, "%s.dat", prefix);
    if (!(out = fopen(path, "w"))) {
        cli_error("cannot write %s: %s", path, strerror(errno));
        status = CLI_FAILED;
        goto done;
    }
    fprintf(out, "# ix iy outcome agreement s_final_mean s_final_sd amp_h_mean power_w_mean\n");
    for (iy = 0; iy < grid.vary[vy].count; ++iy) {
        for (ix = 0; ix < grid.vary[vx].count; ++ix) {
            const double *cell = cells + ((long)iy * grid.vary[vx].count + ix) * FIGURES;
            fprintf(out, "%d %d", ix, iy);
            for (k = 0; k < FIGURES; ++k)
                fprintf(out, isfinite(cell[k]) ? " %.9g" : " NaN", cell[k]);
            fputc('\n', out);
            for (k = 0; k < FIGURES; ++k)
                has[k] |= isfinite(cell[k]) != 0;
        }
        fputc('\n', out);
    }
    if (fclose(out) != 0) {
        cli_error("cannot write %s", path);
        status = CLI_FAILED;
        goto done;
    }
    /* the marks: grid positions and labels */
    snprintf(path, sizeof path, "%s_marks.dat", prefix);
    if (!(out = fopen(path, "w"))) {
        cli_error("cannot write %s: %s", path, strerror(errno));
        status = CLI_FAILED;
        goto done;
    }
    for (k = 0; k < cli.mark_count; ++k) {
        fprintf(out, "%.6g %.6g ", mark_x[k], mark_y[k]);
        quoted(out, mark_label[k]);
        fputc('\n', out);
    }
    if (fclose(out) != 0) {
        cli_error("cannot write %s", path);
        status = CLI_FAILED;
        goto done;
    }

    /* the script */
    snprintf(path, sizeof path, "%s.gp", prefix);
    if (!(out = fopen(path, "w"))) {
        cli_error("cannot write %s: %s", path, strerror(errno));
        status = CLI_FAILED;
        goto done;
    }
    fprintf(out, "# written by beamslider map-plot %s (docs/maps.md); run: gnuplot %s\n", cli.dir, path);
    fprintf(out, "set terminal pngcairo size 1000,700 font 'sans,11' noenhanced\n");
    fprintf(out, "grid = ");
    snprintf(path, sizeof path, "%s.dat", prefix);
    quoted(out, path);
    fprintf(out, "\nmarks = ");
    snprintf(path, sizeof path, "%s_marks.dat", prefix);
    quoted(out, path);
    snprintf(path, sizeof path, "%s.gp", prefix);
    fputc('\n', out);
    fprintf(out, "set datafile missing 'NaN'\nset xrange [-0.5:%d.5]\nset yrange [-0.5:%d.5]\n",
            grid.vary[vx].count - 1, grid.vary[vy].count - 1);
    write_tics(out, "x", &grid.vary[vx]);
    write_tics(out, "y", &grid.vary[vy]);
    axis_label(&grid.vary[vx], label, sizeof label);
    fprintf(out, "set xlabel ");
    quoted(out, label);
    axis_label(&grid.vary[vy], label, sizeof label);
    fprintf(out, "\nset ylabel ");
    quoted(out, label);
    fprintf(out, "\nset tics out nomirror\nset rmargin 24\n");
    fprintf(out, "set palette maxcolors %d\nset palette defined (", OUTCOME_CLASSES);
    for (k = 0; k < OUTCOME_CLASSES; ++k)
        fprintf(out, "%s%d '%s'", k ? ", " : "", k, class_colour[k]);
    fprintf(out, ")\nset cbrange [-0.5:%d.5]\nset cbtics (", OUTCOME_CLASSES - 1);
    for (k = 0; k < OUTCOME_CLASSES; ++k) {
        fprintf(out, "%s", k ? ", " : "");
        quoted(out, outcome_label((outcome_class)k));
        fprintf(out, " %d", k);
    }
    fprintf(out, ")\n");
    write_figure(out, prefix, "outcome", "outcome class: the class most starts ended in", 3, scene, grid.repeat,
                 cli.mark_count > 0);
    fprintf(out, "set palette maxcolors 0\nset palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21908d', "
                 "0.75 '#5dc863', 1 '#fde725')\nset cbtics auto\n");
    fprintf(out, "set cbrange [0:1]\nset cblabel 'fraction of the starts'\n");
    write_figure(out, prefix, "agreement", "agreement: the fraction of the starts in that class", 4, scene,
                 grid.repeat, cli.mark_count > 0);
    fprintf(out, "set cbrange [*:*]\nset cblabel 's = x_C / L'\n");
    write_figure(out, prefix, "s_final", "final position s_final: last 10 s, mean of the starts",
                 5, scene, grid.repeat, cli.mark_count > 0);
    fprintf(out, "set cblabel 'standard deviation of s_final'\n");
    if (has[FIG_SPREAD])
        write_figure(out, prefix, "s_spread", "spread of s_final: standard deviation over the starts", 6, scene,
                     grid.repeat, cli.mark_count > 0);
    fprintf(out, "set cblabel 'w(4L/7) / h'\n");
    write_figure(out, prefix, "amp_h", "settled amplitude amp_h: last 10 s, mean of the starts", 7, scene,
                 grid.repeat, cli.mark_count > 0);
    if (has[FIG_POWER]) {
        fprintf(out, "set cblabel 'W'\n");
        write_figure(out, prefix, "power", "harvested power: last 10 s, mean of the starts", 8, scene, grid.repeat,
                     cli.mark_count > 0);
    }
    if (fclose(out) != 0) {
        cli_error("cannot write %s", path);
        status = CLI_FAILED;
        goto done;
    }
    if (run_gnuplot(path) != 0) {
        cli_error("gnuplot %s failed (is gnuplot installed? Debian: apt-get install gnuplot-nox)", path);
        status = CLI_FAILED;
        goto done;
    }
    fprintf(stderr, "map-plot: wrote %s_{outcome,agreement,s_final%s,amp_h%s}.png\n", prefix,
            has[FIG_SPREAD] ? ",s_spread" : "", has[FIG_POWER] ? ",power" : "");
    status = CLI_OK;
done:
    free(cells);
    map_grid_free(&grid);
    return status;
}
