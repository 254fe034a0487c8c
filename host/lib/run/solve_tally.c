/* solve_tally.c - counts of the contact solves of a run. */
#include "solve_tally.h"

void solve_tally_clear(solve_tally *tally)
{
    tally->contact_steps = tally->unconverged_steps = tally->sweeps = tally->systems = 0;
    tally->max_sweeps = tally->max_systems = 0;
}

void solve_tally_add(solve_tally *tally, const bs_step_report *report)
{
    if (!report->active)
        return;
    ++tally->contact_steps;
    tally->unconverged_steps += report->converged == 0;
    tally->sweeps += (uint64_t)report->sweeps;
    tally->systems += (uint64_t)report->systems;
    if (report->sweeps > tally->max_sweeps)
        tally->max_sweeps = report->sweeps;
    if (report->systems > tally->max_systems)
        tally->max_systems = report->systems;
}

void solve_tally_merge(solve_tally *tally, const solve_tally *part)
{
    tally->contact_steps += part->contact_steps;
    tally->unconverged_steps += part->unconverged_steps;
    tally->sweeps += part->sweeps;
    tally->systems += part->systems;
    if (part->max_sweeps > tally->max_sweeps)
        tally->max_sweeps = part->max_sweeps;
    if (part->max_systems > tally->max_systems)
        tally->max_systems = part->max_systems;
}

static double per_contact_step(const solve_tally *tally, uint64_t count)
{
    return tally->contact_steps ? (double)count / (double)tally->contact_steps : 0.0;
}

double solve_tally_mean_sweeps(const solve_tally *tally)
{
    return per_contact_step(tally, tally->sweeps);
}

double solve_tally_mean_systems(const solve_tally *tally)
{
    return per_contact_step(tally, tally->systems);
}
