/* bs_monitor.c - streaming amplitude and transport per excitation period.
 *
 *   amplitude = (max w - min w) / 2 over the steps of the period (docs/model.md 7:
 *               the streaming estimate; docs/design.md compares it with the
 *               Hilbert envelope the papers use)
 *   transport = (x_C(end) - x_C(start)) / L, formed from the compensated pair
 *               (x_C, x_c_low) so that float keeps the few-ulp drift per period
 */
#include "bs_monitor.h"
#include "bs_sim_internal.h"

static void start_period(bs_monitor *monitor, const bs_sim *sim, bs_real w)
{
    monitor->w_max = w;
    monitor->w_min = w;
    monitor->x_start = sim->slider[0];
    monitor->x_start_low = sim->x_c_low;
}

bs_status bs_monitor_init(bs_monitor *monitor, const bs_sim *sim)
{
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!monitor)
        return BS_E_NULL;
    monitor->last_phase = sim->phase;
    monitor->amplitude = BS_R(0.0);
    monitor->transport = BS_R(0.0);
    monitor->periods = 0;
    start_period(monitor, sim, bs_sim_sensor(sim));
    return BS_OK;
}

int bs_monitor_update(bs_monitor *monitor, const bs_sim *sim)
{
    bs_real w;
    int wrapped;
    const bs_status status = bs_sim_status(sim);
    if (status != BS_OK)
        return status;
    if (!monitor)
        return BS_E_NULL;
    w = bs_sim_sensor(sim);
    wrapped = sim->phase < monitor->last_phase;

    monitor->last_phase = sim->phase;
    if (w > monitor->w_max)
        monitor->w_max = w;
    if (w < monitor->w_min)
        monitor->w_min = w;
    if (!wrapped)
        return 0;
    monitor->amplitude = BS_R(0.5) * (monitor->w_max - monitor->w_min);
    monitor->transport = ((sim->slider[0] - monitor->x_start) + (sim->x_c_low - monitor->x_start_low))
                         / sim->scene->length;
    monitor->periods += 1;
    start_period(monitor, sim, w);
    return 1;
}
