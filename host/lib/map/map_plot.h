/* map_plot.h - what `beamslider map-plot` draws of a map (docs/maps.md
 * section 5): the figures of map.csv over two of its varied fields, the
 * others fixed, as the data files and the gnuplot script that draws them.
 *
 * PREFIX.dat holds the grid (one line per cell, NaN where a figure has no
 * value), PREFIX_marks.dat the marked points, PREFIX.gp the script (kept, so
 * that a figure can be restyled by hand) drawing PREFIX_outcome,
 * _agreement, _s_settled, _s_spread (with two starts or more), _amp_h and,
 * with a transducer, _power (.png). Cells are grid indices, so that a list of
 * values as uneven as 1,2,5,10 still gives equal cells; the tics name the
 * values; the titles name the settled window the runs had. The folder is
 * input: map.csv is checked line by line (map_table_point_parse), and every
 * text in the script (the scene's name or title, the values, the labels,
 * the paths) goes through the gnuplot writer: single-quoted strings, which
 * gnuplot never substitutes. Running gnuplot is the caller's.
 */
#ifndef MAP_PLOT_H
#define MAP_PLOT_H

#include <stddef.h>
#include "map_grid.h"

#define MAP_PLOT_MARKS 16

/* The figures: one value per cell and figure. */
enum {
    MAP_PLOT_OUTCOME, MAP_PLOT_AGREEMENT, MAP_PLOT_S, MAP_PLOT_SPREAD, MAP_PLOT_AMP, MAP_PLOT_POWER,
    MAP_PLOT_WINDOW, MAP_PLOT_FIGURES
};

typedef struct map_plot {
    const map_grid *grid;
    int vx, vy;                        /* the varied fields along x and y */
    int at_index[MAP_MAX_VARY];        /* the value of each other field (-1: x or y) */
    double *cells;                     /* [(iy * nx + ix) * MAP_PLOT_FIGURES + figure], NaN: none */
    const char *scene;                 /* the titles' first line */
    int mark_count;                    /* labelled points, in grid positions */
    double mark_x[MAP_PLOT_MARKS], mark_y[MAP_PLOT_MARKS];
    char mark_label[MAP_PLOT_MARKS][160];
    int has[MAP_PLOT_FIGURES];         /* figures with a value (map_plot_write sets them) */
} map_plot;

/* The grid position of value text of field vary: its index, fractional
 * between two numeric values; -1 if outside. */
double map_plot_position(const map_vary *vary, const char *text);

/* Reads dir's map.csv into plot->cells (set to NaN first by the caller) for
 * the rows at the at_index values. The table must be whole: its header, one
 * row per grid point in order, each as map-merge writes it, nothing after.
 * 0, or -1 with err naming the file and line (bad input). */
int map_plot_read(const char *dir, map_plot *plot, char *err, size_t err_size);

/* Writes PREFIX.dat, PREFIX_marks.dat and PREFIX.gp (dir named in the
 * script's comment); sets plot->has. 0, or -1 with err. */
int map_plot_write(const char *prefix, const char *dir, map_plot *plot, char *err, size_t err_size);

#endif
