/* progress.h - a progress bar with ETA on stderr, shown only on a terminal. */
#ifndef PROGRESS_H
#define PROGRESS_H

typedef struct progress {
    int enabled;        /* stderr is a terminal */
    double start;       /* wall clock at start [s] */
    double last_draw;   /* wall clock of the last redraw [s] */
    const char *label;
} progress;

void progress_start(progress *bar, const char *label);

/* Redraws at most four times a second; fraction in [0, 1]. */
void progress_update(progress *bar, double fraction, const char *detail);

/* Clears the bar's line. */
void progress_end(progress *bar);

#endif
