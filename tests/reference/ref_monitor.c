/* ref_monitor.c - per-period half peak-to-peak of w(4L/7) and x_C transport.
 *
 *   cycles(n) = floor(n dt f_ex)  (long double, from the step count)
 *   a period completes at step n when cycles(n) > cycles(n-1);
 *   amplitude = (max w - min w) / 2 over its samples, transport = x_C(n) - x_C(start). */
#include "ref_monitor.h"

#include <math.h>

void ref_monitor_init(ref_monitor *m, double dt, double frequency, double w_sensor, double x_c)
{
    m->dt = dt;
    m->frequency = frequency;
    m->cycles = 0;
    m->w_min = m->w_max = w_sensor;
    m->x_start = x_c;
    m->amplitude = 0.0;
    m->transport = 0.0;
}

int ref_monitor_update(ref_monitor *m, uint64_t n, double w_sensor, double x_c)
{
    const long double cycles = floorl((long double)n * (long double)m->dt * (long double)m->frequency);

    if (w_sensor < m->w_min)
        m->w_min = w_sensor;
    if (w_sensor > m->w_max)
        m->w_max = w_sensor;
    if (cycles <= (long double)m->cycles)
        return 0;
    m->cycles = (uint64_t)cycles;
    m->amplitude = 0.5 * (m->w_max - m->w_min);
    m->transport = x_c - m->x_start;
    m->w_min = m->w_max = w_sensor;
    m->x_start = x_c;
    return 1;
}
