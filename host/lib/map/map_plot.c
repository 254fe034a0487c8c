/* map_plot.c - what map-plot draws of a map (map_plot.h): the grid read
 * from map.csv, the data files and the gnuplot script, every text in it
 * through the gnuplot writer (out_gnuplot.h). */
#include "map_plot.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "input_file.h"
#include "map_store.h"
#include "map_table.h"
#include "out_gnuplot.h"
#include "outcome.h"

/* The grid position of value text of field v: an index, fractional between
 * two numeric values; -1 if outside. */
double map_plot_position(const map_vary *vary, const char *text)
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

int map_plot_read(const char *dir, map_plot *plot, char *err, size_t err_size)
{
    const map_grid *grid = plot->grid;
    const int vx = plot->vx, vy = plot->vy;
    const int *at_index = plot->at_index;
    double *cells = plot->cells;
    char path[4200], line[4096], header[MAP_POINTS_HEADER], why[256];
    long number = 0, point = 0;
    FILE *in;
    int failed = 0;

    snprintf(path, sizeof path, "%s/%s", dir, MAP_POINTS_TABLE);
    {
        char reason[4600];
        const char *verb;
        if (input_file_open_why(path, INPUT_MAP_TABLE, &in, NULL, &verb, reason, sizeof reason) != 0) {
            if (!strcmp(verb, "open"))
                snprintf(err, err_size, "%s: %s (all cases done? beamslider map-merge %s writes it)", path, reason,
                         dir);
            else
                snprintf(err, err_size, "%s: cannot read %s: %s", path, input_kind_name(INPUT_MAP_TABLE), reason);
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
        cells[cell * MAP_PLOT_FIGURES + MAP_PLOT_OUTCOME] = figures.outcome;
        cells[cell * MAP_PLOT_FIGURES + MAP_PLOT_AGREEMENT] = figures.agreement;
        cells[cell * MAP_PLOT_FIGURES + MAP_PLOT_S] = figures.s_settled_mean;
        cells[cell * MAP_PLOT_FIGURES + MAP_PLOT_SPREAD] = figures.s_settled_sd;
        cells[cell * MAP_PLOT_FIGURES + MAP_PLOT_AMP] = figures.amp_h_mean;
        cells[cell * MAP_PLOT_FIGURES + MAP_PLOT_POWER] = figures.power_w_mean;
        cells[cell * MAP_PLOT_FIGURES + MAP_PLOT_WINDOW] = figures.window_s;
    }
    if (!failed && ferror(in)) {
        snprintf(err, err_size, "%s: %s", path, strerror(errno));
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
            snprintf(err, err_size, "%s:%ld: %s; not a table as map-merge writes it (run beamslider map-merge %s "
                     "again)", path, number, why, dir);
        else
            snprintf(err, err_size, "%s: %s; not a table as map-merge writes it (run beamslider map-merge %s again)",
                     path, why, dir);
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
        const double w = cells[c * MAP_PLOT_FIGURES + MAP_PLOT_WINDOW];
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

/* Writes the script to path: every text through the gnuplot writer. 0, or -1. */
static int write_script(const char *path, const char *dir, const map_plot *plot, const char *prefix,
                        const char *window)
{
    const map_grid *grid = plot->grid;
    const int vx = plot->vx, vy = plot->vy, marks = plot->mark_count;
    const char *scene = plot->scene;
    char text[4400], label[160];
    FILE *out = fopen(path, "w");
    int k, failed;

    if (!out)
        return -1;
    snprintf(text, sizeof text, "written by beamslider map-plot %s (docs/maps.md); run: gnuplot %s", dir, path);
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
    for (k = 0; k < marks; ++k) {
        fprintf(out, "set label %d ", k + 1);
        out_gnuplot_string(out, plot->mark_label[k]);
        fprintf(out, " at %.6g,%.6g left offset 0.9,0.5 tc rgb 'black' font ',10' front\n", plot->mark_x[k], plot->mark_y[k]);
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
    write_figure(out, prefix, "outcome", "outcome class: the class most starts ended in", 3, scene, grid->repeat, marks > 0);
    fprintf(out, "set palette maxcolors 0\nset palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21908d', "
                 "0.75 '#5dc863', 1 '#fde725')\nset cbtics auto\n");
    fprintf(out, "set cbrange [0:1]\nset cblabel 'fraction of the starts'\n");
    write_figure(out, prefix, "agreement", "agreement: the fraction of the starts in that class", 4, scene,
                 grid->repeat, marks > 0);
    fprintf(out, "set cbrange [*:*]\nset cblabel 's = x_C / L'\n");
    snprintf(text, sizeof text, "settled position s_settled: mean s over the %s, mean of the starts", window);
    write_figure(out, prefix, "s_settled", text, 5, scene, grid->repeat, marks > 0);
    fprintf(out, "set cblabel 'standard deviation of s_settled'\n");
    if (plot->has[MAP_PLOT_SPREAD]) {
        snprintf(text, sizeof text, "spread of s_settled (the %s): standard deviation over the starts", window);
        write_figure(out, prefix, "s_spread", text, 6, scene, grid->repeat, marks > 0);
    }
    fprintf(out, "set cblabel 'w(4L/7) / h'\n");
    snprintf(text, sizeof text, "settled amplitude amp_h: the %s, mean of the starts", window);
    write_figure(out, prefix, "amp_h", text, 7, scene, grid->repeat, marks > 0);
    if (plot->has[MAP_PLOT_POWER]) {
        fprintf(out, "set cblabel 'W'\n");
        snprintf(text, sizeof text, "harvested power: the %s, mean of the starts", window);
        write_figure(out, prefix, "power", text, 8, scene, grid->repeat, marks > 0);
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
            const double *cell = cells + ((size_t)iy * (size_t)grid->vary[vx].count + (size_t)ix) * MAP_PLOT_FIGURES;
            fprintf(out, "%d %d", ix, iy);
            for (k = 0; k < MAP_PLOT_FIGURES; ++k) {
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

int map_plot_write(const char *prefix, const char *dir, map_plot *plot, char *err, size_t err_size)
{
    const size_t n_cells = (size_t)plot->grid->vary[plot->vx].count * (size_t)plot->grid->vary[plot->vy].count;
    char path[4300], window[64];

    memset(plot->has, 0, sizeof plot->has);
    snprintf(path, sizeof path, "%s.dat", prefix);
    if (write_grid(path, plot->grid, plot->vx, plot->vy, plot->cells, plot->has) != 0) {
        snprintf(err, err_size, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    snprintf(path, sizeof path, "%s_marks.dat", prefix);
    if (write_marks(path, plot->mark_x, plot->mark_y, plot->mark_count) != 0) {
        snprintf(err, err_size, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    snprintf(path, sizeof path, "%s.gp", prefix);
    window_text(plot->cells, n_cells, window, sizeof window);
    if (write_script(path, dir, plot, prefix, window) != 0) {
        snprintf(err, err_size, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}
