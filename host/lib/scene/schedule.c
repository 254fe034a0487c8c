/* schedule.c - a varying excitation from [excitation] schedule. */
#include "schedule.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One number of a point, up to the next ':' or ',' (or the end); 0 or -1. */
static int number(const char **text, double *value)
{
    char *end;
    while (**text == ' ' || **text == '\t')
        ++*text;
    *value = strtod(*text, &end);
    if (end == *text || !isfinite(*value))
        return -1;
    *text = end;
    while (**text == ' ' || **text == '\t')
        ++*text;
    return 0;
}

int schedule_parse(const char *text, schedule *s, char *why, size_t why_size)
{
    const char *p = text;
    s->points = 0;
    while (*p == ' ' || *p == '\t')
        ++p;
    if (*p == '\0')
        return 0;
    for (;;) {
        const int k = s->points;
        double t, f, a;
        if (k == SCHEDULE_MAX_POINTS) {
            snprintf(why, why_size, "more than %d points", SCHEDULE_MAX_POINTS);
            return -1;
        }
        if (number(&p, &t) || *p++ != ':' || number(&p, &f) || *p++ != ':' || number(&p, &a)
            || (*p != ',' && *p != '\0')) {
            snprintf(why, why_size, "point %d is not t:f:a (three finite numbers: s, Hz, m/s^2)", k + 1);
            return -1;
        }
        if (t < 0.0 || (k > 0 && !(t > s->t[k - 1]))) {
            snprintf(why, why_size, "point %d: time %g s must be >= 0 and after the previous point's", k + 1, t);
            return -1;
        }
        if (!(f > 0.0) || a < 0.0) {
            snprintf(why, why_size, "point %d: frequency %g Hz must be > 0 and amplitude %g m/s^2 >= 0", k + 1, f, a);
            return -1;
        }
        s->t[k] = t;
        s->frequency[k] = f;
        s->amplitude[k] = a;
        s->points = k + 1;
        if (*p == '\0')
            return 0;
        ++p; /* ',' */
    }
}

void schedule_at(const schedule *s, double t, double *frequency, double *amplitude)
{
    int k = 0;
    if (t <= s->t[0]) {
        *frequency = s->frequency[0];
        *amplitude = s->amplitude[0];
        return;
    }
    while (k + 1 < s->points && t > s->t[k + 1])
        ++k;
    if (k + 1 == s->points) {
        *frequency = s->frequency[k];
        *amplitude = s->amplitude[k];
        return;
    }
    {
        const double w = (t - s->t[k]) / (s->t[k + 1] - s->t[k]);
        *frequency = s->frequency[k] + w * (s->frequency[k + 1] - s->frequency[k]);
        *amplitude = s->amplitude[k] + w * (s->amplitude[k + 1] - s->amplitude[k]);
    }
}
