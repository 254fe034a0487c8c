/* bs_prepare.h - the step's constants from the scene (bs_step_constants). */
#ifndef BS_PREPARE_H
#define BS_PREPARE_H

#include "bs_sim_layout.h"

/* Fills sim->k from sim->scene (bs_sim_init calls it; a test that changes
 * a scene under a running sim calls it again). */
void bs_prepare(bs_sim *sim);

#endif
