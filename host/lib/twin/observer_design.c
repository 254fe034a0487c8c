/* observer_design.c - the observer's constants, in double (docs/twin.md,
 * "Observer").
 *
 * Linear model: the beam with the slider rigidly attached at s, in the
 * scene's modal coordinates (host/lib/scene/attached.c),
 *   M(s) = I + m phi phi^T + (J_C + m d^2) phi' phi'^T   (phi, phi' at s),
 *   M q'' + C q' + K q + theta_p v = -(gamma + m phi) a + f,
 * C = diag(2 D omega_k), K = diag(omega_k^2), with the patch voltage v of a
 * resistor load as a state when the scene has one (C_p v' + v/R_l =
 * theta_p^T q'). The gains are those of this model, not of the bare beam:
 * the slider weighs three times the beam and halves f_1, and an injection
 * tuned to the bare beam's 260 Hz pushes the 124 Hz motion with the wrong
 * phase (measured: the twin then drifts off or throws the slider). Steps
 * as the core's (core/src/bs_step.c, bs_piezo.c) with M in the modal mass:
 *   M^ = M + [implicit] (theta dt C + theta^2 dt^2 K)
 *   u' = u + dt M^-1 (F - C u - K (q + theta dt u)),  q' = q + dt ((1 - theta) u + theta u')
 * (theta = 1/2, M^ = M: the explicit midpoint step), the patch in two exact
 * half steps. State x = (q, u[, v]):
 *   x_{k+1} = Phi x_k + Gamma a_k + F f_k,   y_k = C x_k + n_k,
 * C = phi_k(4/7) on q for the deflection, 1 on v for the voltage.
 * Noise: n_k white with variance R = noise^2; the measured a_k carries white
 * noise of variance accel_noise^2 (Q += accel_noise^2 Gamma Gamma^T). The
 * contacts the model leaves out are a force F(t) at a random point x of the
 * beam, white with one-sided density force_noise^2 [N^2/Hz]: per step its
 * modal forces f_k = phi_k(x) F have E[f f^T] = force_noise^2 / (2 dt rho A L) I
 * (the modes are orthonormal, rho A L int phi_i phi_j = delta_ij), so
 *   Q = force_noise^2 / (2 dt rho A L) F F^T + accel_noise^2 Gamma Gamma^T.
 * Steady-state Kalman filter: P solves the discrete algebraic Riccati
 * equation P = Phi P Phi^T - Phi P C^T (C P C^T + R)^-1 C P Phi^T + Q, i.e.
 * X = A^T X (I + G X)^-1 A + Q with A = Phi^T, G = C^T R^-1 C, solved by
 * the structure-preserving doubling algorithm (Chu, Fan, Lin 2005):
 *   W = I + G_j H_j,  A_{j+1} = A_j W^-1 A_j,  G_{j+1} = G_j + A_j W^-1 G_j A_j^T,
 *   H_{j+1} = H_j + A_j^T H_j W^-1 A_j,   H_j -> P
 * (each iteration doubles the horizon: the lightly damped modes, whose plain
 * iteration needs ~1e6 steps, converge in ~25). Gain K = P C^T / (C P C^T + R)
 * corrects x_k with y_k; with the signal d steps late, Phi^d K corrects the
 * present state. One design per point of the gain schedule, BS_OBSERVER_GAINS
 * values of s evenly over the clamp stops (the sensor at 4L/7 is not
 * symmetric, so both halves of the beam).
 * Response map (the s correction's, core/src/bs_observer.c 5): the scene's
 * own first-harmonic response H = Y_1 / A_1 of the signal to the base
 * acceleration at one excitation (the scene's, or each of several across
 * its schedule: observer_design.h), on BS_OBSERVER_TABLE points of s
 * over [stop_min / L, 1/2], from two PCS sweeps with continuation (docs/
 * model.md 6): up from the clamp (the stiff branch, Re H < 0) and down from
 * the centre (the soft branch, Re H > 0); map_hold periods at each point,
 * then one DFT bin over map_record periods. A point whose Re H has the other
 * branch's sign (the down sweep falls onto the stiff branch near the clamp)
 * is stored negative: no such branch there. The beam with the slider rigidly
 * attached (host/lib/scene/attached.c) is no substitute: on the high branch the
 * hardening keeps the response below its resonance where the linear model is
 * far above it, and on the low branch the slider bounces.
 */
#include "observer_design.h"
#include "out_c.h"
#include "schedule.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_STATES (2 * BS_MAX_MODES + 1)
#define SDA_ITERATIONS 80

typedef double matrix[MAX_STATES][MAX_STATES];

/* The work space of a design (large: on the heap). */
typedef struct design_work {
    matrix phi;     /* Phi */
    matrix a, g, h; /* the doubling iterates */
    matrix w;       /* I + G H, factorised */
    matrix wa, wg;  /* W^-1 A, W^-1 G */
    matrix t1, t2;
} design_work;

observer_design_options observer_design_defaults(double noise)
{
    observer_design_options o;
    int i;
    o.signal = BS_SIGNAL_DEFLECTION;
    o.noise = noise;
    o.force_noise = OBSERVER_DEFAULT_FORCE_NOISE;
    o.accel_noise = 0.0;
    o.latency = 0;
    o.map_hold = OBSERVER_DEFAULT_MAP_HOLD;
    o.map_record = OBSERVER_DEFAULT_MAP_RECORD;
    o.map_count = 0; /* the maps' frequencies from the scene */
    o.friction_count = 0; /* one map per excitation, at the scene's mu */
    for (i = 0; i < BS_OBSERVER_MAPS; ++i)
        o.map_frequency[i] = o.map_friction[i] = 0.0;
    o.progress = NULL;
    o.progress_context = NULL;
    return o;
}

/* The linear model at one s (or the bare beam: M = I, forcing gamma). */
typedef struct linear_model {
    const scene_data *d;
    int with_voltage;
    int size;                                   /* 2 N (+ 1) */
    double mass_inv[BS_MAX_MODES][BS_MAX_MODES]; /* M^-1 */
    double forcing[BS_MAX_MODES];               /* gamma + m phi(s) */
} linear_model;

/* One step of the model: x' = Phi x + Gamma a + F force (force may be NULL). */
static void model_step(const linear_model *m, const double *x, double base_accel, const double *force, double *next)
{
    const scene_data *d = m->d;
    const int n = d->n_modes;
    const double dt = d->dt, theta = d->theta;
    const double *q = x, *u = x + n;
    double v_mid = 0.0, current = 0.0, rhs[BS_MAX_MODES];
    int k, j;

    if (m->with_voltage) { /* the patch to the midpoint, driven by the start velocities */
        for (k = 0; k < n; ++k)
            current += d->piezo_theta[k] * u[k];
        v_mid = d->load_decay * x[2 * n] + d->load_gain * current;
    }
    for (k = 0; k < n; ++k)
        rhs[k] = -m->forcing[k] * base_accel - d->piezo_theta[k] * v_mid * m->with_voltage + (force ? force[k] : 0.0)
                 - d->damping[k] * u[k] - d->omega_sq[k] * (q[k] + theta * dt * u[k]);
    for (k = 0; k < n; ++k) {
        double du = 0.0;
        for (j = 0; j < n; ++j)
            du += m->mass_inv[k][j] * rhs[j];
        next[n + k] = u[k] + dt * du;
        next[k] = q[k] + dt * ((1.0 - theta) * u[k] + theta * next[n + k]);
    }
    if (m->with_voltage) { /* on to the end, driven by the end velocities */
        current = 0.0;
        for (k = 0; k < n; ++k)
            current += d->piezo_theta[k] * next[n + k];
        next[2 * n] = d->load_decay * v_mid + d->load_gain * current;
    }
}

/* Inverts the n x n matrix a (overwritten) into inv, Gauss-Jordan with
 * partial pivoting. Returns -1 if singular. */
static int invert(int n, double a[BS_MAX_MODES][BS_MAX_MODES], double inv[BS_MAX_MODES][BS_MAX_MODES])
{
    int i, j, k;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            inv[i][j] = i == j;
    for (k = 0; k < n; ++k) {
        int pivot = k;
        double f;
        for (i = k + 1; i < n; ++i)
            if (fabs(a[i][k]) > fabs(a[pivot][k]))
                pivot = i;
        if (!(fabs(a[pivot][k]) > 0.0))
            return -1;
        for (j = 0; j < n; ++j) {
            double t = a[k][j]; a[k][j] = a[pivot][j]; a[pivot][j] = t;
            t = inv[k][j]; inv[k][j] = inv[pivot][j]; inv[pivot][j] = t;
        }
        f = a[k][k];
        for (j = 0; j < n; ++j) {
            a[k][j] /= f;
            inv[k][j] /= f;
        }
        for (i = 0; i < n; ++i)
            if (i != k && a[i][k] != 0.0) {
                const double g = a[i][k];
                for (j = 0; j < n; ++j) {
                    a[i][j] -= g * a[k][j];
                    inv[i][j] -= g * inv[k][j];
                }
            }
    }
    return 0;
}

/* The model with the slider attached at s (attached = 0: the bare beam). */
static int model_at(const scene_file *file, const scene_model *model, int attached, double s, linear_model *m)
{
    const scene_data *d = &model->data;
    const scene_params *p = &file->params;
    const int n = d->n_modes;
    const double rotary = p->slider_inertia + p->slider_mass * p->com_offset * p->com_offset;
    double mass[BS_MAX_MODES][BS_MAX_MODES], phi[BS_MAX_MODES], slope[BS_MAX_MODES];
    int i, j;

    m->d = d;
    m->with_voltage = d->load == BS_LOAD_RESISTOR;
    m->size = 2 * n + m->with_voltage;
    for (i = 0; i < n; ++i) {
        modal_shape(&model->modes, i, s, &phi[i], &slope[i]);
        slope[i] /= p->beam.length;
        if (!attached)
            phi[i] = slope[i] = 0.0;
        m->forcing[i] = d->gamma[i] + p->slider_mass * phi[i];
    }
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            mass[i][j] = (i == j) + p->slider_mass * phi[i] * phi[j] + rotary * slope[i] * slope[j]
                         + (i == j && d->implicit) * (d->theta * d->dt * d->damping[i]
                                                      + d->theta * d->theta * d->dt * d->dt * d->omega_sq[i]);
    return invert(n, mass, m->mass_inv);
}

/* Phi, column by column. */
static void transition(const linear_model *m, matrix phi)
{
    double x[MAX_STATES], next[MAX_STATES];
    int i, j;
    for (j = 0; j < m->size; ++j) {
        for (i = 0; i < m->size; ++i)
            x[i] = i == j;
        model_step(m, x, 0.0, NULL, next);
        for (i = 0; i < m->size; ++i)
            phi[i][j] = next[i];
    }
}

/* Q = force_var sum_k F_k F_k^T + accel_var Gamma Gamma^T, F_k the step's
 * response to a unit force on mode k. */
static void process_noise(const linear_model *m, double force_var, double accel_var, matrix q)
{
    const int n = m->d->n_modes;
    double zero[MAX_STATES] = { 0 }, force[BS_MAX_MODES], column[MAX_STATES];
    int i, j, k;
    for (i = 0; i < m->size; ++i)
        for (j = 0; j < m->size; ++j)
            q[i][j] = 0.0;
    for (k = 0; k <= n; ++k) {
        const double var = k < n ? force_var : accel_var;
        for (i = 0; i < n; ++i)
            force[i] = i == k;
        model_step(m, zero, k < n ? 0.0 : 1.0, k < n ? force : NULL, column);
        for (i = 0; i < m->size; ++i)
            for (j = 0; j < m->size; ++j)
                q[i][j] += var * column[i] * column[j];
    }
}

static void multiply(int n, matrix x, matrix y, matrix out)
{
    int i, j, k;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            double sum = 0.0;
            for (k = 0; k < n; ++k)
                sum += x[i][k] * y[k][j];
            out[i][j] = sum;
        }
}

/* Solves W [X1 X2] = [B1 B2] by Gaussian elimination with partial pivoting
 * (W is overwritten). Returns -1 if W is singular. */
static int solve_two(int n, matrix w, matrix b1, matrix b2, matrix x1, matrix x2)
{
    int i, j, k;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            x1[i][j] = b1[i][j];
            x2[i][j] = b2[i][j];
        }
    for (k = 0; k < n; ++k) {
        int pivot = k;
        for (i = k + 1; i < n; ++i)
            if (fabs(w[i][k]) > fabs(w[pivot][k]))
                pivot = i;
        if (!(fabs(w[pivot][k]) > 0.0))
            return -1;
        if (pivot != k)
            for (j = 0; j < n; ++j) {
                double t = w[k][j]; w[k][j] = w[pivot][j]; w[pivot][j] = t;
                t = x1[k][j]; x1[k][j] = x1[pivot][j]; x1[pivot][j] = t;
                t = x2[k][j]; x2[k][j] = x2[pivot][j]; x2[pivot][j] = t;
            }
        for (i = k + 1; i < n; ++i) {
            const double f = w[i][k] / w[k][k];
            if (f == 0.0)
                continue;
            for (j = k; j < n; ++j)
                w[i][j] -= f * w[k][j];
            for (j = 0; j < n; ++j) {
                x1[i][j] -= f * x1[k][j];
                x2[i][j] -= f * x2[k][j];
            }
        }
    }
    for (k = n - 1; k >= 0; --k)
        for (j = 0; j < n; ++j) {
            double s1 = x1[k][j], s2 = x2[k][j];
            for (i = k + 1; i < n; ++i) {
                s1 -= w[k][i] * x1[i][j];
                s2 -= w[k][i] * x2[i][j];
            }
            x1[k][j] = s1 / w[k][k];
            x2[k][j] = s2 / w[k][k];
        }
    return 0;
}

/* The doubling iteration: on entry a = Phi^T, g = C^T C / R, h = Q; on
 * success h = P. Returns the iterations used, or -1. */
static int riccati(int n, design_work *m)
{
    int it, i, j;
    for (it = 1; it <= SDA_ITERATIONS; ++it) {
        double change = 0.0, size = 0.0;
        multiply(n, m->g, m->h, m->w);
        for (i = 0; i < n; ++i)
            m->w[i][i] += 1.0;
        if (solve_two(n, m->w, m->a, m->g, m->wa, m->wg) != 0)
            return -1;
        /* H += A^T H W^-1 A */
        multiply(n, m->h, m->wa, m->t1);
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) {
                double sum = 0.0;
                int k;
                for (k = 0; k < n; ++k)
                    sum += m->a[k][i] * m->t1[k][j];
                m->t2[i][j] = sum;
            }
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) {
                change += fabs(m->t2[i][j]);
                size += fabs(m->h[i][j] + m->t2[i][j]);
                m->h[i][j] += m->t2[i][j];
            }
        /* G += A W^-1 G A^T */
        multiply(n, m->a, m->wg, m->t1);
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) {
                double sum = 0.0;
                int k;
                for (k = 0; k < n; ++k)
                    sum += m->t1[i][k] * m->a[j][k];
                m->g[i][j] += sum;
            }
        /* A = A W^-1 A */
        multiply(n, m->a, m->wa, m->t1);
        memcpy(m->a, m->t1, sizeof(matrix));
        if (!(change == change) || !(size == size))
            return -1;
        if (change <= 1e-14 * size)
            return it;
    }
    return -1;
}

/* The signal of the map's PCS sim. */
static double map_signal(const bs_sim *sim, int signal)
{
    bs_transducer_output out;
    if (signal != BS_SIGNAL_VOLTAGE)
        return (double)bs_sim_sensor(sim);
    bs_sim_get_transducer(sim, &out);
    return (double)out.voltage;
}

/* One point of the map: after `hold` excitation periods at s, the first
 * harmonics Y_1, A_1 of the signal and of a over `record` periods (one DFT
 * bin at the excitation phase); *h = |Y_1 / A_1|, or -|Y_1 / A_1| where
 * Re(Y_1 / A_1) has the other branch's sign (stiff: Re < 0). */
static bs_status map_point(bs_sim *sim, double s, const observer_design_options *o, int stiff, double *h)
{
    double y_re = 0.0, y_im = 0.0, a_re = 0.0, a_im = 0.0, previous = (double)bs_sim_phase(sim);
    int periods = 0;
    bs_status status = bs_sim_set_pcs_position(sim, (bs_real)s);
    while (status == BS_OK && periods < o->map_hold + o->map_record) {
        double phase;
        status = bs_sim_step(sim);
        phase = (double)bs_sim_phase(sim);
        periods += phase < previous;
        previous = phase;
        if (periods >= o->map_hold) {
            const double a = (double)bs_sim_base_acceleration(sim), y = map_signal(sim, o->signal);
            const double c = cos(6.283185307179586 * phase), sn = sin(6.283185307179586 * phase);
            y_re += y * c;
            y_im -= y * sn;
            a_re += a * c;
            a_im -= a * sn;
        }
    }
    if (status == BS_OK) {
        const double norm = a_re * a_re + a_im * a_im;
        const double h_re = (y_re * a_re + y_im * a_im) / norm, h_im = (y_im * a_re - y_re * a_im) / norm;
        *h = sqrt(h_re * h_re + h_im * h_im);
        if ((h_re < 0.0) != stiff)
            *h = -*h;
    }
    return status;
}

/* The excitations of the maps (observer_design's rule) into gains. Returns
 * 0, or -1 with a message in err. */
static int map_excitations(const scene_file *file, const bs_scene *scene, const observer_design_options *o,
                           bs_observer_gains *gains, char *err, size_t err_size)
{
    schedule sched;
    char why[160];
    int m, k;

    if (schedule_parse(file->params.schedule, &sched, why, sizeof why) != 0) {
        snprintf(err, err_size, "observer design: [excitation] schedule: %s", why);
        return -1;
    }
    if (o->map_count > 0) {
        gains->map_count = o->map_count;
        for (m = 0; m < o->map_count; ++m)
            gains->map_frequency[m] = (bs_real)o->map_frequency[m];
    } else if (sched.points == 0) {
        gains->map_count = 1;
        gains->map_frequency[0] = scene->frequency;
    } else {
        double lo = sched.frequency[0], hi = sched.frequency[0];
        int count;
        for (k = 1; k < sched.points; ++k) {
            lo = fmin(lo, sched.frequency[k]);
            hi = fmax(hi, sched.frequency[k]);
        }
        count = 1 + (int)ceil(log(hi / lo) / log(OBSERVER_MAP_SPACING) - 1e-9);
        if (count > BS_OBSERVER_MAPS) {
            snprintf(err, err_size, "observer design: the [excitation] schedule spans %g Hz to %g Hz, which needs %d "
                     "response maps spaced by %g; at most %d fit (name the frequencies the twin will meet with "
                     "--map-frequencies)", lo, hi, count, OBSERVER_MAP_SPACING, BS_OBSERVER_MAPS);
            return -1;
        }
        gains->map_count = count;
        for (m = 0; m < count; ++m)
            gains->map_frequency[m] = (bs_real)(count == 1 ? lo : lo * pow(hi / lo, (double)m / (count - 1)));
    }
    for (m = 0; m < gains->map_count; ++m) {
        const double f = (double)gains->map_frequency[m];
        double a = (double)scene->base_accel;
        int nearest = 0;
        for (k = 1; k < sched.points; ++k) { /* the nearest in frequency; of equals, the strongest */
            const double dk = fabs(sched.frequency[k] - f), dn = fabs(sched.frequency[nearest] - f);
            if (dk < dn || (dk == dn && sched.amplitude[k] > sched.amplitude[nearest]))
                nearest = k;
        }
        if (sched.points > 0)
            a = sched.amplitude[nearest];
        gains->map_accel[m] = (bs_real)a;
        if (!(a > 0.0)) {
            snprintf(err, err_size, "observer design: the response map at %g Hz has no excitation (amplitude %g)",
                     (double)gains->map_frequency[m], a);
            return -1;
        }
    }
    return 0;
}

/* Each excitation's map repeated at each of the options' mu (ascending, the
 * maps of one excitation next to each other), or the scene's mu alone.
 * Returns 0, or -1 with a message in err. */
static int map_frictions(const bs_scene *scene, const observer_design_options *o, bs_observer_gains *gains,
                         char *err, size_t err_size)
{
    const int per = o->friction_count > 0 ? o->friction_count : 1;
    int m, f;
    if (gains->map_count * per > BS_OBSERVER_MAPS) {
        snprintf(err, err_size, "observer design: %d excitations with maps at %d friction coefficients each need %d "
                 "response maps; at most %d fit", gains->map_count, per, gains->map_count * per, BS_OBSERVER_MAPS);
        return -1;
    }
    for (m = gains->map_count - 1; m >= 0; --m) /* from the last: slot m * per + f is at or after m */
        for (f = per - 1; f >= 0; --f) {
            gains->map_frequency[m * per + f] = gains->map_frequency[m];
            gains->map_accel[m * per + f] = gains->map_accel[m];
            gains->map_friction[m * per + f] = o->friction_count > 0 ? (bs_real)o->map_friction[f] : scene->mu;
        }
    gains->map_count *= per;
    return 0;
}

/* The response maps: at each map's excitation, PCS sweeps of the scene over
 * [stop_min / L, 1/2], up from the clamp (stiff branch) and down from the
 * centre (soft branch). */
static int response_map(const scene_file *file, const bs_scene *scene, const observer_design_options *o,
                        bs_observer_gains *gains, char *err, size_t err_size)
{
    bs_sim *sim; /* large: on the heap, one per design (designs may run in threads) */
    const bs_solver_options solver = scene_solver(&file->params);
    const double s_low = (double)scene->stop_min / (double)scene->length;
    const int count = BS_OBSERVER_TABLE;
    int i, m, branch;

    double steps = 0.0, done = 0.0;
    if (map_excitations(file, scene, o, gains, err, err_size) != 0 || map_frictions(scene, o, gains, err, err_size) != 0)
        return -1;
    for (m = 0; m < gains->map_count; ++m) /* the cost, before any of it is spent */
        steps += 2.0 * count * (o->map_hold + o->map_record) / ((double)gains->map_frequency[m] * (double)scene->dt);
    if (!(steps <= OBSERVER_DESIGN_MAX_STEPS)) {
        int used = snprintf(err, err_size, "observer design: response maps at");
        for (m = 0; m < gains->map_count && used > 0 && (size_t)used < err_size; ++m)
            used += snprintf(err + used, err_size - (size_t)used, "%s %g", m ? "," : "",
                             (double)gains->map_frequency[m]);
        if (used > 0 && (size_t)used < err_size)
            snprintf(err + used, err_size - (size_t)used,
                     " Hz need about %.3g steps of simulation, more than the design's bound of %.3g (a map "
                     "costs 2 x %d x %d excitation periods of 1 / (f dt) steps each): make them at higher "
                     "frequencies, near the excitation's", steps, OBSERVER_DESIGN_MAX_STEPS, count,
                     o->map_hold + o->map_record);
        return -1;
    }
    if (!(sim = malloc(sizeof *sim))) {
        snprintf(err, err_size, "observer design: out of memory");
        return -1;
    }
    gains->table_count = count;
    for (i = 0; i < count; ++i)
        gains->table_s[i] = (bs_real)(s_low + (0.5 - s_low) * i / (count - 1));
    for (m = 0; m < gains->map_count; ++m)
        for (branch = 0; branch < 2; ++branch) { /* 0: stiff, up from the clamp; 1: soft, down from the centre */
            bs_status status = bs_sim_init(sim, scene, BS_MODEL_PCS, branch ? BS_R(0.5) : gains->table_s[0]);
            if (status == BS_OK)
                status = bs_sim_set_solver(sim, &solver);
            if (status == BS_OK)
                status = bs_sim_set_excitation(sim, gains->map_frequency[m], gains->map_accel[m]);
            if (status == BS_OK)
                status = bs_sim_set_contact_laws(sim, gains->map_friction[m], scene->e_n);
            for (i = 0; status == BS_OK && i < count; ++i) {
                const int j = branch ? count - 1 - i : i;
                double h = 0.0;
                status = map_point(sim, (double)gains->table_s[j], o, !branch, &h);
                (branch ? gains->table_soft : gains->table_stiff)[m][j] = (bs_real)h;
                done += (o->map_hold + o->map_record) / ((double)gains->map_frequency[m] * (double)scene->dt);
                if (o->progress)
                    o->progress(o->progress_context, done / steps, NULL);
            }
            if (status != BS_OK) {
                snprintf(err, err_size, "observer design: the response map's PCS sweep at %g Hz stopped: %s",
                         (double)gains->map_frequency[m], bs_status_text(status));
                free(sim);
                return -1;
            }
        }
    free(sim);
    return 0;
}

/* The Kalman gain of model m, carried latency steps forward, into k_gain.
 * Returns 0, or -1 if the Riccati iteration fails. */
static int kalman_gain(const linear_model *m, const double *c, double force_var, const observer_design_options *o,
                       design_work *w, double *k_gain)
{
    double pc[MAX_STATES], next[MAX_STATES], cpc = 0.0;
    int i, j, it;

    transition(m, w->phi);
    process_noise(m, force_var, o->accel_noise * o->accel_noise, w->h);
    for (i = 0; i < m->size; ++i)
        for (j = 0; j < m->size; ++j) {
            w->a[i][j] = w->phi[j][i];
            w->g[i][j] = c[i] * c[j] / (o->noise * o->noise);
        }
    if (riccati(m->size, w) < 0)
        return -1;
    /* K = P C^T / (C P C^T + R), then Phi^latency K */
    for (i = 0; i < m->size; ++i) {
        pc[i] = 0.0;
        for (j = 0; j < m->size; ++j)
            pc[i] += w->h[i][j] * c[j];
        cpc += c[i] * pc[i];
    }
    for (i = 0; i < m->size; ++i)
        k_gain[i] = pc[i] / (cpc + o->noise * o->noise);
    for (it = 0; it < o->latency; ++it) {
        model_step(m, k_gain, 0.0, NULL, next);
        memcpy(k_gain, next, sizeof(double) * (size_t)m->size);
    }
    return 0;
}

static int check_options(const scene_data *d, const observer_design_options *o, char *err, size_t err_size)
{
    int i;
    if (o->signal == BS_SIGNAL_VOLTAGE && d->load != BS_LOAD_RESISTOR) {
        snprintf(err, err_size, "the voltage signal needs [transducer] load = resistor (the scene's is %s)",
                 d->load == BS_LOAD_NONE ? "none" : "a rectifier, which the linear model cannot follow");
        return -1;
    }
    if (!(o->noise > 0.0 && isfinite(o->noise)) || !(o->force_noise >= 0.0 && isfinite(o->force_noise))
        || !(o->accel_noise >= 0.0 && isfinite(o->accel_noise))
        || o->latency < 0 || o->latency > BS_OBSERVER_MAX_LATENCY || o->map_hold < 0 || o->map_record < 1) {
        snprintf(err, err_size, "observer design: noise must be > 0, force and acceleration noise >= 0, latency in "
                 "[0, %d] steps, map hold >= 0 and record >= 1 periods", BS_OBSERVER_MAX_LATENCY);
        return -1;
    }
    if (o->map_count < 0 || o->map_count > BS_OBSERVER_MAPS) {
        snprintf(err, err_size, "observer design: %d map frequencies; 1 to %d", o->map_count, BS_OBSERVER_MAPS);
        return -1;
    }
    for (i = 0; i < o->map_count; ++i)
        if (!(o->map_frequency[i] > 0.0 && isfinite(o->map_frequency[i]))
            || (i > 0 && !(o->map_frequency[i] > o->map_frequency[i - 1]))) {
            snprintf(err, err_size, "observer design: map frequency %d (%g Hz) must be finite, > 0 and above the "
                     "one before", i + 1, o->map_frequency[i]);
            return -1;
        }
    if (o->friction_count < 0 || o->friction_count > BS_OBSERVER_MAPS) {
        snprintf(err, err_size, "observer design: %d map frictions; 1 to %d", o->friction_count, BS_OBSERVER_MAPS);
        return -1;
    }
    for (i = 0; i < o->friction_count; ++i)
        if (!(o->map_friction[i] >= 0.0 && isfinite(o->map_friction[i]))
            || (i > 0 && !(o->map_friction[i] > o->map_friction[i - 1]))) {
            snprintf(err, err_size, "observer design: map friction %d (%g) must be finite, >= 0 and above the one "
                     "before", i + 1, o->map_friction[i]);
            return -1;
        }
    return 0;
}

int observer_design(const scene_file *file, const scene_model *model, const bs_scene *scene,
                    const observer_design_options *o, bs_observer_gains *gains, char *err, size_t err_size)
{
    const scene_data *d = &model->data;
    const int n = d->n_modes;
    const double s_low = d->stop_min / d->length, s_high = d->stop_max / d->length;
    const double force_var = o->force_noise * o->force_noise / (2.0 * d->dt * model->modes.mass);
    design_work *w;
    double c[MAX_STATES] = { 0 }, k_gain[MAX_STATES];
    int i, j;

    if (check_options(d, o, err, err_size) != 0)
        return -1;
    w = calloc(1, sizeof *w);
    if (!w) {
        snprintf(err, err_size, "observer design: out of memory");
        return -1;
    }
    if (o->signal == BS_SIGNAL_VOLTAGE)
        c[2 * n] = 1.0;
    else
        for (i = 0; i < n; ++i)
            c[i] = d->phi_sensor[i];
    memset(gains, 0, sizeof *gains);
    gains->n_modes = n;
    gains->signal = o->signal;
    gains->latency = o->latency;
    gains->noise = (bs_real)o->noise;
    gains->gain_count = BS_OBSERVER_GAINS;
    for (j = 0; j < BS_OBSERVER_GAINS; ++j) {
        const double s = s_low + (s_high - s_low) * j / (BS_OBSERVER_GAINS - 1);
        linear_model m;
        if (model_at(file, model, 1, s, &m) != 0 || kalman_gain(&m, c, force_var, o, w, k_gain) != 0) {
            free(w);
            snprintf(err, err_size,
                     "observer design: the Riccati iteration failed at s = %.4f with measurement noise %g (a noise "
                     "this small leaves the gain ill-conditioned: state the sensor's noise, --noise or the file's "
                     "noise line)", s, o->noise);
            return -1;
        }
        gains->gain_s[j] = (bs_real)s;
        for (i = 0; i < n; ++i) {
            gains->gain_q[j][i] = (bs_real)k_gain[i];
            gains->gain_u[j][i] = (bs_real)k_gain[n + i];
        }
        gains->gain_v[j] = m.with_voltage ? (bs_real)k_gain[2 * n] : (bs_real)0;
    }
    free(w);
    return response_map(file, scene, o, gains, err, err_size);
}

/* x as BS_R(x) (out_c.h); a value that is not finite fails the header. */
static const char *literal(char text[OUT_C_REAL], double x, int *failed)
{
    *failed |= out_c_real(text, x) != 0;
    return text;
}

static int print_array(FILE *out, const char *name, const bs_real *values, int count)
{
    char text[OUT_C_REAL];
    int i, nonfinite = 0, failed = fprintf(out, "    /* %s */ {", name) < 0;
    for (i = 0; i < count; ++i)
        failed |= fprintf(out, "%s %s", i ? "," : "", literal(text, (double)values[i], &nonfinite)) < 0;
    return failed | nonfinite | (fprintf(out, " },\n") < 0);
}

/* A two-dimensional member: count rows of length values, stride apart. */
static int print_rows(FILE *out, const char *name, const bs_real *first, size_t stride, int count, int length)
{
    int j, failed = fprintf(out, "    /* %s */ {\n", name) < 0;
    for (j = 0; j < count; ++j)
        failed |= print_array(out, "", first + (size_t)j * stride, length);
    return failed | (fprintf(out, "    },\n") < 0);
}

int observer_print_gains(FILE *out, const bs_observer_gains *g, const char *name, const char *comment)
{
    char text[OUT_C_REAL], why[256];
    int failed = 0, nonfinite = 0;
    if (out_c_identifier_check(name, "name", why, sizeof why) != 0)
        return -1;
    failed |= fputs("/* ", out) < 0;
    failed |= out_c_comment_text(out, comment);
    failed |= fprintf(out, "\n * generated by `beamslider twin-gains`: the observer's constants "
                           "(core/include/bs_observer.h, docs/twin.md). */\n") < 0;
    snprintf(why, sizeof why, "%s carries %d response maps: compile with -DBS_OBSERVER_MAPS=%d or more", name,
             g->map_count, g->map_count);
    failed |= fprintf(out, "#include \"bs_observer.h\"\n\n#if BS_OBSERVER_MAPS < %d\n#error ", g->map_count) < 0;
    failed |= out_c_string(out, why);
    failed |= fprintf(out, "\n#endif\n\n") < 0;
    failed |= fprintf(out, "static const bs_observer_gains %s = {\n", name) < 0;
    failed |= fprintf(out, "    /* n_modes */ %d,\n    /* signal */ %d,\n    /* latency */ %d,\n", g->n_modes,
                      g->signal, g->latency) < 0;
    failed |= fprintf(out, "    /* noise */ %s,\n    /* gain_count */ %d,\n", literal(text, (double)g->noise, &nonfinite),
                      g->gain_count) < 0;
    failed |= nonfinite;
    failed |= print_array(out, "gain_s", g->gain_s, g->gain_count);
    failed |= print_rows(out, "gain_q", g->gain_q[0], BS_MAX_MODES, g->gain_count, g->n_modes);
    failed |= print_rows(out, "gain_u", g->gain_u[0], BS_MAX_MODES, g->gain_count, g->n_modes);
    failed |= print_array(out, "gain_v", g->gain_v, g->gain_count);
    failed |= fprintf(out, "    /* map_count */ %d,\n", g->map_count) < 0;
    failed |= print_array(out, "map_frequency", g->map_frequency, g->map_count);
    failed |= print_array(out, "map_accel", g->map_accel, g->map_count);
    failed |= print_array(out, "map_friction", g->map_friction, g->map_count);
    failed |= fprintf(out, "    /* table_count */ %d,\n", g->table_count) < 0;
    failed |= print_array(out, "table_s", g->table_s, g->table_count);
    failed |= print_rows(out, "table_stiff", g->table_stiff[0], BS_OBSERVER_TABLE, g->map_count, g->table_count);
    failed |= print_rows(out, "table_soft", g->table_soft[0], BS_OBSERVER_TABLE, g->map_count, g->table_count);
    failed |= fprintf(out, "};\n") < 0;
    return failed ? -1 : 0;
}
