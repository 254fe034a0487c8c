/* ref_scene.c - reference scene constants (docs/model.md 2-6, 10, 11).
 *
 *   M = diag(1, ..., 1, m, m, J_C) (mass-normalised modes), dense here; the
 *   step uses M~ = M + c theta theta^T (c = 0 without a patch, ref_step.c),
 *   inverted by elimination; a locked slider rotation is a coordinate with no
 *   mobility (row/column beta of M~^-1 = 0).
 *   Corners relative to G: P1 (-B/2, +R/2), P2 (-B/2, -R/2), P3 (+B/2, -R/2),
 *   P4 (+B/2, +R/2); r_GC = (0, -d) so r_CP,i = P_i + (0, d); zeta = +1 for P1, P4.
 *   Gravity in the beam frame: g (-sin tilt, -cos tilt).
 *
 *   Excitation (docs/model.md 1, 10), t = j dt_sub / 2 in long double:
 *     harmonic:  ddw0 = -a cos(Omega t), Omega t = 2 pi frac(f_ex t); the step
 *                mean (dw0(t_E) - dw0(t_B)) / dt = -a cos(Omega t_M) sin(Omega dt/2) / (Omega dt/2)
 *                (exact, no difference of two sines);
 *     schedule:  points (t_k, f_k, a_k); f and a linear between points, held
 *                before the first and after the last; cycles(t) = int_0^t f dt
 *                in closed form (quadratic on each piece), phase = 2 pi frac(cycles),
 *                ddw0 = -a(t) cos(phase); step mean by 8-point Gauss-Legendre on
 *                each piece of [t_B, t_E] between schedule points (the integrand
 *                is analytic there: error ~ (Omega dt)^16 / 16!).
 *
 *   Transducer (docs/model.md 11): theta_k = Theta (phi_k'(x_2) - phi_k'(x_1)),
 *   phi' = (1/L) d phi / d xi; the patch must touch a clamp (x_1 = 0 moves the
 *   left stop to x_2 + B/2, x_2 = L the right one to x_1 - B/2); the patch's
 *   own mass and stiffness are neglected (docs/model.md 11 allows it). */
#include "ref_scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "ref_linalg.h"
#include "schedule.h"

/* x_2 = L within this relative amount counts as touching the right clamp
 * (L and x_2 may be typed differently: 0.14 vs 140e-3 parse alike, sums do not) */
#define REF_PATCH_AT_CLAMP 1e-12

/* Gauss-Legendre nodes and weights on [-1, 1]: Newton on P_n in long double */
static void gauss_legendre(int n, long double *node, long double *weight)
{
    int i, it;
    for (i = 0; i < n; ++i) {
        long double x = cosl(REF_PI * ((long double)i + 0.75L) / ((long double)n + 0.5L));
        long double p0 = 1.0L, p1 = 0.0L, dp = 1.0L;
        for (it = 0; it < 100; ++it) {
            long double dx;
            int k;
            p0 = 1.0L;
            p1 = x;
            for (k = 2; k <= n; ++k) {
                const long double p2 = ((2.0L * k - 1.0L) * x * p1 - (k - 1.0L) * p0) / (long double)k;
                p0 = p1;
                p1 = p2;
            }
            dp = (long double)n * (x * p1 - p0) / (x * x - 1.0L);
            dx = p1 / dp;
            x -= dx;
            if (fabsl(dx) <= 1e-19L * fabsl(x) + 1e-30L)
                break;
        }
        node[i] = x;
        weight[i] = 2.0L / ((1.0L - x * x) * dp * dp);
    }
}

static int init_schedule(ref_scene *scene, const scene_params *p, char *err, size_t err_size)
{
    schedule parsed;
    char why[160];
    int k;

    if (schedule_parse(p->schedule, &parsed, why, sizeof why) != 0) {
        snprintf(err, err_size, "[excitation] schedule: %s", why);
        return -1;
    }
    scene->schedule_points = parsed.points;
    for (k = 0; k < parsed.points; ++k) {
        scene->schedule_t[k] = parsed.t[k];
        scene->schedule_f[k] = parsed.frequency[k];
        scene->schedule_a[k] = parsed.amplitude[k];
        scene->schedule_cycles[k] = k == 0 ? scene->schedule_f[0] * scene->schedule_t[0]
                                           : scene->schedule_cycles[k - 1]
                                                 + 0.5L * (scene->schedule_t[k] - scene->schedule_t[k - 1])
                                                       * (scene->schedule_f[k - 1] + scene->schedule_f[k]);
    }
    gauss_legendre(REF_GL_POINTS, scene->gl_node, scene->gl_weight);
    return 0;
}

/* Patch, stops and circuit constants; M~ is built by the caller. */
static int init_transducer(ref_scene *scene, const scene_params *p, char *err, size_t err_size)
{
    const double L = scene->length, half_b = 0.5 * scene->slot_width;
    int at_left, at_right, k;

    scene->stop_left = half_b;
    scene->stop_right = L - half_b;
    scene->load = p->load == SCENE_LOAD_RESISTOR    ? REF_LOAD_RESISTOR
                  : p->load == SCENE_LOAD_RECTIFIER ? REF_LOAD_RECTIFIER
                                                    : REF_LOAD_NONE;
    for (k = 0; k < REF_MAX_Q; ++k)
        scene->theta[k] = 0.0;
    scene->voltage_weight = 1.0;
    scene->implicit_mass = 0.0;
    if (scene->load == REF_LOAD_NONE)
        return 0;

    scene->patch_start = p->patch_start;
    scene->patch_end = p->patch_end;
    scene->coupling = p->coupling;
    scene->capacitance = p->capacitance;
    scene->resistance = p->resistance;
    scene->storage_capacitance = p->storage_capacitance;
    scene->storage_resistance = p->storage_resistance;
    scene->diode_drop = p->diode_drop;
    if (!(p->patch_start >= 0.0 && p->patch_start < p->patch_end && p->patch_end <= L * (1.0 + REF_PATCH_AT_CLAMP))) {
        snprintf(err, err_size,
                 "[transducer] patch_start = %.9g m, patch_end = %.9g m: need 0 <= patch_start < patch_end <= L = %.9g m",
                 p->patch_start, p->patch_end, L);
        return -1;
    }
    at_left = p->patch_start == 0.0;
    at_right = p->patch_end >= L * (1.0 - REF_PATCH_AT_CLAMP);
    if (!at_left && !at_right) {
        snprintf(err, err_size,
                 "[transducer] patch from %.9g m to %.9g m touches neither clamp: the slider could not pass it "
                 "(allowed: patch_start = 0 or patch_end = L = %.9g m)",
                 p->patch_start, p->patch_end, L);
        return -1;
    }
    if (at_left)
        scene->stop_left = p->patch_end + half_b;
    if (at_right)
        scene->stop_right = p->patch_start - half_b;
    if (!(scene->stop_left < scene->stop_right)) {
        snprintf(err, err_size,
                 "[transducer] patch from %.9g m to %.9g m leaves no room for the slider (slot width B = %.9g m)",
                 p->patch_start, p->patch_end, scene->slot_width);
        return -1;
    }
    {
        const double x0 = p->s0 * L;
        if (!(x0 >= scene->stop_left && x0 <= scene->stop_right)) {
            snprintf(err, err_size,
                     "[run] s0 = %.9g puts the slider over the patch (from %.9g m to %.9g m); allowed: s0 in [%.9g, %.9g]",
                     p->s0, p->patch_start, p->patch_end, scene->stop_left / L, scene->stop_right / L);
            return -1;
        }
    }
    for (k = 0; k < scene->n_modes; ++k) {
        long double a[3], b[3];
        ref_modes_shape(&scene->modes, k, (long double)p->patch_start / (long double)L, a);
        ref_modes_shape(&scene->modes, k, at_right ? 1.0L : (long double)p->patch_end / (long double)L, b);
        scene->theta[k] = (double)((long double)p->coupling * (b[1] - a[1]) / (long double)L);
    }
    if (scene->load == REF_LOAD_RESISTOR) {
        /* v over the step: exact for the step's constant current i = theta . (u_B + u_E)/2:
         * mean v = mean v_B + rise R_l i, so M~ gains dt R_l rise / 2 (ref_step.c) */
        const long double tau = (long double)p->resistance * (long double)p->capacitance;
        ref_circuit_factors_init((long double)scene->dt_sub / tau, &scene->patch);
        scene->voltage_weight = (double)scene->patch.mean;
        scene->implicit_mass = (double)((long double)scene->dt_sub * (long double)p->resistance * scene->patch.rise / 2.0L);
    } else {
        /* rectifier: the patch is a capacitor, v linear over the step (constant
         * currents), mean v = v_B + (dt i - sigma Q) / (2 C_p): M~ gains dt^2 / (4 C_p);
         * the storage C_s with R_s across it is charged by the constant current Q / dt */
        const long double tau_s = (long double)p->storage_resistance * (long double)p->storage_capacitance;
        ref_circuit_factors_init((long double)scene->dt_sub / tau_s, &scene->storage);
        scene->voltage_weight = 1.0;
        scene->implicit_mass = (double)((long double)scene->dt_sub * (long double)scene->dt_sub
                                        / (4.0L * (long double)p->capacitance));
    }
    return 0;
}

int ref_scene_init(ref_scene *scene, const scene_params *p, int substeps, char *err, size_t err_size)
{
    ref_beam beam;
    long double tilt;
    long double a[REF_MAX_Q * REF_MAX_Q], col[REF_MAX_Q];
    int free_index[REF_MAX_Q];
    int n_free = 0, i, j, k;

    memset(scene, 0, sizeof *scene);
    if (p->modes < 0 || p->modes > REF_MAX_MODES) {
        snprintf(err, err_size, "modes = %d: the reference supports 0..%d", p->modes, REF_MAX_MODES);
        return -1;
    }
    if (p->implicit) {
        snprintf(err, err_size, "integrator = implicit: the reference implements docs/model.md 5's explicit midpoint step only");
        return -1;
    }
    if (substeps < 1) {
        snprintf(err, err_size, "substeps = %d: must be >= 1", substeps);
        return -1;
    }
    beam.length = p->beam.length;
    beam.thickness = p->beam.thickness;
    beam.density = p->beam.density;
    beam.youngs_modulus = p->beam.youngs_modulus;
    beam.mass = p->beam.mass;
    beam.k_rot = p->beam.k_rot;
    beam.k_axial = p->beam.k_axial;
    if (ref_modes_compute(&beam, p->modes, &scene->modes) != 0) {
        snprintf(err, err_size, "the beam's modes could not be computed");
        return -1;
    }
    scene->n_modes = p->modes;
    scene->n_q = p->modes + 3;
    scene->i_x = p->modes;
    scene->i_z = p->modes + 1;
    scene->i_beta = p->modes + 2;
    scene->length = p->beam.length;
    scene->half_thickness = 0.5 * p->beam.thickness;
    scene->damping = p->damping_ratio;
    scene->stretch_factor = p->stretching
        ? (double)(scene->modes.k_ax / (2.0L * (long double)p->beam.length * (long double)p->beam.length))
        : 0.0;
    scene->slider_mass = p->slider_mass;
    scene->slider_inertia = p->slider_inertia;
    scene->rotation = p->rotation;
    scene->slot_width = p->slot_width;
    scene->com_offset = p->com_offset;
    scene->slot_height = p->play_ratio * p->beam.thickness;
    for (i = 0; i < REF_CORNERS; ++i) {
        const double x = i < 2 ? -0.5 * p->slot_width : 0.5 * p->slot_width;
        const double z = (i == 0 || i == 3) ? 0.5 * scene->slot_height : -0.5 * scene->slot_height;
        scene->corner[i][0] = x;
        scene->corner[i][1] = z + p->com_offset;
        scene->zeta[i] = (i == 0 || i == 3) ? 1.0 : -1.0;
    }
    scene->mu = p->mu;
    scene->e_n = p->e_n;
    tilt = (long double)p->tilt * REF_PI / 180.0L;
    scene->gravity[0] = (double)(-(long double)p->gravity * sinl(tilt));
    scene->gravity[1] = (double)(-(long double)p->gravity * cosl(tilt));
    scene->frequency = p->frequency;
    scene->acceleration = p->acceleration;
    scene->omega_ex = (double)(2.0L * REF_PI * (long double)p->frequency);
    scene->dt = p->dt;
    scene->substeps = substeps;
    scene->dt_sub = (double)((long double)p->dt / (long double)substeps);
    {
        const long double half = REF_PI * (long double)p->frequency * ((long double)p->dt / (long double)substeps);
        scene->step_sinc = half > 0.0L ? sinl(half) / half : 1.0L;
    }
    if (init_schedule(scene, p, err, err_size) != 0)
        return -1;
    scene->model = p->model == 1 ? REF_MODEL_PCS : REF_MODEL_FREE;
    scene->s_pcs = p->s0;
    scene->s0 = p->s0;
    scene->end_stops = scene->model == REF_MODEL_FREE;
    if (init_transducer(scene, p, err, err_size) != 0)
        return -1;

    for (i = 0; i < scene->n_q; ++i)
        for (j = 0; j < scene->n_q; ++j)
            scene->mass[i][j] = scene->mass_inv[i][j] = 0.0;
    for (k = 0; k < scene->n_modes; ++k)
        scene->mass[k][k] = 1.0;
    scene->mass[scene->i_x][scene->i_x] = p->slider_mass;
    scene->mass[scene->i_z][scene->i_z] = p->slider_mass;
    scene->mass[scene->i_beta][scene->i_beta] = p->slider_inertia;
    for (i = 0; i < scene->n_q; ++i)
        if (i != scene->i_beta || scene->rotation)
            free_index[n_free++] = i;
    for (j = 0; j < n_free; ++j) {
        for (i = 0; i < n_free; ++i) {
            for (k = 0; k < n_free; ++k)
                a[i * n_free + k] = (long double)scene->mass[free_index[i]][free_index[k]]
                                    + (long double)scene->implicit_mass * scene->theta[free_index[i]]
                                          * scene->theta[free_index[k]];
            col[i] = i == j ? 1.0L : 0.0L;
        }
        if (ref_linalg_solve(n_free, a, col, 1e-300L) != 0) {
            snprintf(err, err_size, "the mass matrix is singular");
            return -1;
        }
        for (i = 0; i < n_free; ++i)
            scene->mass_inv[free_index[i]][free_index[j]] = (double)col[i];
    }
    for (k = 0; k < scene->n_modes; ++k) {
        long double v[3];
        ref_modes_shape(&scene->modes, k, 4.0L / 7.0L, v);
        scene->sensor_phi[k] = (double)v[0];
    }
    return 0;
}

long double ref_scene_time(const ref_scene *scene, uint64_t half_steps)
{
    return (long double)half_steps * ((long double)scene->dt / (long double)scene->substeps) / 2.0L;
}

/* The schedule's piece holding t: -1 before the first point, k for
 * t_k <= t < t_k+1, points - 1 after the last. */
static int schedule_piece(const ref_scene *scene, long double t)
{
    int k = -1;
    while (k + 1 < scene->schedule_points && t >= scene->schedule_t[k + 1])
        ++k;
    return k;
}

long double ref_scene_cycles(const ref_scene *scene, long double t)
{
    const int last = scene->schedule_points - 1;
    long double s;
    int k;

    if (scene->schedule_points == 0)
        return t * (long double)scene->frequency;
    k = schedule_piece(scene, t);
    if (k < 0)
        return scene->schedule_f[0] * t;
    s = t - scene->schedule_t[k];
    if (k == last)
        return scene->schedule_cycles[k] + scene->schedule_f[k] * s;
    return scene->schedule_cycles[k] + scene->schedule_f[k] * s
           + 0.5L * (scene->schedule_f[k + 1] - scene->schedule_f[k]) / (scene->schedule_t[k + 1] - scene->schedule_t[k])
                 * s * s;
}

/* a(t) of the schedule */
static long double schedule_amplitude(const ref_scene *scene, long double t)
{
    const int k = schedule_piece(scene, t);
    if (k < 0)
        return scene->schedule_a[0];
    if (k == scene->schedule_points - 1)
        return scene->schedule_a[k];
    return scene->schedule_a[k]
           + (scene->schedule_a[k + 1] - scene->schedule_a[k]) * (t - scene->schedule_t[k])
                 / (scene->schedule_t[k + 1] - scene->schedule_t[k]);
}

static long double phase_of(long double cycles)
{
    return 2.0L * REF_PI * (cycles - floorl(cycles));
}

static long double schedule_accel(const ref_scene *scene, long double t)
{
    return -schedule_amplitude(scene, t) * cosl(phase_of(ref_scene_cycles(scene, t)));
}

void ref_scene_excitation(const ref_scene *scene, long double t, ref_excitation *ex)
{
    ex->cycles = ref_scene_cycles(scene, t);
    if (scene->schedule_points == 0) {
        const long double phase = phase_of(ex->cycles);
        const long double omega = 2.0L * REF_PI * (long double)scene->frequency;
        const long double a = scene->acceleration;
        ex->w0 = (double)(a / (omega * omega) * cosl(phase));
        ex->w0_dot = (double)(-a / omega * sinl(phase));
        ex->w0_ddot = (double)(-a * cosl(phase));
    } else {
        ex->w0 = ex->w0_dot = NAN;
        ex->w0_ddot = (double)schedule_accel(scene, t);
    }
}

long double ref_scene_mean_accel(const ref_scene *scene, long double t_b, long double t_e)
{
    long double sum = 0.0L, from = t_b;
    int k = 0;

    if (scene->schedule_points == 0) {
        const long double half = REF_PI * (long double)scene->frequency * (t_e - t_b);
        const long double sinc = half > 0.0L ? sinl(half) / half : 1.0L;
        return -(long double)scene->acceleration * sinc * cosl(phase_of(ref_scene_cycles(scene, 0.5L * (t_b + t_e))));
    }
    if (!(t_e > t_b))
        return schedule_accel(scene, t_b);
    for (;;) {
        long double to = t_e, mid, half;
        int g;
        while (k < scene->schedule_points && scene->schedule_t[k] <= from)
            ++k;
        if (k < scene->schedule_points && scene->schedule_t[k] < t_e)
            to = scene->schedule_t[k];
        mid = 0.5L * (from + to);
        half = 0.5L * (to - from);
        for (g = 0; g < REF_GL_POINTS; ++g)
            sum += half * scene->gl_weight[g] * schedule_accel(scene, mid + half * scene->gl_node[g]);
        if (to >= t_e)
            break;
        from = to;
    }
    return sum / (t_e - t_b);
}

double ref_scene_step_accel(const ref_scene *scene, uint64_t step)
{
    if (scene->schedule_points == 0) /* the step's own sinc, from the half-step count */
        return (double)(-(long double)scene->acceleration * scene->step_sinc
                        * cosl(phase_of(ref_scene_cycles(scene, ref_scene_time(scene, 2 * step + 1)))));
    return (double)ref_scene_mean_accel(scene, ref_scene_time(scene, 2 * step), ref_scene_time(scene, 2 * step + 2));
}

void ref_scene_beam(const ref_scene *scene, const double *q_b, double x, double *w, double *w_x,
                    double *phi, double *phi_x)
{
    double phi_local[REF_MAX_MODES], phi_xi[REF_MAX_MODES];
    double *ph = phi ? phi : phi_local;
    double value = 0.0, slope = 0.0;
    int k;

    ref_modes_eval(&scene->modes, x / scene->length, ph, phi_xi);
    for (k = 0; k < scene->n_modes; ++k) {
        const double d = phi_xi[k] / scene->length;
        value += ph[k] * q_b[k];
        slope += d * q_b[k];
        if (phi_x)
            phi_x[k] = d;
    }
    *w = value;
    *w_x = slope;
}

double ref_scene_sensor(const ref_scene *scene, const double *q)
{
    double w = 0.0;
    int k;
    for (k = 0; k < scene->n_modes; ++k)
        w += scene->sensor_phi[k] * q[k];
    return w;
}

const char *ref_scene_load_name(ref_load load)
{
    return load == REF_LOAD_RESISTOR ? "resistor" : load == REF_LOAD_RECTIFIER ? "rectifier" : "none";
}
