/* out_text.h - what the writers of other languages (out_json.h,
 * out_gnuplot.h) share about the text they are given, and the writer of
 * user text into the line-based files beamslider writes (a map's identity,
 * the measured-signals header of twin-plant).
 *
 * A scene's name may hold any byte (the default name is the file's name):
 * JSON must be UTF-8 (RFC 8259) and gnuplot's pngcairo reads its strings as
 * UTF-8, so a byte that starts no valid character is written as a
 * replacement by each writer; in a line-based file a line break would start
 * a line of its own (a forged "# sample_rate = ..." or "vary ..."), so text
 * from the user is made one line first. */
#ifndef OUT_TEXT_H
#define OUT_TEXT_H

#include <stddef.h>

/* The length (1 to 4) of the valid UTF-8 character at text, 0 if the bytes
 * there are not one (a stray continuation byte, an overlong form, a
 * surrogate, above U+10FFFF, cut short). text is NUL-terminated. */
size_t out_text_utf8_length(const char *text);

/* Makes text one line of a line-based file, in place: every control
 * character (a line break, a carriage return, a tab, 0x7f) becomes '?'.
 * Returns text. */
char *out_text_one_line(char *text);

#endif
