/* out_c.c - the writer of C source text (out_c.h). */
#include "out_c.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int printable(unsigned char c)
{
    return c >= 0x20 && c < 0x7f;
}

int out_c_string(FILE *out, const char *text)
{
    const unsigned char *c;
    int failed = fputc('"', out) == EOF;
    for (c = (const unsigned char *)text; *c && !failed; ++c) {
        if (*c == '"' || *c == '\\' || *c == '?')
            failed = fprintf(out, "\\%c", *c) < 0;
        else if (printable(*c))
            failed = fputc(*c, out) == EOF;
        else
            failed = fprintf(out, "\\%03o", *c) < 0;
    }
    return failed || fputc('"', out) == EOF ? -1 : 0;
}

int out_c_comment_text(FILE *out, const char *text)
{
    const unsigned char *c;
    int last = ' '; /* the last character written */
    int failed = 0;
    for (c = (const unsigned char *)text; *c && !failed; ++c) {
        if (!printable(*c) || *c == '\\') {
            failed = fprintf(out, "\\%03o", *c) < 0;
            last = '0';
            continue;
        }
        /* a pair that would end or start the comment, or begin a trigraph */
        if ((last == '*' && *c == '/') || (last == '/' && *c == '*') || (last == '?' && *c == '?'))
            failed = fputc('\\', out) == EOF;
        failed = failed || fputc(*c, out) == EOF;
        last = *c;
    }
    return failed ? -1 : 0;
}

/* Keywords of C99, C11, C23 and C++ (C++20): a header declares names that
 * must compile in both. */
static const char *const keywords[] = {
    "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
    "char", "char16_t", "char32_t", "char8_t", "class", "co_await", "co_return", "co_yield", "compl", "concept",
    "const", "const_cast", "consteval", "constexpr", "constinit", "continue", "decltype", "default", "delete",
    "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
    "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
    "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
    "requires", "restrict", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast",
    "struct", "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid",
    "typename", "typeof", "typeof_unqual", "union", "unsigned", "using", "virtual", "void", "volatile",
    "wchar_t", "while", "xor", "xor_eq", NULL
};

int out_c_identifier_check(const char *name, const char *option, char *err, size_t size)
{
    static const char allowed[] = "allowed: a C identifier ([A-Za-z_][A-Za-z0-9_]*, at most 63 characters, "
                                  "not a keyword, not starting with __ or _ and a capital)";
    const size_t length = strlen(name);
    size_t i;
    int k;

    if (length == 0 || length > OUT_C_IDENTIFIER) {
        snprintf(err, size, "%s %.*s%s: %s; %s", option, 40, name, length > 40 ? "..." : "",
                 length ? "too long" : "empty", allowed);
        return -1;
    }
    for (i = 0; i < length; ++i) {
        const char c = name[i];
        const int letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
        if (!letter && !(i > 0 && c >= '0' && c <= '9')) {
            if (printable((unsigned char)c))
                snprintf(err, size, "%s %s: character %zu ('%c') cannot be in a C name; %s", option, name, i + 1, c,
                         allowed);
            else
                snprintf(err, size, "%s: character %zu (byte 0x%02x) cannot be in a C name; %s", option, i + 1,
                         (unsigned)(unsigned char)c, allowed);
            return -1;
        }
    }
    if (name[0] == '_' && (name[1] == '_' || (name[1] >= 'A' && name[1] <= 'Z'))) {
        snprintf(err, size, "%s %s: a name reserved to the compiler and its library; %s", option, name, allowed);
        return -1;
    }
    for (k = 0; keywords[k]; ++k)
        if (!strcmp(name, keywords[k])) {
            snprintf(err, size, "%s %s: a keyword of C or C++; %s", option, name, allowed);
            return -1;
        }
    return 0;
}

void out_c_macro_name(const char *prefix, const char *text, char *out, size_t size)
{
    size_t used;
    if (size == 0)
        return;
    snprintf(out, size, "%s", prefix);
    for (used = strlen(out); *text && used + 1 < size; ++text) {
        const char c = *text;
        if (c >= 'a' && c <= 'z')
            out[used++] = (char)(c - 'a' + 'A');
        else if ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))
            out[used++] = c;
        else
            out[used++] = '_';
    }
    out[used] = '\0';
}

int out_c_real(char text[OUT_C_REAL], double x)
{
    char number[32];
    if (!isfinite(x)) {
        snprintf(text, OUT_C_REAL, "BS_R(0.0)");
        return -1;
    }
    snprintf(number, sizeof number, "%.17g", x);
    snprintf(text, OUT_C_REAL, "BS_R(%s%s)", number, strpbrk(number, ".e") ? "" : ".0");
    return 0;
}
