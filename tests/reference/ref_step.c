/* ref_step.c - Moreau midpoint time-stepping (docs/model.md 5), fixed step dt.
 *
 *   t_M = t_B + dt/2,  q_M = q_B + dt/2 u_B,  h_M = h(t_M, q_M, u_B)
 *   closed set: g_N,i(q_M) < 0 (corners and end stops)
 *   none:       u_E = u_B + M^-1 h_M dt
 *   otherwise:  W, w~ at (t_M, q_M);  G = W^T M^-1 W
 *               c = (I + eps)(W^T u_B + w~) + W^T M^-1 h_M dt,  eps = diag(e_N, 0, ...)
 *               xi = G P + c, P from the contact laws (ref_lcp.c)
 *               u_E = u_B + M^-1 (h_M dt + W P)
 *   q_E = q_M + dt/2 u_E,  t_E = t_B + dt  (t from the step count, never summed)
 *   Warm start: each contact's percussion and mode of the previous step.
 *   options->compliance (diagnostic, default 0: docs/model.md has none) replaces
 *   G_ii by G_ii (1 + compliance), to reproduce a regularised solver. */
#include "ref_step.h"

#include <math.h>
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
    ref_excitation ex;
    int i;

    ref_scene_excitation(scene, 0.0L, &ex);
    state->step = 0;
    for (i = 0; i < REF_MAX_Q; ++i)
        state->q[i] = state->u[i] = 0.0;
    state->q[scene->i_x] = (scene->model == REF_MODEL_PCS ? scene->s_pcs : scene->s0) * scene->length;
    state->q[scene->i_z] = -scene->com_offset + ex.w0;
    state->q[scene->i_beta] = 0.0;
    for (i = 0; i < REF_MAX_CONTACTS; ++i) {
        state->percussion[i][0] = state->percussion[i][1] = 0.0;
        state->mode[i] = REF_TAKEOFF;
        state->active[i] = 0;
    }
}

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

/* Builds and solves the contact problem; adds M^-1 W P to u_E. */
static int contact_impulse(const ref_scene *scene, const ref_step_options *options, ref_state *state,
                           const ref_contact *contacts, int n, const double *minv_h, double *u_e,
                           ref_step_report *report)
{
    static ref_lcp lcp; /* static: the reference runs one step at a time */
    double w[REF_MAX_ROWS][REF_MAX_Q], minv_w[REF_MAX_ROWS][REF_MAX_Q];
    double percussion[REF_MAX_ROWS], restitution[REF_MAX_ROWS], w_tilde[REF_MAX_ROWS];
    int dim[REF_MAX_CONTACTS];
    double mu[REF_MAX_CONTACTS];
    ref_mode mode[REF_MAX_CONTACTS];
    ref_lcp_info info;
    const double dt = scene->dt_sub;
    int i, r, s, k, status;

    for (i = 0; i < n; ++i) {
        dim[i] = contacts[i].dim;
        mu[i] = contacts[i].mu;
    }
    ref_lcp_layout(&lcp, n, dim, mu);
    for (i = 0; i < n; ++i) {
        const ref_contact *c = &contacts[i];
        const int id = c->id;
        for (s = 0; s < c->dim; ++s) {
            r = lcp.row[i] + s;
            for (k = 0; k < scene->n_q; ++k)
                w[r][k] = c->dir[s][k];
            w_tilde[r] = c->w_tilde[s];
            restitution[r] = s == 0 ? c->e_n : 0.0;
            percussion[r] = state->active[id] ? state->percussion[id][s] : 0.0;
        }
        mode[i] = state->active[id] ? state->mode[id] : REF_STICK;
    }
    for (r = 0; r < lcp.rows; ++r)
        mass_inverse_times(scene, w[r], minv_w[r]);
    for (r = 0; r < lcp.rows; ++r) {
        double gamma_minus = w_tilde[r], force = 0.0;
        for (s = 0; s < lcp.rows; ++s) {
            double sum = 0.0;
            for (k = 0; k < scene->n_q; ++k)
                sum += w[r][k] * minv_w[s][k];
            lcp.g[r][s] = sum;
        }
        for (k = 0; k < scene->n_q; ++k) {
            gamma_minus += w[r][k] * state->u[k];
            force += w[r][k] * minv_h[k];
        }
        lcp.c[r] = (1.0 + restitution[r]) * gamma_minus + force * dt;
    }
    for (r = 0; r < lcp.rows; ++r)
        lcp.g[r][r] *= 1.0 + options->compliance;
    if (options->solver == REF_SOLVER_PGS)
        status = ref_lcp_pgs(&lcp, percussion, options->pgs_tol_rel, options->pgs_max_sweeps, &info);
    else
        status = ref_lcp_enumerate(&lcp, percussion, mode, options->exhaustive, &info);
    report->iterations = info.iterations;
    report->residual = info.residual;
    report->residual_rel = info.residual_rel;
    report->converged = info.converged;
    report->exhaustive = info.exhaustive;
    report->ambiguous = info.ambiguous;
    for (r = 0; r < lcp.rows; ++r)
        for (k = 0; k < scene->n_q; ++k)
            u_e[k] += minv_w[r][k] * percussion[r];
    for (i = 0; i < n; ++i) {
        const int id = contacts[i].id;
        state->active[id] = 1;
        state->percussion[id][0] = percussion[lcp.row[i]];
        state->percussion[id][1] = contacts[i].dim == 2 ? percussion[lcp.row[i] + 1] : 0.0;
        state->mode[id] = mode[i];
    }
    return status;
}

int ref_step(const ref_scene *scene, const ref_step_options *options, ref_state *state, ref_step_report *report)
{
    static ref_contact contacts[REF_MAX_CONTACTS];
    const double dt = scene->dt_sub;
    double q_m[REF_MAX_Q], h[REF_MAX_Q], minv_h[REF_MAX_Q], u_e[REF_MAX_Q];
    int seen[REF_MAX_CONTACTS];
    ref_excitation ex;
    int n, i, k, status = 0;

    ref_scene_excitation(scene, ref_scene_time(scene, 2 * state->step + 1), &ex);
    for (k = 0; k < scene->n_q; ++k)
        q_m[k] = state->q[k] + 0.5 * dt * state->u[k];
    ref_dynamics_force(scene, &ex, q_m, state->u, h);
    mass_inverse_times(scene, h, minv_h);
    for (k = 0; k < scene->n_q; ++k)
        u_e[k] = state->u[k] + minv_h[k] * dt;

    n = ref_kinematics_closed(scene, &ex, q_m, contacts);
    report->active = n;
    report->mask = 0;
    for (i = 0; i < n; ++i)
        report->mask |= 1u << contacts[i].id;
    report->iterations = 0;
    report->residual = report->residual_rel = 0.0;
    report->converged = 1;
    report->exhaustive = report->ambiguous = 0;
    if (n > 0)
        status = contact_impulse(scene, options, state, contacts, n, minv_h, u_e, report);
    for (i = 0; i < REF_MAX_CONTACTS; ++i)
        seen[i] = 0;
    for (i = 0; i < n; ++i)
        seen[contacts[i].id] = 1;
    for (i = 0; i < REF_MAX_CONTACTS; ++i)
        if (!seen[i])
            state->active[i] = 0;

    for (k = 0; k < scene->n_q; ++k) {
        state->u[k] = u_e[k];
        state->q[k] = q_m[k] + 0.5 * dt * u_e[k];
        if (!isfinite(state->q[k]) || !isfinite(state->u[k]))
            status = -1;
    }
    ++state->step;
    return status;
}
