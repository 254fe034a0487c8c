/* test_map.c - the map's grid, shards, rows, folder identity and result
 * files (host/lib/map/map_grid.c, map_case.c, map_store.c, map_table.c). The
 * whole command (workers, resume after a kill, shards, refusals) is checked
 * by tests/check_map.sh. Run from the repository root. */
#define _GNU_SOURCE /* RTLD_NEXT */

#include "support.h"

#include <dirent.h>
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "map_case.h"
#include "map_grid.h"
#include "map_store.h"
#include "map_table.h"

static scene_file base;  /* static: large */
static scene_file one;
static bs_scene scene;
static scene_model model;
static char dir[64];
static char err[2048];

static void load_base(void)
{
    support_load("configs/fig6.ini", &base, &scene, &model);
    assert_int_equal(scene_set_assignment(&base, "--set", "run.t_end=0.004", err, sizeof err), 0);
}

static void remove_dir(const char *path)
{
    DIR *d = opendir(path);
    struct dirent *entry;
    char name[512];
    if (!d)
        return;
    while ((entry = readdir(d)) != NULL) {
        if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
            continue;
        snprintf(name, sizeof name, "%s/%s", path, entry->d_name);
        unlink(name);
    }
    closedir(d);
    rmdir(path);
}

static int make_dir(void **state)
{
    (void)state;
    strcpy(dir, "/tmp/test_map.XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int drop_dir(void **state)
{
    (void)state;
    remove_dir(dir);
    return 0;
}

/* A grid of specs (NULL-terminated) with repeat; fails the test on error. */
static void grid_of(map_grid *grid, const char *const *specs, int repeat)
{
    map_grid_init(grid);
    for (; *specs; ++specs)
        if (map_grid_add(grid, &base, *specs, err, sizeof err) != 0) {
            print_error("%s\n", err);
            fail();
        }
    assert_int_equal(map_grid_finish(grid, repeat, err, sizeof err), 0);
}

#define assert_err_has(text)                                                    \
    do {                                                                        \
        if (!strstr(err, text)) {                                               \
            print_error("message \"%s\" lacks \"%s\"\n", err, text);            \
            fail();                                                             \
        }                                                                       \
    } while (0)

static void test_ranges_and_lists_give_canonical_values(void **state)
{
    static const char *const specs[] = { "excitation.frequency=90:140:1", "excitation.acceleration=0.1:0.3:0.1",
                                         "numerics.modes=1,3", "run.model=free,pcs", NULL };
    map_grid grid;
    (void)state;
    load_base();
    grid_of(&grid, specs, 3);
    assert_int_equal(grid.vary_count, 4);
    assert_int_equal(grid.vary[0].count, 51);
    assert_string_equal(grid.vary[0].values[0], "90");
    assert_string_equal(grid.vary[0].values[50], "140");
    /* FROM + i STEP to 12 digits: 0.1 * 3 is not 0.30000000000000004 */
    assert_int_equal(grid.vary[1].count, 3);
    assert_string_equal(grid.vary[1].values[2], "0.3");
    assert_string_equal(grid.vary[2].values[1], "3");
    assert_string_equal(grid.vary[3].values[1], "pcs");
    assert_int_equal(grid.points, 51 * 3 * 2 * 2);
    assert_int_equal(grid.cases, 51 * 3 * 2 * 2 * 3);
    map_grid_free(&grid);
}

static void test_bad_vary_specs_are_refused_with_the_reason(void **state)
{
    static const struct {
        const char *spec, *reason;
    } bad[] = {
        { "excitation.freq=1:2:1", "unknown field excitation.freq" },
        { "frequency=1,2", "unknown field" },
        { "excitation.frequency", "expected section.key=" },
        { "excitation.frequency=", "no values" },
        { "excitation.frequency=100:100:1", "empty range" },
        { "excitation.frequency=140:90:1", "inverted range" },
        { "excitation.frequency=90:140:0", "STEP must be above 0" },
        { "excitation.frequency=90:140:3", "does not divide" },
        { "excitation.frequency=90:x:1", "TO x is not a finite number" },
        { "excitation.frequency=90:140", "expected FROM:TO:STEP" },
        { "excitation.frequency=90,,100", "an empty value" },
        { "excitation.frequency=90,1e2,100", "value 100 given twice" },
        { "excitation.frequency=-5,10", "[excitation] frequency = -5: out of range" },
        { "numerics.modes=1:3:0.5", "not an integer" },
        { "run.model=free:pcs:1", "is a choice" },
        { "run.model=free,fixed", "unknown value" },
        { "scene.description=a,b", "is a text" },
        { NULL, NULL }
    };
    map_grid grid;
    int i;
    (void)state;
    load_base();
    for (i = 0; bad[i].spec; ++i) {
        map_grid_init(&grid);
        err[0] = '\0';
        if (map_grid_add(&grid, &base, bad[i].spec, err, sizeof err) != -1) {
            print_error("--vary %s was taken\n", bad[i].spec);
            fail();
        }
        assert_err_has(bad[i].reason);
        assert_err_has("--vary");
        assert_int_equal(grid.vary_count, 0);
        map_grid_free(&grid);
    }
    /* the same field twice, or set and varied */
    map_grid_init(&grid);
    assert_int_equal(map_grid_add(&grid, &base, "excitation.frequency=90,100", err, sizeof err), 0);
    assert_int_equal(map_grid_add(&grid, &base, "excitation.frequency=110,120", err, sizeof err), -1);
    assert_err_has("varied twice");
    assert_int_equal(map_grid_add(&grid, &base, "run.t_end=1,2", err, sizeof err), -1);
    assert_err_has("also set by --set run.t_end=0.004");
    map_grid_free(&grid);
    /* too many cases, a repeat out of range */
    map_grid_init(&grid);
    assert_int_equal(map_grid_add(&grid, &base, "excitation.frequency=1:10000:1", err, sizeof err), 0);
    assert_int_equal(map_grid_finish(&grid, 101, err, sizeof err), -1);
    assert_err_has("--repeat 101: 10000 grid points times 101 repeats, more than a map may have (at most 1000000 cases)");
    assert_int_equal(map_grid_finish(&grid, 0, err, sizeof err), -1);
    /* counts refused before any value is checked or allocated: a second field
     * of 1000 values, a range of 1e300 / 1e-300 values (inf as a count) */
    assert_int_equal(map_grid_add(&grid, &base, "excitation.acceleration=1:1000:1", err, sizeof err), -1);
    assert_err_has("--vary excitation.acceleration=1:1000:1: 1e+07 grid points with the fields varied before it");
    assert_int_equal(grid.vary_count, 1);
    map_grid_free(&grid);
    map_grid_init(&grid);
    assert_int_equal(map_grid_add(&grid, &base, "excitation.frequency=1:1e300:1e-300", err, sizeof err), -1);
    assert_err_has("inf values, at most 100000 a field");
    assert_int_equal(map_grid_add(&grid, &base, "excitation.frequency=1:100001:1", err, sizeof err), -1);
    assert_err_has("100001 values, at most 100000 a field");
    /* a value twice, found among many (sorted, not pairwise) */
    assert_int_equal(map_grid_add(&grid, &base, "excitation.frequency=1,2,3,4,5,6,7,8,9,3", err, sizeof err), -1);
    assert_err_has("value 3 given twice");
    map_grid_free(&grid);
}

static void test_cases_run_the_last_field_fastest_and_repeat_in_place(void **state)
{
    static const char *const specs[] = { "excitation.frequency=120,122,124", "excitation.acceleration=10,14",
                                         NULL };
    map_grid grid;
    long c;
    (void)state;
    load_base();
    grid_of(&grid, specs, 2);
    assert_int_equal(grid.cases, 12);
    for (c = 0; c < grid.cases; ++c) {
        const long point = map_case_point(&grid, c);
        assert_int_equal(point, c / 2);
        assert_int_equal(map_case_repeat(&grid, c), c % 2);
        assert_int_equal(map_point_value(&grid, point, 0), point / 2);
        assert_int_equal(map_point_value(&grid, point, 1), point % 2);
    }
    /* case 7: point 3 (122 Hz, 14 m/s^2), repeat 1: s0 + 1e-5 */
    assert_int_equal(map_case_scene(&grid, &base, 7, &one, err, sizeof err), 0);
    assert_true(one.params.frequency == 122.0);
    assert_true(one.params.acceleration == 14.0);
    assert_true(one.params.s0 == 0.30001);
    assert_true(one.params.t_end == 0.004);
    map_grid_free(&grid);
}

static void test_shards_deal_out_every_case_once(void **state)
{
    int count, index;
    long c;
    (void)state;
    for (count = 1; count <= 7; ++count)
        for (c = 0; c < 100; ++c) {
            int owners = 0;
            for (index = 1; index <= count; ++index)
                owners += map_shard_has(c, index, count);
            assert_int_equal(owners, 1);
        }
    assert_int_equal(map_shard_parse("3/4", &index, &count, err, sizeof err), 0);
    assert_int_equal(index, 3);
    assert_int_equal(count, 4);
    assert_int_equal(map_shard_parse("0/4", &index, &count, err, sizeof err), -1);
    assert_err_has("shard index out of range; allowed: 1 to 4");
    assert_int_equal(map_shard_parse("5/4", &index, &count, err, sizeof err), -1);
    assert_err_has("out of range");
    assert_int_equal(map_shard_parse("1/0", &index, &count, err, sizeof err), -1);
    assert_int_equal(map_shard_parse("two", &index, &count, err, sizeof err), -1);
    assert_err_has("expected I/N");
}

/* A row made by map_case_run: whole, and refused once damaged or cut. */
static void test_rows_carry_a_check_that_finds_damage(void **state)
{
    static const char *const specs[] = { "excitation.frequency=120,124", NULL };
    map_grid grid;
    char row[MAP_ROW], copy[MAP_ROW];
    size_t length;
    long c;
    (void)state;
    load_base();
    grid_of(&grid, specs, 2);
    assert_int_equal(map_case_run(&grid, &base, 3, row, sizeof row, err, sizeof err), 0);
    length = strlen(row);
    assert_true(map_row_valid(&grid, row, length, &c));
    assert_int_equal(c, 3);
    assert_non_null(strstr(row, "3,1,1,124,0.30001,ok,"));
    /* every single-character change, and every cut, is caught */
    for (size_t i = 0; i + 1 < length; ++i) {
        strcpy(copy, row);
        copy[i] = copy[i] == '7' ? '8' : '7';
        if (copy[i] != row[i] && map_row_valid(&grid, copy, length, &c)) {
            print_error("a change at %lu went unnoticed: %s", (unsigned long)i, copy);
            fail();
        }
        assert_false(map_row_valid(&grid, row, i + 1, &c));
    }
    /* a NUL byte behind a check made for it (a forged or damaged file, not
     * text: the row would be cut there when read as a string; found by
     * tests/fuzz/fuzz_map.c) */
    {
        char *last;
        strcpy(copy, row);
        last = strrchr(copy, ',');
        copy[(size_t)(last - copy) - 2] = '\0';
        snprintf(last + 1, 10, "%08lx\n", (unsigned long)map_row_check(copy, (size_t)(last - copy) + 1));
        assert_false(map_row_valid(&grid, copy, length, &c));
    }
    /* result columns that map_case_run never writes, behind checks made for
     * them (a count of 100 digits made map-merge write a map.csv that
     * map-plot refuses; found by tests/fuzz/fuzz_map.c). Columns: case,
     * point, repeat, the varied field, then s0 (4), status, outcome,
     * s_settled (7), window_s, ..., cycles (16), ..., steps (19),
     * unconverged_steps (20), ..., hash (23), wall_s, check. */
    {
        static const struct {
            int column;
            const char *text;
        } forged[] = {
            { 20, "1" "0000000000" "0000000000" "0000000000" "0000000000" "0000000000" "0000000000" },
            { 20, "-1" },
            { 19, "9007199254740993" },
            { 16, "1.5" },
            { 5, "fine" },
            { 5, "nan" },
            { 6, "sideways" },
            { 4, "inf" },
            { 7, "1e999" },
            { 8, "1e999" },
            { 23, "D33833D5" },
        };
        size_t k;
        for (k = 0; k <= sizeof forged / sizeof forged[0]; ++k) {
            const char *at = row;
            char *last;
            int i;
            for (i = 0; k < sizeof forged / sizeof forged[0] && i < forged[k].column; ++i)
                at = strchr(at, ',') + 1;
            if (k < sizeof forged / sizeof forged[0])
                snprintf(copy, sizeof copy, "%.*s%s%s", (int)(at - row), row, forged[k].text, at + strcspn(at, ","));
            else
                strcpy(copy, row); /* the row itself, re-sealed, still is one */
            last = strrchr(copy, ',');
            snprintf(last + 1, 10, "%08lx\n", (unsigned long)map_row_check(copy, (size_t)(last - copy) + 1));
            if (map_row_valid(&grid, copy, strlen(copy), &c) != (k == sizeof forged / sizeof forged[0])) {
                print_error("a forged row was taken, or the row re-sealed refused: %s", copy);
                fail();
            }
        }
    }
    /* a row of another grid */
    map_grid_free(&grid);
    {
        static const char *const other[] = { "excitation.frequency=120,125", NULL };
        grid_of(&grid, other, 2);
        assert_false(map_row_valid(&grid, row, length, &c));
    }
    map_grid_free(&grid);
}

static void write_text(const char *name, const char *text)
{
    char path[256];
    FILE *out;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    out = fopen(path, "w");
    assert_non_null(out);
    assert_true(fputs(text, out) >= 0);
    assert_int_equal(fclose(out), 0);
}

static void test_a_folder_holds_one_map_only(void **state)
{
    static const char *const specs[] = { "excitation.frequency=120,122,124", NULL };
    static const char *const others[] = { "excitation.frequency=120,122", NULL };
    map_grid grid, read_back;
    char sub[128], scene_name[SCENE_TEXT];
    char *a, *b;
    int k;
    (void)state;
    load_base();
    snprintf(sub, sizeof sub, "%s/map", dir);
    grid_of(&grid, specs, 2);
    a = map_identity_text(&grid, &base, "configs/fig6.ini", "beamslider map ...");
    assert_non_null(a);
    assert_int_equal(map_dir_claim(sub, a, err, sizeof err), 0);
    assert_int_equal(map_dir_claim(sub, a, err, sizeof err), 0); /* the same map again: resume */
    /* another command line, another scene file name: the same map */
    b = map_identity_text(&grid, &base, "elsewhere/fig6.ini", "another command");
    assert_int_equal(map_dir_claim(sub, b, err, sizeof err), 0);
    free(b);
    /* other repeats */
    map_grid_free(&grid);
    grid_of(&grid, specs, 3);
    b = map_identity_text(&grid, &base, "configs/fig6.ini", "");
    assert_int_equal(map_dir_claim(sub, b, err, sizeof err), -1);
    assert_err_has("its repeats (--repeat) is 2, this command's 3");
    free(b);
    map_grid_free(&grid);
    /* other values */
    grid_of(&grid, others, 2);
    b = map_identity_text(&grid, &base, "configs/fig6.ini", "");
    assert_int_equal(map_dir_claim(sub, b, err, sizeof err), -1);
    assert_err_has("the values of excitation.frequency differ: 3 values 120 .. 124 there, 2 values 120 .. 122");
    free(b);
    map_grid_free(&grid);
    /* another scene */
    grid_of(&grid, specs, 2);
    one = base;
    assert_int_equal(scene_set_assignment(&one, "--set", "contact.friction=0.3", err, sizeof err), 0);
    b = map_identity_text(&grid, &one, "configs/fig6.ini", "");
    assert_int_equal(map_dir_claim(sub, b, err, sizeof err), -1);
    assert_err_has("its scene (hash of its fields after --set)");
    free(b);
    /* the identity reads back as the grid */
    assert_int_equal(map_identity_read(sub, &read_back, scene_name, err, sizeof err), 0);
    assert_string_equal(scene_name, "fig6");
    assert_int_equal(read_back.cases, grid.cases);
    assert_int_equal(read_back.vary_count, 1);
    for (k = 0; k < 3; ++k)
        assert_string_equal(read_back.vary[0].values[k], grid.vary[0].values[k]);
    map_grid_free(&read_back);
    /* a folder with files but no identity is no map's */
    write_text("stray.txt", "x\n");
    assert_int_equal(map_dir_claim(dir, a, err, sizeof err), -1);
    assert_err_has("not a map's folder");
    free(a);
    map_grid_free(&grid);
    remove_dir(sub);
    snprintf(sub, sizeof sub, "%s/stray.txt", dir);
    unlink(sub);
}

/* ---- shards started together ----
 * Shards started at once race to make the folder and its identity. Here
 * another shard's whole start (its claim, then its result file) is made to
 * happen just before the n-th folder call of this process's claim, for every
 * n: the functions below stand in for the C library's (a definition in the
 * program comes before the library's) and run that start in a child (another
 * process id, as a shard has) when the count comes. Every claim must
 * succeed, whatever call it is overtaken at. */
static int race_at;                /* the call to be overtaken at (0: none) */
static int race_calls;             /* calls seen since race_at was set */
static int race_failed;            /* the other shard's start failed */
static char race_dir[128];
static const char *race_identity;
static const map_grid *race_grid;

static void race_point(void)
{
    pid_t pid;
    int status;
    if (!race_at || ++race_calls != race_at)
        return;
    pid = fork();
    if (pid == 0) {
        char why[2048], path[4400];
        int fd = -1;
        race_at = 0;
        if (map_dir_claim(race_dir, race_identity, why, sizeof why) != 0
            || (fd = map_results_create(race_dir, race_grid, path, sizeof path, why, sizeof why)) < 0)
            fprintf(stderr, "the other shard: %s\n", why);
        _exit(fd < 0);
    }
    race_failed |= pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0;
}

/* The C library's function name, found behind this program's. */
static void *next_function(const char *name)
{
    void *real = dlsym(RTLD_NEXT, name);
    if (!real)
        abort();
    return real;
}

int mkdir(const char *path, mode_t mode)
{
    int (*real)(const char *, mode_t);
    *(void **)&real = next_function("mkdir");
    race_point();
    return real(path, mode);
}

int access(const char *path, int mode)
{
    int (*real)(const char *, int);
    *(void **)&real = next_function("access");
    race_point();
    return real(path, mode);
}

DIR *opendir(const char *path)
{
    DIR *(*real)(const char *);
    *(void **)&real = next_function("opendir");
    race_point();
    return real(path);
}

int link(const char *from, const char *to)
{
    int (*real)(const char *, const char *);
    *(void **)&real = next_function("link");
    race_point();
    return real(from, to);
}

static void test_claims_overtaken_at_any_point_succeed(void **state)
{
    static const char *const specs[] = { "excitation.frequency=120,122", NULL };
    map_grid grid;
    char *identity;
    int made, n, claimed;
    (void)state;
    load_base();
    grid_of(&grid, specs, 1);
    identity = map_identity_text(&grid, &base, "configs/fig6.ini", "beamslider map ...");
    assert_non_null(identity);
    snprintf(race_dir, sizeof race_dir, "%s/race", dir);
    race_identity = identity;
    race_grid = &grid;
    for (made = 0; made < 2; ++made) /* the folder absent, or just made by another shard */
        for (n = 1;; ++n) {
            if (made)
                assert_int_equal(mkdir(race_dir, 0777), 0);
            race_at = n;
            race_calls = 0;
            race_failed = 0;
            claimed = map_dir_claim(race_dir, identity, err, sizeof err);
            race_at = 0;
            if (claimed != 0 || race_failed)
                print_error("%s, overtaken at folder call %d: %s\n", made ? "the folder made" : "no folder", n,
                            claimed ? err : "the other shard failed");
            assert_int_equal(claimed, 0);
            assert_false(race_failed);
            remove_dir(race_dir);
            if (race_calls < n) /* the claim made fewer calls: each was overtaken once */
                break;
        }
    free(identity);
    map_grid_free(&grid);
}

/* An identity is input when read back: every line map never writes is
 * refused with its line; text it does write (any scene name without a line
 * break) is taken as it is. */
static void test_identity_read_back_refuses_what_map_never_writes(void **state)
{
    static const char *const specs[] = { "excitation.frequency=120,122", "run.model=free,pcs", NULL };
    static const struct { const char *from, *to, *message; } edits[] = {
        { "info scene = fig6", "info scene = m\001x", ":12: a control character" },
        { "info scene = fig6", "info scene = " "0123456789012345678901234567890123456789012345678901234567890123"
                               "0123456789012345678901234567890123456789012345678901234567890123",
          "longer than a scene's name" },
        { "vary excitation.frequency = 120,122", "vary excitation.frequency = 120,122`touch PWNED`",
          ":9: a value the field cannot take" },
        { "vary excitation.frequency = 120,122", "vary excitation.frequency = 120,120", ":9: a value given twice" },
        { "vary excitation.frequency = 120,122", "vary excitation.frequency = 120,,122", "cannot take" },
        { "vary excitation.frequency = 120,122", "vary excitation.frequency = 1e999", "cannot take" },
        { "vary run.model = free,pcs", "vary run.model = free,'pcs'", ":10: a value the field cannot take" },
        { "vary run.model = free,pcs", "vary scene.name = a,b", ":10: not a field a map varies" },
        { "vary run.model = free,pcs", "vary run.colour = a,b", "not a field a map varies" },
        { "vary run.model = free,pcs", "vary excitation.frequency = 1,2", "a field varied twice" },
        { "repeat = 2", "repeat = 0", ":7: repeat is not an integer in [1, 1000]" },
        { "repeat = 2", "repeat = 2x", "repeat is not an integer" },
        { "repeat = 2\n", "", "no repeat line" },
        { "format = 2", "format = 1", ":3: a format this version does not read" }, /* an older map's columns */
        { "precision = ", "!touch PWNED\nprecision = ", ":5: not a line of an identity" },
    };
    map_grid grid, back;
    char sub[128], path[256], scene_name[SCENE_TEXT];
    char *identity;
    size_t k;
    FILE *out;
    (void)state;
    load_base();
    grid_of(&grid, specs, 2);
    /* a path with a line break is made one line; the name with a backquote is kept */
    snprintf(base.params.name, sizeof base.params.name, "m`touch PWNED`x @m '");
    identity = map_identity_text(&grid, &base, "two\nvary x = 1", "beamslider map ...");
    assert_non_null(identity);
    assert_non_null(strstr(identity, "info scene_file = two?vary x = 1\n"));
    snprintf(sub, sizeof sub, "%s/identity", dir);
    assert_int_equal(map_dir_claim(sub, identity, err, sizeof err), 0);
    assert_int_equal(map_identity_read(sub, &back, scene_name, err, sizeof err), 0);
    assert_string_equal(scene_name, "m`touch PWNED`x @m '");
    assert_int_equal(back.cases, 8);
    map_grid_free(&back);
    free(identity);
    /* the same with fig6 and edits */
    snprintf(base.params.name, sizeof base.params.name, "fig6");
    identity = map_identity_text(&grid, &base, "configs/fig6.ini", "beamslider map ...");
    snprintf(path, sizeof path, "%s/" MAP_IDENTITY_FILE, sub);
    for (k = 0; k < sizeof edits / sizeof *edits; ++k) {
        const char *at = strstr(identity, edits[k].from);
        assert_non_null(at);
        out = fopen(path, "w");
        assert_non_null(out);
        fprintf(out, "%.*s%s%s", (int)(at - identity), identity, edits[k].to, at + strlen(edits[k].from));
        assert_int_equal(fclose(out), 0);
        assert_int_equal(map_identity_read(sub, &back, scene_name, err, sizeof err), -1);
        if (!strstr(err, edits[k].message) || !strstr(err, MAP_IDENTITY_FILE)) {
            print_error("edit %zu: message \"%s\" lacks \"%s\" or the file\n", k, err, edits[k].message);
            fail();
        }
    }
    /* cut short: the last line without its end */
    out = fopen(path, "w");
    assert_non_null(out);
    fprintf(out, "%.*s", (int)strlen(identity) - 1, identity);
    assert_int_equal(fclose(out), 0);
    assert_int_equal(map_identity_read(sub, &back, scene_name, err, sizeof err), -1);
    assert_err_has("no line end");
    free(identity);
    map_grid_free(&grid);
    remove_dir(sub);
}

/* Rows spread over result files in any way, with torn and foreign lines,
 * merge into the same table. */
static void test_result_files_merge_whole_rows_only(void **state)
{
    static const char *const specs[] = { "excitation.frequency=120,124", NULL };
    map_grid grid;
    map_found found;
    char row[4][MAP_ROW];
    char header[4096], text[4 * MAP_ROW + 4096];
    char *table_a = NULL, *table_b = NULL;
    size_t size_a = 0, size_b = 0;
    FILE *out;
    long c;
    (void)state;
    load_base();
    grid_of(&grid, specs, 2);
    for (c = 0; c < 4; ++c)
        assert_int_equal(map_case_run(&grid, &base, c, row[c], sizeof row[c], err, sizeof err), 0);
    map_case_header(&grid, header, sizeof header);
    /* file 1: case 2, a foreign line, case 0; file 2: case 3, case 1 torn */
    snprintf(text, sizeof text, "%s%sgarbage,1,2\n%s", header, row[2], row[0]);
    write_text("runs-a-1.csv", text);
    snprintf(text, sizeof text, "%s%s%.*s", header, row[3], (int)strlen(row[1]) - 4, row[1]);
    write_text("runs-b-2.csv", text);
    assert_int_equal(map_found_read(dir, &grid, &found, err, sizeof err), 0);
    assert_int_equal(found.done, 3);
    assert_int_equal(found.torn, 1);
    assert_int_equal(found.invalid, 1);
    assert_null(found.row[1]);
    map_found_free(&found, grid.cases);
    /* resume: case 1 appended whole to a new file; merge in file order */
    snprintf(text, sizeof text, "%s%s", header, row[1]);
    write_text("runs-c-3.csv", text);
    assert_int_equal(map_found_read(dir, &grid, &found, err, sizeof err), 0);
    assert_int_equal(found.done, 4);
    out = open_memstream(&table_a, &size_a);
    assert_int_equal(map_table_runs(out, &grid, found.row), 0);
    assert_int_equal(map_table_points(out, &grid, found.row), 0);
    fclose(out);
    map_found_free(&found, grid.cases);
    /* the same rows as one file, in order: the same tables */
    snprintf(text, sizeof text, "%s%s%s%s%s", header, row[0], row[1], row[2], row[3]);
    {
        char path[256];
        const char *names[] = { "runs-a-1.csv", "runs-b-2.csv", "runs-c-3.csv" };
        int i;
        for (i = 0; i < 3; ++i) {
            snprintf(path, sizeof path, "%s/%s", dir, names[i]);
            unlink(path);
        }
    }
    write_text("runs-one.csv", text);
    assert_int_equal(map_found_read(dir, &grid, &found, err, sizeof err), 0);
    out = open_memstream(&table_b, &size_b);
    assert_int_equal(map_table_runs(out, &grid, found.row), 0);
    assert_int_equal(map_table_points(out, &grid, found.row), 0);
    fclose(out);
    map_found_free(&found, grid.cases);
    assert_string_equal(table_a, table_b);
    /* map-plot reads the points table back: each row parses as its point's */
    {
        char points_header[MAP_POINTS_HEADER], why[256], line[4096];
        map_point_figures figures;
        const char *at;
        long point;
        assert_int_equal(map_table_points_header(&grid, points_header, sizeof points_header), 0);
        at = strstr(table_a, points_header);
        assert_non_null(at);
        at = strchr(at, '\n') + 1;
        for (point = 0; point < grid.points; ++point) {
            const size_t n = strcspn(at, "\n");
            snprintf(line, sizeof line, "%.*s", (int)n, at);
            if (map_table_point_parse(&grid, point, line, &figures, why, sizeof why) != 0) {
                print_error("%s: %s\n", line, why);
                fail();
            }
            assert_int_equal(figures.point, point);
            at += n + 1;
        }
        assert_int_equal(*at, '\0');
        snprintf(line, sizeof line, "%.*s", (int)strcspn(strstr(table_a, points_header), "\n"), strstr(table_a, points_header));
        assert_string_equal(line, points_header);
        assert_int_equal(map_table_point_parse(&grid, 1, "0,120,2", &figures, why, sizeof why), -1);
    }
    /* the runs table has no wall_s, the points table one row per point */
    assert_null(strstr(table_a, "wall_s"));
    assert_non_null(strstr(table_a, "\n1,124,2,"));
    free(table_a);
    free(table_b);
    {
        char path[256];
        snprintf(path, sizeof path, "%s/runs-one.csv", dir);
        unlink(path);
    }
    map_grid_free(&grid);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ranges_and_lists_give_canonical_values),
        cmocka_unit_test(test_bad_vary_specs_are_refused_with_the_reason),
        cmocka_unit_test(test_cases_run_the_last_field_fastest_and_repeat_in_place),
        cmocka_unit_test(test_shards_deal_out_every_case_once),
        cmocka_unit_test(test_rows_carry_a_check_that_finds_damage),
        cmocka_unit_test(test_a_folder_holds_one_map_only),
        cmocka_unit_test(test_result_files_merge_whole_rows_only),
        cmocka_unit_test(test_identity_read_back_refuses_what_map_never_writes),
        cmocka_unit_test(test_claims_overtaken_at_any_point_succeed),
    };
    return cmocka_run_group_tests(tests, make_dir, drop_dir);
}
