/* ref_monitor.h - per-excitation-period amplitude and transport of a run. */
#ifndef REF_MONITOR_H
#define REF_MONITOR_H

#include <stdint.h>

/* Period k ends at the first outer step n with floor(n dt f_ex) >= k (the
 * cycle count from the step count in long double). Its samples are the
 * steps from the previous period's last step to its own, both included. */
typedef struct ref_monitor {
    double dt, frequency;
    uint64_t cycles;         /* completed excitation periods */
    double w_min, w_max;     /* sensor extremes in the current period [m] */
    double x_start;          /* x_C at the period's first sample [m] */
    double amplitude;        /* last completed period: (max - min) / 2 of w(4L/7) [m] */
    double transport;        /* last completed period: x_C displacement [m] */
} ref_monitor;

void ref_monitor_init(ref_monitor *m, double dt, double frequency, double w_sensor, double x_c);

/* Feeds outer step n (time n dt). Returns 1 when it completed a period
 * (amplitude and transport then hold its values), else 0. */
int ref_monitor_update(ref_monitor *m, uint64_t n, double w_sensor, double x_c);

#endif
