/* out_gnuplot.c - the writer of gnuplot script text (out_gnuplot.h). */
#include "out_gnuplot.h"

#include <string.h>
#include "out_text.h"

static int control(unsigned char c)
{
    return c < 0x20 || c == 0x7f;
}

int out_gnuplot_string(FILE *out, const char *text)
{
    int failed = fputc('\'', out) == EOF;
    while (*text && !failed) {
        const size_t n = out_text_utf8_length(text);
        if (n == 0 || control((unsigned char)*text)) {
            failed = fputc('?', out) == EOF;
            ++text;
            continue;
        }
        if (*text == '\'')
            failed = fputc('\'', out) == EOF; /* '' is a quote */
        failed = failed || fwrite(text, 1, n, out) != n;
        text += n;
    }
    return failed || fputc('\'', out) == EOF ? -1 : 0;
}

int out_gnuplot_path_ok(const char *path)
{
    const unsigned char *c;
    for (c = (const unsigned char *)path; *c; ++c)
        if (control(*c))
            return 0;
    return 1;
}

int out_gnuplot_path(FILE *out, const char *path)
{
    int failed;
    if (!out_gnuplot_path_ok(path))
        return -1;
    failed = fputc('\'', out) == EOF;
    for (; *path && !failed; ++path)
        failed = (*path == '\'' && fputc('\'', out) == EOF) || fputc(*path, out) == EOF;
    return failed || fputc('\'', out) == EOF ? -1 : 0;
}

int out_gnuplot_comment(FILE *out, const char *text)
{
    const size_t length = strlen(text);
    size_t i;
    int failed = fputs("# ", out) == EOF;
    for (i = 0; i < length && !failed; ++i) {
        const unsigned char c = (unsigned char)text[i];
        failed = fputc(control(c) || (c == '\\' && i + 1 == length) ? '?' : c, out) == EOF;
    }
    return failed || fputc('\n', out) == EOF ? -1 : 0;
}
