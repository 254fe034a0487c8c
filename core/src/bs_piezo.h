/* bs_piezo.h - the piezoelectric patch and its load, half a step at a time. */
#ifndef BS_PIEZO_H
#define BS_PIEZO_H

#include "bs_scene.h"
#include "bs_types.h"

/* The patch current source sum_k theta_k u_k [A] at modal velocities u. */
bs_real bs_piezo_current(const bs_scene *scene, const bs_real *u_beam);

/* Advances the patch voltage *voltage (and, with the rectifier, the storage
 * voltage *storage) over half a step with the patch current held at current. */
void bs_piezo_half_step(const bs_scene *scene, bs_real current, bs_real *voltage, bs_real *storage);

/* The open patch's stiffness theta theta^T / C_p bounded by its largest
 * row sum, max_k |theta_k| sum_j |theta_j| / C_p [1/s^2]: what the patch adds
 * to the stiffness under the step's stability limit (0 without a load). */
bs_real bs_piezo_stiffness(const bs_scene *scene);

/* Power into the load [W] at these voltages. */
bs_real bs_piezo_power(const bs_scene *scene, bs_real voltage, bs_real storage);

#endif
