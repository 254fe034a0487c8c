/* schedule.h - a varying excitation: frequency and amplitude over time, from
 * the text of [excitation] schedule ("t:f:a, t:f:a, ...": seconds, Hz, m/s^2).
 * Between two points both change linearly in time; before the first point
 * and after the last they hold. The run loop hands the values to the core
 * (bs_sim_set_excitation), which keeps the phase continuous. */
#ifndef SCHEDULE_H
#define SCHEDULE_H

#include <stddef.h>

#define SCHEDULE_MAX_POINTS 16

typedef struct schedule {
    int points;                          /* 0: no schedule (the scene's constant excitation) */
    double t[SCHEDULE_MAX_POINTS];       /* [s], strictly increasing, >= 0 */
    double frequency[SCHEDULE_MAX_POINTS]; /* [Hz], > 0 */
    double amplitude[SCHEDULE_MAX_POINTS]; /* [m/s^2], >= 0 */
} schedule;

/* Parses text (empty: no points). Returns 0, or -1 with what is wrong (the
 * point, by number, and why) in why. */
int schedule_parse(const char *text, schedule *s, char *why, size_t why_size);

/* Frequency and amplitude at time t (s must have points). */
void schedule_at(const schedule *s, double t, double *frequency, double *amplitude);

#endif
