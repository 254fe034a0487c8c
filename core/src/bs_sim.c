/* bs_sim.c - Moreau midpoint time-stepping of the beam-slider system.
 *
 * Coordinates q = (q_1..q_N, x_C, z_C, beta), M = diag(1..1, m, m, J_C),
 * smooth forces h = (-gamma w0'' - omega^2 q_b - 2 D omega u_b - N(q_b); m g_x; m g_z; 0).
 * One step from (t_B, q_B, u_B) with fixed dt (MODEL.md 5):
 *   1. t_M = t_B + dt/2,  q_M = q_B + dt/2 u_B,  h_M = h(t_M, q_M, u_B)
 *   2. u_free = u_B + M^-1 h_M dt
 *   3. contacts with g_N(q_M) < 0:  c = W^T u_free + w~ + diag(e_N, 0) (W^T u_B + w~),
 *      G = W^T M^-1 W;  solve xi = G P + c under the contact laws (bs_pgs.c)
 *   4. u_E = u_free + M^-1 W P,  q_E = q_M + dt/2 u_E,  t_E = t_B + dt
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
 * PCS model (MODEL.md 6): the contact kinematics use x_pcs instead of x_C;
 * x_C stays a free coordinate whose drift is the transport velocity. The clamp
 * stops act only in the free model.
 *
 * x_C moves by a few ulps of float per step; it is accumulated as an unevaluated
 * sum x_C + x_c_low (Knuth's TwoSum) so that float rounding does not bias the
 * slow drift (MODEL.md 9.2).
 *
 * Features a compiled scene leaves out (bs_config.h) drop out here: gravity,
 * restitution (no pre-step velocities needed), rotation (beta stays 0), PCS.
 */
#include "beamslider.h"
#include "bs_beam.h"
#include "bs_contact.h"
#include "bs_excitation.h"
#include "bs_pgs.h"
#include "bs_shape.h"

/* sum + low += increment, exactly up to the rounding of the new low part. */
static void add_compensated(bs_real *sum, bs_real *low, bs_real increment)
{
    const bs_real b = increment + *low;
    const bs_real s = *sum + b;
    const bs_real b_virtual = s - *sum;
    *low = (*sum - (s - b_virtual)) + (b - b_virtual);
    *sum = s;
}

static void clear_percussions(bs_sim *sim)
{
    int k, r;
    for (k = 0; k < BS_MAX_CONTACTS; ++k)
        for (r = 0; r < BS_ROWS; ++r)
            sim->percussion[k][r] = BS_R(0.0);
}

bs_status bs_sim_init(bs_sim *sim, const bs_scene *scene, bs_model model, bs_real s0)
{
    bs_status status;
    int i;

    if (!sim || !scene)
        return BS_E_NULL;
    status = bs_scene_check(scene, 0);
    if (status != BS_OK)
        return status;
    if (model != BS_MODEL_FREE && (model != BS_MODEL_PCS || !BS_WITH_PCS))
        return BS_E_ARGUMENT;
    if (model == BS_MODEL_FREE
            ? !(s0 * scene->length >= scene->stop_min && s0 * scene->length <= scene->stop_max)
            : !(s0 >= BS_R(0.0) && s0 <= BS_R(1.0)))
        return BS_E_ARGUMENT;

    sim->scene = scene;
    sim->model = model;
    sim->x_pcs = s0 * scene->length;
    sim->step = 0;
    sim->phase = 0;
    for (i = 0; i < BS_MAX_MODES; ++i) {
        sim->q_beam[i] = BS_R(0.0);
        sim->u_beam[i] = BS_R(0.0);
    }
    /* slot centred on the beam axis, which sits at w0(0) */
    sim->slider[0] = s0 * scene->length;
    sim->slider[1] = -scene->com_offset + scene->base_displacement;
    sim->slider[2] = BS_R(0.0);
    for (i = 0; i < 3; ++i)
        sim->slider_velocity[i] = BS_R(0.0);
    sim->x_c_low = BS_R(0.0);
    clear_percussions(sim);
    sim->report.active = 0;
    sim->report.sweeps = 0;
    sim->report.residual = BS_R(0.0);
    sim->report.converged = 1;
    sim->contacts.count = 0;
    bs_shape_bounds(scene, &sim->shape_bound);
    return BS_OK;
}

bs_status bs_sim_set_pcs_position(bs_sim *sim, bs_real s)
{
    if (!sim)
        return BS_E_NULL;
    if (sim->model != BS_MODEL_PCS || !(s >= BS_R(0.0) && s <= BS_R(1.0)))
        return BS_E_ARGUMENT;
    sim->x_pcs = s * sim->scene->length;
    return BS_OK;
}

/* Contact solve of step 3; updates u_beam, u_slider (free velocities on entry). */
static void solve_contacts(bs_sim *sim, const bs_real base_term[BS_MAX_CONTACTS][BS_ROWS],
                           bs_real *u_beam, bs_real *u_slider)
{
    const bs_scene *scene = sim->scene;
    bs_contact_set *set = &sim->contacts;
    bs_pgs_result result;
    int a, r;

    bs_contact_free_velocity(scene, set, u_beam, u_slider, sim->u_beam, sim->slider_velocity, base_term);
    for (a = 0; a < set->count; ++a) /* warm start */
        for (r = 0; r < BS_ROWS; ++r)
            set->percussion[BS_ROWS * a + r] = sim->percussion[set->id[a]][r];
    bs_contact_delassus(scene, set);
    result = bs_pgs_solve(set, scene->pgs_max_sweeps, scene->pgs_tol_rel, scene->pgs_tol_abs);
    bs_contact_apply(scene, set, u_beam, u_slider);
    sim->report.sweeps = result.sweeps;
    sim->report.residual = result.residual;
    sim->report.converged = result.converged;
}

bs_status bs_sim_step(bs_sim *sim)
{
    const bs_scene *scene;
    bs_real dt, half, stiffness;
    bs_real q_mid[BS_MAX_MODES];
    bs_real force[BS_MAX_MODES];
    bs_real u_beam[BS_MAX_MODES];
    bs_real slider_mid[3];
    bs_real u_slider[3];
    bs_real base_term[BS_MAX_CONTACTS][BS_ROWS];
    bs_real x_new, x_low_new, check;
    bs_contact_frame frame;
    unsigned active = 0;
    int n, k, a, r;

    if (!sim || !sim->scene)
        return BS_E_NULL;
    scene = sim->scene;
    n = BS_NMODES(scene);
    dt = scene->dt;
    half = BS_R(0.5) * dt;

    /* 1. midpoint */
    frame.base = bs_excitation_at(scene, sim->phase + scene->phase_step_half);
    for (k = 0; k < n; ++k)
        q_mid[k] = sim->q_beam[k] + half * sim->u_beam[k];
    for (k = 0; k < 3; ++k)
        slider_mid[k] = sim->slider[k] + half * sim->slider_velocity[k];
#if BS_WITH_IMPLICIT
    if (scene->implicit) {
        /* linear stiffness at q + theta dt u (theta = 1/2: the midpoint); the
         * explicit remainder is the cubic term alone */
        bs_real q_stiff[BS_MAX_MODES];
        for (k = 0; k < n; ++k)
            q_stiff[k] = sim->q_beam[k] + scene->theta * dt * sim->u_beam[k];
        stiffness = bs_beam_force(scene, q_mid, q_stiff, sim->u_beam, frame.base.acceleration, 0, force);
    } else
#endif
        stiffness = bs_beam_force(scene, q_mid, q_mid, sim->u_beam, frame.base.acceleration, 1, force);
    if (!(stiffness * dt * dt < BS_R(4.0)))
        return BS_E_UNSTABLE;

    /* 2. smooth velocity update */
    for (k = 0; k < n; ++k)
#if BS_WITH_IMPLICIT
        u_beam[k] = sim->u_beam[k] + dt * scene->mode_gain[k] * force[k];
#else
        u_beam[k] = sim->u_beam[k] + dt * force[k];
#endif
    for (k = 0; k < 3; ++k)
        u_slider[k] = sim->slider_velocity[k];
#if BS_WITH_GRAVITY
    u_slider[0] += dt * scene->gravity[0];
    u_slider[1] += dt * scene->gravity[1];
#endif

    /* 3. contacts at the midpoint */
    frame.q_beam = q_mid;
    frame.x_kinematic = BS_WITH_PCS && sim->model == BS_MODEL_PCS ? sim->x_pcs : slider_mid[0];
    frame.x_stops = slider_mid[0];
    frame.z = slider_mid[1];
    frame.beta = slider_mid[2];
    frame.stops = sim->model == BS_MODEL_FREE;
    frame.shape_bound = &sim->shape_bound;
    bs_contact_detect(scene, &frame, &sim->contacts, base_term);
    sim->report.sweeps = 0;
    sim->report.residual = BS_R(0.0);
    sim->report.converged = 1;
    if (sim->contacts.count > 0)
        solve_contacts(sim, base_term, u_beam, u_slider);

    /* 4. end of step; nothing is committed unless every value is finite */
    check = BS_R(0.0);
    for (k = 0; k < n; ++k) {
#if BS_WITH_IMPLICIT
        if (scene->implicit) /* q_E = q_B + dt ((1 - theta) u_B + theta u_E) */
            q_mid[k] = sim->q_beam[k] + dt * ((BS_R(1.0) - scene->theta) * sim->u_beam[k] + scene->theta * u_beam[k]);
        else
#endif
            q_mid[k] += half * u_beam[k];
        check += q_mid[k] + u_beam[k];
    }
    x_new = sim->slider[0];
    x_low_new = sim->x_c_low;
    add_compensated(&x_new, &x_low_new, half * (sim->slider_velocity[0] + u_slider[0]));
    slider_mid[1] += half * u_slider[1];
    slider_mid[2] += half * u_slider[2];
    check += x_new + slider_mid[1] + slider_mid[2] + u_slider[0] + u_slider[1] + u_slider[2];
    if (check - check != BS_R(0.0))
        return BS_E_NONFINITE;

    for (k = 0; k < n; ++k) {
        sim->q_beam[k] = q_mid[k];
        sim->u_beam[k] = u_beam[k];
    }
    sim->slider[0] = x_new;
    sim->x_c_low = x_low_new;
    sim->slider[1] = slider_mid[1];
    sim->slider[2] = slider_mid[2];
    for (k = 0; k < 3; ++k)
        sim->slider_velocity[k] = u_slider[k];
    clear_percussions(sim);
    for (a = 0; a < sim->contacts.count; ++a) {
        const int id = sim->contacts.id[a];
        active |= 1u << id;
        for (r = 0; r < BS_ROWS; ++r)
            sim->percussion[id][r] = sim->contacts.percussion[BS_ROWS * a + r];
    }
    sim->report.active = active;
    sim->step += 1;
    sim->phase += 2 * scene->phase_step_half;
    return BS_OK;
}

const bs_step_report *bs_sim_report(const bs_sim *sim)
{
    return &sim->report;
}

bs_real bs_sim_sensor(const bs_sim *sim)
{
    bs_real w = BS_R(0.0);
    int k;
    for (k = 0; k < BS_NMODES(sim->scene); ++k)
        w += sim->scene->phi_sensor[k] * sim->q_beam[k];
    return w;
}

bs_real bs_sim_position(const bs_sim *sim)
{
    return (sim->slider[0] + sim->x_c_low) / sim->scene->length;
}

void bs_sim_get_state(const bs_sim *sim, bs_real *q_beam, bs_real *u_beam, bs_real *slider,
                      bs_real *slider_velocity)
{
    int k;
    for (k = 0; k < sim->scene->n_modes; ++k) {
        if (q_beam)
            q_beam[k] = sim->q_beam[k];
        if (u_beam)
            u_beam[k] = sim->u_beam[k];
    }
    for (k = 0; k < 3; ++k) {
        if (slider)
            slider[k] = k == 0 ? sim->slider[0] + sim->x_c_low : sim->slider[k];
        if (slider_velocity)
            slider_velocity[k] = sim->slider_velocity[k];
    }
}

static int all_finite(const bs_real *values, int count)
{
    int k;
    for (k = 0; values && k < count; ++k)
        if (values[k] - values[k] != BS_R(0.0))
            return 0;
    return 1;
}

bs_status bs_sim_set_state(bs_sim *sim, const bs_real *q_beam, const bs_real *u_beam,
                           const bs_real *slider, const bs_real *slider_velocity)
{
    int k;

    if (!sim || !sim->scene)
        return BS_E_NULL;
    if (!all_finite(q_beam, sim->scene->n_modes) || !all_finite(u_beam, sim->scene->n_modes)
        || !all_finite(slider, 3) || !all_finite(slider_velocity, 3))
        return BS_E_ARGUMENT;
    if (slider && sim->model == BS_MODEL_FREE
        && !(slider[0] >= sim->scene->stop_min && slider[0] <= sim->scene->stop_max))
        return BS_E_ARGUMENT;
    for (k = 0; k < sim->scene->n_modes; ++k) {
        if (q_beam)
            sim->q_beam[k] = q_beam[k];
        if (u_beam)
            sim->u_beam[k] = u_beam[k];
    }
    for (k = 0; k < 3; ++k) {
        if (slider)
            sim->slider[k] = slider[k];
        if (slider_velocity)
            sim->slider_velocity[k] = slider_velocity[k];
    }
    if (slider)
        sim->x_c_low = BS_R(0.0);
    clear_percussions(sim);
    return BS_OK;
}

bs_real bs_sim_phase(const bs_sim *sim)
{
    return (bs_real)(uint32_t)(sim->phase >> 40) * BS_R(5.9604644775390625e-08); /* 2^-24 */
}

static uint32_t hash_bytes(uint32_t hash, const void *data, unsigned long size)
{
    const unsigned char *byte = (const unsigned char *)data;
    unsigned long i;
    for (i = 0; i < size; ++i) {
        hash ^= byte[i];
        hash *= 16777619u;
    }
    return hash;
}

uint32_t bs_sim_hash(const bs_sim *sim)
{
    const int n = sim->scene->n_modes;
    uint32_t hash = 2166136261u;
    hash = hash_bytes(hash, &sim->step, sizeof sim->step);
    hash = hash_bytes(hash, &sim->phase, sizeof sim->phase);
    hash = hash_bytes(hash, sim->q_beam, (unsigned long)n * sizeof(bs_real));
    hash = hash_bytes(hash, sim->u_beam, (unsigned long)n * sizeof(bs_real));
    hash = hash_bytes(hash, sim->slider, sizeof sim->slider);
    hash = hash_bytes(hash, sim->slider_velocity, sizeof sim->slider_velocity);
    hash = hash_bytes(hash, &sim->x_c_low, sizeof sim->x_c_low);
    hash = hash_bytes(hash, sim->percussion, sizeof sim->percussion);
    return hash;
}

const char *bs_status_text(bs_status status)
{
    switch (status) {
    case BS_OK: return "ok";
    case BS_E_NULL: return "null pointer";
    case BS_E_SCENE: return "scene field out of range";
    case BS_E_ARGUMENT: return "argument out of range";
    case BS_E_UNSTABLE: return "stability limit omega*dt < 2 of the explicitly integrated stiffness violated";
    case BS_E_NONFINITE: return "state became NaN or infinite";
    }
    return "unknown status";
}
