/* out_c.h - the one writer of C source text (the headers `beamslider gen`
 * and `beamslider twin-gains` print). Text that came from the user (a scene's
 * name or description, a path, an option) reaches C only through these
 * functions, each of which makes it one thing of C whatever it holds:
 *
 *   out_c_string          a string literal: ", \ and ? escaped (no
 *                         trigraph), every byte outside printable ASCII as a
 *                         three-digit octal escape (no following character
 *                         can extend it).
 *   out_c_comment_text    text inside a block comment: never a comment's
 *                         end or start (star slash, slash star), two question
 *                         marks (a trigraph), a line break, nor a backslash
 *                         at its end (a line splice). A pair that would be one
 *                         is broken by a backslash (star, backslash, slash);
 *                         a backslash and every byte outside printable ASCII
 *                         are octal escapes (\134, \012). The caller writes
 *                         it after the comment's opening and a space, and
 *                         before a space or a line end.
 *   out_c_identifier_check  a name a caller wants declared: refused unless
 *                         [A-Za-z_][A-Za-z0-9_]*, at most OUT_C_IDENTIFIER
 *                         characters, not a keyword of C (C99 to C23) or C++
 *                         (the headers are also compiled as C++), not
 *                         reserved (__x, _X).
 *   out_c_macro_name      a name made from any text (an include guard):
 *                         PREFIX, then the text's letters and digits upper-cased
 *                         and every other byte as _.
 *   out_c_real            a number as BS_R(x): 17 digits, with a point or an
 *                         exponent (a float build pastes an f to it).
 */
#ifndef OUT_C_H
#define OUT_C_H

#include <stddef.h>
#include <stdio.h>

#define OUT_C_IDENTIFIER 63 /* C99's significant initial characters of an internal identifier */
#define OUT_C_REAL 40       /* out_c_real's text with its NUL */

/* Write text to out as described above; 0, or -1 on a write error. */
int out_c_string(FILE *out, const char *text);
int out_c_comment_text(FILE *out, const char *text);

/* 0 if name may be declared; else -1 with "OPTION NAME: why; allowed: ..."
 * in err (option: what the name was given as, such as "--name"). */
int out_c_identifier_check(const char *name, const char *option, char *err, size_t size);

/* PREFIX followed by text mapped as above into out (size bytes; the text is
 * cut to fit, the result is always an identifier when prefix is one). */
void out_c_macro_name(const char *prefix, const char *text, char *out, size_t size);

/* x (finite) as BS_R(x) into text; 0, or -1 if x is not finite (no C
 * literal: the caller refuses). */
int out_c_real(char text[OUT_C_REAL], double x);

#endif
