/* scene_limits.c - inputs too extreme for the numbers derived from them.
 *
 * Every quantity the host derives from the fields (in double: the beam
 * width, the bending stiffness, the modal data; in bs_real: what goes into
 * the core's scene) is, up to a bounded factor, a product of powers of the
 * fields: q = c prod f_i^p_i (docs/model.md 3 and 8; host/lib/scene/modal.c). Its
 * logarithm is checked against the limits of the number type it is held in
 * before it is computed, so that no NaN or infinity is ever formed and then
 * blamed on a later check (a denormal thickness used to give NaN frequencies
 * and a message about dt). The same products give, for each field, the range
 * it may take with the others as set: linear bounds on its logarithm.
 *
 * The factor c is taken at its bound: lambda_k lies in ((k+1) pi, (k+2) pi),
 * so lambda_1 > pi and lambda_N < (N+1) pi; a mode shape |phi_k| sqrt(m_b)
 * and its fitted coefficients stay below 4; the slope integrals I_ij m_b
 * below 2 lambda_N^2. The limits keep a factor MARGIN inside the number
 * range. A range printed from these is one that is sure to pass them.
 */
#include "scene_limits.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "beamslider.h"
#include "scene_origins.h"

#define PI 3.14159265358979323846
#define MARGIN 4.0

typedef scene_origin derived;

static const field_spec *spec_of(const char *section, const char *key)
{
    int i;
    for (i = 0; scene_fields[i].key; ++i)
        if (!strcmp(scene_fields[i].section, section) && !strcmp(scene_fields[i].key, key))
            return &scene_fields[i];
    return NULL;
}

static double value_of(const scene_params *p, const char *section, const char *key)
{
    const field_spec *f = spec_of(section, key);
    return f && f->kind == FIELD_REAL ? *(const double *)((const char *)p + f->offset) : 0.0;
}

/* log of c; upper: the c of the upper limit (lambda_N), else of the lower (lambda_1). */
static double log_constant(origin_constant c, const scene_params *p, int upper)
{
    const double lambda = upper ? (p->modes + 1) * PI : PI;
    switch (c) {
    case ORIGIN_K_ONE: return 0.0;
    case ORIGIN_K_HALF: return log(0.5);
    case ORIGIN_K_TWO: return log(2.0);
    case ORIGIN_K_FOUR: return log(4.0);
    case ORIGIN_K_TWELFTH: return -log(12.0);
    case ORIGIN_K_TWELVE: return log(12.0);
    case ORIGIN_K_OMEGA_SQ: return 4.0 * log(lambda) - log(12.0);
    case ORIGIN_K_DAMPING: return log(2.0) + 2.0 * log(lambda) - 0.5 * log(12.0);
    case ORIGIN_K_SLOPE: return log(2.0) + 2.0 * log(lambda);
    case ORIGIN_K_STRETCH: return 0.5 * log(2.0) + 2.0 * log(lambda);
    case ORIGIN_K_PIECES: return log((double)BS_SHAPE_MAX_PIECES);
    case ORIGIN_K_GAIN: return log(2.0) + 2.0 * log(p->theta) + 4.0 * log(lambda) - log(12.0);
    }
    return 0.0;
}

static void log_limits(origin_holder held, double *low, double *high)
{
    const double real_min = BS_REAL_FLOAT ? (double)FLT_MIN : DBL_MIN;
    const double real_max = BS_REAL_FLOAT ? (double)FLT_MAX : DBL_MAX;
    *low = -HUGE_VAL;
    *high = HUGE_VAL;
    switch (held) {
    case ORIGIN_UNCHECKED: return;
    case ORIGIN_IN_DOUBLE: *low = log(DBL_MIN * MARGIN); *high = log(DBL_MAX / MARGIN); return;
    case ORIGIN_IN_CORE: *low = log(real_min * MARGIN); *high = log(real_max / MARGIN); return;
    case ORIGIN_PHASE_STEP: *low = log(ldexp(1.0, -63)); *high = HUGE_VAL; return;
    case ORIGIN_MODE_GAIN: *low = -HUGE_VAL; *high = -log(real_min * MARGIN); return;
    }
}

static const char *holder_text(origin_holder held)
{
    switch (held) {
    case ORIGIN_UNCHECKED: return "";
    case ORIGIN_IN_DOUBLE: return "the host computes it in double";
    case ORIGIN_IN_CORE: return BS_REAL_FLOAT ? "the core holds it in float" : "the core holds it in double";
    case ORIGIN_PHASE_STEP: return "the phase counts 2^-64 of a period";
    case ORIGIN_MODE_GAIN: return BS_REAL_FLOAT ? "1 / the mode gain, in float" : "1 / the mode gain, in double";
    }
    return "";
}

/* Whether the quantity exists for this scene (stretching: the smaller of
 * k_t and EA / L sets k_ax = (L / EA + 1 / k_t)^-1). */
static int applies(const derived *d, const scene_params *p)
{
    const double log_beam_axial = log(p->beam.youngs_modulus) + log(p->beam.mass) - log(p->beam.density)
                                  - 2.0 * log(p->beam.length);
    if (d->held == ORIGIN_UNCHECKED) /* a row that only names inputs */
        return 0;
    switch (d->when) {
    case ORIGIN_ALWAYS: return 1;
    case ORIGIN_IF_ROTATION: return p->rotation;
    case ORIGIN_IF_IMPLICIT: return p->implicit;
    case ORIGIN_IF_AXIAL_STRETCH: return p->stretching && log(p->beam.k_axial) <= log_beam_axial;
    case ORIGIN_IF_BEAM_STRETCH: return p->stretching && log(p->beam.k_axial) > log_beam_axial;
    case ORIGIN_IF_TRANSDUCER: return p->load != SCENE_LOAD_NONE;
    case ORIGIN_IF_RESISTOR: return p->load == SCENE_LOAD_RESISTOR;
    case ORIGIN_IF_RECTIFIER: return p->load == SCENE_LOAD_RECTIFIER;
    }
    return 0;
}

/* sum of p_i log|f_i| over the factors other than skip; 0, or -1 if one of
 * them is 0 (then q = 0 whatever the others: nothing can overflow). */
static int log_product(const derived *d, const scene_params *p, int skip, double *sum)
{
    int i;
    *sum = 0.0;
    for (i = 0; i < SCENE_ORIGIN_FACTORS && d->factors[i].section; ++i) {
        const double value = fabs(value_of(p, d->factors[i].section, d->factors[i].key));
        if (i == skip)
            continue;
        if (value == 0.0)
            return -1;
        *sum += d->factors[i].power * log(value);
    }
    return 0;
}

/* 0 if d is within its limits; else -1 (above: 1 if beyond the upper one)
 * with the estimate of log q in log_q. */
static int check_quantity(const derived *d, const scene_params *p, int *above, double *log_q)
{
    double sum, low, high;
    if (!applies(d, p) || log_product(d, p, -1, &sum) != 0)
        return 0;
    log_limits(d->held, &low, &high);
    *log_q = log_constant(d->c, p, 1) + sum;
    if ((d->bounds & ORIGIN_ABOVE) && *log_q > high) {
        *above = 1;
        return -1;
    }
    *log_q = log_constant(d->c, p, 0) + sum;
    if ((d->bounds & ORIGIN_BELOW) && *log_q < low) {
        *above = 0;
        return -1;
    }
    return 0;
}

/* Narrows [log_low, log_high] of |field| by quantity d (the others as set). */
static void narrow(const derived *d, const scene_params *p, int factor_index, double *log_low, double *log_high)
{
    const double power = d->factors[factor_index].power;
    double rest, low, high;

    if (!applies(d, p) || log_product(d, p, factor_index, &rest) != 0)
        return;
    log_limits(d->held, &low, &high);
    if (d->bounds & ORIGIN_ABOVE) { /* power log x + c + rest <= high */
        const double edge = (high - log_constant(d->c, p, 1) - rest) / power;
        if (power > 0.0 && edge < *log_high)
            *log_high = edge;
        if (power < 0.0 && edge > *log_low)
            *log_low = edge;
    }
    if (d->bounds & ORIGIN_BELOW) { /* power log x + c + rest >= low */
        const double edge = (low - log_constant(d->c, p, 0) - rest) / power;
        if (power > 0.0 && edge > *log_low)
            *log_low = edge;
        if (power < 0.0 && edge < *log_high)
            *log_high = edge;
    }
}

int scene_limits_range(const scene_file *file, const char *section, const char *key, double *low,
                       double *high)
{
    const field_spec *f = spec_of(section, key);
    double log_low = -HUGE_VAL, log_high = HUGE_VAL;
    int i, j;

    if (!f)
        return -1;
    for (i = 0; i < scene_origin_count; ++i)
        for (j = 0; j < SCENE_ORIGIN_FACTORS && scene_origins[i].factors[j].section; ++j)
            if (!strcmp(scene_origins[i].factors[j].section, section) && !strcmp(scene_origins[i].factors[j].key, key))
                narrow(&scene_origins[i], &file->params, j, &log_low, &log_high);
    *low = f->low;
    *high = f->high;
    if (f->low < 0.0) { /* a signed field (com_offset): the limits bound |x| */
        if (-exp(log_high) > *low)
            *low = -exp(log_high);
    } else if (exp(log_low) > *low) {
        *low = exp(log_low);
    }
    if (exp(log_high) < *high)
        *high = exp(log_high);
    return *low <= *high ? 0 : -1;
}

/* Appends text to out (used: what is there), "..." when it does not fit. */
static void append(char *out, size_t size, const char *text)
{
    const size_t used = strlen(out);
    if (used + strlen(text) < size)
        memcpy(out + used, text, strlen(text) + 1);
    else if (size > used + 4)
        snprintf(out + used, size - used, "%.*s...", (int)(size - used - 4), text);
}

/* "[low, high]" of field f, with ( or ) at an end that is not allowed: an
 * infinite one, or the field's own open bound. */
static void interval_text(const field_spec *f, double low, double high, char *out, size_t size)
{
    char low_text[40], high_text[40];
    const int low_open = isinf(low) || (low == f->low && f->low_open);
    const int high_open = isinf(high) || (high == f->high && f->high_open);
    range_ends_text(low, high, low_text, high_text, sizeof low_text);
    snprintf(out, size, "%c%s, %s%c", low_open ? '(' : '[', low_text, high_text, high_open ? ')' : ']');
}

static void describe_input(const scene_file *file, const scene_input *input, char *out, size_t size)
{
    const field_spec *f = spec_of(input->section, input->key);
    const char *unit = f && *f->unit ? f->unit : "";
    char where[SCENE_PATH + 16], interval[96];
    double low, high;

    scene_where(file, input->section, input->key, where, sizeof where);
    if (!f || f->kind != FIELD_REAL) {
        snprintf(out, size, "[%s] %s (%s)", input->section, input->key, where);
        return;
    }
    if (scene_limits_range(file, input->section, input->key, &low, &high) != 0) {
        snprintf(out, size, "[%s] %s = %g%s%s (%s): no value works while the others are as set", input->section,
                 input->key, value_of(&file->params, input->section, input->key), *unit ? " " : "", unit, where);
        return;
    }
    interval_text(f, low, high, interval, sizeof interval);
    snprintf(out, size, "[%s] %s = %g%s%s (%s): %s%s%s", input->section, input->key,
             value_of(&file->params, input->section, input->key), *unit ? " " : "", unit, where, interval,
             *unit ? " " : "", unit);
}

void scene_limits_describe(const scene_file *file, const scene_input *inputs, int count, char *out, size_t size)
{
    char text[SCENE_PATH + 200];
    int i;
    for (i = 0; i < count; ++i) {
        describe_input(file, &inputs[i], text, sizeof text);
        if (i)
            append(out, size, "; ");
        append(out, size, text);
    }
}

/* How specifically a field was set: an option 0, the file asked for 1, its
 * bases 2, 3, ..., the default last. */
static int specificity(const scene_file *file, const scene_input *input)
{
    int i;
    for (i = 0; scene_fields[i].key; ++i)
        if (!strcmp(scene_fields[i].section, input->section) && !strcmp(scene_fields[i].key, input->key))
            break;
    if (!scene_fields[i].key || file->set_file[i] == SCENE_NOT_SET)
        return SCENE_MAX_FILES + 2;
    return file->set_file[i] == SCENE_BY_OPTION ? 0 : 1 + file->set_file[i];
}

int scene_limits_specific(const scene_file *file, const scene_input *inputs, int count)
{
    int i, best = 0;
    for (i = 1; i < count; ++i)
        if (specificity(file, &inputs[i]) < specificity(file, &inputs[best]))
            best = i;
    return best;
}

const char *scene_limits_blame(const scene_file *file, const scene_input *inputs, int count, char *out,
                               size_t size)
{
    int i;
    for (i = 0; i < count; ++i) {
        const double value = value_of(&file->params, inputs[i].section, inputs[i].key);
        double low, high;
        if (scene_limits_range(file, inputs[i].section, inputs[i].key, &low, &high) != 0
            || value < low || value > high)
            return scene_where(file, inputs[i].section, inputs[i].key, out, size);
    }
    i = scene_limits_specific(file, inputs, count);
    return scene_where(file, inputs[i].section, inputs[i].key, out, size);
}

/* The factors of d as scene_inputs, the one that weighs most (|p log10 f|)
 * first: the likely culprit. Returns their count. */
static int inputs_of(const derived *d, const scene_params *p, scene_input *inputs)
{
    double weight[SCENE_ORIGIN_FACTORS];
    int count, i;
    for (count = 0; count < SCENE_ORIGIN_FACTORS && d->factors[count].section; ++count) {
        inputs[count].section = d->factors[count].section;
        inputs[count].key = d->factors[count].key;
        weight[count] = fabs(d->factors[count].power * log10(fabs(value_of(p, inputs[count].section, inputs[count].key))));
    }
    for (i = 1; i < count; ++i)
        if (weight[i] > weight[0]) {
            const scene_input first = inputs[0];
            const double first_weight = weight[0];
            inputs[0] = inputs[i];
            weight[0] = weight[i];
            inputs[i] = first;
            weight[i] = first_weight;
        }
    return count;
}

/* "about 2.3e+12", or "about 1e+318" beyond double. */
static void estimate_text(double log_q, char *out, size_t size)
{
    const double log10_q = log_q / log(10.0);
    if (fabs(log10_q) < 300.0)
        snprintf(out, size, "about %.2g", exp(log_q));
    else
        snprintf(out, size, "about 1e%+.0f", log10_q);
}

static void report(const scene_file *file, const derived *d, int above, double log_q, char *err, size_t size)
{
    scene_input inputs[SCENE_ORIGIN_FACTORS];
    const int count = inputs_of(d, &file->params, inputs);
    char where[SCENE_PATH + 16], estimate[40], limit[40];
    double low, high;

    log_limits(d->held, &low, &high);
    bound_text(exp(above ? high : low), above ? 1 : -1, limit, sizeof limit);
    estimate_text(log_q, estimate, sizeof estimate);
    snprintf(err, size, "%s: the values make %s %s, %s %s (%s); allowed, each with the others as set: ",
             scene_limits_blame(file, inputs, count, where, sizeof where), d->what, estimate,
             above ? "above" : "below", limit, holder_text(d->held));
    scene_limits_describe(file, inputs, count, err, size);
}

int scene_limits_check(const scene_file *file, char *err, size_t size)
{
    int i, above = 0;
    double log_q = 0.0;
    for (i = 0; i < scene_origin_count; ++i)
        if (check_quantity(&scene_origins[i], &file->params, &above, &log_q) != 0) {
            report(file, &scene_origins[i], above, log_q, err, size);
            return -1;
        }
    return 0;
}
