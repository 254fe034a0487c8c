/* bs_step.c - one Moreau midpoint time step of the beam-slider system.
 *
 * Coordinates q = (q_1..q_N, x_C, z_r, beta), z_r = z_C - w0 the slot's height
 * relative to the base (docs/model.md 10), M = diag(1..1, m, m, J_C), smooth
 * forces h = (-gamma a_B - omega^2 q_b - 2 D omega u_b - N(q_b); m g_x; m (g_z - a_B); 0)
 * with a_B the mean base acceleration over the step: the harmonic excitation's
 * (bs_sim_step) or a measured one (bs_sim_step_measured). Nothing else of the
 * base motion enters: no base displacement, no base velocity, so nothing
 * integrates a measured acceleration.
 * One step from (t_B, q_B, u_B) with fixed dt (docs/model.md 5), in the stages
 * of step() below:
 *   1. midpoint:        t_M = t_B + dt/2,  q_M = q_B + dt/2 u_B,  h_M = h(q_M, u_B, a_B)
 *   2. smooth velocity: u_free = u_B + M^-1 h_M dt
 *   3. contacts:        those with g_N(q_M) < 0;  c = W^T u_free + diag(e_N, 0) W^T u_B,
 *                       G = W^T M^-1 W;  solve xi = G P + c under the contact laws (bs_pgs.c);
 *                       u_E = u_free + M^-1 W P
 *   4. end of step:     q_E = q_M + dt/2 u_E,  t_E = t_B + dt; committed only if finite and
 *                       on the beam
 * The smooth part is explicit (leapfrog): stable while omega_max dt < 2, with
 * omega_max including the cubic stiffening (checked every step, in O(1) when
 * far from the limit: core/src/bs_beam.c).
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
 * The step's cost should be its arithmetic (docs/design.md 4): the constants
 * come prepared in the sim (bs_prepare.c: pre-multiplied by dt, in RAM), the
 * state of the step is one local struct that the stages share and nothing
 * else writes until the commit, the contact rows are products of two shape
 * vectors formed once (bs_contact.c), one and two contacts are solved in
 * closed form (bs_pgs.c), and only what changed is written back.
 *
 * Features a compiled scene leaves out (bs_config.h) drop out here: gravity,
 * restitution (no pre-step velocities needed), rotation (beta stays 0), PCS.
 */
#include "bs_beam.h"
#include "bs_contact.h"
#include "bs_excitation.h"
#include "bs_inline.h"
#include "bs_pgs.h"
#include "bs_piezo.h"
#include "bs_sim_internal.h"

#include <stddef.h>

/* The step under way: stage results not yet committed to the sim. */
typedef struct step_state {
    bs_real q[BS_MAX_MODES];           /* q_M, then q_E */
    bs_real u_beam[BS_MAX_MODES];      /* u_free, then u_E */
    bs_real slider[3];                 /* slider pose at the midpoint, then at the end */
    bs_real u_slider[3];
    bs_real x_end, x_end_low;          /* compensated x_C at the end */
    bs_real base_accel;                /* mean base acceleration over the step */
#if BS_WITH_PIEZO
    bs_real voltage, storage;          /* patch and storage voltage at the midpoint, then at the end */
    bs_real power;                     /* into the load, at the midpoint */
#endif
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

/* The state a step starts from and the one it commits, q, u, the slider's
 * pose and velocity (n modes) and x_C's low part, lie one after the other in
 * the sim (bs_sim_layout.h): with five modes 17 words. On a Cortex-M4F with
 * float the step reads the first 16 with one vldm (bs_load_16) and writes all
 * 17 with one vstm (bs_store_state): 18 cycles each way, 32 and 34 with a vldr
 * or vstr a word (mid-fig6-float 2437.0 -> 2424.0 cycles a step, 2414.6 with
 * the store). Elsewhere member by member. BS_STATE_AS_BLOCK: bs_sim_internal.h. */
BS_INLINE void read_start(const bs_sim *sim, const int n, bs_real *q, bs_real *u, bs_real *pose, bs_real *velocity)
{
    int i;
#if BS_STATE_AS_BLOCK
    bs_real block[16];
    bs_load_16(sim->q_beam, block);
    for (i = 0; i < n; ++i) {
        q[i] = block[i];
        u[i] = block[BS_MAX_MODES + i];
    }
    for (i = 0; i < 3; ++i) {
        pose[i] = block[2 * BS_MAX_MODES + i];
        velocity[i] = block[2 * BS_MAX_MODES + 3 + i];
    }
#else
    for (i = 0; i < n; ++i) {
        q[i] = sim->q_beam[i];
        u[i] = sim->u_beam[i];
    }
    for (i = 0; i < 3; ++i) {
        pose[i] = sim->slider[i];
        velocity[i] = sim->slider_velocity[i];
    }
#endif
}

/* 1 and 2: midpoint configuration, smooth forces there and the free
 * velocities (the slider's from its velocity as read_start has it in
 * registers, not read again after the detection); BS_E_UNSTABLE if the
 * explicit stiffness exceeds its limit. */
BS_INLINE bs_status smooth_part(const bs_sim *sim, step_state *s, const int n)
{
    const bs_step_constants *k = &sim->k;
    const bs_real half = k->half_dt;
    const bs_real a = s->base_accel;
    bs_real q_start[BS_MAX_MODES], u_start[BS_MAX_MODES], pose[3], velocity[3]; /* read_start */
    bs_real sq[BS_MAX_MODES];  /* S' q_M (bs_beam.h) */
    bs_real energy = BS_R(0.0); /* E' = q_M^T S' q_M */
    bs_real piezo = BS_R(0.0);  /* dt theta_k v per unit theta_k */
    bs_real extra = BS_R(0.0);  /* the open patch's stiffness */
    int i;

    read_start(sim, n, q_start, u_start, pose, velocity);
    for (i = 0; i < n; ++i)
        s->q[i] = q_start[i] + half * u_start[i];
    for (i = 0; i < 3; ++i) {
        s->slider[i] = pose[i] + half * velocity[i];
        s->u_slider[i] = velocity[i];
    }
#if BS_WITH_GRAVITY
    s->u_slider[0] += k->dt_gravity[0];
    s->u_slider[1] += k->dt_gravity[1];
#endif
    s->u_slider[1] -= k->dt * a; /* the base frame's inertial force */
#if BS_WITH_STRETCHING
    energy = bs_beam_stretch(k, n, s->q, sq);
#else
    for (i = 0; i < n; ++i)
        sq[i] = BS_R(0.0);
#endif
#if BS_WITH_PIEZO
    if (sim->scene->load != BS_LOAD_NONE) { /* the patch to the midpoint; the beam feels its voltage there */
        s->voltage = sim->voltage;
        s->storage = sim->storage_voltage;
        bs_piezo_half_step(sim->scene, bs_piezo_current(sim->scene, sim->u_beam), &s->voltage, &s->storage);
        s->power = bs_piezo_power(sim->scene, s->voltage, s->storage);
        piezo = k->dt * s->voltage;
        extra = sim->piezo_stiffness;
    }
#endif
#if BS_WITH_IMPLICIT
    if (sim->scene->implicit) {
        /* linear stiffness at q_B + theta dt u_B; the explicit remainder is the cubic term alone */
        const bs_scene *scene = sim->scene;
#if BS_WITH_STRETCHING
        if (BS_UNLIKELY(!(energy >= BS_ZERO && energy < k->stretch_limit))
            && !bs_beam_stable(k, n, 0, sq, energy, extra))
            return BS_E_UNSTABLE;
#endif
        for (i = 0; i < n; ++i) {
            const bs_real q_stiff = q_start[i] + scene->theta * k->dt * u_start[i];
            s->u_beam[i] = u_start[i] + scene->mode_gain[i] * (-k->dt_gamma[i] * a - k->dt_omega_sq[i] * q_stiff
                                                                - k->dt_damping[i] * u_start[i]
                                                                - energy * sq[i] - piezo * scene->piezo_theta[i]);
        }
    } else
#endif
    {
#if BS_WITH_STRETCHING
        /* E' >= +0 from a core register (BS_ZERO): with one mode GCC read
         * the 0 of BS_R(0.0) from a literal in flash every step
         * (mid-fig6_1mode-float 1026.5 -> 1015.5 cycles a step) */
        if (BS_UNLIKELY(!(energy >= BS_ZERO && energy < k->stretch_limit))
            && !bs_beam_stable(k, n, k->dt_omega_sq, sq, energy, extra))
            return BS_E_UNSTABLE;
#endif
        for (i = 0; i < n; ++i) {
            s->u_beam[i] = (BS_GAMMA_USED(i) ? u_start[i] - k->dt_gamma[i] * a : u_start[i])
                           - k->dt_omega_sq[i] * s->q[i] - k->dt_damping[i] * u_start[i] - energy * sq[i];
#if BS_WITH_PIEZO
            s->u_beam[i] -= piezo * sim->scene->piezo_theta[i];
#endif
        }
    }
    (void)piezo;
    (void)extra;
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
    frame.cache = sim->side;
    frame.reach = sim->shape_reach;
    frame.warm = (const bs_real(*)[BS_ROWS])sim->percussion;
    return bs_contact_detect(sim->scene, &sim->k, &frame, &sim->contacts);
}

/* 3b: the contact problem, warm-started from the last step's percussions
 * (which the detection put in the set); adds M^-1 W P to the free
 * velocities. */
BS_INLINE void solve_contacts(bs_sim *sim, step_state *s, bs_step_report *report)
{
    bs_contact_set *set = &sim->contacts;

    bs_contact_problem(sim->scene, &sim->k, set, s->u_beam, s->u_slider, sim->u_beam, sim->slider_velocity);
    bs_pgs_solve(set, &sim->solver, report);
    bs_contact_apply(sim->scene, &sim->k, set, s->u_beam, s->u_slider);
}

/* 4: the end-of-step configuration; BS_E_NONFINITE or BS_E_ESCAPED if it
 * must not be committed. */
BS_INLINE bs_status end_of_step(const bs_sim *sim, step_state *s, const int n)
{
    const bs_step_constants *k = &sim->k;
    const bs_real half = k->half_dt;
    /* only its finiteness counts: the sums start at their first term (the 0, a
     * load from flash on a Cortex-M, is left for a beam without modes) */
    bs_real check = BS_R(0.0);
    int i;

#if BS_WITH_IMPLICIT
    if (sim->scene->implicit) { /* q_E = q_B + dt ((1 - theta) u_B + theta u_E) */
        const bs_real theta = sim->scene->theta;
        for (i = 0; i < n; ++i) {
            s->q[i] = sim->q_beam[i] + k->dt * ((BS_R(1.0) - theta) * sim->u_beam[i] + theta * s->u_beam[i]);
            check = i > 0 ? check + (s->q[i] + s->u_beam[i]) : s->q[i] + s->u_beam[i];
        }
    } else
#endif
        for (i = 0; i < n; ++i) {
            s->q[i] += half * s->u_beam[i];
            check = i > 0 ? check + (s->q[i] + s->u_beam[i]) : s->q[i] + s->u_beam[i];
        }
    s->x_end = sim->slider[0];
    s->x_end_low = sim->x_c_low;
    add_compensated(&s->x_end, &s->x_end_low, half * (sim->slider_velocity[0] + s->u_slider[0]));
    s->slider[1] += half * s->u_slider[1];
    s->slider[2] += half * s->u_slider[2];
#if BS_WITH_PIEZO
    if (sim->scene->load != BS_LOAD_NONE) { /* the patch on to the end, driven by the end velocities */
        bs_piezo_half_step(sim->scene, bs_piezo_current(sim->scene, s->u_beam), &s->voltage, &s->storage);
        check += s->voltage + s->storage;
    }
#endif
    check += s->x_end + s->slider[1] + s->slider[2] + s->u_slider[0] + s->u_slider[1] + s->u_slider[2];
    if (check - check != BS_R(0.0))
        return BS_E_NONFINITE;
    if (sim->model == BS_MODEL_FREE && !bs_within_stops(&sim->k, s->x_end))
        return BS_E_ESCAPED;
    return BS_OK;
}

/* q_E, u_E, the slider's pose and velocity at the end and x_C's low part
 * into the sim (BS_STATE_AS_BLOCK). */
BS_INLINE void write_end(bs_sim *sim, const step_state *s, const int n)
{
    int i;
#if BS_STATE_AS_BLOCK
    if (n == BS_MAX_MODES) { /* the block is written whole: no mode slot beyond n */
        bs_store_state(sim, s->q, s->u_beam, s->x_end, s->slider[1], s->slider[2], s->u_slider, s->x_end_low);
        return;
    }
#endif
    for (i = 0; i < n; ++i) {
        sim->q_beam[i] = s->q[i];
        sim->u_beam[i] = s->u_beam[i];
    }
    sim->slider[0] = s->x_end;
    sim->x_c_low = s->x_end_low;
    sim->slider[1] = s->slider[1];
    sim->slider[2] = s->slider[2];
    for (i = 0; i < 3; ++i)
        sim->slider_velocity[i] = s->u_slider[i];
}

/* The step's result becomes the sim's state. The warm starts: the slots of
 * the contacts of the last step that are not active now are cleared, the
 * active ones written; the others are 0 already. */
BS_INLINE void commit(bs_sim *sim, const step_state *s, const bs_step_report *report, const int n)
{
    const bs_contact_set *set = &sim->contacts;
    unsigned active = 0, gone;
    int a, i, r;

    write_end(sim, s, n);
    for (a = 0; a < set->count; ++a) {
        const int id = set->id[a];
        active |= 1u << id;
        for (r = 0; r < BS_ROWS; ++r)
            sim->percussion[id][r] = set->percussion[BS_ROWS * a + r];
    }
    gone = sim->report.active & ~active;
    if (BS_UNLIKELY(gone)) /* rare: a contact left since the last step */
        for (i = 0; gone; gone >>= 1, ++i)
            if (gone & 1u)
                for (r = 0; r < BS_ROWS; ++r)
                    sim->percussion[i][r] = BS_R(0.0);
    sim->report.active = active; /* member by member: no memcpy in the core */
    sim->report.sweeps = report->sweeps;
    sim->report.systems = report->systems;
    sim->report.residual = report->residual;
    sim->report.converged = report->converged;
    sim->base_accel = s->base_accel;
#if BS_WITH_PIEZO
    if (sim->scene->load != BS_LOAD_NONE) {
        sim->voltage = s->voltage;
        sim->storage_voltage = s->storage;
        sim->power = s->power;
        add_compensated(&sim->energy, &sim->energy_low, s->power * sim->k.dt);
    }
#endif
    sim->step += 1;
    sim->phase += 2 * sim->phase_step_half;
}

/* 4 and the commit, inlined into each of the step's two ends, with contacts
 * and without: where the two joined, the contact path's end velocities went
 * through the stack on the way there. */
BS_INLINE bs_status finish(bs_sim *sim, step_state *s, const bs_step_report *report, const int n)
{
    const bs_status status = end_of_step(sim, s, n);
    if (status != BS_OK)
        return status;
    commit(sim, s, report, n);
    return BS_OK;
}

/* The step with mean base acceleration base_accel, for n modes. */
BS_INLINE bs_status step_modes(bs_sim *sim, bs_real base_accel, const int n)
{
    step_state s;
    bs_step_report report;
    bs_status status;

    s.base_accel = base_accel;
    status = smooth_part(sim, &s, n);
    if (status != BS_OK)
        return status;
    status = find_contacts(sim, &s);
    if (status != BS_OK)
        return status;
    /* the report too is committed only with the step: a failed step leaves
     * the sim as it was. The solve fills in all of it. */
    if (sim->contacts.count > 0) {
        solve_contacts(sim, &s, &report);
        return finish(sim, &s, &report, n);
    }
    report.sweeps = 0;
    report.systems = 0;
    report.residual = BS_R(0.0);
    report.converged = 1;
    return finish(sim, &s, &report, n);
}

/* The step, its mode count a constant for the common counts (bs_inline.h). */
static bs_status step(bs_sim *sim, bs_real base_accel)
{
    BS_MODES_SWITCH(BS_NMODES(sim->scene), return step_modes(sim, base_accel, MODES));
    return BS_OK; /* not reached */
}

bs_status bs_sim_step(bs_sim *sim)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    return step(sim, bs_excitation_step_mean_of(sim));
}

bs_status bs_sim_step_measured(bs_sim *sim, bs_real base_accel)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (base_accel - base_accel != BS_R(0.0)) /* NaN or infinite: refused, nothing changes */
        return BS_E_ARGUMENT;
    return step(sim, base_accel);
}

bs_status bs_step_measured(bs_sim *sim, bs_real base_accel)
{
    /* A firmware's observer steps one sim, a global: under -flto GCC
     * specialises the step for its address and reads the address of each
     * member it uses from flash (a literal each); forgotten, the address is
     * a value in a register, the members offsets from it. */
    BS_FORGET(sim);
    return step(sim, base_accel);
}
