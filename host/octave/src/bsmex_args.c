/* bsmex_args.c - the gateway's arguments and errors (bsmex.h).
 *
 * Options are name/value pairs, as MATLAB functions take them. The ones that
 * name a scene field ('t_end', 's0', 'dt', 'model') and every pair of 'set'
 * become overrides "section.key=value" in the order given, which the host
 * library checks as `beamslider run --set` does: the same field named twice
 * takes the last value, as on the command line. A number becomes the
 * shortest text that reads back to the same double, so 120 is "120" and
 * 0.1 is "0.1", as a user would type them.
 */
#include "bsmex.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void bsmex_fail(const char *id, const char *format, ...)
{
    char text[BS_HOST_ERROR_TEXT];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof text, format, args);
    va_end(args);
    mexErrMsgIdAndTxt(id, "%s", text);
}

void bsmex_fail_host(const bs_host_error *error)
{
    const char *id = "beamslider:failed";
    switch (error->status) {
    case BS_HOST_E_INPUT: id = "beamslider:input"; break;
    case BS_HOST_E_MEMORY: id = "beamslider:memory"; break;
    case BS_HOST_E_BUILD: id = "beamslider:build"; break;
    case BS_HOST_E_NULL: id = "beamslider:null"; break;
    case BS_HOST_E_FAILED:
    case BS_HOST_OK: break;
    }
    mexErrMsgIdAndTxt(id, "%s", error->text[0] ? error->text : bs_host_status_text(error->status));
}

char *bsmex_text(const mxArray *value, const char *what)
{
    char *text;
    if (!value || !mxIsChar(value) || (mxGetM(value) > 1 && mxGetN(value) > 0))
        bsmex_fail("beamslider:usage", "%s: expected a character row (text)", what);
    text = mxArrayToString(value);
    if (!text)
        bsmex_fail("beamslider:memory", "%s: out of memory", what);
    return text;
}

static int is_real_scalar(const mxArray *value)
{
    return value && mxIsDouble(value) && !mxIsComplex(value) && !mxIsSparse(value)
        && mxGetNumberOfElements(value) == 1;
}

double bsmex_number(const mxArray *value, const char *what)
{
    double x;
    if (!is_real_scalar(value))
        bsmex_fail("beamslider:usage", "%s: expected a real double scalar", what);
    x = *(const double *)mxGetData(value);
    if (!isfinite(x))
        bsmex_fail("beamslider:usage", "%s = %g: expected a finite number", what, x);
    return x;
}

uint64_t bsmex_count(const mxArray *value, const char *what, uint64_t low, uint64_t high)
{
    const double x = bsmex_number(value, what);
    if (x != floor(x) || x < (double)low || x > (double)high)
        bsmex_fail("beamslider:usage", "%s = %g: allowed: a whole number in [%.0f, %.0f]", what, x, (double)low,
                   (double)high);
    return (uint64_t)x;
}

/* The shortest %.Ng text of x that reads back as x. */
static void number_text(double x, char *out, size_t size)
{
    int digits;
    for (digits = 15; digits < 17; ++digits) {
        snprintf(out, size, "%.*g", digits, x);
        if (strtod(out, NULL) == x)
            return;
    }
    snprintf(out, size, "%.17g", x);
}

/* Appends "field=value" (value: text, or a number as number_text writes it). */
static void add_override(bsmex_overrides *overrides, const char *field, const mxArray *value, const char *what)
{
    char number[40];
    const char *value_text;
    char *text;
    size_t size;

    if (overrides->count >= BSMEX_MAX_OVERRIDES)
        bsmex_fail("beamslider:usage", "%s: more than %d overrides", what, BSMEX_MAX_OVERRIDES);
    if (value && mxIsChar(value)) {
        value_text = bsmex_text(value, what);
    } else if (is_real_scalar(value)) {
        number_text(*(const double *)mxGetData(value), number, sizeof number);
        value_text = number; /* a value that is not finite goes on to the scene's check, which names it */
    } else {
        bsmex_fail("beamslider:usage", "%s: expected a number or a text as the value of %s", what, field);
        return;
    }
    size = strlen(field) + strlen(value_text) + 2;
    text = mxMalloc(size);
    snprintf(text, size, "%s=%s", field, value_text);
    overrides->text[overrides->count++] = text;
}

/* 'set', {'section.key', value, ...}: pairs in a cell. */
static void add_set(bsmex_overrides *overrides, const mxArray *cell)
{
    size_t n, i;
    char what[64];
    if (!cell || !mxIsCell(cell))
        bsmex_fail("beamslider:usage", "'set': expected a cell {'section.key', value, ...}");
    n = mxGetNumberOfElements(cell);
    if (n % 2 != 0)
        bsmex_fail("beamslider:usage", "'set': a cell of %lu elements: expected pairs {'section.key', value, ...}",
                   (unsigned long)n);
    for (i = 0; i < n; i += 2) {
        snprintf(what, sizeof what, "'set' element %lu", (unsigned long)i + 1);
        add_override(overrides, bsmex_text(mxGetCell(cell, i), what), mxGetCell(cell, i + 1), what);
    }
}

/* The options that stand for a scene field (beamslider run's --t-end ...). */
static const struct field_option {
    const char *name;
    const char *field;
} field_options[] = {
    { "t_end", "run.t_end" },
    { "s0", "run.s0" },
    { "dt", "numerics.dt" },
    { "model", "run.model" },
};

void bsmex_options(int count, const mxArray *const *pairs, bsmex_overrides *overrides, long *every,
                   int every_allowed)
{
    int i;
    size_t k;
    overrides->count = 0;
    if (count % 2 != 0)
        bsmex_fail("beamslider:usage", "options come in name/value pairs; %d arguments after the scene", count);
    for (i = 0; i < count; i += 2) {
        const char *name = bsmex_text(pairs[i], "an option's name");
        for (k = 0; k < sizeof field_options / sizeof field_options[0]; ++k)
            if (strcmp(name, field_options[k].name) == 0)
                break;
        if (k < sizeof field_options / sizeof field_options[0])
            add_override(overrides, field_options[k].field, pairs[i + 1], name);
        else if (strcmp(name, "set") == 0)
            add_set(overrides, pairs[i + 1]);
        else if (every_allowed && strcmp(name, "every") == 0)
            *every = (long)bsmex_count(pairs[i + 1], "'every'", 1, 1000000000);
        else
            bsmex_fail("beamslider:usage", "unknown option '%s'; allowed: 't_end', 's0', 'dt', 'model', 'set'%s",
                       name, every_allowed ? ", 'every'" : "");
    }
}

bs_host_scene *bsmex_scene_load(const char *path, const bsmex_overrides *overrides)
{
    bs_host_scene *scene;
    bs_host_error error;
    if (bs_host_scene_load(path, overrides->text, overrides->count, &scene, &error) != BS_HOST_OK)
        bsmex_fail_host(&error);
    return scene;
}
