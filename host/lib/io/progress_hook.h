/* progress_hook.h - how long work (a run, a sweep, a map, an observer
 * design) tells its caller how far it has come. The library never draws:
 * the CLI turns the calls into a bar on a terminal (host/cli/cli_progress.c),
 * a bridge into whatever its language shows. */
#ifndef PROGRESS_HOOK_H
#define PROGRESS_HOOK_H

/* Called now and then (a few times a second at most, from the thread that
 * called the work) with the part done, in [0, 1], and a short text of where
 * the work is (NULL: none). NULL hook: nobody is told. */
typedef void (*progress_hook)(void *context, double fraction, const char *detail);

#endif
