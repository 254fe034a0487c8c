/* scene_header.c - a scene as a C header for a compile-time (embedded)
 * build: what `beamslider gen SCENE.ini > configs/NAME.h` prints
 * (scene_header.h).
 *
 * The header has two parts. The first records the run and the solver
 * settings the scene file describes and, read by core/include/bs_config.h when
 * the build configuration names it (BS_SCENE_CONFIG), fixes the sizes (mode
 * count, shape pieces) and switches off the features the scene does not need:
 *   friction     mu > 0            restitution  e_N > 0
 *   gravity      g > 0             rotation     [slider] rotation = free
 *   stretching   [numerics] stretching = on      pcs   [run] model = pcs
 *   implicit     [numerics] integrator = implicit
 * The sizes and switches are left out when bs_scene is already defined: a
 * program using a run-time-scene build of the core (the installed library)
 * includes the header once, after beamslider.h, and takes the scene as data
 * within that build's limits; defining them there would change its build tag
 * (BS_E_BUILD) or redefine the limits. The second part, seen once bs_scene is
 * defined (include the header again after beamslider.h), is the scene itself
 * as `static const bs_scene bs_compiled_scene` (const: it stays in flash),
 * a positional initialiser
 * printed field by field from the field table (core/include/bs_scene_fields.h),
 * which C99 and C++ compilers both accept. Values are printed in double with
 * 17 digits inside BS_R(), so that a float build rounds each once; the shape
 * table is fitted twice, at the float and at the double tolerance, because
 * float needs fewer pieces, and a field whose text differs between the two is
 * printed under #if BS_REAL_FLOAT. Text from the scene file (name,
 * description, the path) reaches the header only through the C writer
 * (host/lib/io/out_c.h): as string literals, and the name mapped into the
 * include guard. The output depends only on the scene file, not
 * on this binary's bs_real.
 */
#define _POSIX_C_SOURCE 200809L /* open_memstream */

#include "scene_header.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "out_c.h"

/* A growing text buffer. */
typedef struct text {
    char *data;
    size_t length, size;
    int failed;       /* a value had no C literal */
    int out_of_memory; /* the text is cut short */
} text;

static void append(text *t, const char *format, ...)
{
    va_list args;
    int need;
    if (t->out_of_memory)
        return;
    va_start(args, format);
    need = vsnprintf(t->data ? t->data + t->length : NULL, t->data ? t->size - t->length : 0, format, args);
    va_end(args);
    if (need < 0) {
        t->out_of_memory = 1;
        return;
    }
    if (!t->data || t->length + (size_t)need + 1 > t->size) {
        char *grown = realloc(t->data, 2 * (t->length + (size_t)need + 1));
        if (!grown) {
            t->out_of_memory = 1;
            return;
        }
        t->size = 2 * (t->length + (size_t)need + 1);
        t->data = grown;
        va_start(args, format);
        vsnprintf(t->data + t->length, t->size - t->length, format, args);
        va_end(args);
    }
    t->length += (size_t)need;
}

/* text as a C string literal (out_c.h says how). */
static void append_string(text *t, const char *value)
{
    char *literal = NULL;
    size_t size = 0;
    FILE *memory = open_memstream(&literal, &size);
    if (!memory || out_c_string(memory, value) != 0 || fclose(memory) != 0) {
        t->out_of_memory = 1; /* as append */
        free(literal);
        return;
    }
    append(t, "%s", literal);
    free(literal);
}

/* BS_R(x) (out_c.h); a value that is not finite marks the text failed. */
static void append_real(text *t, double value)
{
    char literal[OUT_C_REAL];
    t->failed |= out_c_real(literal, value) != 0;
    append(t, "%s", literal);
}

/* The used part [used1][used2][used3] of a field declared [.][size2][size3],
 * flat in values, with one level of braces per dimension of rank. */
static void append_values(text *t, const double *values, int rank, int used1, int size2, int used2,
                          int size3, int used3)
{
    int i, j, k;
    if (rank == 0) {
        append_real(t, values[0]);
        return;
    }
    append(t, "{");
    for (i = 0; i < used1; ++i) {
        if (rank == 1) {
            append(t, i ? ", " : " ");
            append_real(t, values[i * size2 * size3]);
            continue;
        }
        append(t, rank == 3 ? "\n        { /* %d */" : "\n        {", i);
        for (j = 0; j < used2; ++j) {
            if (rank == 2) {
                append(t, j ? ", " : " ");
                append_real(t, values[i * size2 * size3 + j * size3]);
                continue;
            }
            append(t, "\n            {");
            for (k = 0; k < used3; ++k) {
                append(t, k ? ", " : " ");
                append_real(t, values[(i * size2 + j) * size3 + k]);
            }
            append(t, " },");
        }
        append(t, rank == 3 ? "\n        }," : " },");
    }
    append(t, rank == 1 ? " }" : "\n    }");
}

#define RANK_OF(d1, d2, d3) (BS_ARRAY_##d1 + BS_ARRAY_##d2 + BS_ARRAY_##d3)
#define PRINT_REAL(t, d, name, d1, d2, d3)                                                           \
    append_values(t, (const double *)&(d)->name, RANK_OF(d1, d2, d3), BS_USED_##d1(d), BS_SIZE_##d2, \
                  BS_USED_##d2(d), BS_SIZE_##d3, BS_USED_##d3(d))
#define PRINT_INT(t, d, name, d1, d2, d3) append(t, "%d", (d)->name)
#define PRINT_U64(t, d, name, d1, d2, d3) append(t, "UINT64_C(%llu)", (unsigned long long)(d)->name)

/* One field's initialiser: under #if BS_REAL_FLOAT where the float and the
 * double scene print differently (the shape table). */
#define PRINT_FIELD(kind, name, d1, d2, d3, rule, unit, meaning)                                      \
    {                                                                                               \
        text single = { 0, 0, 0, 0, 0 }, twin = { 0, 0, 0, 0, 0 };                                  \
        PRINT_##kind(&single, as_float, name, d1, d2, d3);                                          \
        PRINT_##kind(&twin, as_double, name, d1, d2, d3);                                           \
        append(out, "    /* %s%s%s%s */\n", #name, *unit ? " [" : "", unit, *unit ? "]" : "");    \
        out->out_of_memory |= single.out_of_memory | twin.out_of_memory;                            \
        if (out->out_of_memory)                                                                     \
            ;                                                                                       \
        else if (strcmp(single.data, twin.data) == 0)                                               \
            append(out, "    %s,\n", single.data);                                                  \
        else                                                                                        \
            append(out, "#if BS_REAL_FLOAT\n    %s,\n#else\n    %s,\n#endif\n", single.data, twin.data); \
        out->failed |= single.failed | twin.failed;                                                 \
        free(single.data);                                                                          \
        free(twin.data);                                                                            \
    }

static void append_initialiser(text *out, const scene_data *as_float, const scene_data *as_double)
{
    BS_SCENE_FIELDS(PRINT_FIELD)
}

/* The run and solver settings (always), then the sizes and switches of a
 * build compiled against the scene (only ahead of bs_scene, see above). */
/* Which entries of S and gamma are not 0, as bit masks (bit N i + j of S_ij,
 * bit k of gamma_k) for scenes of up to 8 modes: the core compiled against
 * the scene skips the zeros (fig6: 12 of S's 25 entries, 2 of its 5 gamma),
 * and bs_sim_init refuses a scene with a value where the mask has none. */
static void append_zero_patterns(text *t, const scene_data *d)
{
    unsigned long long stretch = 0, gamma = 0;
    int i, j;
    if (d->n_modes > 8)
        return;
    for (i = 0; i < d->n_modes; ++i) {
        gamma |= (unsigned long long)(d->gamma[i] != 0.0) << i;
        for (j = 0; j < d->n_modes; ++j)
            stretch |= (unsigned long long)(d->stretch[i][j] != 0.0) << (d->n_modes * i + j);
    }
    append(t, "/* entries of S and gamma that are not 0: bit N i + j of S_ij, bit k of gamma_k */\n");
    append(t, "#define BS_SCENE_STRETCH_USED UINT64_C(0x%llx)\n#define BS_SCENE_GAMMA_USED UINT64_C(0x%llx)\n",
           stretch, gamma);
}

static void append_switches(text *t, const scene_params *p, const scene_model *model,
                            const shape_fit fits[2], const char *guard)
{
    const scene_data *d = &model->data;
    append(t, "#ifndef %s_CONFIG\n#define %s_CONFIG\n", guard, guard);
    append(t, "#define BS_SCENE_NAME ");
    append_string(t, p->name);
    append(t, "\n#define BS_SCENE_DESCRIPTION ");
    append_string(t, p->description);
    append(t, "\n/* the run the scene file describes */\n");
    append(t, "#define BS_SCENE_MODEL %s\n", p->model == BS_MODEL_PCS ? "BS_MODEL_PCS" : "BS_MODEL_FREE");
    append(t, "#define BS_SCENE_START ");
    append_real(t, p->s0);
    append(t, " /* s0 */\n");
    append(t, "#define BS_SCENE_STEPS %.0fu /* t_end / dt */\n", floor(p->t_end / p->dt + 0.5));
    append(t, "/* its contact-solve settings ([solver]; bs_sim_set_solver) */\n");
    append(t, "#define BS_SCENE_SOLVER_MAX_SWEEPS %d\n#define BS_SCENE_SOLVER_TOL_REL ", p->solver_max_sweeps);
    append_real(t, p->solver_tol_rel);
    append(t, "\n#define BS_SCENE_SOLVER_TOL_ABS ");
    append_real(t, p->solver_tol_abs);
    append(t, "\n#define BS_SCENE_SOLVER_RESIDUAL %d\n", p->solver_residual);
    append(t, "/* sizes and features of a build compiled against this scene (not when bs_scene\n");
    append(t, " * is already defined: a run-time-scene build takes the data only) */\n");
    append(t, "#ifndef BS_SCENE_TYPE_DEFINED\n");
    append(t, "#define BS_SCENE_MODES %d\n#define BS_MAX_MODES %d\n", d->n_modes, d->n_modes);
    append(t, "#if BS_REAL_FLOAT\n#define BS_SHAPE_MAX_PIECES %d\n#else\n#define BS_SHAPE_MAX_PIECES %d\n#endif\n",
           fits[1].pieces, fits[0].pieces);
    append(t, "#define BS_WITH_FRICTION %d\n", d->mu > 0.0);
    append(t, "#define BS_WITH_RESTITUTION %d\n", d->e_n > 0.0);
    append(t, "#define BS_WITH_GRAVITY %d\n", d->gravity[0] != 0.0 || d->gravity[1] != 0.0);
    append(t, "#define BS_WITH_ROTATION %d\n", d->inertia_inv > 0.0);
    append(t, "#define BS_WITH_STRETCHING %d\n", model->stretch_norm > 0.0);
    append(t, "#define BS_WITH_PCS %d\n", p->model == BS_MODEL_PCS);
    append(t, "#define BS_WITH_IMPLICIT %d\n", d->implicit);
    append(t, "#define BS_WITH_PIEZO %d\n", d->load != BS_LOAD_NONE);
    append_zero_patterns(t, d);
    append(t, "#endif\n#endif\n\n");
}

/* The fits and the data of both precisions: large, on the heap. */
typedef struct header_work {
    shape_fit fits[2];             /* [0] double, [1] float */
    scene_data as_precision[2];
} header_work;

int scene_header(const scene_file *file, const scene_model *model, const char *source, char **out_text, char *err,
                 size_t err_size)
{
    header_work *w = malloc(sizeof *w);
    text out = { 0, 0, 0, 0, 0 };
    char guard[57]; /* with _CONFIG or _DATA, within 63 characters */
    int is_float;

    *out_text = NULL;
    if (!w) {
        snprintf(err, err_size, "%s: out of memory for the header", source);
        return -1;
    }
    for (is_float = 0; is_float < 2; ++is_float) {
        if (shape_fit_modes(&model->modes, scene_fit_tolerance_for(is_float), &w->fits[is_float]) != 0) {
            snprintf(err, err_size, "%s: the mode shapes need more than %d pieces", source, BS_SHAPE_MAX_PIECES);
            free(w);
            return -2;
        }
        w->as_precision[is_float] = model->data;
        scene_data_set_shapes(&w->as_precision[is_float], &w->fits[is_float]);
    }
    out_c_macro_name("BS_SCENE_", file->params.name, guard, sizeof guard);

    append(&out, "/* Compile-time scene BS_SCENE_NAME (below), generated from BS_SCENE_SOURCE by\n");
    append(&out, " * `beamslider gen`; do not edit: `make configs` regenerates it. Build the core\n");
    append(&out, " * with a build configuration naming this file (BS_SCENE_CONFIG) and include it\n");
    append(&out, " * again after beamslider.h to get `bs_compiled_scene`; with a run-time-scene\n");
    append(&out, " * build (the installed library), include it once after beamslider.h\n");
    append(&out, " * (docs/porting.md). */\n\n");
    append_switches(&out, &file->params, model, w->fits, guard);
    append(&out, "#if defined(BS_SCENE_TYPE_DEFINED) && !defined(%s_DATA)\n#define %s_DATA\n", guard, guard);
    append(&out, "#define BS_SCENE_SOURCE ");
    append_string(&out, source);
    append(&out, "\nstatic const bs_scene bs_compiled_scene = {\n");
    append_initialiser(&out, &w->as_precision[1], &w->as_precision[0]);
    append(&out, "};\n#endif\n");
    free(w);
    if (out.out_of_memory || out.failed) {
        snprintf(err, err_size, out.out_of_memory ? "%s: out of memory for the header"
                                                  : "%s: a value of the scene is not finite: no header written",
                 source);
        free(out.data);
        return -1;
    }
    *out_text = out.data;
    return 0;
}
