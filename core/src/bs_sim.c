/* bs_sim.c - a simulation's life outside the step: start, solver settings,
 * reading and overwriting its state, its hash. The step is core/src/bs_step.c.
 *
 * Every entry point checks its pointers and that the sim is ready (bs_sim.ready
 * is set only by a successful bs_sim_init), so a NULL, zeroed or failed sim is
 * refused with a status, never dereferenced beyond that field.
 */
#include "beamslider.h"
#include "bs_excitation.h"
#include "bs_port.h"
#include "bs_piezo.h"
#include "bs_prepare.h"
#include "bs_shape.h"
#include "bs_sim_internal.h"

static void clear_percussions(bs_sim *sim)
{
    int k, r;
    for (k = 0; k < BS_MAX_CONTACTS; ++k)
        for (r = 0; r < BS_ROWS; ++r)
            sim->percussion[k][r] = BS_R(0.0);
}

/* a sinc(Omega dt / 2): the amplitude of the step mean (core/src/bs_excitation.c). */
static bs_real step_amplitude(bs_real amplitude, uint64_t phase_step_half)
{
    return (bs_real)((double)amplitude * bs_excitation_step_factor(phase_step_half));
}

bs_solver_options bs_solver_defaults(void)
{
    bs_solver_options options;
    options.max_sweeps = BS_SOLVER_DEFAULT_MAX_SWEEPS;
    options.tol_rel = (bs_real)BS_SOLVER_DEFAULT_TOL_REL;
    options.tol_abs = (bs_real)BS_SOLVER_DEFAULT_TOL_ABS;
    options.measure_residual = 1;
    return options;
}

static int valid_solver(const bs_solver_options *o)
{
    return o->max_sweeps >= 1 && o->max_sweeps <= BS_SOLVER_MAX_SWEEPS
           && o->tol_rel - o->tol_rel == BS_R(0.0) && o->tol_rel >= BS_R(0.0)
           && o->tol_abs - o->tol_abs == BS_R(0.0) && o->tol_abs >= BS_R(0.0)
           && (o->measure_residual == 0 || o->measure_residual == 1);
}

bs_status bs_sim_init_(uint32_t tag, size_t sim_size, size_t scene_size, bs_sim *sim,
                       const bs_scene *scene, bs_model model, bs_real s0)
{
    bs_status status;
    int i;

    if (!sim || !scene)
        return BS_E_NULL;
    status = bs_build_matches(tag, sim_size, scene_size);
    if (status != BS_OK)
        return status; /* a sim of another layout: not even its ready field is ours to write */
    sim->ready = 0;
    status = bs_scene_check_(tag, scene_size, scene, 0);
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
    sim->solver = bs_solver_defaults();
    sim->x_pcs = s0 * scene->length;
    sim->step = 0;
    sim->phase = 0;
    sim->phase_step_half = scene->phase_step_half;
    sim->excitation[0] = scene->frequency;
    sim->excitation[1] = scene->base_accel;
    sim->step_accel = step_amplitude(scene->base_accel, scene->phase_step_half);
    sim->base_accel = BS_R(0.0);
    for (i = 0; i < BS_MAX_MODES; ++i) {
        sim->q_beam[i] = BS_R(0.0);
        sim->u_beam[i] = BS_R(0.0);
    }
    /* slot centred on the beam axis (heights relative to the base) */
    sim->slider[0] = s0 * scene->length;
    sim->slider[1] = -scene->com_offset;
    sim->slider[2] = BS_R(0.0);
    for (i = 0; i < 3; ++i)
        sim->slider_velocity[i] = BS_R(0.0);
    sim->x_c_low = BS_R(0.0);
    clear_percussions(sim);
    sim->report.active = 0;
    sim->report.sweeps = 0;
    sim->report.systems = 0;
    sim->report.residual = BS_R(0.0);
    sim->report.converged = 1;
    sim->contacts.count = 0;
    bs_shape_forget(&sim->side[0]);
    bs_shape_forget(&sim->side[1]);
    sim->shape_reach = bs_shape_reach(scene);
    bs_prepare(sim);
#if BS_WITH_PIEZO
    sim->voltage = sim->storage_voltage = sim->power = BS_R(0.0);
    sim->energy = sim->energy_low = BS_R(0.0);
    sim->piezo_stiffness = bs_piezo_stiffness(scene);
#endif
    sim->ready = BS_SIM_READY;
    return BS_OK;
}

bs_status bs_sim_set_solver(bs_sim *sim, const bs_solver_options *options)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!options)
        return BS_E_NULL;
    if (!valid_solver(options))
        return BS_E_ARGUMENT;
    sim->solver = *options;
    return BS_OK;
}

bs_status bs_sim_get_solver(const bs_sim *sim, bs_solver_options *options)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!options)
        return BS_E_NULL;
    *options = sim->solver;
    return BS_OK;
}

bs_status bs_sim_set_excitation(bs_sim *sim, bs_real frequency, bs_real amplitude)
{
    const bs_status status = bs_sim_status(sim);
    uint64_t half;
    if (status != BS_OK)
        return status;
    half = bs_excitation_phase_step_half((double)frequency, (double)sim->scene->dt);
    if (half == 0 || !(amplitude >= BS_R(0.0)) || amplitude - amplitude != BS_R(0.0))
        return BS_E_ARGUMENT;
    sim->phase_step_half = half;
    sim->excitation[0] = frequency;
    sim->excitation[1] = amplitude;
    sim->step_accel = step_amplitude(amplitude, half);
    return BS_OK;
}

int bs_contact_laws_acceptable(bs_real mu, bs_real e_n)
{
    if (!(mu >= BS_R(0.0)) || mu - mu != BS_R(0.0) || !(e_n >= BS_R(0.0) && e_n <= BS_R(1.0)))
        return 0;
    return (BS_WITH_FRICTION || mu == BS_R(0.0)) && (BS_WITH_RESTITUTION || e_n == BS_R(0.0));
}

bs_status bs_sim_set_contact_laws(bs_sim *sim, bs_real mu, bs_real e_n)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!bs_contact_laws_acceptable(mu, e_n))
        return BS_E_ARGUMENT;
    sim->k.mu = mu;
    sim->k.e_n = e_n;
    return BS_OK;
}

bs_status bs_sim_get_contact_laws(const bs_sim *sim, bs_real *mu, bs_real *e_n)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (mu)
        *mu = sim->k.mu;
    if (e_n)
        *e_n = sim->k.e_n;
    return BS_OK;
}

int bs_excitation_acceptable(const bs_sim *sim, bs_real frequency, bs_real amplitude, uint64_t phase_step_half,
                             bs_real step_accel)
{
    const bs_scene *scene = sim->scene;
    const int scenes_own = frequency == scene->frequency && phase_step_half == scene->phase_step_half;
    if (!(amplitude >= BS_R(0.0)) || amplitude - amplitude != BS_R(0.0))
        return 0;
    if (!scenes_own
        && (phase_step_half == 0
            || phase_step_half != bs_excitation_phase_step_half((double)frequency, (double)scene->dt)))
        return 0;
    return step_accel == step_amplitude(amplitude, phase_step_half);
}

bs_status bs_sim_get_excitation(const bs_sim *sim, bs_real *frequency, bs_real *amplitude)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (frequency)
        *frequency = sim->excitation[0];
    if (amplitude)
        *amplitude = sim->excitation[1];
    return BS_OK;
}

bs_status bs_sim_get_transducer(const bs_sim *sim, bs_transducer_output *out)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!out)
        return BS_E_NULL;
    out->present = 0;
    out->voltage = out->storage_voltage = out->power = out->energy = BS_R(0.0);
#if BS_WITH_PIEZO
    if (sim->scene->load != BS_LOAD_NONE) {
        out->present = 1;
        out->voltage = sim->voltage;
        out->storage_voltage = sim->storage_voltage;
        out->power = sim->power;
        out->energy = sim->energy + sim->energy_low;
    }
#endif
    return BS_OK;
}

bs_real bs_sim_base_acceleration(const bs_sim *sim)
{
    return bs_sim_is_ready(sim) ? sim->base_accel : bs_real_nan();
}

bs_status bs_sim_set_pcs_position(bs_sim *sim, bs_real s)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (sim->model != BS_MODEL_PCS || !(s >= BS_R(0.0) && s <= BS_R(1.0)))
        return BS_E_ARGUMENT;
    sim->x_pcs = s * sim->scene->length;
    return BS_OK;
}

bs_status bs_sim_get_report(const bs_sim *sim, bs_step_report *report)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!report)
        return BS_E_NULL;
    /* member by member, as the step writes them: a whole-struct copy reads
     * them in wider loads than those stores, which a host CPU cannot forward
     * from its store buffer (measured: 2.6 % of a host run's cycles here) */
    report->active = sim->report.active;
    report->sweeps = sim->report.sweeps;
    report->systems = sim->report.systems;
    report->residual = sim->report.residual;
    report->converged = sim->report.converged;
    return BS_OK;
}

bs_real bs_sim_sensor(const bs_sim *sim)
{
    if (!bs_sim_is_ready(sim))
        return bs_real_nan();
    return bs_sensor_of(sim);
}

bs_real bs_sim_position(const bs_sim *sim)
{
    if (!bs_sim_is_ready(sim))
        return bs_real_nan();
    return (sim->slider[0] + sim->x_c_low) / sim->scene->length;
}

bs_status bs_sim_beam_at(const bs_sim *sim, bs_real x, bs_real *w, bs_real *w_slope)
{
    bs_real phi[BS_MAX_MODES], slope[BS_MAX_MODES], value, value_slope;
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (x - x != BS_R(0.0))
        return BS_E_ARGUMENT;
    bs_shape_deflection(sim->scene, x, sim->q_beam, phi, slope, &value, &value_slope);
    if (w)
        *w = value;
    if (w_slope)
        *w_slope = value_slope;
    return BS_OK;
}

bs_status bs_sim_get_state(const bs_sim *sim, bs_real *q_beam, bs_real *u_beam, bs_real *slider,
                           bs_real *slider_velocity)
{
    int k;
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
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
    return BS_OK;
}

static int all_finite(const bs_real *values, int count)
{
    int k;
    for (k = 0; values && k < count; ++k)
        if (values[k] - values[k] != BS_R(0.0))
            return 0;
    return 1;
}

int bs_state_acceptable(const bs_sim *sim, const bs_real *q_beam, const bs_real *u_beam, const bs_real *slider,
                        const bs_real *slider_velocity)
{
    if (!all_finite(q_beam, sim->scene->n_modes) || !all_finite(u_beam, sim->scene->n_modes)
        || !all_finite(slider, 3) || !all_finite(slider_velocity, 3))
        return 0;
    return !slider || sim->model != BS_MODEL_FREE || bs_within_stops(&sim->k, slider[0]);
}

bs_status bs_sim_set_state(bs_sim *sim, const bs_real *q_beam, const bs_real *u_beam,
                           const bs_real *slider, const bs_real *slider_velocity)
{
    int k;
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!bs_state_acceptable(sim, q_beam, u_beam, slider, slider_velocity))
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
    if (!bs_sim_is_ready(sim))
        return bs_real_nan();
    return (bs_real)(uint32_t)(sim->phase >> 40) * BS_R(5.9604644775390625e-08); /* 2^-24 */
}

uint64_t bs_sim_steps(const bs_sim *sim)
{
    return bs_sim_is_ready(sim) ? sim->step : 0;
}

bs_real bs_sim_time(const bs_sim *sim)
{
    if (!bs_sim_is_ready(sim))
        return bs_real_nan();
    return (bs_real)sim->step * sim->scene->dt; /* steps times dt, never accumulated */
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
    uint32_t hash = 2166136261u;
    int n;
    if (!bs_sim_is_ready(sim))
        return 0;
    n = sim->scene->n_modes;
    hash = hash_bytes(hash, &sim->step, sizeof sim->step);
    hash = hash_bytes(hash, &sim->phase, sizeof sim->phase);
    hash = hash_bytes(hash, &sim->phase_step_half, sizeof sim->phase_step_half);
    hash = hash_bytes(hash, &sim->step_accel, sizeof sim->step_accel);
    hash = hash_bytes(hash, sim->q_beam, (unsigned long)n * sizeof(bs_real));
    hash = hash_bytes(hash, sim->u_beam, (unsigned long)n * sizeof(bs_real));
    hash = hash_bytes(hash, sim->slider, sizeof sim->slider);
    hash = hash_bytes(hash, sim->slider_velocity, sizeof sim->slider_velocity);
    hash = hash_bytes(hash, &sim->x_c_low, sizeof sim->x_c_low);
    hash = hash_bytes(hash, sim->percussion, sizeof sim->percussion);
#if BS_WITH_PIEZO
    if (sim->scene->load != BS_LOAD_NONE) { /* a scene without a transducer hashes as before */
        hash = hash_bytes(hash, &sim->voltage, sizeof sim->voltage);
        hash = hash_bytes(hash, &sim->storage_voltage, sizeof sim->storage_voltage);
    }
#endif
    return hash;
}
