/* scene_ini.c - reading scene files with libinih, every field checked.
 *
 * libinih (Debian's libinih-dev) does the INI syntax. Its handler gets no line
 * number in the Debian build, so the file is fed through a reader that counts
 * lines (and refuses over-long lines instead of letting them be split, and NUL
 * bytes, which would cut a line short unseen). The first error wins and names
 * file, line, field, value and the allowed range.
 */
#include "scene_ini.h"

#include <errno.h>
#include <ini.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct reader {
    FILE *file;
    int line;
    int bad_line;     /* line number of the first over-long line or NUL byte, 0 if none */
    int bad_is_nul;   /* 1: bad_line holds a NUL byte; 0: it is over-long */
    int read_errno;   /* errno of a failed read (e.g. the path is a folder), 0 if none */
} reader;

typedef struct parse {
    scene_file *scene;
    reader *in;
    int file;         /* index into scene->files */
    int scan_base;    /* 1: only look for [scene] base */
    char base[SCENE_PATH];
    int base_line;    /* line of [scene] base, 0 if none */
    char *err;
    size_t err_size;
    int failed;
} parse;

/* fgets for libinih, by characters: fgets cannot tell a NUL byte (a binary
 * or UTF-16 file) from the end of the line. */
static char *read_line(char *str, int num, void *stream)
{
    reader *in = (reader *)stream;
    int length = 0;
    int c = 0;

    errno = 0;
    while (length < num - 1 && (c = getc(in->file)) != EOF) {
        if (c == '\0' && !in->bad_line) {
            in->bad_line = in->line + 1;
            in->bad_is_nul = 1;
        }
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
    if (str[length - 1] != '\n' && length == num - 1 && !in->bad_line) {
        c = getc(in->file); /* full buffer: over-long unless the file ends here */
        if (c != EOF) {
            ungetc(c, in->file);
            in->bad_line = in->line;
        }
    }
    return str;
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

static int set_field(scene_file *scene, int file, int line, const char *section, const char *key,
                     const char *value, char *err, size_t err_size)
{
    const int i = field_index(section, key);
    char why[192];

    if (i < 0) {
        snprintf(err, err_size, "%s:%d: unknown field [%s] %s", scene->files[file], line, section, key);
        return -1;
    }
    if (scene->set_file[i] == file && line > 0) {
        snprintf(err, err_size, "%s:%d: [%s] %s set twice (first at line %d)", scene->files[file], line,
                 section, key, scene->set_line[i]);
        return -1;
    }
    if (assign(&scene->params, &scene_fields[i], value, why, sizeof why) != 0) {
        if (line > 0)
            snprintf(err, err_size, "%s:%d: [%s] %s = %s: %s", scene->files[file], line, section, key,
                     value, why);
        else
            snprintf(err, err_size, "%s %s: %s", scene->files[file], value, why);
        return -1;
    }
    scene->set_file[i] = file;
    scene->set_line[i] = line;
    return 0;
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
    if (set_field(p->scene, p->file, p->in->line, section, key, value, p->err, p->err_size) != 0) {
        p->failed = 1;
        return 0;
    }
    return 1;
}

/* One pass of libinih over the file; 0 or -1 with err filled. */
static int run_parser(parse *p)
{
    const char *path = p->scene->files[p->file];
    reader in;
    int result;

    in.file = fopen(path, "r");
    in.line = 0;
    in.bad_line = 0;
    in.bad_is_nul = 0;
    in.read_errno = 0;
    if (!in.file) {
        snprintf(p->err, p->err_size, "%s: cannot open scene file", path);
        return -1;
    }
    p->in = &in;
    result = ini_parse_stream(read_line, &in, on_entry, p);
    fclose(in.file);
    if (in.read_errno) {
        snprintf(p->err, p->err_size, "%s: cannot read scene file: %s", path, strerror(in.read_errno));
        return -1;
    }
    if (in.bad_line && !p->failed && !(result > 0 && result < in.bad_line)) {
        if (in.bad_is_nul)
            snprintf(p->err, p->err_size, "%s:%d: NUL byte: not a text file (UTF-16? save it as UTF-8)",
                     path, in.bad_line);
        else
            snprintf(p->err, p->err_size, "%s:%d: line longer than %d characters", path, in.bad_line,
                     ini_max_line - 3);
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

/* reuse: an option given twice reuses its entry; a base file never does, so
 * a cycle of bases runs into SCENE_MAX_FILES instead of recursing forever. */
static int add_file(scene_file *scene, const char *path, int reuse, char *err, size_t err_size)
{
    int i;
    for (i = 1; reuse && i < scene->file_count; ++i)
        if (!strcmp(scene->files[i], path))
            return i;
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

static int load_file(scene_file *scene, const char *path, char *err, size_t err_size)
{
    parse p;
    const int file = add_file(scene, path, 0, err, err_size);

    if (file < 0)
        return -1;
    memset(&p, 0, sizeof p);
    p.scene = scene;
    p.file = file;
    p.err = err;
    p.err_size = err_size;
    p.scan_base = 1;
    if (run_parser(&p) != 0)
        return -1;
    if (p.base[0]) {
        char base_path[SCENE_PATH];
        FILE *probe;
        const char *slash = strrchr(path, '/');
        const int folder = slash && p.base[0] != '/' ? (int)(slash - path + 1) : 0;
        if (snprintf(base_path, sizeof base_path, "%.*s%s", folder, path, p.base) >= (int)sizeof base_path) {
            snprintf(err, err_size, "%s: [scene] base: path too long", path);
            return -1;
        }
        probe = fopen(base_path, "r"); /* name the line that asked for it */
        if (!probe) {
            snprintf(err, err_size, "%s:%d: [scene] base = %s: cannot open %s", path, p.base_line, p.base,
                     base_path);
            return -1;
        }
        fclose(probe);
        if (load_file(scene, base_path, err, err_size) != 0)
            return -1;
    }
    p.scan_base = 0;
    return run_parser(&p);
}

static void default_name(scene_file *scene, const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t length = strlen(base);
    if (length > 4 && !strcmp(base + length - 4, ".ini"))
        length -= 4;
    if (length >= SCENE_TEXT)
        length = SCENE_TEXT - 1;
    memcpy(scene->params.name, base, length);
    scene->params.name[length] = '\0';
}

int scene_load(const char *path, scene_file *scene, char *err, size_t err_size)
{
    int i;

    memset(scene, 0, sizeof *scene);
    for (i = 0; i < SCENE_MAX_FIELDS; ++i)
        scene->set_file[i] = -1;
    ini_allow_multiline = 0; /* an indented line is an error, not a silent continuation */
    default_name(scene, path);
    for (i = 0; scene_fields[i].key; ++i) { /* optional fields start at their defaults */
        const field_spec *f = &scene_fields[i];
        char why[160];
        if (f->default_text && f->kind != FIELD_TEXT && assign(&scene->params, f, f->default_text, why, sizeof why) != 0) {
            snprintf(err, err_size, "internal: default of [%s] %s: %s", f->section, f->key, why);
            return -1;
        }
    }
    if (load_file(scene, path, err, err_size) != 0)
        return -1;
    for (i = 0; scene_fields[i].key; ++i) {
        const field_spec *f = &scene_fields[i];
        char range[96];
        if (scene->set_file[i] >= 0 || f->default_text)
            continue;
        field_range_text(f, range, sizeof range);
        snprintf(err, err_size, "%s: missing field [%s] %s (%s; allowed: %s)%s", path, f->section, f->key,
                 f->meaning, range, scene->file_count > 1 ? " in the file and its base" : "");
        return -1;
    }
    return 0;
}

int scene_set(scene_file *scene, const char *section, const char *key, const char *value,
              const char *origin, char *err, size_t err_size)
{
    const int file = add_file(scene, origin, 1, err, err_size);
    if (file < 0)
        return -1;
    return set_field(scene, file, 0, section, key, value, err, err_size);
}

const char *scene_where(const scene_file *scene, const char *section, const char *key,
                        char *out, size_t size)
{
    const int i = field_index(section, key);
    if (i < 0 || scene->set_file[i] < 0)
        snprintf(out, size, "(default)");
    else if (scene->set_line[i] > 0)
        snprintf(out, size, "%s:%d", scene->files[scene->set_file[i]], scene->set_line[i]);
    else
        snprintf(out, size, "%s", scene->files[scene->set_file[i]]);
    return out;
}
