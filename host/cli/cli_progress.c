/* cli_progress.c - terminal progress bar on stderr (cli_progress.h). */
#define _POSIX_C_SOURCE 200112L
#include "cli_progress.h"

#include <stdio.h>
#include <unistd.h>
#include "bs_platform.h"

#define BAR_WIDTH 30

void cli_progress_start(cli_progress *bar, const char *label)
{
    bar->enabled = isatty(STDERR_FILENO);
    bar->start = bs_platform_seconds();
    bar->last_draw = 0.0;
    bar->label = label;
}

void cli_progress_update(cli_progress *bar, double fraction, const char *detail)
{
    const double now = bs_platform_seconds();
    const double elapsed = now - bar->start;
    char cells[BAR_WIDTH + 1];
    int filled;
    int i;

    if (!bar->enabled || now - bar->last_draw < 0.25)
        return;
    bar->last_draw = now;
    if (fraction < 0.0)
        fraction = 0.0;
    if (fraction > 1.0)
        fraction = 1.0;
    if (!detail)
        detail = "";
    filled = (int)(fraction * BAR_WIDTH);
    for (i = 0; i < BAR_WIDTH; ++i)
        cells[i] = i < filled ? '#' : '.';
    cells[BAR_WIDTH] = '\0';
    if (fraction > 0.0)
        fprintf(stderr, "\r%s [%s] %3.0f%% %s ETA %.1f s  ", bar->label, cells, 100.0 * fraction, detail,
                elapsed * (1.0 - fraction) / fraction);
    else
        fprintf(stderr, "\r%s [%s] %3.0f%% %s  ", bar->label, cells, 0.0, detail);
    fflush(stderr);
}

void cli_progress_hook(void *bar, double fraction, const char *detail)
{
    cli_progress_update((cli_progress *)bar, fraction, detail);
}

void cli_progress_end(cli_progress *bar)
{
    if (bar->enabled && bar->last_draw > 0.0) {
        fprintf(stderr, "\r%*s\r", BAR_WIDTH + 60, "");
        fflush(stderr);
    }
}
