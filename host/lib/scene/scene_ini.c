/* scene_ini.c - reading scene files with libinih, every field checked.
 *
 * libinih (Debian's libinih-dev) does the INI syntax. Its handler gets no line
 * number in the Debian build, and it never sees section lines, so the file is
 * fed through a reader that counts lines and refuses, line by line, what
 * libinih would take silently or misread:
 *   - an over-long line (libinih would split it) and a NUL byte (it would cut
 *     the line short);
 *   - a carriage return not followed by a line feed (classic Mac line ends:
 *     the whole file would be one line) and other control characters (a text
 *     file has none; a tab is a space);
 *   - a section line that is not exactly [name] with a known name, followed
 *     at most by a ; comment: text after the ] would be ignored;
 *   - a file larger than SCENE_MAX_BYTES.
 * Only regular files are read (a FIFO or /dev/zero would never end). Each
 * file is read twice (for its base, then for its values): errors in the text
 * itself (the reader's, libinih's syntax errors) are found in the first pass
 * and so come before errors of values, even at a later line. The first error
 * wins and names file, line, field, value and the allowed range.
 */

#define _POSIX_C_SOURCE 200809L /* fmemopen */

#include "scene_ini.h"

#include <ctype.h>
#include <errno.h>
#include <ini.h>
#include <pthread.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_file.h"
#include "schedule.h"

typedef struct reader {
    FILE *file;
    int line;
    long bytes;          /* read so far */
    int too_big;         /* 1: stopped after SCENE_MAX_BYTES */
    int bad_line;        /* the first line the reader refuses, 0 if none */
    char bad_why[320];   /* what is wrong with it */
    int read_errno;      /* errno of a failed read, 0 if none */
} reader;

typedef struct parse {
    scene_file *scene;
    reader *in;
    int file;         /* index into scene->files */
    const char *text; /* NULL, or the text of this file (scene_load_text) */
    int scan_base;    /* 1: only look for [scene] base */
    char base[SCENE_PATH];
    int base_line;    /* line of [scene] base, 0 if none */
    char *err;
    size_t err_size;
    int failed;
} parse;

/* Records the first line the reader refuses (libinih still gets it, but
 * on_entry takes nothing from that line on). */
static void refuse_line(reader *in, int line, const char *why)
{
    if (in->bad_line)
        return;
    in->bad_line = line;
    snprintf(in->bad_why, sizeof in->bad_why, "%s", why);
}

/* The byte c of the line being read: a NUL byte, a carriage return without
 * a line feed, or another control character makes the line bad. */
static void check_byte(reader *in, int c)
{
    char why[96];
    const int line = in->line + 1;

    if (c == '\0') {
        refuse_line(in, line, "NUL byte: not a text file (UTF-16? save it as UTF-8)");
    } else if (c == '\r') {
        const int next = getc(in->file);
        if (next != EOF)
            ungetc(next, in->file);
        if (next != '\n')
            refuse_line(in, line, "carriage return without a line feed (classic Mac line ends? "
                                  "save the file with LF or CRLF line ends)");
    } else if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7f) {
        snprintf(why, sizeof why, "control character 0x%02x: not a text file", (unsigned)c);
        refuse_line(in, line, why);
    }
}

static int is_section_name_char(char c)
{
    return isalnum((unsigned char)c) || c == '_';
}

/* 1 if [section] is a section of the field table. */
static int section_known(const char *name, size_t length)
{
    int i;
    for (i = 0; scene_fields[i].key; ++i)
        if (strlen(scene_fields[i].section) == length && !strncmp(scene_fields[i].section, name, length))
            return 1;
    return 0;
}

/* "scene, beam, ...": every section of the field table once, in its order. */
static void section_list(char *out, size_t size)
{
    size_t used = 0;
    int i, j;

    out[0] = '\0';
    for (i = 0; scene_fields[i].key && used < size; ++i) {
        for (j = 0; j < i && strcmp(scene_fields[j].section, scene_fields[i].section); ++j)
            ;
        if (j == i)
            used += (size_t)snprintf(out + used, size - used, "%s%s", used ? ", " : "", scene_fields[i].section);
    }
}

/* A line that opens with [ must be [name] with a known name, then nothing
 * but spaces and a ; comment: libinih ignores whatever follows the ] (a key
 * written there would be lost), keeps spaces inside the brackets in the name
 * and takes an empty name as "no section". A line without ] is left to
 * libinih's syntax error. */
static void check_section_line(reader *in, const char *text)
{
    const char *open = text;
    const char *close;
    const char *after;
    char why[300];
    char known[160];
    size_t length;

    if (in->line == 1 && !strncmp(open, "\xEF\xBB\xBF", 3)) /* UTF-8 byte-order mark */
        open += 3;
    while (*open == ' ' || *open == '\t')
        ++open;
    if (*open != '[' || !(close = strchr(open, ']')))
        return;
    length = (size_t)(close - open - 1);
    for (after = close + 1; *after == ' ' || *after == '\t' || *after == '\r' || *after == '\n'; ++after)
        ;
    if (length == 0) {
        refuse_line(in, in->line, "empty section name []");
    } else if (strspn(open + 1, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != length) {
        size_t i;
        for (i = 0; i < length && is_section_name_char(open[1 + i]); ++i)
            ;
        snprintf(why, sizeof why, "section name [%.*s] holds %s; allowed: letters, digits and _, as in [numerics]",
                 (int)length, open + 1, isspace((unsigned char)open[1 + i]) ? "a space" : "a character other than letters, digits and _");
        refuse_line(in, in->line, why);
    } else if (!section_known(open + 1, length)) {
        section_list(known, sizeof known);
        snprintf(why, sizeof why, "unknown section [%.*s]; allowed: %s", (int)length, open + 1, known);
        refuse_line(in, in->line, why);
    } else if (*after != '\0' && *after != ';') {
        length = strcspn(after, "\r\n");
        snprintf(why, sizeof why, "text after [%.*s]: \"%.*s\" (a section line holds only [name] and a ; comment; "
                 "put each key = value on its own line)", (int)(close - open - 1), open + 1, (int)length, after);
        refuse_line(in, in->line, why);
    }
}

/* fgets for libinih, by characters (fgets cannot tell a NUL byte from the end
 * of the line), checking each byte and each complete line. */
static char *read_line(char *str, int num, void *stream)
{
    reader *in = (reader *)stream;
    int length = 0;
    int c = 0;

    errno = 0;
    while (length < num - 1 && (c = getc(in->file)) != EOF) {
        if (++in->bytes > SCENE_MAX_BYTES) { /* a file that grows, or says it is empty (/proc) */
            in->too_big = 1;
            return NULL; /* the end of the file, for libinih */
        }
        check_byte(in, c);
        str[length++] = (char)c;
        if (c == '\n')
            break;
    }
    if (c == EOF && ferror(in->file) && !in->read_errno)
        in->read_errno = errno ? errno : EIO;
    if (length == 0)
        return NULL;
    str[length] = '\0';
    ++in->line;
    if (str[length - 1] != '\n' && length == num - 1) {
        c = getc(in->file); /* full buffer: over-long unless the file ends here */
        if (c != EOF) {
            char why[64];
            ungetc(c, in->file);
            snprintf(why, sizeof why, "line longer than %d characters", ini_max_line - 3);
            refuse_line(in, in->line, why);
            return str;
        }
    }
    check_section_line(in, str);
    return str;
}

/* 1 if text is well-formed UTF-8 (no overlong forms, surrogates or code
 * points above U+10FFFF): texts end up in the JSON summary, which must be
 * UTF-8. */
static int is_utf8(const char *text)
{
    static const unsigned long smallest[4] = { 0, 0x80, 0x800, 0x10000 }; /* by continuation bytes */
    const unsigned char *c = (const unsigned char *)text;

    while (*c) {
        int more, i;
        unsigned long code;
        if (*c < 0x80) {
            ++c;
            continue;
        }
        if ((*c & 0xE0) == 0xC0)
            more = 1, code = *c & 0x1Fu;
        else if ((*c & 0xF0) == 0xE0)
            more = 2, code = *c & 0x0Fu;
        else if ((*c & 0xF8) == 0xF0)
            more = 3, code = *c & 0x07u;
        else
            return 0;
        for (i = 1; i <= more; ++i) {
            if ((c[i] & 0xC0) != 0x80) /* also stops at the terminating NUL */
                return 0;
            code = code << 6 | (c[i] & 0x3Fu);
        }
        if (code < smallest[more] || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF)
            return 0;
        c += 1 + more;
    }
    return 1;
}

static int field_index(const char *section, const char *key)
{
    int i;
    for (i = 0; scene_fields[i].key; ++i)
        if (!strcmp(scene_fields[i].section, section) && !strcmp(scene_fields[i].key, key))
            return i;
    return -1;
}

/* Parses value for field f into the params; 0 or -1 with the reason. */
static int assign(scene_params *params, const field_spec *f, const char *value, char *why, size_t size)
{
    char *target = (char *)params + f->offset;
    char range[96];
    char *end;

    field_range_text(f, range, sizeof range);
    if (f->kind == FIELD_TEXT) {
        if (strlen(value) >= SCENE_TEXT) {
            snprintf(why, size, "too long; allowed: %s", range);
            return -1;
        }
        if (!is_utf8(value)) {
            snprintf(why, size, "not UTF-8 text; allowed: %s (UTF-8)", range);
            return -1;
        }
        if (f->offset == offsetof(scene_params, schedule)) { /* a text with a syntax of its own */
            schedule parsed;
            char what[160];
            if (schedule_parse(value, &parsed, what, sizeof what) != 0) {
                snprintf(why, size, "%s", what);
                return -1;
            }
        }
        strcpy(target, value);
        return 0;
    }
    if (f->kind == FIELD_CHOICE) {
        int i;
        for (i = 0; f->choices[i]; ++i)
            if (!strcmp(value, f->choices[i])) {
                *(int *)target = i;
                return 0;
            }
        snprintf(why, size, "unknown value; allowed: %s", range);
        return -1;
    }
    if (*value == '\0') {
        snprintf(why, size, "no value; allowed: %s", range);
        return -1;
    }
    if (f->kind == FIELD_INT) {
        long number = strtol(value, &end, 10);
        if (*end != '\0') {
            snprintf(why, size, "not an integer; allowed: %s", range);
            return -1;
        }
        if (number < (long)f->low || number > (long)f->high) {
            snprintf(why, size, "out of range; allowed: %s", range);
            return -1;
        }
        *(int *)target = (int)number;
        return 0;
    }
    {
        double number = strtod(value, &end);
        if (*end != '\0') {
            snprintf(why, size, "not a number; allowed: %s", range);
            return -1;
        }
        if (!isfinite(number)) {
            snprintf(why, size, "not finite; allowed: %s", range);
            return -1;
        }
        if ((f->low_open ? number <= f->low : number < f->low)
            || (f->high_open ? number >= f->high : number > f->high)) {
            snprintf(why, size, "out of range; allowed: %s", range);
            return -1;
        }
        *(double *)target = number;
    }
    return 0;
}

/* Sets field [section] key from file (an index into files, line > 0) or
 * from an option (file = SCENE_BY_OPTION, origin: its name, line 0). An
 * option that names the field itself (--dt) is reported as "--dt abc: why";
 * an assignment (line SCENE_ASSIGNMENT: origin is "--set numerics.dt=abc")
 * like a file's line, with origin in place of "file:line". */
#define SCENE_ASSIGNMENT (-1)
static int set_field(scene_file *scene, int file, const char *origin, int line, const char *section,
                     const char *key, const char *value, char *err, size_t err_size)
{
    const int i = field_index(section, key);
    char place[SCENE_PATH + 32];
    char why[192];

    if (file >= 0)
        snprintf(place, sizeof place, "%s:%d", origin, line);
    else
        snprintf(place, sizeof place, "%s", origin);
    if (i < 0) {
        snprintf(err, err_size, "%s: unknown field [%s] %s%s", place, section, key,
                 file >= 0 ? "" : " (beamslider fields lists every field)");
        return -1;
    }
    if (file >= 0 && scene->set_file[i] == file) {
        snprintf(err, err_size, "%s: [%s] %s set twice (first at line %d)", place, section, key,
                 scene->set_line[i]);
        return -1;
    }
    if (assign(&scene->params, &scene_fields[i], value, why, sizeof why) != 0) {
        if (file >= 0 || line == SCENE_ASSIGNMENT)
            snprintf(err, err_size, "%s: [%s] %s = %s: %s", place, section, key, value, why);
        else
            snprintf(err, err_size, "%s %s: %s", origin, value, why);
        return -1;
    }
    scene->set_file[i] = file;
    scene->set_line[i] = file >= 0 ? line : 0;
    if (file == SCENE_BY_OPTION)
        snprintf(scene->set_option[i], SCENE_OPTION, "%s", origin); /* the callers checked its length */
    return 0;
}

/* A key before the first section line, or a line "= value" without a key:
 * 0, or -1 with the error. */
static int check_entry_shape(parse *p, const char *section, const char *key, const char *value)
{
    const char *path = p->scene->files[p->file];

    if (!*key)
        snprintf(p->err, p->err_size, "%s:%d: no key before the = of \"= %s\" (expected key = value)", path,
                 p->in->line, value);
    else if (!*section)
        snprintf(p->err, p->err_size, "%s:%d: %s = %s comes before any [section] line (each key belongs "
                 "to a section, such as [numerics] dt)", path, p->in->line, key, value);
    else
        return 0;
    return -1;
}

static int on_entry(void *user, const char *section, const char *key, const char *value)
{
    parse *p = (parse *)user;
    const int is_base = !strcmp(section, "scene") && !strcmp(key, "base");

    if (p->failed || p->in->bad_line) /* that line may be cut short: take nothing from it on */
        return 0;
    if (p->scan_base) {
        if (is_base) {
            if (p->base_line) {
                snprintf(p->err, p->err_size, "%s:%d: [scene] base set twice (first at line %d)",
                         p->scene->files[p->file], p->in->line, p->base_line);
                p->failed = 1;
                return 0;
            }
            if (strlen(value) >= sizeof p->base) {
                snprintf(p->err, p->err_size, "%s:%d: [scene] base: path too long",
                         p->scene->files[p->file], p->in->line);
                p->failed = 1;
                return 0;
            }
            strcpy(p->base, value);
            p->base_line = p->in->line;
        }
        return 1;
    }
    if (is_base)
        return 1;
    if (check_entry_shape(p, section, key, value) != 0
        || set_field(p->scene, p->file, p->scene->files[p->file], p->in->line, section, key, value, p->err,
                     p->err_size) != 0) {
        p->failed = 1;
        return 0;
    }
    return 1;
}

/* Opens a scene or base file for reading: a regular file of at most
 * SCENE_MAX_BYTES (the helper every reader uses, input_file.h). 0, or -1
 * with what failed ("open", "read") in verb and why in why. */
static int open_scene_file(const char *path, FILE **file, const char **verb, char *why, size_t size)
{
    return input_file_open_why(path, INPUT_SCENE, file, NULL, verb, why, size);
}

/* One pass of libinih over the file; 0 or -1 with err filled. */
static int run_parser(parse *p)
{
    const char *path = p->scene->files[p->file];
    const char *verb;
    char why[160];
    reader in;
    int result;

    memset(&in, 0, sizeof in);
    if (p->text) {
        /* fmemopen reads the caller's text as the file (it is not written:
         * "r" mode) */
        if (!(in.file = fmemopen((char *)p->text, strlen(p->text), "r"))) {
            snprintf(p->err, p->err_size, "%s: cannot read the scene text: %s", path, strerror(errno));
            return -1;
        }
    } else if (open_scene_file(path, &in.file, &verb, why, sizeof why) != 0) {
        snprintf(p->err, p->err_size, "%s: cannot %s scene file: %s", path, verb, why);
        return -1;
    }
    p->in = &in;
    result = ini_parse_stream(read_line, &in, on_entry, p);
    fclose(in.file);
    if (in.read_errno) {
        snprintf(p->err, p->err_size, "%s: cannot read scene file: %s", path, strerror(in.read_errno));
        return -1;
    }
    if (in.too_big) {
        snprintf(p->err, p->err_size, "%s: cannot read scene file: more than a scene file may have "
                 "(%ld bytes, 1 MiB)", path, SCENE_MAX_BYTES);
        return -1;
    }
    if (in.bad_line && !p->failed && !(result > 0 && result < in.bad_line)) {
        snprintf(p->err, p->err_size, "%s:%d: %s", path, in.bad_line, in.bad_why);
        return -1;
    }
    if (p->failed)
        return -1;
    if (result != 0) {
        snprintf(p->err, p->err_size, "%s:%d: syntax error (expected [section], key = value or a comment)",
                 path, result);
        return -1;
    }
    return 0;
}

/* A base file is never reused, so a cycle of bases runs into
 * SCENE_MAX_FILES instead of recursing for ever. */
static int add_file(scene_file *scene, const char *path, char *err, size_t err_size)
{
    if (scene->file_count >= SCENE_MAX_FILES) {
        snprintf(err, err_size, "%s: too many nested base files (at most %d; a cycle of bases?)", path,
                 SCENE_MAX_FILES);
        return -1;
    }
    if (strlen(path) >= SCENE_PATH) {
        snprintf(err, err_size, "%s: path too long", path);
        return -1;
    }
    strcpy(scene->files[scene->file_count], path);
    return scene->file_count++;
}

static int load_file(scene_file *scene, const char *path, const char *text, char *err, size_t err_size)
{
    parse p;
    const int file = add_file(scene, path, err, err_size);

    if (file < 0)
        return -1;
    memset(&p, 0, sizeof p);
    p.scene = scene;
    p.file = file;
    p.text = text;
    p.err = err;
    p.err_size = err_size;
    p.scan_base = 1;
    if (run_parser(&p) != 0)
        return -1;
    if (p.base[0]) {
        char base_path[SCENE_PATH];
        const char *verb;
        char why[160];
        FILE *probe;
        const char *slash = strrchr(path, '/');
        const int folder = slash && p.base[0] != '/' ? (int)(slash - path + 1) : 0;
        if (snprintf(base_path, sizeof base_path, "%.*s%s", folder, path, p.base) >= (int)sizeof base_path) {
            snprintf(err, err_size, "%s: [scene] base: path too long", path);
            return -1;
        }
        if (open_scene_file(base_path, &probe, &verb, why, sizeof why) != 0) { /* name the line that asked for it */
            snprintf(err, err_size, "%s:%d: [scene] base = %s: cannot %s %s: %s", path, p.base_line, p.base,
                     verb, base_path, why);
            return -1;
        }
        fclose(probe);
        if (load_file(scene, base_path, NULL, err, err_size) != 0)
            return -1;
    }
    p.scan_base = 0;
    return run_parser(&p);
}

/* 1 if text holds a control character (a tab aside): refused in a value,
 * as the reader refuses it in a file's line, since values reach one-line
 * texts (a map's identity, a stream's header). */
static int has_control(const char *text, size_t *at)
{
    const unsigned char *c = (const unsigned char *)text;
    for (*at = 0; c[*at]; ++*at)
        if ((c[*at] < 0x20 && c[*at] != '\t') || c[*at] == 0x7f)
            return 1;
    return 0;
}

/* The file name without its folder and .ini, unless it cannot serve as the
 * name (too long, not UTF-8): then 0, and a [scene] name must be given. A
 * file name may hold control characters: whatever writes the name escapes
 * it (the JSON summary; tests/test_summary.c). */
static int default_name(scene_file *scene, const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t length = strlen(base);
    if (length > 4 && !strcmp(base + length - 4, ".ini"))
        length -= 4;
    if (length >= SCENE_TEXT)
        return 0;
    memcpy(scene->params.name, base, length);
    scene->params.name[length] = '\0';
    return is_utf8(scene->params.name);
}

/* libinih's switches are globals of that library: set once, whichever
 * thread loads the first scene (an indented line without = is an error,
 * not a silent continuation). */
static pthread_once_t inih_configured = PTHREAD_ONCE_INIT;

static void configure_inih(void)
{
    ini_allow_multiline = 0;
}

/* Reads path, or text under the name path when text is not NULL. */
static int load(const char *path, const char *text, scene_file *scene, char *err, size_t err_size)
{
    int i;
    int name_from_path;

    memset(scene, 0, sizeof *scene);
    for (i = 0; i < SCENE_MAX_FIELDS; ++i)
        scene->set_file[i] = SCENE_NOT_SET;
    pthread_once(&inih_configured, configure_inih);
    name_from_path = default_name(scene, path);
    for (i = 0; scene_fields[i].key; ++i) { /* optional fields start at their defaults */
        const field_spec *f = &scene_fields[i];
        char why[160];
        if (f->default_text && f->kind != FIELD_TEXT && assign(&scene->params, f, f->default_text, why, sizeof why) != 0) {
            snprintf(err, err_size, "internal: default of [%s] %s: %s", f->section, f->key, why);
            return -1;
        }
    }
    if (text && strlen(text) > (size_t)SCENE_MAX_BYTES) {
        snprintf(err, err_size, "%s: cannot read scene text: more than a scene file may have (%ld bytes, 1 MiB)",
                 path, SCENE_MAX_BYTES);
        return -1;
    }
    if (load_file(scene, path, text, err, err_size) != 0)
        return -1;
    for (i = 0; scene_fields[i].key; ++i) {
        const field_spec *f = &scene_fields[i];
        char range[96];
        if (scene->set_file[i] != SCENE_NOT_SET || f->default_text)
            continue;
        field_range_text(f, range, sizeof range);
        snprintf(err, err_size, "%s: missing field [%s] %s (%s; allowed: %s)%s", path, f->section, f->key,
                 f->meaning, range, scene->file_count > 1 ? " in the file and its base" : "");
        return -1;
    }
    if (!name_from_path && scene->set_file[field_index("scene", "name")] == SCENE_NOT_SET) {
        snprintf(err, err_size, "%s: the file name cannot be the scene's name (longer than %d characters "
                 "or not UTF-8): set [scene] name", path, SCENE_TEXT - 1);
        return -1;
    }
    return 0;
}

int scene_load(const char *path, scene_file *scene, char *err, size_t err_size)
{
    return load(path, NULL, scene, err, err_size);
}

int scene_load_text(const char *name, const char *text, scene_file *scene, char *err, size_t err_size)
{
    return load(name, text, scene, err, err_size);
}

/* An option's text with a control character is refused as a file's line
 * would be; 0 or -1 with "OPTION TEXT...: control character 0x0a ...". */
static int check_option_text(const char *option, const char *text, char *err, size_t err_size)
{
    size_t at;
    if (!has_control(text, &at))
        return 0;
    snprintf(err, err_size, "%s %.*s...: control character 0x%02x after %lu characters: not allowed in a value "
             "(as in a scene file, where it is not text)", option, (int)at, text, (unsigned)(unsigned char)text[at],
             (unsigned long)at);
    return -1;
}

int scene_set(scene_file *scene, const char *section, const char *key, const char *value,
              const char *origin, char *err, size_t err_size)
{
    if (check_option_text(origin, value, err, err_size) != 0)
        return -1;
    if (strlen(origin) >= SCENE_OPTION) {
        snprintf(err, err_size, "%.*s...: option name too long (at most %d characters)", SCENE_OPTION,
                 origin, SCENE_OPTION - 1);
        return -1;
    }
    return set_field(scene, SCENE_BY_OPTION, origin, 0, section, key, value, err, err_size);
}

int scene_field_named(const char *name, size_t length, char *section, char *key)
{
    const char *dot = memchr(name, '.', length);
    int i;

    if (!dot)
        return -1;
    for (i = 0; scene_fields[i].key; ++i) {
        const field_spec *f = &scene_fields[i];
        if ((size_t)(dot - name) == strlen(f->section) && !strncmp(name, f->section, (size_t)(dot - name))
            && length - (size_t)(dot - name) - 1 == strlen(f->key)
            && !strncmp(dot + 1, f->key, strlen(f->key))) {
            if (section)
                strcpy(section, f->section);
            if (key)
                strcpy(key, f->key);
            return i;
        }
    }
    return -1;
}

int scene_set_assignment(scene_file *scene, const char *option, const char *assignment, char *err,
                         size_t err_size)
{
    char origin[SCENE_OPTION];
    char section[SCENE_NAME], key[SCENE_NAME];
    const char *equals = strchr(assignment, '=');
    const char *dot = strchr(assignment, '.');

    if (check_option_text(option, assignment, err, err_size) != 0)
        return -1;
    if (!equals || !dot || dot > equals || dot == assignment || dot + 1 == equals) {
        snprintf(err, err_size, "%s %s: expected section.key=value, such as %s excitation.frequency=110 "
                 "(beamslider fields lists every field)", option, assignment, option);
        return -1;
    }
    if (scene_field_named(assignment, (size_t)(equals - assignment), section, key) < 0) {
        snprintf(err, err_size, "%s %s: unknown field [%.*s] %.*s (beamslider fields lists every field)", option,
                 assignment, (int)(dot - assignment), assignment, (int)(equals - dot - 1), dot + 1);
        return -1;
    }
    /* where the value came from, as messages and the JSON summary name it: the
     * whole assignment when it fits, else the option and the field */
    if (snprintf(origin, sizeof origin, "%s %s", option, assignment) >= (int)sizeof origin)
        snprintf(origin, sizeof origin, "%s %s.%s=...", option, section, key);
    if (set_field(scene, SCENE_BY_OPTION, origin, SCENE_ASSIGNMENT, section, key, equals + 1, err, err_size) != 0) {
        /* a message naming the whole option, even where origin was cut */
        char why[1024];
        const char *detail = strstr(err, ": [");
        snprintf(why, sizeof why, "%s", detail ? detail : "");
        if (detail)
            snprintf(err, err_size, "%s %s%s", option, assignment, why);
        return -1;
    }
    return 0;
}

const char *scene_where(const scene_file *scene, const char *section, const char *key,
                        char *out, size_t size)
{
    const int i = field_index(section, key);
    if (i < 0 || scene->set_file[i] == SCENE_NOT_SET)
        snprintf(out, size, "(default)");
    else if (scene->set_file[i] == SCENE_BY_OPTION)
        snprintf(out, size, "%s", scene->set_option[i]);
    else
        snprintf(out, size, "%s:%d", scene->files[scene->set_file[i]], scene->set_line[i]);
    return out;
}
