/* bs_step.c - one Moreau midpoint time step of the beam-slider system.
 *
 * Coordinates q = (q_1..q_N, x_C, z_C, beta), M = diag(1..1, m, m, J_C),
 * smooth forces h = (-gamma w0'' - omega^2 q_b - 2 D omega u_b - N(q_b); m g_x; m g_z; 0).
 * One step from (t_B, q_B, u_B) with fixed dt (docs/model.md 5), in the stages
 * of bs_sim_step below:
 *   1. midpoint:        t_M = t_B + dt/2,  q_M = q_B + dt/2 u_B,  h_M = h(t_M, q_M, u_B)
 *   2. smooth velocity: u_free = u_B + M^-1 h_M dt
 *   3. contacts:        those with g_N(q_M) < 0;  c = W^T u_free + w~ + diag(e_N, 0) (W^T u_B + w~),
 *                       G = W^T M^-1 W;  solve xi = G P + c under the contact laws (bs_pgs.c);
 *                       u_E = u_free + M^-1 W P
 *   4. end of step:     q_E = q_M + dt/2 u_E,  t_E = t_B + dt; committed only if finite and
 *                       on the beam
 * The smooth part is explicit (leapfrog): stable while omega_max dt < 2, with
 * omega_max including the cubic stiffening (checked every step).
 *
 * Linearly implicit variant (scene->implicit; theta in [1/2, 1]): the modal
 * stiffness K and damping C act on the end-of-step state (Moreau-Jean theta
 * method); with the cubic term and the excitation F explicit at the midpoint,
 *   M^ = I + theta dt C + theta^2 dt^2 K  (diagonal: mode_gain = 1 / M^)
 *   u_free = u_B + M^-1 dt (F - C u_B - K (q_B + theta dt u_B))
 *   u_E = u_free + M^-1 W P,   q_E = q_B + dt ((1 - theta) u_B + theta u_E)
 * The linear part is then unconditionally stable (theta = 1/2: trapezoidal,
 * no numerical damping; theta > 1/2 damps high modes); with M^ = I and
 * theta = 1/2 it is the explicit step above.
 *
 * PCS model (docs/model.md 6): the contact kinematics use x_pcs instead of
 * x_C; x_C stays a free coordinate whose drift is the transport velocity. The
 * clamp stops act only in the free model.
 *
 * x_C moves by a few ulps of float per step; it is accumulated as an unevaluated
 * sum x_C + x_c_low (Knuth's TwoSum) so that float rounding does not bias the
 * slow drift (docs/model.md 9.2).
 *
 * Features a compiled scene leaves out (bs_config.h) drop out here: gravity,
 * restitution (no pre-step velocities needed), rotation (beta stays 0), PCS.
 */
#include "bs_beam.h"
#include "bs_contact.h"
#include "bs_excitation.h"
#include "bs_pgs.h"
#include "bs_sim_internal.h"

/* The step under way: stage results not yet committed to the sim. */
typedef struct step_state {
    bs_real q[BS_MAX_MODES];           /* q_M, then q_E */
    bs_real u_beam[BS_MAX_MODES];      /* u_free, then u_E */
    bs_real slider[3];                 /* slider pose at the midpoint, then at the end */
    bs_real u_slider[3];
    bs_real x_end, x_end_low;          /* compensated x_C at the end */
    bs_real base_term[BS_MAX_CONTACTS][BS_ROWS]; /* w~ of each active contact */
    bs_base base;                      /* base motion at t_M */
} step_state;

/* sum + low += increment, exactly up to the rounding of the new low part. */
static void add_compensated(bs_real *sum, bs_real *low, bs_real increment)
{
    const bs_real b = increment + *low;
    const bs_real s = *sum + b;
    const bs_real b_virtual = s - *sum;
    *low = (*sum - (s - b_virtual)) + (b - b_virtual);
    *sum = s;
}

/* 1 and 2: midpoint configuration, smooth forces there and the free
 * velocities; BS_E_UNSTABLE if the explicit stiffness exceeds its limit. */
static bs_status smooth_part(const bs_sim *sim, step_state *s)
{
    const bs_scene *scene = sim->scene;
    const int n = BS_NMODES(scene);
    const bs_real dt = scene->dt;
    const bs_real half = BS_R(0.5) * dt;
    bs_real force[BS_MAX_MODES];
    bs_real stiffness;
    int k;

    s->base = bs_excitation_at(scene, sim->phase + scene->phase_step_half);
    for (k = 0; k < n; ++k)
        s->q[k] = sim->q_beam[k] + half * sim->u_beam[k];
    for (k = 0; k < 3; ++k)
        s->slider[k] = sim->slider[k] + half * sim->slider_velocity[k];
#if BS_WITH_IMPLICIT
    if (scene->implicit) {
        /* linear stiffness at q + theta dt u (theta = 1/2: the midpoint); the
         * explicit remainder is the cubic term alone */
        bs_real q_stiff[BS_MAX_MODES];
        for (k = 0; k < n; ++k)
            q_stiff[k] = sim->q_beam[k] + scene->theta * dt * sim->u_beam[k];
        stiffness = bs_beam_force(scene, sim->stretch_rows, s->q, q_stiff, sim->u_beam, s->base.acceleration, 0,
                                  force);
    } else
#endif
        stiffness = bs_beam_force(scene, sim->stretch_rows, s->q, s->q, sim->u_beam, s->base.acceleration, 1, force);
    if (!(stiffness * dt * dt < BS_R(4.0)))
        return BS_E_UNSTABLE;

    for (k = 0; k < n; ++k)
#if BS_WITH_IMPLICIT
        s->u_beam[k] = sim->u_beam[k] + dt * scene->mode_gain[k] * force[k];
#else
        s->u_beam[k] = sim->u_beam[k] + dt * force[k];
#endif
    for (k = 0; k < 3; ++k)
        s->u_slider[k] = sim->slider_velocity[k];
#if BS_WITH_GRAVITY
    s->u_slider[0] += dt * scene->gravity[0];
    s->u_slider[1] += dt * scene->gravity[1];
#endif
    return BS_OK;
}

/* 3a: the contacts active at the midpoint, into sim->contacts;
 * BS_E_ESCAPED if a slot corner is past the beam's axis. */
static bs_status find_contacts(bs_sim *sim, step_state *s)
{
    bs_contact_frame frame;
    frame.q_beam = s->q;
    frame.x_kinematic = BS_WITH_PCS && sim->model == BS_MODEL_PCS ? sim->x_pcs : s->slider[0];
    frame.x_stops = s->slider[0];
    frame.z = s->slider[1];
    frame.beta = s->slider[2];
    frame.stops = sim->model == BS_MODEL_FREE;
    frame.base = s->base;
    frame.cache = sim->side;
    frame.reach = sim->shape_reach;
    return bs_contact_detect(sim->scene, &frame, &sim->contacts, s->base_term);
}

/* 3b: the contact problem, warm-started from the last step's percussions;
 * adds M^-1 W P to the free velocities. */
static void solve_contacts(bs_sim *sim, step_state *s)
{
    const bs_scene *scene = sim->scene;
    bs_contact_set *set = &sim->contacts;
    int a, r;

    bs_contact_free_velocity(scene, set, s->u_beam, s->u_slider, sim->u_beam, sim->slider_velocity,
                             s->base_term);
    for (a = 0; a < set->count; ++a)
        for (r = 0; r < BS_ROWS; ++r)
            set->percussion[BS_ROWS * a + r] = sim->percussion[set->id[a]][r];
    bs_contact_delassus(scene, set);
    bs_pgs_solve(set, &sim->solver, &sim->report);
    bs_contact_apply(scene, set, s->u_beam, s->u_slider);
}

/* 4: the end-of-step configuration; BS_E_NONFINITE or BS_E_ESCAPED if it
 * must not be committed. */
static bs_status end_of_step(const bs_sim *sim, step_state *s)
{
    const bs_scene *scene = sim->scene;
    const int n = BS_NMODES(scene);
    const bs_real dt = scene->dt;
    const bs_real half = BS_R(0.5) * dt;
    bs_real check = BS_R(0.0);
    int k;

    for (k = 0; k < n; ++k) {
#if BS_WITH_IMPLICIT
        if (scene->implicit) /* q_E = q_B + dt ((1 - theta) u_B + theta u_E) */
            s->q[k] = sim->q_beam[k] + dt * ((BS_R(1.0) - scene->theta) * sim->u_beam[k] + scene->theta * s->u_beam[k]);
        else
#endif
            s->q[k] += half * s->u_beam[k];
        check += s->q[k] + s->u_beam[k];
    }
    s->x_end = sim->slider[0];
    s->x_end_low = sim->x_c_low;
    add_compensated(&s->x_end, &s->x_end_low, half * (sim->slider_velocity[0] + s->u_slider[0]));
    s->slider[1] += half * s->u_slider[1];
    s->slider[2] += half * s->u_slider[2];
    check += s->x_end + s->slider[1] + s->slider[2] + s->u_slider[0] + s->u_slider[1] + s->u_slider[2];
    if (check - check != BS_R(0.0))
        return BS_E_NONFINITE;
    if (sim->model == BS_MODEL_FREE && !bs_within_stops(scene, s->x_end))
        return BS_E_ESCAPED;
    return BS_OK;
}

/* The step's result becomes the sim's state. */
static void commit(bs_sim *sim, const step_state *s)
{
    const int n = BS_NMODES(sim->scene);
    unsigned active = 0;
    int a, k, r;

    for (k = 0; k < n; ++k) {
        sim->q_beam[k] = s->q[k];
        sim->u_beam[k] = s->u_beam[k];
    }
    sim->slider[0] = s->x_end;
    sim->x_c_low = s->x_end_low;
    sim->slider[1] = s->slider[1];
    sim->slider[2] = s->slider[2];
    for (k = 0; k < 3; ++k)
        sim->slider_velocity[k] = s->u_slider[k];
    for (k = 0; k < BS_MAX_CONTACTS; ++k)
        for (r = 0; r < BS_ROWS; ++r)
            sim->percussion[k][r] = BS_R(0.0);
    for (a = 0; a < sim->contacts.count; ++a) {
        const int id = sim->contacts.id[a];
        active |= 1u << id;
        for (r = 0; r < BS_ROWS; ++r)
            sim->percussion[id][r] = sim->contacts.percussion[BS_ROWS * a + r];
    }
    sim->report.active = active;
    sim->step += 1;
    sim->phase += 2 * sim->scene->phase_step_half;
}

bs_status bs_sim_step(bs_sim *sim)
{
    step_state s;
    bs_status status = bs_sim_status(sim);

    if (status != BS_OK)
        return status;
    status = smooth_part(sim, &s);
    if (status != BS_OK)
        return status;
    status = find_contacts(sim, &s);
    if (status != BS_OK)
        return status;
    sim->report.sweeps = 0;
    sim->report.systems = 0;
    sim->report.residual = BS_R(0.0);
    sim->report.converged = 1;
    if (sim->contacts.count > 0)
        solve_contacts(sim, &s);
    status = end_of_step(sim, &s);
    if (status != BS_OK)
        return status;
    commit(sim, &s);
    return BS_OK;
}
