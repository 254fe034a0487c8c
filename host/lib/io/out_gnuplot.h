/* out_gnuplot.h - the one writer of gnuplot script text (`beamslider
 * map-plot`). gnuplot runs a backquoted command inside a double-quoted string
 * (`set title "m`touch PWNED`x"` runs touch) and expands its escapes; in a
 * single-quoted string it does neither: no backquote substitution, no @
 * macro, no $ and no backslash escape, '' is a quote (checked with gnuplot
 * 5.4, tests/check_outputs.sh). So every text from the user is written as a
 * single-quoted string, and only through these functions:
 *
 *   out_gnuplot_string   text to be shown (a title, a label, a tic): a
 *                        quote doubled, every control character (a line
 *                        break would end the command) and every byte that
 *                        starts no valid UTF-8 character (pngcairo reads
 *                        UTF-8) as '?'.
 *   out_gnuplot_path     a file name: written byte for byte (a replaced
 *                        byte would name another file), quotes doubled;
 *                        refused (-1, nothing written) when it holds a
 *                        control character: check it first with
 *                        out_gnuplot_path_ok and refuse the option.
 *   out_gnuplot_comment  a comment line: "# TEXT\n", TEXT one line (control
 *                        characters as '?') and without a backslash at its
 *                        end (gnuplot continues a comment ending in one onto
 *                        the next line, which would hide that line).
 *
 * The script must use a terminal with `noenhanced`, so that the shown text
 * is not read as enhanced-text markup either.
 */
#ifndef OUT_GNUPLOT_H
#define OUT_GNUPLOT_H

#include <stdio.h>

/* 0, or -1 on a write error (out_gnuplot_path: or a control character). */
int out_gnuplot_string(FILE *out, const char *text);
int out_gnuplot_path(FILE *out, const char *path);
int out_gnuplot_comment(FILE *out, const char *text);

/* 1 if out_gnuplot_path takes path (no control character). */
int out_gnuplot_path_ok(const char *path);

#endif
