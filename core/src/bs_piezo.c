/* bs_piezo.c - the piezoelectric patch and its load (docs/model.md 11).
 *
 * The patch between x_1 and x_2 couples the beam to its voltage v:
 *   beam:    q_k'' + ... + theta_k v = ...,   theta_k = Theta (phi_k'(x_2) - phi_k'(x_1))
 *   patch:   C_p v' = i - i_load,              i = sum_k theta_k q_k' (a current source)
 * Loads:
 *   resistor   i_load = v / R_l
 *   rectifier  a full bridge of ideal diodes (drop V_f each) into C_s with
 *              R_s across it: C_s V_s' + V_s / R_s = i_d, and the bridge
 *              current i_d >= 0 _|_ V_s + 2 V_f - |v| >= 0 (a diode conducts
 *              only while the patch voltage reaches the storage's plus the
 *              drop: the complementarity of Signorini's contact law)
 *
 * The step advances the circuit in two half steps, like the positions
 * (docs/design.md 4): the start velocities drive it to the midpoint, where
 * the beam feels -theta_k v_M; the end velocities drive it on to the end of
 * the step. Each half step of length h = dt / 2 holds i constant and is
 * solved exactly, so no load makes the step unstable:
 *   resistor   v <- v e^(-h / (R_l C_p)) + R_l (1 - e^(-h / (R_l C_p))) i
 *              (decay and gain per half step come with the scene);
 *   rectifier  the storage decays, V_s <- V_s e^(-h / (R_s C_s)), the patch
 *              charges, v <- v + h i / C_p; where then |v| > V_s + 2 V_f the
 *              bridge conducts the charge Q that brings both to the clamp,
 *              |v| - Q / C_p = V_s + Q / C_s + 2 V_f:
 *                Q = (|v| - V_s - 2 V_f) / (1 / C_p + 1 / C_s),
 *              the one-unknown complementarity problem solved exactly
 *              (Q = 0 where the bridge blocks).
 * With the patch open (no conduction, R_l -> infinity) both reduce to
 * v <- v + h i / C_p, the exact analogue of q <- q + h u; the electrical
 * stiffness theta theta^T / C_p then adds to the beam's, which the step's
 * stability bound includes.
 */
#include "bs_piezo.h"
#include "bs_port.h"

bs_real bs_piezo_current(const bs_scene *scene, const bs_real *u_beam)
{
    bs_real current = BS_R(0.0);
    int k;
    for (k = 0; k < BS_NMODES(scene); ++k)
        current += scene->piezo_theta[k] * u_beam[k];
    return current;
}

void bs_piezo_half_step(const bs_scene *scene, bs_real current, bs_real *voltage, bs_real *storage)
{
    if (scene->load == BS_LOAD_RESISTOR) {
        *voltage = scene->load_decay * *voltage + scene->load_gain * current;
        return;
    }
    /* rectifier */
    *storage *= scene->load_decay;
    *voltage += BS_R(0.5) * scene->dt * current * scene->piezo_capacitance_inv;
    {
        const bs_real magnitude = *voltage < BS_R(0.0) ? -*voltage : *voltage;
        const bs_real excess = magnitude - *storage - scene->bridge_drop;
        if (excess > BS_R(0.0)) {
            const bs_real charge = excess / (scene->piezo_capacitance_inv + scene->storage_capacitance_inv);
            const bs_real drop = charge * scene->piezo_capacitance_inv;
            *voltage += *voltage < BS_R(0.0) ? drop : -drop;
            *storage += charge * scene->storage_capacitance_inv;
        }
    }
}

bs_real bs_piezo_stiffness(const bs_scene *scene)
{
    bs_real largest = BS_R(0.0), sum = BS_R(0.0);
    int k;
    if (scene->load == BS_LOAD_NONE)
        return BS_R(0.0);
    for (k = 0; k < BS_NMODES(scene); ++k) {
        const bs_real theta = bs_fabs(scene->piezo_theta[k]);
        sum += theta;
        largest = theta > largest ? theta : largest;
    }
    return largest * sum * scene->piezo_capacitance_inv;
}

bs_real bs_piezo_power(const bs_scene *scene, bs_real voltage, bs_real storage)
{
    const bs_real across = scene->load == BS_LOAD_RESISTOR ? voltage : storage;
    return scene->load_conductance * across * across;
}
