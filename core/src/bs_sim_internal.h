/* bs_sim_internal.h - what the core's files share about a bs_sim: whether it
 * is ready, the value read functions return for a bad one, and the band of
 * x_C the clamp stops hold. */
#ifndef BS_SIM_INTERNAL_H
#define BS_SIM_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "bs_inline.h"
#include "bs_sim_layout.h"

/* bs_sim.ready of an initialised sim ("mmmm"); anything else is not ready.
 * One byte repeated: a Thumb-2 immediate, which the check of every step
 * compares with directly instead of reading a literal from flash. */
#define BS_SIM_READY 0x6d6d6d6du

/* The library's own build tag and sizes (core/src/bs_version.c). */
bs_status bs_build_matches(uint32_t tag, size_t sim_size, size_t scene_size);

static inline int bs_sim_is_ready(const bs_sim *sim)
{
    return sim && sim->ready == BS_SIM_READY;
}

/* w(4L/7) = sum_k phi_k(4/7) q_k of a ready sim: bs_sim_sensor without its
 * check, inlined where it runs every sample (the observer). */
static inline bs_real bs_sensor_of(const bs_sim *sim)
{
    bs_real w = BS_ZERO;
    int k;
    for (k = 0; k < BS_NMODES(sim->scene); ++k)
        w += sim->k.phi_sensor[k] * sim->q_beam[k];
    return w;
}

/* The state a step starts from and commits (q, u, the slider's pose and
 * velocity, x_C's low part) lies in the sim as one block of 2 BS_MAX_MODES
 * + 7 words. With five modes and float on a Cortex-M4F (BS_STATE_AS_BLOCK)
 * the step reads the first 16 with one vldm (bs_load_16), and the step and
 * the observer's correction write all 17 with one vstm (bs_store_17):
 * bs_step.c and bs_observer.c. */
#define BS_STATE_AS_BLOCK (BS_LOAD_4_VLDM && 2 * BS_MAX_MODES + 6 == 16)
#if BS_STATE_AS_BLOCK
/* a build where they are not one block fails here */
typedef char
    bs_state_is_one_block[offsetof(bs_sim, x_c_low) - offsetof(bs_sim, q_beam) == 16 * sizeof(bs_real) ? 1 : -1];

/* q, u (all BS_MAX_MODES), the slider's pose (x, z, beta) and velocity and
 * x_C's low part into sim's state block with one vstm: the step's commit
 * and the observer's correction. */
BS_INLINE void bs_store_state(bs_sim *sim, const bs_real *q, const bs_real *u, bs_real x, bs_real z, bs_real beta,
                              const bs_real *velocity, bs_real x_low)
{
    bs_real block[2 * BS_MAX_MODES + 7];
    int i;
    for (i = 0; i < BS_MAX_MODES; ++i) {
        block[i] = q[i];
        block[BS_MAX_MODES + i] = u[i];
    }
    block[2 * BS_MAX_MODES] = x;
    block[2 * BS_MAX_MODES + 1] = z;
    block[2 * BS_MAX_MODES + 2] = beta;
    for (i = 0; i < 3; ++i)
        block[2 * BS_MAX_MODES + 3 + i] = velocity[i];
    block[2 * BS_MAX_MODES + 6] = x_low;
    bs_store_17(sim->q_beam, block);
}
#endif

/* The excitation's series coefficients into k (bs_prepare), and the mean
 * base acceleration over sim's next step (bs_excitation_step_mean) with
 * those: read from the sim's RAM, not from flash (core/src/bs_excitation.c). */
void bs_excitation_prepare(bs_step_constants *k);
bs_real bs_excitation_step_mean_of(const bs_sim *sim);

/* bs_sim_step_measured for a caller that has checked what it checks (the
 * sim ready, base_accel finite): the observer, every sample. */
bs_status bs_step_measured(bs_sim *sim, bs_real base_accel);

/* BS_E_NULL or BS_E_UNINITIALISED for a sim that is not ready, else BS_OK. */
static inline bs_status bs_sim_status(const bs_sim *sim)
{
    return !sim ? BS_E_NULL : (sim->ready == BS_SIM_READY ? BS_OK : BS_E_UNINITIALISED);
}

/* A quiet NaN, what read functions return for a sim that is not ready
 * (built from its bits: the core has no libm and no 0/0). */
static inline bs_real bs_real_nan(void)
{
    union {
        bs_real value;
#if BS_REAL_FLOAT
        uint32_t bits;
#else
        uint64_t bits;
#endif
    } nan;
#if BS_REAL_FLOAT
    nan.bits = 0x7fc00000u;
#else
    nan.bits = UINT64_C(0x7ff8000000000000);
#endif
    return nan.value;
}

/* 1 if x_C lies within the clamp stops widened by h/2: Moreau's step lets a
 * stop be penetrated by about |u_x| dt (micrometres), so a slot centre
 * further out means the stop did not hold (docs/design.md 5). The step
 * refuses to end outside this band (BS_E_ESCAPED) and bs_sim_set_state
 * accepts exactly this band. NaN is outside. */
static inline int bs_within_stops(const bs_step_constants *k, bs_real x)
{
    return x >= k->escape_min && x <= k->escape_max;
}

/* The rules a state must meet to be a sim's, shared by the setters and
 * bs_sim_restore (core/src/bs_sim.c): */

/* bs_sim_set_state's: q, u, slider pose and velocity finite (NULL: not
 * given), x_C within the stops band in the free model. */
int bs_state_acceptable(const bs_sim *sim, const bs_real *q_beam, const bs_real *u_beam, const bs_real *slider,
                        const bs_real *slider_velocity);

/* bs_sim_set_contact_laws's: mu finite and >= 0, e_N in [0, 1], within what
 * the build has (friction, restitution). */
int bs_contact_laws_acceptable(bs_real mu, bs_real e_n);

/* bs_sim_set_excitation's: a frequency and amplitude it accepts, with the
 * phase step and step amplitude it derives from them (or, for the scene's
 * own frequency, the scene's phase step, which bs_sim_init takes as it is). */
int bs_excitation_acceptable(const bs_sim *sim, bs_real frequency, bs_real amplitude, uint64_t phase_step_half,
                             bs_real step_accel);

#endif
