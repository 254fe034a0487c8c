/* out_text.c - text checks shared by the writers (out_text.h). */
#include "out_text.h"

size_t out_text_utf8_length(const char *text)
{
    const unsigned char *c = (const unsigned char *)text;
    unsigned long code;
    size_t length, i;

    if (c[0] < 0x80)
        return 1;
    if (c[0] >= 0xc2 && c[0] <= 0xdf)
        length = 2, code = c[0] & 0x1fu;
    else if (c[0] >= 0xe0 && c[0] <= 0xef)
        length = 3, code = c[0] & 0x0fu;
    else if (c[0] >= 0xf0 && c[0] <= 0xf4)
        length = 4, code = c[0] & 0x07u;
    else
        return 0; /* a continuation byte, an overlong lead (c0, c1) or beyond U+10FFFF (f5..ff) */
    for (i = 1; i < length; ++i) {
        if ((c[i] & 0xc0u) != 0x80u) /* also the NUL of a text cut short */
            return 0;
        code = code << 6 | (c[i] & 0x3fu);
    }
    if ((length == 3 && code < 0x800) || (length == 4 && (code < 0x10000 || code > 0x10ffff))
        || (code >= 0xd800 && code <= 0xdfff))
        return 0;
    return length;
}

char *out_text_one_line(char *text)
{
    char *c;
    for (c = text; *c; ++c)
        if ((unsigned char)*c < 0x20 || *c == 0x7f)
            *c = '?';
    return text;
}
