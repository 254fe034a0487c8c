/* bs_monitor.h - per-excitation-period amplitude and transport, streaming.
 *
 * What a digital twin reports: for each completed excitation period, the
 * amplitude of the sensor signal w(4L/7) (half its peak-to-peak value over the
 * period) and the slider displacement over the period. Periods start where the
 * phase accumulator wraps (theta = 0, base at its top), so they are exact.
 */
#ifndef BS_MONITOR_H
#define BS_MONITOR_H

#include "beamslider.h"

typedef struct bs_monitor {
    uint64_t last_phase;
    bs_real w_max, w_min;      /* sensor extremes in the running period [m] */
    bs_real x_start, x_start_low; /* x_C at the start of the running period (compensated) */
    bs_real amplitude;         /* half peak-to-peak of w(4L/7) over the last complete period [m] */
    bs_real transport;         /* x_C displacement over the last complete period / L */
    uint32_t periods;          /* completed periods */
} bs_monitor;

/* Starts monitoring at the sim's current state. */
void bs_monitor_init(bs_monitor *monitor, const bs_sim *sim);

/* Call after every step. Returns 1 when a period has just completed (then
 * amplitude and transport hold its values), else 0. */
int bs_monitor_update(bs_monitor *monitor, const bs_sim *sim);

#endif
