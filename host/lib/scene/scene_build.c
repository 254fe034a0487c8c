/* scene_build.c - modal precomputation and scene assembly, in double.
 *
 * From the parameters of docs/model.md 8, in double (scene_data), then rounded to
 * bs_real (scene_data_round):
 *   omega_k, gamma_k, phi_k(4/7), I_ij          host/lib/scene/modal.c
 *   mode-shape pieces                           host/lib/scene/shape_fit.c
 *   S = sqrt(k_ax / 2L^2) I,  |S| by power iteration (S is positive semidefinite);
 *   S = 0 when the scene leaves stretching out
 *   1/J_C, or 0 when the scene locks the slider's rotation
 *   R = r_h h;  corners r_CP,i = P_i + (0, d): P1 (-B/2, R/2), P2 (-B/2, -R/2),
 *               P3 (B/2, -R/2), P4 (B/2, R/2)
 *   clamp stops x_C in [B/2, L - B/2] (the slot corners reach the clamp faces)
 *   gravity in the beam frame for a beam tilted by theta: g (-sin theta, -cos theta)
 *   phase step f_ex dt / 2 * 2^64, rounded once here
 */
#include "scene_build.h"
#include "scene_limits.h"
#include "schedule.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

double scene_fit_tolerance_for(int is_float)
{
    /* a few ulps of the working precision; double: far below every other error */
    return is_float ? 1e-7 : 1e-9;
}

double scene_fit_tolerance(void)
{
    return scene_fit_tolerance_for(BS_REAL_FLOAT);
}

static double largest_eigenvalue(const double s[BS_MAX_MODES][BS_MAX_MODES], int n)
{
    double v[BS_MAX_MODES];
    double value = 0.0;
    int i;
    int j;
    int iteration;

    for (i = 0; i < n; ++i)
        v[i] = 1.0 + 0.01 * i; /* not orthogonal to the dominant eigenvector */
    for (iteration = 0; iteration < 2000; ++iteration) {
        double next[BS_MAX_MODES];
        double norm = 0.0;
        for (i = 0; i < n; ++i) {
            next[i] = 0.0;
            for (j = 0; j < n; ++j)
                next[i] += s[i][j] * v[j];
            norm += next[i] * next[i];
        }
        norm = sqrt(norm);
        if (norm == 0.0)
            return 0.0;
        for (i = 0; i < n; ++i)
            v[i] = next[i] / norm;
        if (fabs(norm - value) <= 1e-15 * norm)
            return norm;
        value = norm;
    }
    return value;
}

static void compute_modes(const scene_params *p, const modal_set *modes, scene_data *d, double *stretch_norm)
{
    const double stretch_scale = p->stretching ? sqrt(modes->k_axial_total / (2.0 * p->beam.length * p->beam.length)) : 0.0;
    int i;
    int j;

    d->n_modes = modes->n;
    for (i = 0; i < modes->n; ++i) {
        double slope;
        d->omega_sq[i] = modes->omega[i] * modes->omega[i];
        if (p->prewarp) { /* the leapfrog's frequency w_d obeys sin(w_d dt / 2) = w dt / 2: give it the w that makes w_d the mode's */
            const double w = 2.0 / p->dt * sin(0.5 * modes->omega[i] * p->dt);
            d->omega_sq[i] = w * w;
        }
        d->damping[i] = 2.0 * p->damping_ratio * modes->omega[i];
        d->gamma[i] = modes->gamma[i];
        modal_shape(modes, i, 4.0 / 7.0, &d->phi_sensor[i], &slope);
        for (j = 0; j < modes->n; ++j)
            d->stretch[i][j] = stretch_scale * modes->slope_gram[i][j];
    }
    /* a hair above the true value: the stability check needs an upper bound */
    *stretch_norm = largest_eigenvalue(d->stretch, modes->n) * (1.0 + 1e-6);
}

static void compute_slider(const scene_params *p, scene_data *d)
{
    const double pi = 3.14159265358979323846;
    const double half_width = 0.5 * p->slot_width;
    const double half_slot = 0.5 * p->play_ratio * p->beam.thickness;
    const double tilt = p->tilt * pi / 180.0;
    const double corner[BS_CORNERS][2] = {
        { -half_width, half_slot }, { -half_width, -half_slot },
        { half_width, -half_slot }, { half_width, half_slot } };
    int i;

    d->length = p->beam.length;
    d->half_thickness = 0.5 * p->beam.thickness;
    for (i = 0; i < BS_CORNERS; ++i) {
        d->corner[i][0] = corner[i][0];
        d->corner[i][1] = corner[i][1] + p->com_offset;
    }
    d->com_offset = p->com_offset;
    d->stop_min = half_width;
    d->stop_max = p->beam.length - half_width;
    d->mass_inv = 1.0 / p->slider_mass;
    d->inertia_inv = p->rotation ? 1.0 / p->slider_inertia : 0.0; /* 0: locked */
    d->gravity[0] = -p->gravity * sin(tilt);
    d->gravity[1] = -p->gravity * cos(tilt);
    d->mu = p->mu;
    d->e_n = p->e_n;
}

/* The patch's modal couplings theta_k = Theta (phi_k'(x_2) - phi_k'(x_1))
 * (phi' = d phi / dx; docs/model.md 11). */
static void patch_couplings(const scene_params *p, const modal_set *modes, double *theta)
{
    int k;
    for (k = 0; k < modes->n; ++k) {
        double phi, start_slope, end_slope;
        modal_shape(modes, k, p->patch_start / p->beam.length, &phi, &start_slope);
        modal_shape(modes, k, p->patch_end / p->beam.length, &phi, &end_slope);
        theta[k] = p->coupling * (end_slope - start_slope) / p->beam.length;
    }
}

/* The patch and its load (docs/model.md 11): the modal couplings, the clamp
 * stop on the patch's side moved to its end plus B/2 (the slider cannot pass
 * over it), and the exact half-step factors of the circuit (core/src/bs_piezo.c). */
static void compute_transducer(const scene_params *p, const modal_set *modes, scene_data *d)
{
    const double half_step = 0.5 * p->dt;

    d->load = p->load;
    if (p->load == SCENE_LOAD_NONE)
        return;
    patch_couplings(p, modes, d->piezo_theta);
    if (p->patch_start == 0.0)
        d->stop_min = fmax(d->stop_min, p->patch_end + 0.5 * p->slot_width);
    else
        d->stop_max = fmin(d->stop_max, p->patch_start - 0.5 * p->slot_width);
    d->piezo_capacitance_inv = 1.0 / p->capacitance;
    if (p->load == SCENE_LOAD_RESISTOR) {
        const double tau = p->resistance * p->capacitance;
        d->load_decay = exp(-half_step / tau);
        d->load_gain = -p->resistance * expm1(-half_step / tau); /* R (1 - decay), exact for large R */
        d->load_conductance = 1.0 / p->resistance;
    } else {
        d->load_decay = exp(-half_step / (p->storage_resistance * p->storage_capacitance));
        d->load_conductance = 1.0 / p->storage_resistance;
        d->storage_capacitance_inv = 1.0 / p->storage_capacitance;
        d->bridge_drop = 2.0 * p->diode_drop;
    }
}

static void compute_numerics(const scene_params *p, scene_data *d)
{
    int k;
    d->base_accel = p->acceleration;
    d->frequency = p->frequency;
    d->phase_step_half = (uint64_t)llround(ldexp(0.5 * p->frequency * p->dt, 64));
    d->dt = p->dt;
    d->implicit = p->implicit;
    d->theta = p->implicit ? p->theta : 0.5;
    for (k = 0; k < d->n_modes; ++k) /* 1 / (1 + theta dt 2 D omega + theta^2 dt^2 omega^2) */
        d->mode_gain[k] = p->implicit ? 1.0 / (1.0 + d->theta * p->dt * d->damping[k]
                                               + d->theta * d->theta * p->dt * p->dt * d->omega_sq[k])
                                      : 1.0;
}

void scene_data_set_shapes(scene_data *data, const shape_fit *fit)
{
    data->shape_pieces = fit->pieces;
    data->shape_scale = fit->pieces / data->length;
    memcpy(data->shape_coef, fit->coef, sizeof data->shape_coef);
}

/* Every element of every field, whole arrays (the unused parts are zero). */
#define ROUND_REAL(name)                                                                          \
    for (i = 0; i < sizeof data->name / sizeof(double); ++i)                                        \
        ((bs_real *)&scene->name)[i] = (bs_real)((const double *)&data->name)[i];
#define ROUND_INT(name) scene->name = data->name;
#define ROUND_U64(name) scene->name = data->name;
#define ROUND_FIELD(kind, name, dim1, dim2, dim3, rule, unit, meaning) ROUND_##kind(name)

void scene_data_round(const scene_data *data, bs_scene *scene)
{
    size_t i;
    BS_SCENE_FIELDS(ROUND_FIELD)
}

/* A cross-field check names the input set most specifically as the culprit
 * (scene_limits_specific: the user's latest change, an option or the file
 * itself rather than its base): "WHERE: [section] key = value unit" into
 * culprit, its place into where. The others are named in the message with
 * their places. */
static int culprit_of(const scene_file *file, const scene_input *inputs, int count, char *where, size_t where_size,
                      char *culprit, size_t culprit_size)
{
    const int k = scene_limits_specific(file, inputs, count);
    int i;
    scene_where(file, inputs[k].section, inputs[k].key, where, where_size);
    for (i = 0; scene_fields[i].key; ++i)
        if (!strcmp(scene_fields[i].section, inputs[k].section) && !strcmp(scene_fields[i].key, inputs[k].key))
            break;
    if (scene_fields[i].key && scene_fields[i].kind == FIELD_REAL)
        snprintf(culprit, culprit_size, "[%s] %s = %g%s%s", inputs[k].section, inputs[k].key,
                 *(const double *)((const char *)&file->params + scene_fields[i].offset),
                 *scene_fields[i].unit ? " " : "", scene_fields[i].unit);
    else
        snprintf(culprit, culprit_size, "[%s] %s", inputs[k].section, inputs[k].key);
    return k;
}

/* ", with [section] key = value unit (where)" for the input named section
 * key unless it is the culprit k of inputs, into out. */
static const char *other_text(const scene_file *file, const scene_input *inputs, int k, int i, char *out,
                              size_t size)
{
    char where[SCENE_PATH + 16];
    int f;
    out[0] = '\0';
    if (i == k)
        return out;
    for (f = 0; scene_fields[f].key; ++f)
        if (!strcmp(scene_fields[f].section, inputs[i].section) && !strcmp(scene_fields[f].key, inputs[i].key))
            break;
    if (!scene_fields[f].key || scene_fields[f].kind != FIELD_REAL)
        return out;
    scene_where(file, inputs[i].section, inputs[i].key, where, sizeof where);
    snprintf(out, size, ", with [%s] %s = %g%s%s %s%s%s", inputs[i].section, inputs[i].key,
             *(const double *)((const char *)&file->params + scene_fields[f].offset), *scene_fields[f].unit ? " " : "",
             scene_fields[f].unit, where[0] == '(' ? "" : "(", where, where[0] == '(' ? "" : ")");
    return out;
}

#define INPUTS(list) list, (int)(sizeof list / sizeof list[0])
static const scene_input slot_inputs[] = { { "slider", "slot_width" }, { "beam", "length" } };
static const scene_input patch_inputs[] = { { "transducer", "patch_end" }, { "transducer", "patch_start" },
                                            { "beam", "length" } };
static const scene_input room_inputs[] = { { "transducer", "patch_end" }, { "transducer", "patch_start" },
                                           { "slider", "slot_width" }, { "beam", "length" } };
static const scene_input explicit_inputs[] = { { "numerics", "dt" }, { "beam", "youngs_modulus" },
                                               { "beam", "thickness" }, { "beam", "density" }, { "beam", "length" } };
static const scene_input coupling_inputs[] = { { "transducer", "coupling" }, { "transducer", "capacitance" },
                                               { "numerics", "dt" } };
static const scene_input period_inputs[] = { { "numerics", "dt" }, { "excitation", "frequency" } };
static const scene_input steps_inputs[] = { { "run", "t_end" }, { "numerics", "dt" } };

/* Cross-field checks that need derived quantities. Bounds are printed with
 * bound_text: on the allowed side, to as many digits as that takes. */
static int check_derived(const scene_file *file, const scene_model *model, char *err, size_t size)
{
    const scene_params *p = &file->params;
    const double omega_max = model->modes.omega[model->modes.n - 1];
    char where[SCENE_PATH + 16];
    char where2[SCENE_PATH + 16];
    char culprit[SCENE_PATH + 96], other[SCENE_PATH + 96], other2[SCENE_PATH + 96];
    char value[40], limit[40];
    int k;

    if (!(p->slot_width < p->beam.length)) {
        values_text(p->slot_width, p->beam.length, value, limit, sizeof value);
        k = culprit_of(file, INPUTS(slot_inputs), where2, sizeof where2, culprit, sizeof culprit);
        scene_where(file, slot_inputs[1 - k].section, slot_inputs[1 - k].key, where, sizeof where);
        if (k == 0)
            snprintf(err, size, "%s: [slider] slot_width = %s m must be below [beam] length = %s m (%s)", where2,
                     value, limit, where);
        else
            snprintf(err, size, "%s: [beam] length = %s m must be above [slider] slot_width = %s m (%s)", where2,
                     limit, value, where);
        return -1;
    }
    if (p->load != SCENE_LOAD_NONE) {
        const double stop = p->patch_start == 0.0 ? p->patch_end + 0.5 * p->slot_width
                                                  : p->patch_start - 0.5 * p->slot_width;
        if (!(p->patch_start < p->patch_end && p->patch_end <= p->beam.length)) {
            k = culprit_of(file, INPUTS(patch_inputs), where, sizeof where, culprit, sizeof culprit);
            snprintf(err, size, "%s: %s: the patch must lie within the beam, 0 <= patch_start < patch_end <= length "
                     "([transducer] patch_start = %g m, patch_end = %g m, [beam] length = %g m)", where, culprit,
                     p->patch_start, p->patch_end, p->beam.length);
            return -1;
        }
        if (p->patch_start != 0.0 && p->patch_end != p->beam.length) {
            k = culprit_of(file, INPUTS(patch_inputs), where, sizeof where, culprit, sizeof culprit);
            snprintf(err, size, "%s: %s: the patch (%g m to %g m) must start at the left clamp "
                     "(patch_start = 0) or end at the right one (patch_end = length = %g m): the slider "
                     "could not pass it", where, culprit, p->patch_start, p->patch_end, p->beam.length);
            return -1;
        }
        if (!(p->patch_start == 0.0 ? stop < p->beam.length - 0.5 * p->slot_width : stop > 0.5 * p->slot_width)) {
            k = culprit_of(file, INPUTS(room_inputs), where, sizeof where, culprit, sizeof culprit);
            snprintf(err, size, "%s: %s: the patch (%g m to %g m) leaves the slider (slot width %g m) no room "
                     "between it and the other clamp", where, culprit, p->patch_start, p->patch_end, p->slot_width);
            return -1;
        }
    }
    if (p->prewarp && p->implicit) {
        scene_where(file, "numerics", "prewarp", where, sizeof where);
        snprintf(err, size, "%s: [numerics] prewarp = on matches the explicit step's frequencies; the implicit "
                 "integrator has its own: allowed with integrator = explicit only", where);
        return -1;
    }
    if (!p->implicit && !(omega_max * p->dt < 2.0)) {
        bound_text(2.0 / omega_max, 1, limit, sizeof limit);
        k = culprit_of(file, INPUTS(explicit_inputs), where, sizeof where, culprit, sizeof culprit);
        snprintf(err, size,
                 "%s: %s: omega_max dt = %.4g, above the explicit limit 2 "
                 "(mode %d, %.5g Hz%s); allowed: dt < %s s, or [numerics] integrator = implicit", where, culprit,
                 omega_max * p->dt, model->modes.n, omega_max / (2.0 * 3.14159265358979323846),
                 other_text(file, explicit_inputs, k, 0, other, sizeof other), limit);
        return -1;
    }
    if (p->load != SCENE_LOAD_NONE) {
        /* The open patch stiffens the beam by theta theta^T / C_p, explicitly
         * integrated by either integrator: the step's bound (core/src/bs_step.c,
         * bs_sim_init) adds max_k |theta_k| sum_j |theta_j| / C_p to omega_max^2
         * (explicit) or to nothing (implicit), so a scene beyond it could not
         * take its first step. */
        double theta[BS_MAX_MODES], largest = 0.0, sum = 0.0, patch, stiffness;
        int m;
        patch_couplings(p, &model->modes, theta);
        for (m = 0; m < model->modes.n; ++m) {
            sum += fabs(theta[m]);
            largest = fmax(largest, fabs(theta[m]));
        }
        patch = largest * sum / p->capacitance;
        stiffness = (p->implicit ? 0.0 : omega_max * omega_max) + patch;
        if (!(stiffness * p->dt * p->dt < 4.0)) {
            char capacitance[40];
            const double room = 4.0 / (p->dt * p->dt) - (p->implicit ? 0.0 : omega_max * omega_max);
            bound_text(2.0 / sqrt(stiffness), 1, limit, sizeof limit);
            bound_text(room > 0.0 ? largest * sum / room : HUGE_VAL, -1, capacitance, sizeof capacitance);
            k = culprit_of(file, INPUTS(coupling_inputs), where, sizeof where, culprit, sizeof culprit);
            snprintf(err, size,
                     "%s: %s: the open patch's stiffness theta theta^T / C_p (bound %.4g 1/s^2%s%s) brings the "
                     "explicitly integrated stiffness to %.4g 1/s^2, above the limit 4 / dt^2 = %.4g 1/s^2; "
                     "allowed: dt < %s s, a smaller |coupling| or a capacitance > %s F", where, culprit, patch,
                     other_text(file, coupling_inputs, k, k == 0 ? 1 : 0, other, sizeof other),
                     other_text(file, coupling_inputs, k, k == 2 ? 1 : 2, other2, sizeof other2), stiffness,
                     4.0 / (p->dt * p->dt), limit, capacitance);
            return -1;
        }
    }
    if (!(p->frequency * p->dt < 0.5)) {
        k = culprit_of(file, INPUTS(period_inputs), where, sizeof where, culprit, sizeof culprit);
        if (k == 0) {
            bound_text(0.5 / p->frequency, 1, limit, sizeof limit);
            snprintf(err, size, "%s: %s: fewer than two steps per excitation period (f_ex = %g Hz); allowed: dt < "
                     "%s s", where, culprit, p->frequency, limit);
        } else {
            bound_text(0.5 / p->dt, 0, limit, sizeof limit); /* exclusive */
            snprintf(err, size, "%s: %s: fewer than two steps per excitation period%s; allowed: f_ex < %s Hz (or a "
                     "smaller dt)", where, culprit, other_text(file, period_inputs, k, 0, other, sizeof other), limit);
        }
        return -1;
    }
    /* steps are counted exactly in a double: t = n dt */
    if (!(p->t_end / p->dt <= 9007199254740992.0)) {
        bound_text(9007199254740992.0 * p->dt, 1, limit, sizeof limit);
        k = culprit_of(file, INPUTS(steps_inputs), where, sizeof where, culprit, sizeof culprit);
        if (k == 0) {
            snprintf(err, size, "%s: [run] t_end = %g s is more than 2^53 steps of dt = %g s; allowed: t_end <= %s "
                     "s (or a larger dt)", where, p->t_end, p->dt, limit);
        } else {
            bound_text(p->t_end / 9007199254740992.0, -1, limit, sizeof limit);
            snprintf(err, size, "%s: [numerics] dt = %g s: [run] t_end = %g s (%s) is more than 2^53 steps of it; "
                     "allowed: dt >= %s s (or a shorter t_end)", where, p->dt, p->t_end,
                     scene_where(file, "run", "t_end", where2, sizeof where2), limit);
        }
        return -1;
    }
    return 0;
}

/* The points of [excitation] schedule, each checked as the scene's own
 * frequency and acceleration are (they reach the core the same way, through
 * bs_sim_set_excitation, only later): a frequency within the core's range,
 * with a phase step f dt 2^63 that does not round to 0 and at least two
 * steps per period (f dt < 1/2); an amplitude within the range of
 * [excitation] acceleration. Else the run would start, write its output and
 * stop at the point with "argument out of range". */
static int check_schedule(const scene_file *file, char *err, size_t size)
{
    const scene_params *p = &file->params;
    schedule plan;
    double f_low, f_high, a_low, a_high;
    char where[SCENE_PATH + 16], low[40], high[40], why[160];
    int k;

    if (schedule_parse(p->schedule, &plan, why, sizeof why) != 0 || plan.points == 0)
        return 0; /* its syntax was checked when it was read */
    if (scene_limits_range(file, "excitation", "frequency", &f_low, &f_high) != 0)
        f_low = HUGE_VAL; /* nothing works: every point is refused */
    if (scene_limits_range(file, "excitation", "acceleration", &a_low, &a_high) != 0)
        a_high = -1.0;
    scene_where(file, "excitation", "schedule", where, sizeof where);
    for (k = 0; k < plan.points; ++k) {
        const double f = plan.frequency[k], a = plan.amplitude[k];
        if (!(f >= f_low && f <= f_high && f * p->dt < 0.5)) {
            bound_text(f_low, -1, low, sizeof low);
            bound_text(fmin(f_high, 0.5 / p->dt), 0, high, sizeof high); /* exclusive: %.6g */
            snprintf(err, size, "%s: [excitation] schedule point %d: frequency %g Hz is out of range at dt = %g s; "
                     "allowed: %s <= f < %s Hz (at least two steps per period, and a phase step f dt 2^63 that "
                     "does not round to 0)", where, k + 1, f, p->dt, low, high);
            return -1;
        }
        if (!(a >= a_low && a <= a_high)) {
            bound_text(a_high, 1, high, sizeof high);
            snprintf(err, size, "%s: [excitation] schedule point %d: amplitude %g m/s^2 is out of range; allowed: "
                     "0 .. %s m/s^2 (the range of [excitation] acceleration)", where, k + 1, a, high);
            return -1;
        }
    }
    return 0;
}

/* x_C = s0 L within the clamp stops, as the core computes it (in bs_real). */
static int start_inside(const bs_scene *scene, bs_real s0)
{
    const bs_real x0 = s0 * scene->length;
    return x0 >= scene->stop_min && x0 <= scene->stop_max;
}

static bs_real real_next(bs_real x, bs_real toward)
{
#if BS_REAL_FLOAT
    return nextafterf(x, toward);
#else
    return nextafter(x, toward);
#endif
}

/* The end of the start range nearest to s (stop_min / L or stop_max / L),
 * moved in bs_real until the core's own check takes it: every s0 between
 * the two ends is then a start the core accepts. */
static double start_range_end(const bs_scene *scene, bs_real s, bs_real inward)
{
    int i;
    for (i = 0; i < 64 && !start_inside(scene, s); ++i)
        s = real_next(s, inward);
    return (double)s;
}

/* The start position, checked as the core checks it: in bs_real, against the
 * rounded stops (in double the edge of the range can come out the other way). */
static int check_start(const scene_file *file, const bs_scene *scene, char *err, size_t size)
{
    const scene_params *p = &file->params;
    char where[SCENE_PATH + 16];
    char low[40], high[40];

    if (p->model == BS_MODEL_FREE && !start_inside(scene, (bs_real)p->s0)) {
        range_ends_text(start_range_end(scene, scene->stop_min / scene->length, BS_R(1.0)),
                        start_range_end(scene, scene->stop_max / scene->length, BS_R(0.0)), low, high,
                        sizeof low);
        snprintf(err, size, "%s: [run] s0 = %.17g: the slider would start inside a clamp; "
                 "allowed: [%s, %s] (slot corners between the clamps)",
                 scene_where(file, "run", "s0", where, sizeof where), p->s0, low, high);
        return -1;
    }
    return 0;
}

/* Inputs whose combination overflows a derived quantity, found before
 * anything is computed from them (scene_limits.c). */
static int check_extremes(const scene_file *file, char *err, size_t size)
{
    return scene_limits_check(file, err, size);
}

/* The modal results, where they are computed: all finite, frequencies
 * positive. check_extremes keeps the inputs away from overflow; should a
 * combination still slip through, its NaN is named here, at its origin, and
 * not blamed on dt by the explicit-limit check that reads it next. */
static int check_modal_results(const scene_file *file, const modal_set *modes, char *err, size_t size)
{
    scene_input inputs[2 * SCENE_ORIGIN_FACTORS];
    const int count = scene_origin_inputs("modal", inputs, (int)(sizeof inputs / sizeof inputs[0]));
    char where[SCENE_PATH + 16];
    int k, j;
    int finite = isfinite(modes->k_axial_total);

    for (k = 0; k < modes->n; ++k) {
        finite = finite && isfinite(modes->lambda[k]) && isfinite(modes->omega[k]) && modes->omega[k] > 0.0
                 && isfinite(modes->amplitude[k]) && isfinite(modes->gamma[k]);
        for (j = 0; j < modes->n; ++j)
            finite = finite && isfinite(modes->slope_gram[k][j]);
    }
    if (finite)
        return 0;
    snprintf(err, size, "%s: the modal analysis of these values does not give finite modes (f_1 = %g Hz, "
             "f_%d = %g Hz): the values are too extreme for double; allowed, each with the others as set: ",
             scene_limits_blame(file, inputs, count, where, sizeof where),
             modes->omega[0] / (2.0 * 3.14159265358979323846), modes->n,
             modes->omega[modes->n - 1] / (2.0 * 3.14159265358979323846));
    scene_limits_describe(file, inputs, count, err, size);
    return -1;
}

static const scene_input slot_play_inputs[] = { { "slider", "com_offset" }, { "slider", "play_ratio" },
                                                { "beam", "thickness" } };

/* The slot holds the beam as bs_scene_check sees it: the corner heights
 * R/2 + d and -R/2 + d, rounded to bs_real, still at least h apart. A large
 * offset d next to a small play rounds the play away. */
static int check_slot_rounding(const scene_file *file, const bs_scene *scene, char *err, size_t size)
{
    const scene_params *p = &file->params;
    const double eps = (double)BS_REAL_EPS;
    const double slot = p->play_ratio * p->beam.thickness;
    char where[3][SCENE_PATH + 16], low[40], high[40];
    double largest;

    if (scene->corner[0][1] - scene->corner[1][1]
            >= BS_R(2.0) * scene->half_thickness * (BS_R(1.0) - BS_R(16.0) * BS_REAL_EPS)
        && scene->corner[3][1] - scene->corner[2][1]
            >= BS_R(2.0) * scene->half_thickness * (BS_R(1.0) - BS_R(16.0) * BS_REAL_EPS))
        return 0;
    /* a rounding moves a value x by at most eps |x| / 2; counted as eps |x|:
     * the corners by eps (|d| + R/2) each, their difference by eps R, h by
     * eps h. Enough room: R (1 - eps) - 2 eps (|d| + R/2) >= h (1 + eps) (1 - 16 eps). */
    largest = (slot * (1.0 - eps) - p->beam.thickness * (1.0 + eps) * (1.0 - 16.0 * eps)) / (2.0 * eps)
              - 0.5 * slot;
    switch (scene_limits_specific(file, slot_play_inputs, 3)) {
    case 0:
        range_ends_text(-largest, largest, low, high, sizeof low);
        snprintf(err, size, "%s: [slider] com_offset = %g m is too large for the slot height R = play_ratio "
                 "thickness = %g m (%s, %s): rounded to %s, the corners lose the play; allowed: [%s, %s] m, "
                 "or a larger play_ratio", scene_where(file, "slider", "com_offset", where[0], sizeof where[0]),
                 p->com_offset, slot, scene_where(file, "slider", "play_ratio", where[1], sizeof where[1]),
                 scene_where(file, "beam", "thickness", where[2], sizeof where[2]), BS_REAL_NAME, low, high);
        return -1;
    case 1: /* r h (1 - 2 eps) >= 2 eps |d| + h (1 + eps) (1 - 16 eps) */
        bound_text((2.0 * eps * fabs(p->com_offset) + p->beam.thickness * (1.0 + eps) * (1.0 - 16.0 * eps))
                   / (p->beam.thickness * (1.0 - 2.0 * eps)), -1, low, sizeof low);
        snprintf(err, size, "%s: [slider] play_ratio = %g is too small for the slot's offset [slider] com_offset = "
                 "%g m (%s) on a beam of thickness %g m: rounded to %s, the corners lose the play; allowed: "
                 "play_ratio >= %s, or a smaller |com_offset|",
                 scene_where(file, "slider", "play_ratio", where[0], sizeof where[0]), p->play_ratio, p->com_offset,
                 scene_where(file, "slider", "com_offset", where[1], sizeof where[1]), p->beam.thickness,
                 BS_REAL_NAME, low);
        return -1;
    default: { /* h (r (1 - 2 eps) - (1 + eps) (1 - 16 eps)) >= 2 eps |d| */
        const double room = p->play_ratio * (1.0 - 2.0 * eps) - (1.0 + eps) * (1.0 - 16.0 * eps);
        bound_text(room > 0.0 ? 2.0 * eps * fabs(p->com_offset) / room : HUGE_VAL, -1, low, sizeof low);
        snprintf(err, size, "%s: [beam] thickness = %g m makes the slot height R = play_ratio thickness = %g m too "
                 "small for the slot's offset [slider] com_offset = %g m (%s): rounded to %s, the corners lose the "
                 "play; allowed: thickness >= %s m, or a smaller |com_offset|",
                 scene_where(file, "beam", "thickness", where[0], sizeof where[0]), p->beam.thickness, slot,
                 p->com_offset, scene_where(file, "slider", "com_offset", where[1], sizeof where[1]), BS_REAL_NAME,
                 low);
        return -1;
    }
    }
}

/* The clamp stops B/2 < L - B/2 once rounded to bs_real: a slot a hair
 * narrower than the beam passes the check in double and not this one. */
static int check_stop_rounding(const scene_file *file, const bs_scene *scene, char *err, size_t size)
{
    const scene_params *p = &file->params;
    char where[2][SCENE_PATH + 16], value[40], limit[40];

    if (scene->stop_min < scene->stop_max)
        return 0;
    values_text(p->slot_width, p->beam.length, value, limit, sizeof value);
    snprintf(err, size, "%s: [slider] slot_width = %s m must be below [beam] length = %s m (%s) by more "
             "than %s rounding: ", scene_where(file, "slider", "slot_width", where[0], sizeof where[0]), value,
             limit, scene_where(file, "beam", "length", where[1], sizeof where[1]), BS_REAL_NAME);
    bound_text(p->beam.length * (1.0 - (double)BS_REAL_EPS), 1, limit, sizeof limit);
    snprintf(err + strlen(err), size - strlen(err), "allowed: slot_width < %s m", limit);
    return -1;
}

/* The core refuses a scene the host's checks let through: name the core
 * field, each input it comes from with where it was set and the range it may
 * take with the others as set. */
static void report_core_refusal(const scene_file *file, bs_status status, const char *field, char *err,
                                size_t size)
{
    scene_input inputs[3 * SCENE_ORIGIN_FACTORS];
    const int count = scene_origin_inputs(field, inputs, (int)(sizeof inputs / sizeof inputs[0]));
    char where[SCENE_PATH + 16];

    if (!BS_WITH_PIEZO && strcmp(field, "load") == 0) {
        snprintf(err, size, "%s: this beamslider is built without the transducer (BS_WITH_PIEZO 0): "
                 "[transducer] load must be none", scene_limits_blame(file, inputs, count, where, sizeof where));
        return;
    }
    snprintf(err, size, "%s: the core refuses the scene: %s (field %.*s): the values are too extreme for %s; "
             "allowed, each with the others as set: ",
             scene_limits_blame(file, inputs, count, where, sizeof where), bs_status_text(status),
             (int)strcspn(field, " "), field, BS_REAL_NAME);
    scene_limits_describe(file, inputs, count, err, size);
}

int scene_build(const scene_file *file, bs_scene *scene, scene_model *model, char *err, size_t size)
{
    const scene_params *p = &file->params;
    const char *field = "";
    bs_status status;

    memset(scene, 0, sizeof *scene);
    if (check_extremes(file, err, size) != 0)
        return -1;
    model->kappa = modal_kappa(&p->beam);
    model->width = modal_width(&p->beam);
    if (modal_compute(&p->beam, p->modes, &model->modes) != 0) {
        snprintf(err, size, "%s: modal analysis failed (no root of the frequency equation found)",
                 file->files[0]);
        return -1;
    }
    if (check_modal_results(file, &model->modes, err, size) != 0 || check_derived(file, model, err, size) != 0
        || check_schedule(file, err, size) != 0)
        return -1;
    if (shape_fit_modes(&model->modes, scene_fit_tolerance(), &model->fit) != 0) {
        snprintf(err, size, "%s: %d modes need more than %d shape pieces for a fit error of %g "
                 "(reached %.3g); lower [numerics] modes", file->files[0], p->modes,
                 BS_SHAPE_MAX_PIECES, scene_fit_tolerance(), model->fit.error_slope);
        return -1;
    }
    memset(&model->data, 0, sizeof model->data);
    compute_modes(p, &model->modes, &model->data, &model->stretch_norm);
    compute_slider(p, &model->data);
    compute_transducer(p, &model->modes, &model->data);
    compute_numerics(p, &model->data);
    scene_data_set_shapes(&model->data, &model->fit);
    scene_data_round(&model->data, scene);
    if (check_slot_rounding(file, scene, err, size) != 0 || check_stop_rounding(file, scene, err, size) != 0)
        return -1;
    status = bs_scene_check(scene, &field);
    if (status != BS_OK) {
        report_core_refusal(file, status, field, err, size);
        return -1;
    }
    return check_start(file, scene, err, size);
}

bs_solver_options scene_solver(const scene_params *params)
{
    bs_solver_options options;
    options.max_sweeps = params->solver_max_sweeps;
    options.tol_rel = (bs_real)params->solver_tol_rel;
    options.tol_abs = (bs_real)params->solver_tol_abs;
    options.measure_residual = params->solver_residual;
    return options;
}

int scene_read(const char *path, scene_file *file, bs_scene *scene, scene_model *model, char *err,
               size_t size)
{
    if (scene_load(path, file, err, size) != 0)
        return -1;
    return scene_build(file, scene, model, err, size);
}
