/* map_store.c - a map's folder: identity and result files (map_store.h). */
#define _POSIX_C_SOURCE 200809L /* getline, scandir, link, fdatasync, gethostname */
#define _DEFAULT_SOURCE         /* alphasort, gethostname with glibc */

#include "map_store.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "input_file.h"
#include "map_case.h"
#include "out_text.h"
#include "scene_values.h"
#include "source_revision.h"

/* The identity's format; raised whenever the result rows' columns change
 * (2: s_final became s_settled, window_s added), so that a folder of an
 * older map is refused, never merged with rows that mean other things. */
#define IDENTITY_FORMAT 2

/* ---- the identity ------------------------------------------------------ */

/* A growing text. */
typedef struct text {
    char *data;
    size_t used, size;
    int failed;
} text;

static void append(text *t, const char *part)
{
    const size_t n = strlen(part);
    if (t->failed)
        return;
    if (t->used + n + 1 > t->size) {
        size_t size = t->size ? t->size : 1024;
        char *grown;
        while (t->used + n + 1 > size)
            size *= 2;
        if (!(grown = realloc(t->data, size))) {
            t->failed = 1;
            return;
        }
        t->data = grown;
        t->size = size;
    }
    memcpy(t->data + t->used, part, n + 1);
    t->used += n;
}

/* "info KEY = VALUE" with VALUE made one line (out_text.h): a name, a path
 * or a command line may hold a line break, which would forge a line. */
static void append_info(text *t, const char *key, const char *value)
{
    char *line = malloc(strlen(key) + strlen(value) + 10);
    if (!line) {
        t->failed = 1;
        return;
    }
    sprintf(line, "info %s = %s", key, value);
    append(t, out_text_one_line(line));
    append(t, "\n");
    free(line);
}

char *map_identity_text(const map_grid *grid, const scene_file *base, const char *scene_path,
                        const char *command)
{
    unsigned char skip[SCENE_MAX_FIELDS];
    char line[512];
    text t;
    int v, i;

    memset(&t, 0, sizeof t);
    memset(skip, 0, sizeof skip);
    for (v = 0; v < grid->vary_count; ++v)
        skip[grid->vary[v].field] = 1; /* the base's value of a varied field is never used */
    append(&t, "# beamslider map: what this folder's results are of (docs/maps.md). A map command\n"
               "# whose identity differs is refused here; lines starting with info are not compared.\n");
    snprintf(line, sizeof line, "format = %d\nversion = %s\nprecision = %s\n", IDENTITY_FORMAT, bs_version(),
             BS_REAL_NAME);
    append(&t, line);
    snprintf(line, sizeof line, "fields_hash = %016llx\nrepeat = %d\nperturbation = %g\n",
             (unsigned long long)scene_values_hash(&base->params, skip), grid->repeat, MAP_PERTURBATION);
    append(&t, line);
    for (v = 0; v < grid->vary_count; ++v) {
        int k;
        snprintf(line, sizeof line, "vary %s = ", grid->vary[v].name);
        append(&t, line);
        for (k = 0; k < grid->vary[v].count; ++k) {
            append(&t, k ? "," : "");
            append(&t, grid->vary[v].values[k]);
        }
        append(&t, "\n");
    }
    snprintf(line, sizeof line, "info revision = %s\n", source_revision());
    append(&t, line);
    append_info(&t, "scene", base->params.name);
    append_info(&t, "scene_file", scene_path);
    for (i = 0; scene_fields[i].key; ++i)
        if (base->set_file[i] == SCENE_BY_OPTION)
            append_info(&t, "set", base->set_option[i]);
    append_info(&t, "command", command);
    if (t.failed) {
        free(t.data);
        return NULL;
    }
    return t.data;
}

/* The value of the compared line "key = value" in identity (the first
 * character after "key = "), its length in *length; NULL if none. For
 * "vary", the n-th vary line (its text from the field's name). */
static const char *identity_value(const char *identity, const char *key, int n, size_t *length)
{
    const char *line = identity;
    const size_t key_length = strlen(key);

    while (line && *line) {
        if (!strncmp(line, key, key_length) && line[key_length] == ' ') {
            const char *value = line + key_length + 1;
            if (strcmp(key, "vary") && !strncmp(value, "= ", 2))
                value += 2;
            if (n-- == 0) {
                *length = strcspn(value, "\n");
                return value;
            }
        }
        line = strchr(line, '\n');
        if (line)
            ++line;
    }
    return NULL;
}

/* "N values FIRST .. LAST" of a vary line's value list. */
static void describe_values(const char *value, size_t length, char *out, size_t size)
{
    const char *list = strstr(value, " = ");
    const char *first_end, *last;
    int count = 1;
    size_t i;

    if (!list || (size_t)(list - value) > length) {
        snprintf(out, size, "?");
        return;
    }
    list += 3;
    length -= (size_t)(list - value);
    for (i = 0; i < length; ++i)
        count += list[i] == ',';
    first_end = memchr(list, ',', length);
    for (last = list + length; last > list && last[-1] != ','; --last)
        ;
    if (!first_end)
        snprintf(out, size, "1 value %.*s", (int)length, list);
    else
        snprintf(out, size, "%d values %.*s .. %.*s", count, (int)(first_end - list), list,
                 (int)(list + length - last), last);
}

/* 0 if the compared lines of a (the folder's) and b (this command's) agree,
 * else -1 with what differs in err. */
static int compare_identities(const char *dir, const char *a, const char *b, char *err, size_t size)
{
    static const char *const keys[] = { "format", "version", "precision", "fields_hash", "repeat",
                                        "perturbation", NULL };
    static const char *const meaning[] = { "identity format", "beamslider version", "precision",
                                           "scene (hash of its fields after --set)", "repeats (--repeat)",
                                           "perturbation of the repeats" };
    size_t la = 0, lb = 0;
    const char *va, *vb;
    int k, n;

    for (k = 0; keys[k]; ++k) {
        va = identity_value(a, keys[k], 0, &la);
        vb = identity_value(b, keys[k], 0, &lb);
        if (!va || !vb || la != lb || strncmp(va, vb, la)) {
            snprintf(err, size, "%s holds another map: its %s is %.*s, this command's %.*s "
                     "(%s/" MAP_IDENTITY_FILE "; use another --out folder, or remove it to start again)",
                     dir, meaning[k], va ? (int)la : 6, va ? va : "(none)", (int)lb, vb, dir);
            return -1;
        }
    }
    for (n = 0;; ++n) {
        size_t name_a, name_b;
        va = identity_value(a, "vary", n, &la);
        vb = identity_value(b, "vary", n, &lb);
        if (!va && !vb)
            return 0;
        name_a = va ? strcspn(va, " ") : 0;
        name_b = vb ? strcspn(vb, " ") : 0;
        if (!va || !vb || name_a != name_b || strncmp(va, vb, name_a)) {
            snprintf(err, size, "%s holds another map: its varied field %d is %.*s, this command's %.*s "
                     "(use another --out folder, or remove it to start again)", dir, n + 1,
                     va ? (int)name_a : 6, va ? va : "(none)", vb ? (int)name_b : 6, vb ? vb : "(none)");
            return -1;
        }
        if (la != lb || strncmp(va, vb, la)) {
            char there[256], here[256];
            describe_values(va, la, there, sizeof there);
            describe_values(vb, lb, here, sizeof here);
            snprintf(err, size, "%s holds another map: the values of %.*s differ: %s there, %s in this "
                     "command (use another --out folder, or remove it to start again)", dir, (int)name_a, va,
                     there, here);
            return -1;
        }
    }
}

/* The whole of an identity file (opened as every input is, input_file.h),
 * malloc'd and NUL-terminated; NULL with why (the path named) set. */
static char *read_all(const char *path, char *why, size_t why_size)
{
    FILE *in;
    char *data = NULL;
    size_t used = 0, size = 0;

    if (input_file_open(path, INPUT_MAP_IDENTITY, &in, NULL, why, why_size) != 0)
        return NULL;
    for (;;) {
        size_t n;
        if (used + 4096 + 1 > size) {
            char *grown = realloc(data, size ? 2 * size : 8192);
            if (!grown || (long long)used > input_kind_max_bytes(INPUT_MAP_IDENTITY)) { /* a file that grows */
                free(grown ? grown : data);
                fclose(in);
                snprintf(why, why_size, "%s: cannot read map identity: %s", path,
                         grown ? "it grew past its bound while being read" : strerror(ENOMEM));
                return NULL;
            }
            data = grown;
            size = size ? 2 * size : 8192;
        }
        n = fread(data + used, 1, 4096, in);
        used += n;
        if (n < 4096)
            break;
    }
    if (ferror(in)) {
        free(data);
        fclose(in);
        snprintf(why, why_size, "%s: cannot read map identity: %s", path, strerror(EIO));
        return NULL;
    }
    fclose(in);
    data[used] = '\0';
    return data;
}

/* 1 if dir holds nothing but . and .. and identities being written by
 * commands that started at the same time (publish_identity) */
static int folder_is_empty(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    int empty = 1;
    if (!d)
        return 0;
    while (empty && (entry = readdir(d)))
        empty = !strcmp(entry->d_name, ".") || !strcmp(entry->d_name, "..")
                || !strncmp(entry->d_name, ".map-identity-", 14);
    closedir(d);
    return empty;
}

/* Writes identity to a name of this process's in dir, then links it into
 * place; 0 (written), 1 (another process's identity is there), -1. */
static int publish_identity(const char *dir, const char *identity, char *err, size_t size)
{
    char aside[4200], path[4200], host[64];
    const size_t length = strlen(identity);
    int fd, status = 0;

    if (gethostname(host, sizeof host) != 0)
        strcpy(host, "host");
    host[sizeof host - 1] = '\0';
    snprintf(path, sizeof path, "%s/" MAP_IDENTITY_FILE, dir);
    snprintf(aside, sizeof aside, "%s/.map-identity-%s-%ld", dir, host, (long)getpid());
    fd = open(aside, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (fd < 0 || write(fd, identity, length) != (ssize_t)length || fsync(fd) != 0) {
        snprintf(err, size, "cannot write %s: %s", aside, strerror(errno));
        if (fd >= 0)
            close(fd);
        unlink(aside);
        return -1;
    }
    close(fd);
    if (link(aside, path) != 0) {
        if (errno == EEXIST) {
            status = 1;
        } else {
            snprintf(err, size, "cannot write %s: %s", path, strerror(errno));
            status = -1;
        }
    }
    unlink(aside);
    return status;
}

/* Creates dir and the folders above it that are missing (mkdir -p; another
 * shard may make one at the same time: EEXIST is fine). Returns 1 + the
 * length of the first folder it created (for remove_folders), 0 if another
 * made them all, or -1 with err naming the folder that could not be made
 * and why; *made_dir = 1 if this call made dir itself (not another shard). */
static int make_folders(const char *dir, int *made_dir, char *err, size_t size)
{
    char prefix[4200];
    const size_t length = strlen(dir);
    size_t end;
    int first = 0;

    for (end = 1; end <= length; ++end) {
        struct stat info;
        if (end < length && dir[end] != '/')
            continue;
        if (dir[end - 1] == '/')
            continue; /* "//" */
        memcpy(prefix, dir, end);
        prefix[end] = '\0';
        if (stat(prefix, &info) == 0) {
            if (!S_ISDIR(info.st_mode)) {
                snprintf(err, size, "--out %s: cannot create the folder: %s is a file, not a folder", dir, prefix);
                return -1;
            }
            continue;
        }
        if (errno != ENOENT) {
            snprintf(err, size, "--out %s: cannot create the folder %s: %s", dir, prefix, strerror(errno));
            return -1;
        }
        if (mkdir(prefix, 0777) != 0) {
            if (errno != EEXIST) {
                snprintf(err, size, "--out %s: cannot create the folder %s: %s", dir, prefix, strerror(errno));
                return -1;
            }
            if (stat(prefix, &info) != 0 || !S_ISDIR(info.st_mode)) { /* another made a file there */
                snprintf(err, size, "--out %s: cannot create the folder: %s is a file, not a folder", dir, prefix);
                return -1;
            }
            continue; /* another shard made it just now */
        }
        if (end == length)
            *made_dir = 1;
        if (!first)
            first = (int)end + 1;
    }
    return first;
}

/* Removes the folders make_folders created (1 + the length of the first), deepest first. */
static void remove_folders(const char *dir, int created)
{
    char prefix[4200];
    size_t end = strlen(dir);
    snprintf(prefix, sizeof prefix, "%s", dir);
    while (end + 1 >= (size_t)created && end > 0) {
        prefix[end] = '\0';
        if (rmdir(prefix) != 0)
            return;
        while (end > 0 && prefix[end - 1] != '/')
            --end;
        while (end > 0 && prefix[end - 1] == '/')
            --end;
    }
}

/* Shards started together race here, so every step allows for another
 * process having done any of its own since the last look: the folder made
 * (EEXIST is success), the identity linked (EEXIST: compare with it), and
 * files beside the identity. A map command makes other files only after the
 * identity is in place, so a folder that holds files is refused as not a
 * map's only if it still has no identity after they were seen. */
int map_dir_claim(const char *dir, const char *identity, char *err, size_t size)
{
    char path[4200];
    char *there;
    int created = 0, first_made, status;

    if (strlen(dir) > 4000) {
        snprintf(err, size, "--out %.40s...: path too long", dir);
        return -1;
    }
    if ((first_made = make_folders(dir, &created, err, size)) < 0)
        return -1;
    snprintf(path, sizeof path, "%s/" MAP_IDENTITY_FILE, dir);
    if (access(path, F_OK) != 0) {
        if (!created && !folder_is_empty(dir) && access(path, F_OK) != 0) {
            snprintf(err, size, "--out %s: the folder holds files but no " MAP_IDENTITY_FILE ": not a map's "
                     "folder (use a new or an empty folder)", dir);
            return -1;
        }
        status = publish_identity(dir, identity, err, size);
        if (status < 0) {
            if (first_made > 0)
                remove_folders(dir, first_made);
            return -1;
        }
        if (status == 0)
            return 0;
    }
    there = read_all(path, err, size);
    if (!there)
        return -1;
    status = compare_identities(dir, there, identity, err, size);
    if (status == 0) {
        size_t la = 0, lb = 0;
        const char *a = identity_value(there, "info revision", 0, &la);
        const char *b = identity_value(identity, "info revision", 0, &lb);
        if (!a || !b || la != lb || strncmp(a, b, la)) {
            snprintf(err, size, "%s was started by source revision %.*s, this is %.*s (the same version): "
                     "their rows are merged", dir, a ? (int)la : 7, a ? a : "unknown", (int)lb, b);
            status = 1;
        }
    }
    free(there);
    return status;
}

/* ---- reading an identity back (map-merge, map-plot) ---------------------
 * The folder is input like any file: its identity may have been edited, by
 * hand or to attack what is made of it (map-plot writes its scene name and
 * values into a gnuplot script). Every line is checked for its shape before
 * anything is taken from it, and refused with its line. */

/* The longest line an identity may hold (info command: a whole command line). */
#define IDENTITY_LINE 65536

/* One value of a varied field: a number the field takes (REAL, INT), or one
 * of its choices. */
static int identity_value_ok(const field_spec *f, const char *value, size_t length)
{
    char copy[MAP_VALUE], *end;
    double x;
    int k;

    if (length == 0 || length >= MAP_VALUE)
        return 0;
    memcpy(copy, value, length);
    copy[length] = '\0';
    if (f->kind == FIELD_CHOICE) {
        for (k = 0; f->choices[k]; ++k)
            if (!strcmp(copy, f->choices[k]))
                return 1;
        return 0;
    }
    x = strtod(copy, &end);
    return end != copy && !*end && isfinite(x) && strspn(copy, "+-.0123456789eE") == length
           && (f->kind != FIELD_INT || x == floor(x));
}

/* "vary NAME = v1,v2,..." into the next field of grid; NULL, or what is wrong. */
static const char *read_vary(map_grid *grid, const char *line, size_t length)
{
    const char *list = strstr(line, " = ");
    const char *at, *end = line + length;
    map_vary *vary;
    int field, k, j;

    if (grid->vary_count >= MAP_MAX_VARY)
        return "more varied fields than a map has";
    if (!list || list > end || list - line <= 5 || list - line - 5 >= MAP_FIELD)
        return "expected vary SECTION.KEY = VALUE,VALUE,...";
    field = scene_field_named(line + 5, (size_t)(list - line) - 5, NULL, NULL);
    if (field < 0 || scene_fields[field].kind == FIELD_TEXT)
        return "not a field a map varies";
    for (k = 0; k < grid->vary_count; ++k)
        if (grid->vary[k].field == field)
            return "a field varied twice";
    vary = &grid->vary[grid->vary_count];
    memset(vary, 0, sizeof *vary);
    vary->field = field;
    snprintf(vary->name, sizeof vary->name, "%.*s", (int)(list - line) - 5, line + 5);
    list += 3;
    vary->count = 1;
    for (at = list; at < end; ++at)
        if (*at == ',' && ++vary->count > MAP_MAX_VALUES)
            return "more values than a field may take";
    vary->values = malloc((size_t)vary->count * sizeof *vary->values);
    if (!vary->values)
        return "out of memory";
    ++grid->vary_count; /* owned by grid from here: map_grid_free frees the values */
    for (k = 0, at = list; k < vary->count; ++k) {
        const size_t n = strcspn(at, ",\n");
        if (!identity_value_ok(&scene_fields[field], at, n))
            return "a value the field cannot take (a number in its kind, or one of its choices)";
        snprintf(vary->values[k], MAP_VALUE, "%.*s", (int)n, at);
        for (j = 0; j < k; ++j)
            if (!strcmp(vary->values[j], vary->values[k]))
                return "a value given twice";
        at += n + 1;
    }
    return NULL;
}

int map_identity_read(const char *dir, map_grid *grid, char *scene, char *err, size_t size)
{
    char path[4200], unread[4400];
    char *identity;
    const char *line, *why = NULL;
    long number = 0;
    int repeat = 0, format = 0;

    map_grid_init(grid);
    snprintf(scene, SCENE_TEXT, "map");
    snprintf(path, sizeof path, "%s/" MAP_IDENTITY_FILE, dir);
    identity = read_all(path, unread, sizeof unread);
    if (!identity) {
        snprintf(err, size, "%s: no map here: %s", dir, unread);
        return -1;
    }
    for (line = identity; *line && !why; line += strcspn(line, "\n") + 1) {
        const size_t length = strcspn(line, "\n");
        size_t i;
        char *end;
        ++number;
        if (line[length] != '\n')
            why = "the last line has no line end (cut short?)";
        else if (length > IDENTITY_LINE)
            why = "line too long";
        for (i = 0; i < length && !why; ++i)
            if ((unsigned char)line[i] < 0x20 || line[i] == 0x7f)
                why = "a control character";
        if (why || line[0] == '#')
            continue;
        if (!strncmp(line, "format = ", 9)) {
            format = (int)strtol(line + 9, &end, 10);
            if (end != line + length || format != IDENTITY_FORMAT)
                why = "a format this version does not read";
        } else if (!strncmp(line, "repeat = ", 9)) {
            const long k = strtol(line + 9, &end, 10);
            if (end != line + length || k < 1 || k > MAP_MAX_REPEAT)
                why = "repeat is not an integer in [1, " SCENE_TEXT_OF(MAP_MAX_REPEAT) "]";
            repeat = (int)k;
        } else if (!strncmp(line, "vary ", 5)) {
            why = read_vary(grid, line, length);
        } else if (!strncmp(line, "info scene = ", 13)) {
            if (length - 13 >= SCENE_TEXT)
                why = "the scene's name is longer than a scene's name may be";
            else
                snprintf(scene, SCENE_TEXT, "%.*s", (int)(length - 13), line + 13);
        } else if (strncmp(line, "version = ", 10) && strncmp(line, "precision = ", 12)
                   && strncmp(line, "fields_hash = ", 14) && strncmp(line, "perturbation = ", 15)
                   && strncmp(line, "info ", 5)) {
            why = "not a line of an identity";
        }
    }
    free(identity);
    if (!why && !format)
        why = "no format line", number = 0;
    else if (!why && !repeat)
        why = "no repeat line", number = 0;
    if (why) {
        if (number > 0)
            snprintf(err, size, "%s:%ld: %s (not as beamslider map writes it: edited or damaged)", path, number, why);
        else
            snprintf(err, size, "%s: %s (not as beamslider map writes it: edited or damaged)", path, why);
        map_grid_free(grid);
        return -1;
    }
    if (map_grid_finish(grid, repeat, err, size) != 0) {
        char reason[1024];
        snprintf(reason, sizeof reason, "%s", err);
        snprintf(err, size, "%s: %s", path, reason);
        map_grid_free(grid);
        return -1;
    }
    return 0;
}

/* ---- results ----------------------------------------------------------- */

static int is_results_name(const struct dirent *entry)
{
    const size_t n = strlen(entry->d_name);
    return n > 9 && !strncmp(entry->d_name, "runs-", 5) && !strcmp(entry->d_name + n - 4, ".csv");
}

/* Takes one file's lines into found (opened as every input is,
 * input_file.h): 0, or -1 with err. */
static int read_results_file(const char *path, const map_grid *grid, map_found *found, char *err, size_t size)
{
    FILE *in;
    char *line = NULL;
    size_t capacity = 0;
    ssize_t length;

    if (input_file_open(path, INPUT_MAP_RESULTS, &in, NULL, err, size) != 0)
        return -1;
    while ((length = getline(&line, &capacity, in)) > 0) {
        long c;
        if (!strncmp(line, "case,", 5))
            continue; /* the header */
        if (line[length - 1] != '\n') {
            ++found->torn; /* only a last line can lack its newline */
            continue;
        }
        if (!map_row_valid(grid, line, (size_t)length, &c)) {
            ++found->invalid;
            continue;
        }
        if (found->row[c]) {
            /* the same case again (a shard rerun while the first still ran):
             * the result columns must agree; wall_s and check may not */
            const char *a = found->row[c], *b = line;
            const char *end_a = a + strlen(a), *end_b = b + length;
            int commas = 0;
            ++found->duplicates;
            while (end_a > a && commas < 2)
                commas += *--end_a == ',';
            commas = 0;
            while (end_b > b && commas < 2)
                commas += *--end_b == ',';
            if (end_a - a != end_b - b || strncmp(a, b, (size_t)(end_a - a)))
                ++found->differing;
            continue;
        }
        found->row[c] = malloc((size_t)length + 1);
        if (found->row[c]) {
            memcpy(found->row[c], line, (size_t)length + 1);
            ++found->done;
        }
    }
    free(line);
    fclose(in);
    return 0;
}

int map_found_read(const char *dir, const map_grid *grid, map_found *found, char *err, size_t size)
{
    struct dirent **names;
    char path[4400];
    int count, i, failed = 0;

    memset(found, 0, sizeof *found);
    found->row = calloc((size_t)grid->cases, sizeof *found->row);
    if (!found->row) {
        snprintf(err, size, "%s: out of memory for %ld cases", dir, grid->cases);
        return -1;
    }
    count = scandir(dir, &names, is_results_name, alphasort); /* a fixed order: the first row of a case wins */
    if (count < 0) {
        snprintf(err, size, "cannot read the folder %s: %s", dir, strerror(errno));
        free(found->row);
        found->row = NULL;
        return -1;
    }
    for (i = 0; i < count; ++i) {
        snprintf(path, sizeof path, "%s/%s", dir, names[i]->d_name);
        if (!failed && read_results_file(path, grid, found, err, size) != 0)
            failed = 1;
        free(names[i]);
    }
    free(names);
    if (failed)
        map_found_free(found, grid->cases);
    return failed ? -1 : 0;
}

void map_found_free(map_found *found, long cases)
{
    long c;
    if (found->row)
        for (c = 0; c < cases; ++c)
            free(found->row[c]);
    free(found->row);
    found->row = NULL;
}

int map_results_create(const char *dir, const map_grid *grid, char *path, size_t path_size, char *err,
                       size_t size)
{
    char host[64];
    char header[8192];
    int fd = -1, k;

    if (gethostname(host, sizeof host) != 0)
        strcpy(host, "host");
    host[sizeof host - 1] = '\0';
    for (k = 1; k < 1000 && fd < 0; ++k) {
        if (k == 1)
            snprintf(path, path_size, "%s/runs-%s-%ld.csv", dir, host, (long)getpid());
        else
            snprintf(path, path_size, "%s/runs-%s-%ld-%d.csv", dir, host, (long)getpid(), k);
        fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_APPEND, 0666);
        if (fd < 0 && errno != EEXIST)
            break;
    }
    if (fd < 0) {
        snprintf(err, size, "cannot create %s: %s", path, strerror(errno));
        return -1;
    }
    map_case_header(grid, header, sizeof header);
    if (write(fd, header, strlen(header)) != (ssize_t)strlen(header)) {
        snprintf(err, size, "cannot write %s: %s", path, strerror(errno));
        close(fd);
        return -1;
    }
    return fd;
}

int map_results_append(int fd, const char *row, off_t *length, char *err, size_t size)
{
    const size_t n = strlen(row);
    const ssize_t written = write(fd, row, n); /* O_APPEND: one write, one whole line */

    if (written != (ssize_t)n) {
        const int why = written < 0 ? errno : ENOSPC;
        /* cut the torn row off again; if that fails too, readers still
         * ignore it (no newline, or a failing check) */
        const int cut = written > 0 ? ftruncate(fd, *length) : 0;
        snprintf(err, size, "cannot append a row: %s%s", strerror(why),
                 cut ? " (and the part written could not be cut off)" : "");
        return -1;
    }
    *length += (off_t)n;
    if (fdatasync(fd) != 0) {
        snprintf(err, size, "cannot sync a row to disk: %s", strerror(errno));
        return -1;
    }
    return 0;
}
