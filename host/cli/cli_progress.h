/* cli_progress.h - the CLI's progress bar with ETA on stderr, drawn only on
 * a terminal: what the library's progress hooks (progress_hook.h) become
 * on the command line. */
#ifndef CLI_PROGRESS_H
#define CLI_PROGRESS_H

typedef struct cli_progress {
    int enabled;        /* stderr is a terminal */
    double start;       /* wall clock at start [s] */
    double last_draw;   /* wall clock of the last redraw [s] */
    const char *label;
} cli_progress;

void cli_progress_start(cli_progress *bar, const char *label);

/* Redraws at most four times a second; fraction in [0, 1]; detail may be NULL. */
void cli_progress_update(cli_progress *bar, double fraction, const char *detail);

/* A progress_hook drawing bar (the context). */
void cli_progress_hook(void *bar, double fraction, const char *detail);

/* Clears the bar's line. */
void cli_progress_end(cli_progress *bar);

#endif
