/* ref_step.c - Moreau midpoint time-stepping (docs/model.md 5) in the base
 * frame (docs/model.md 10) with the piezoelectric transducer (docs/model.md 11).
 *
 * Symbols (-> variables): q = (q_b, x_C, z_r, beta) -> q, z_r = z_C - w0;
 * u -> u; a = (dw0(t_E) - dw0(t_B)) / dt, the step's mean base acceleration
 * -> base_accel; M~ -> scene->mass, M~^-1 -> scene->mass_inv; theta -> scene->theta;
 * v -> state->voltage; V_s -> state->storage_voltage; dt = dt_sub.
 *
 * Mechanics (docs/model.md 5, 10; w~ = 0 in the base frame):
 *   q_M = q_B + dt/2 u_B,  h_M = h(a, q_M, u_B)   (ref_dynamics.c: -gamma a on the
 *   modes, -m a on z_r); closed set: g_N,i(q_M) < 0 (corners and end stops)
 *   M (u_E - u_B) = h_M dt - theta dt mean(v) + W P + [bridge]
 *   q_E = q_M + dt/2 u_E,  t from the step count (never summed)
 *
 * Transducer (docs/model.md 11): the current the beam drives into the patch,
 * i = theta . u, is held constant over the step at its trapezoidal value
 * i = theta . (u_B + u_E)/2. Then the circuit is solved exactly over the step
 * and the patch's work on the beam, -dt mean(v) i, equals what the circuit
 * receives: no energy is made or lost in the coupling.
 *   resistor:  C_p v' + v/R_l = i:  v(s) = v_B e + R_l i (1 - e), e = e^(-s/tau), tau = R_l C_p
 *              mean v = kappa v_B + rise R_l i,  v_E = decay v_B + gain R_l i
 *              energy into R_l = dt/R_l mean(v^2) = dt/R_l (mean2 v_B^2 + 2 cross v_B R_l i + square (R_l i)^2)
 *              (factors: ref_circuit.h; exact for every R_l > 0, so no R_l destabilises the step)
 *   rectifier: full bridge of ideal diodes (drop V_f each, two conduct) into
 *              C_s with R_s across it; Q >= 0 the charge through the bridge in
 *              the step, sigma = +-1 the branch (the sign of the patch voltage):
 *              C_p (v_E - v_B) = dt i - sigma Q  (v linear: mean v = (v_B + v_E)/2,
 *              kappa = 1), V_sE = decay_s V_sB + gain_s R_s Q/dt (C_s V_s' + V_s/R_s = Q/dt),
 *              diode:  0 <= Q  _|_  V_sE + 2 V_f - sigma v_E >= 0   (at the step's end),
 *              energy into R_s = dt/R_s mean(V_s^2)
 *   Both: mean v = kappa v_B + (c/dt) theta . (u_B + u_E) - sigma Q / (2 C_p)
 *   with c = dt R_l rise / 2 (resistor), dt^2 / (4 C_p) (rectifier), so
 *     M~ (u_E - u_B) = f + W P + d Lambda,   M~ = M + c theta theta^T (ref_scene.c)
 *     f = h_M dt - theta (dt kappa v_B + 2 c theta . u_B),
 *     d = sigma theta, Lambda = dt Q / (2 C_p) [V s]: the bridge acts on the beam
 *     like a percussion Lambda along d (units of P, so the residual can mix them).
 *   u_free = u_B + M~^-1 f; u_E = u_free + M~^-1 (W P + d Lambda).
 *
 * The complementarity problem of the step: unknowns x = (P, Lambda), rows
 * xi = G x + c with, for contact rows (W_r, restitution e_r = e_N normal, 0 tangent)
 *   xi_r = W_r^T u_E + e_r W_r^T u_B:  G_rs = W_r^T M~^-1 D_s,  c_r = W_r^T u_free + e_r W_r^T u_B
 * and for the bridge row the reverse voltage scaled by 2 C_p / dt (amperes),
 *   xi_b = (2 C_p/dt)(V_sE + 2 V_f - sigma v_E)
 *        = (2 C_p/dt)(decay_s V_sB + 2 V_f - sigma v_B) - d . (u_B + u_E) + k_b Lambda,
 *   k_b = 4 C_p/dt^2 (1 + C_p R_s gain_s / dt):
 *     G_bs = -d^T M~^-1 D_s (+ k_b on the diagonal),  c_b = (2 C_p/dt)(...) - d . (u_B + u_free)
 * (D_s: W_s or d). G is not symmetric (the bridge is not a constraint of the
 * mechanics), but its symmetric part diag(W^T M~^-1 W, k_b - d^T M~^-1 d) is
 * positive semidefinite; the bridge is one more 1-row unilateral unknown of
 * ref_lcp.c (TAKEOFF = blocking, STICK = conducting). sigma is the sign of the
 * end voltage the step would reach without the bridge and the contacts; if the
 * other branch turns out to be forward biased (-sigma v_E > V_sE + 2 V_f), the
 * problem is solved again with -sigma (both cannot conduct at once).
 *
 * With load none no patch term is computed: the step is docs/model.md 5 in
 * the base frame exactly.
 * Warm start: each contact's percussion and mode of the previous step, the
 * bridge's likewise. options->compliance (diagnostic, default 0: docs/model.md
 * has none) replaces G_ii by G_ii (1 + compliance) on the contact rows. */
#include "ref_step.h"

#include <math.h>
#include "ref_circuit.h"
#include "ref_dynamics.h"
#include "ref_kinematics.h"

void ref_step_default_options(ref_step_options *options)
{
    options->solver = REF_SOLVER_ENUM;
    options->exhaustive = 0;
    options->pgs_tol_rel = 1e-13;
    options->pgs_max_sweeps = 100000000L;
    options->compliance = 0.0;
}

void ref_state_init(const ref_scene *scene, ref_state *state)
{
    int i;

    state->step = 0;
    for (i = 0; i < REF_MAX_Q; ++i)
        state->q[i] = state->u[i] = 0.0;
    state->q[scene->i_x] = (scene->model == REF_MODEL_PCS ? scene->s_pcs : scene->s0) * scene->length;
    state->q[scene->i_z] = -scene->com_offset;
    state->q[scene->i_beta] = 0.0;
    state->voltage = state->storage_voltage = state->load_energy = 0.0;
    for (i = 0; i < REF_MAX_CONTACTS; ++i) {
        state->percussion[i][0] = state->percussion[i][1] = 0.0;
        state->mode[i] = REF_TAKEOFF;
        state->active[i] = 0;
    }
    state->bridge_flux = 0.0;
    state->bridge_mode = REF_TAKEOFF;
}

/* M~^-1 v */
static void mass_inverse_times(const ref_scene *scene, const double *v, double *out)
{
    int i, j;
    for (i = 0; i < scene->n_q; ++i) {
        double sum = 0.0;
        for (j = 0; j < scene->n_q; ++j)
            sum += scene->mass_inv[i][j] * v[j];
        out[i] = sum;
    }
}

static double dot(int n, const double *a, const double *b)
{
    double sum = 0.0;
    int k;
    for (k = 0; k < n; ++k)
        sum += a[k] * b[k];
    return sum;
}

/* theta . u */
static double patch_current(const ref_scene *scene, const double *u)
{
    return dot(scene->n_q, scene->theta, u);
}

/* Adds M~^-1 (-theta (dt kappa v_B + 2 c theta . u_B)) to u_free: the part of
 * the patch's force known at the step's start (the rest is in M~). */
static void add_patch_impulse(const ref_scene *scene, const ref_state *state, double *u_free)
{
    const double dt = scene->dt_sub;
    const double magnitude = -(dt * scene->voltage_weight * state->voltage
                               + 2.0 * scene->implicit_mass * patch_current(scene, state->u));
    double impulse[REF_MAX_Q], change[REF_MAX_Q];
    int k;

    for (k = 0; k < scene->n_q; ++k)
        impulse[k] = magnitude * scene->theta[k];
    mass_inverse_times(scene, impulse, change);
    for (k = 0; k < scene->n_q; ++k)
        u_free[k] += change[k];
}

/* The step's complementarity problem in the making: one direction D_r (in q)
 * per row, and what the solve returns. */
typedef struct step_problem {
    ref_lcp lcp;
    int contacts;                         /* contact unknowns; the bridge, if any, is unknown [contacts] */
    int bridge;                           /* 1: the bridge takes part */
    int bridge_row;                       /* its row */
    double dir[REF_MAX_ROWS][REF_MAX_Q];  /* D_r: W_r (contacts) or d = sigma theta (bridge) */
    double minv_dir[REF_MAX_ROWS][REF_MAX_Q];
    double restitution[REF_MAX_ROWS];     /* e_r: e_N (normal), 0 (tangent), 1 (bridge: u_B + u_E) */
    double unknown[REF_MAX_ROWS];         /* P, Lambda: warm start in, solution out */
    ref_mode mode[REF_MAX_UNILATERAL];
} step_problem;

/* Layout and the contact rows' directions and warm start. */
static void stack_contacts(const ref_scene *scene, const ref_state *state, const ref_contact *contacts, int n,
                           int bridge, step_problem *sp)
{
    int dim[REF_MAX_UNILATERAL];
    double mu[REF_MAX_UNILATERAL];
    int i, s, k;

    for (i = 0; i < n; ++i) {
        dim[i] = contacts[i].dim;
        mu[i] = contacts[i].mu;
    }
    if (bridge) {
        dim[n] = 1;
        mu[n] = 0.0;
    }
    ref_lcp_layout(&sp->lcp, n + bridge, dim, mu);
    sp->contacts = n;
    sp->bridge = bridge;
    sp->bridge_row = bridge ? sp->lcp.row[n] : -1;
    for (i = 0; i < n; ++i) {
        const ref_contact *c = &contacts[i];
        for (s = 0; s < c->dim; ++s) {
            const int r = sp->lcp.row[i] + s;
            for (k = 0; k < scene->n_q; ++k)
                sp->dir[r][k] = c->dir[s][k];
            sp->restitution[r] = s == 0 ? c->e_n : 0.0;
            sp->unknown[r] = state->active[c->id] ? state->percussion[c->id][s] : 0.0;
            mass_inverse_times(scene, sp->dir[r], sp->minv_dir[r]);
        }
        sp->mode[i] = state->active[c->id] ? state->mode[c->id] : REF_STICK;
    }
}

/* The bridge's row for branch sigma: direction d = sigma theta, warm start. */
static void stack_bridge(const ref_scene *scene, const ref_state *state, int sigma, step_problem *sp)
{
    const int r = sp->bridge_row;
    int k;

    for (k = 0; k < scene->n_q; ++k)
        sp->dir[r][k] = (double)sigma * scene->theta[k];
    mass_inverse_times(scene, sp->dir[r], sp->minv_dir[r]);
    sp->restitution[r] = 1.0;
    sp->unknown[r] = state->bridge_flux;
    sp->mode[sp->contacts] = state->bridge_mode;
}

/* G and c of the stacked rows (see the top of the file). */
static void assemble(const ref_scene *scene, const ref_step_options *options, const ref_state *state,
                     const double *u_free, int sigma, step_problem *sp)
{
    ref_lcp *lcp = &sp->lcp;
    int r, s;

    for (r = 0; r < lcp->rows; ++r) {
        const double sign = r == sp->bridge_row ? -1.0 : 1.0;
        for (s = 0; s < lcp->rows; ++s)
            lcp->g[r][s] = sign * dot(scene->n_q, sp->dir[r], sp->minv_dir[s]);
        lcp->c[r] = sign * (dot(scene->n_q, sp->dir[r], u_free) + sp->restitution[r] * dot(scene->n_q, sp->dir[r], state->u));
        if (r != sp->bridge_row)
            lcp->g[r][r] *= 1.0 + options->compliance;
    }
    if (sp->bridge) {
        const double dt = scene->dt_sub, cp = scene->capacitance;
        const double scale = 2.0 * cp / dt;
        const double k_b = 4.0 * cp / (dt * dt)
                           * (1.0 + (double)((long double)cp * (long double)scene->storage_resistance
                                             * scene->storage.gain / (long double)dt));
        const double reverse = (double)(scene->storage.decay * (long double)state->storage_voltage)
                               + 2.0 * scene->diode_drop - (double)sigma * state->voltage;
        r = sp->bridge_row;
        lcp->g[r][r] += k_b;
        lcp->c[r] += scale * reverse;
    }
}

static int solve(const ref_step_options *options, step_problem *sp, ref_lcp_info *info)
{
    if (options->solver == REF_SOLVER_PGS)
        return ref_lcp_pgs(&sp->lcp, sp->unknown, options->pgs_tol_rel, options->pgs_max_sweeps, info);
    return ref_lcp_enumerate(&sp->lcp, sp->unknown, sp->mode, options->exhaustive, info);
}

/* u_E = u_free + sum_r M~^-1 D_r x_r */
static void end_velocity(const ref_scene *scene, const step_problem *sp, const double *u_free, double *u_e)
{
    int r, k;
    for (k = 0; k < scene->n_q; ++k)
        u_e[k] = u_free[k];
    for (r = 0; r < sp->lcp.rows; ++r)
        for (k = 0; k < scene->n_q; ++k)
            u_e[k] += sp->minv_dir[r][k] * sp->unknown[r];
}

/* Rectifier: v_E and V_sE for the bridge charge Q (u_E known). */
static void rectifier_end(const ref_scene *scene, const ref_state *state, const double *u_e, int sigma,
                          double charge, double *v_e, double *v_s_e)
{
    const double dt = scene->dt_sub;
    const double current = 0.5 * (patch_current(scene, state->u) + patch_current(scene, u_e));
    *v_e = state->voltage + (dt * current - (double)sigma * charge) / scene->capacitance;
    *v_s_e = (double)(scene->storage.decay * (long double)state->storage_voltage
                      + scene->storage.gain * (long double)scene->storage_resistance * (long double)charge
                            / (long double)dt);
}

/* The branch that may conduct: the sign of the end voltage without bridge and contacts. */
static int bridge_branch(const ref_scene *scene, const ref_state *state, const double *u_free)
{
    double v_e, v_s_e;
    rectifier_end(scene, state, u_free, 1, 0.0, &v_e, &v_s_e);
    if (v_e == 0.0)
        v_e = state->voltage;
    return v_e >= 0.0 ? 1 : -1;
}

static void copy_info(const ref_lcp_info *info, ref_step_report *report)
{
    report->solved = 1;
    report->iterations += info->iterations;
    report->residual = info->residual;
    report->residual_rel = info->residual_rel;
    report->converged = info->converged;
    report->exhaustive |= info->exhaustive;
    report->ambiguous |= info->ambiguous;
}

/* Solves the step's problem (contacts and, with a rectifier, the bridge) and
 * sets u_E; returns the solver's status. sigma receives the bridge's branch. */
static int solve_impulses(const ref_scene *scene, const ref_step_options *options, ref_state *state,
                          const ref_contact *contacts, int n, const double *u_free, double *u_e, int *sigma,
                          ref_step_report *report)
{
    static step_problem sp; /* static: the reference runs one step at a time */
    const int bridge = scene->load == REF_LOAD_RECTIFIER;
    ref_lcp_info info;
    int status, i;

    *sigma = bridge ? bridge_branch(scene, state, u_free) : 0;
    stack_contacts(scene, state, contacts, n, bridge, &sp);
    if (bridge)
        stack_bridge(scene, state, *sigma, &sp);
    assemble(scene, options, state, u_free, *sigma, &sp);
    status = solve(options, &sp, &info);
    copy_info(&info, report);
    end_velocity(scene, &sp, u_free, u_e);
    if (bridge && sp.unknown[sp.bridge_row] <= 0.0) {
        double v_e, v_s_e;
        rectifier_end(scene, state, u_e, *sigma, 0.0, &v_e, &v_s_e);
        if (-(double)*sigma * v_e > v_s_e + 2.0 * scene->diode_drop) { /* the other branch is forward biased */
            *sigma = -*sigma;
            stack_contacts(scene, state, contacts, n, bridge, &sp);
            stack_bridge(scene, state, *sigma, &sp);
            sp.mode[n] = REF_STICK;
            assemble(scene, options, state, u_free, *sigma, &sp);
            status = solve(options, &sp, &info);
            copy_info(&info, report);
            end_velocity(scene, &sp, u_free, u_e);
        }
    }

    report->contact_work = 0.0;
    for (i = 0; i < n; ++i) {
        const int r0 = sp.lcp.row[i], id = contacts[i].id;
        int s;
        for (s = 0; s < contacts[i].dim; ++s)
            report->contact_work += sp.unknown[r0 + s] * 0.5
                                    * (dot(scene->n_q, sp.dir[r0 + s], state->u) + dot(scene->n_q, sp.dir[r0 + s], u_e));
        state->active[id] = 1;
        state->percussion[id][0] = sp.unknown[r0];
        state->percussion[id][1] = contacts[i].dim == 2 ? sp.unknown[r0 + 1] : 0.0;
        state->mode[id] = sp.mode[i];
    }
    if (bridge) {
        state->bridge_flux = sp.unknown[sp.bridge_row];
        state->bridge_mode = sp.mode[n];
        report->bridge_charge = 2.0 * scene->capacitance * state->bridge_flux / scene->dt_sub;
    }
    return status;
}

/* The circuit over the step, once u_E is known: v_E, V_sE and the energy into the load. */
static void circuit_end(const ref_scene *scene, ref_state *state, const double *u_e, int sigma,
                        ref_step_report *report)
{
    const long double dt = scene->dt_sub;

    if (scene->load == REF_LOAD_RESISTOR) {
        const long double current = 0.5L * ((long double)patch_current(scene, state->u) + patch_current(scene, u_e));
        const long double r_l = scene->resistance, v_b = state->voltage;
        const long double rise = r_l * current; /* A = R_l i */
        report->load_energy = (double)(dt / r_l * ref_circuit_mean_square(&scene->patch, v_b, rise));
        state->voltage = (double)(scene->patch.decay * v_b + scene->patch.gain * rise);
    } else if (scene->load == REF_LOAD_RECTIFIER) {
        const long double r_s = scene->storage_resistance, v_s_b = state->storage_voltage;
        const long double target = r_s * (long double)report->bridge_charge / dt; /* A = R_s Q / dt */
        double v_e, v_s_e;
        report->load_energy = (double)(dt / r_s * ref_circuit_mean_square(&scene->storage, v_s_b, target));
        rectifier_end(scene, state, u_e, sigma, report->bridge_charge, &v_e, &v_s_e);
        state->voltage = v_e;
        state->storage_voltage = v_s_e;
        report->bridge_branch = sigma;
    }
    state->load_energy += report->load_energy;
}

static void report_init(double base_accel, ref_step_report *report)
{
    report->active = 0;
    report->mask = 0;
    report->solved = 0;
    report->iterations = 0;
    report->residual = report->residual_rel = 0.0;
    report->converged = 1;
    report->exhaustive = report->ambiguous = 0;
    report->base_accel = base_accel;
    report->contact_work = 0.0;
    report->load_energy = 0.0;
    report->bridge_charge = 0.0;
    report->bridge_branch = 0;
}

int ref_step_with_accel(const ref_scene *scene, const ref_step_options *options, double base_accel,
                        ref_state *state, ref_step_report *report)
{
    static ref_contact contacts[REF_MAX_CONTACTS];
    const double dt = scene->dt_sub;
    double q_m[REF_MAX_Q], h[REF_MAX_Q], minv_h[REF_MAX_Q], u_free[REF_MAX_Q], u_e[REF_MAX_Q];
    int seen[REF_MAX_CONTACTS];
    int n, i, k, sigma = 0, status = 0;

    report_init(base_accel, report);
    for (k = 0; k < scene->n_q; ++k)
        q_m[k] = state->q[k] + 0.5 * dt * state->u[k];
    ref_dynamics_force(scene, base_accel, q_m, state->u, h);
    mass_inverse_times(scene, h, minv_h);
    for (k = 0; k < scene->n_q; ++k)
        u_free[k] = state->u[k] + minv_h[k] * dt;
    if (scene->load != REF_LOAD_NONE)
        add_patch_impulse(scene, state, u_free);

    n = ref_kinematics_closed(scene, q_m, contacts);
    report->active = n;
    for (i = 0; i < n; ++i)
        report->mask |= 1u << contacts[i].id;
    if (n > 0 || scene->load == REF_LOAD_RECTIFIER)
        status = solve_impulses(scene, options, state, contacts, n, u_free, u_e, &sigma, report);
    else
        for (k = 0; k < scene->n_q; ++k)
            u_e[k] = u_free[k];
    for (i = 0; i < REF_MAX_CONTACTS; ++i)
        seen[i] = 0;
    for (i = 0; i < n; ++i)
        seen[contacts[i].id] = 1;
    for (i = 0; i < REF_MAX_CONTACTS; ++i)
        if (!seen[i])
            state->active[i] = 0;
    if (scene->load != REF_LOAD_NONE)
        circuit_end(scene, state, u_e, sigma, report);

    for (k = 0; k < scene->n_q; ++k) {
        state->u[k] = u_e[k];
        state->q[k] = q_m[k] + 0.5 * dt * u_e[k];
        if (!isfinite(state->q[k]) || !isfinite(state->u[k]))
            status = -1;
    }
    if (!isfinite(state->voltage) || !isfinite(state->storage_voltage))
        status = -1;
    ++state->step;
    return status;
}

int ref_step(const ref_scene *scene, const ref_step_options *options, ref_state *state, ref_step_report *report)
{
    return ref_step_with_accel(scene, options, ref_scene_step_accel(scene, state->step), state, report);
}
