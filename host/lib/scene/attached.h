/* attached.h - the beam with the slider rigidly attached: where its first
 * natural frequency meets the excitation (the resonance the slider tunes). */
#ifndef ATTACHED_H
#define ATTACHED_H

#include "modal.h"
#include "scene_params.h"

/* Lowest natural frequency [Hz] of the beam (the scene's modes) with the
 * slider rigidly attached at s = x/L. */
double attached_frequency(const modal_set *modes, const scene_params *p, double s);

/* The s in [B/2L, 1/2] where attached_frequency equals frequency [Hz], or
 * -1 if it does not in that range. */
double attached_position(const modal_set *modes, const scene_params *p, double frequency);

#endif
