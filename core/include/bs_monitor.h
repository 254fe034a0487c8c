/* bs_monitor.h - per-excitation-period amplitude and transport, streaming.
 *
 * What a digital twin reports: for each completed excitation period, the
 * amplitude of the sensor signal w(4L/7) (half its peak-to-peak value over the
 * period) and the slider displacement over the period. Periods start where the
 * phase accumulator wraps (theta = 0, base at its top), so they are exact.
 * The caller owns the struct; amplitude, transport and periods are its
 * outputs, the other members are private.
 */
#ifndef BS_MONITOR_H
#define BS_MONITOR_H

#include "beamslider.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct bs_monitor {
    bs_real amplitude;         /* half peak-to-peak of w(4L/7) over the last complete period [m] */
    bs_real transport;         /* x_C displacement over the last complete period / L */
    uint32_t periods;          /* completed periods */
    /* private */
    uint64_t last_phase;
    bs_real w_max, w_min;      /* sensor extremes in the running period [m] */
    bs_real x_start, x_start_low; /* x_C at the start of the running period (compensated) */
} bs_monitor;

/* Starts monitoring at the sim's current state. Returns BS_OK, BS_E_NULL or
 * BS_E_UNINITIALISED. */
bs_status bs_monitor_init(bs_monitor *monitor, const bs_sim *sim);

/* Call after every step. Returns 1 when a period has just completed (then
 * amplitude and transport hold its values), 0 if not, or a negative
 * bs_status (BS_E_NULL, BS_E_UNINITIALISED). */
int bs_monitor_update(bs_monitor *monitor, const bs_sim *sim);

#ifdef __cplusplus
}
#endif

#endif
