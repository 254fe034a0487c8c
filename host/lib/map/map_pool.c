/* map_pool.c - a map's cases on worker threads (map_pool.h). */
#define _POSIX_C_SOURCE 200809L /* nanosleep */

#include "map_pool.h"

#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "bs_platform.h"
#include "map_case.h"
#include "map_store.h"

/* What the workers share: the next case to take, the cases done, the
 * workers that have finished. Changed only by atomic adds (GCC's builtins,
 * also clang's). */
typedef struct shared_counts {
    volatile long next;
    volatile long done;
    volatile long finished;
} shared_counts;

/* One worker: its own row buffer and, when it fails, why. */
typedef struct worker {
    pthread_t thread;
    const map_pool_options *options;
    shared_counts *counts;
    int failed;
    char row[MAP_ROW];
    char err[1024];
    char path[4400];
} worker;

static long atomic_add(volatile long *counter, long amount)
{
    return __sync_fetch_and_add(counter, amount);
}

static long atomic_read(volatile long *counter)
{
    return __sync_fetch_and_add(counter, 0);
}

/* Takes cases until none is left; on an error it stops and says why. */
static void *work(void *argument)
{
    worker *w = argument;
    const map_pool_options *o = w->options;
    off_t length = 0;
    int fd = -1;

    for (;;) {
        const long i = atomic_add(&w->counts->next, 1);
        if (i >= o->count)
            break;
        if (map_case_run(o->grid, o->base, o->cases[i], w->row, sizeof w->row, w->err, sizeof w->err) != 0)
            goto failed;
        if (fd < 0) { /* the file is made with the first row: a worker without cases leaves none */
            if ((fd = map_results_create(o->dir, o->grid, w->path, sizeof w->path, w->err, sizeof w->err)) < 0)
                goto failed;
            length = lseek(fd, 0, SEEK_END);
        }
        if (map_results_append(fd, w->row, &length, w->err, sizeof w->err) != 0)
            goto failed;
        atomic_add(&w->counts->done, 1);
    }
    if (fd >= 0 && close(fd) != 0) {
        snprintf(w->err, sizeof w->err, "%s", strerror(errno));
        fd = -1;
        goto failed;
    }
    atomic_add(&w->counts->finished, 1);
    return NULL;
failed:
    if (fd >= 0)
        close(fd);
    w->failed = 1;
    atomic_add(&w->counts->finished, 1);
    return NULL;
}

int map_pool_run(const map_pool_options *o, map_pool_result *result, char *err, size_t size)
{
    const double start = bs_platform_seconds();
    shared_counts counts = { 0, 0, 0 };
    worker *workers;
    const worker *first_failed = NULL;
    int started = 0, j;

    memset(result, 0, sizeof *result);
    *err = '\0';
    if (o->jobs < 1 || o->jobs > MAP_MAX_JOBS) {
        snprintf(err, size, "%d workers: allowed: 1 to %d", o->jobs, MAP_MAX_JOBS);
        return -1;
    }
    workers = calloc((size_t)o->jobs, sizeof *workers);
    if (!workers) {
        snprintf(err, size, "out of memory for %d workers", o->jobs);
        return -1;
    }
    for (j = 0; j < o->jobs; ++j) {
        int why;
        workers[j].options = o;
        workers[j].counts = &counts;
        if ((why = pthread_create(&workers[j].thread, NULL, work, &workers[j])) != 0) {
            snprintf(err, size, "cannot start worker %d: %s", j + 1, strerror(why));
            ++result->failed_workers;
            break;
        }
        ++started;
    }
    while (atomic_read(&counts.finished) < started) {
        const struct timespec pause = { 0, 100000000L }; /* 0.1 s */
        if (o->progress) {
            char detail[64];
            const long done = atomic_read(&counts.done);
            snprintf(detail, sizeof detail, "%ld/%ld cases", done, o->count);
            o->progress(o->progress_context, o->count ? (double)done / (double)o->count : 1.0, detail);
        }
        nanosleep(&pause, NULL);
    }
    for (j = 0; j < started; ++j) {
        pthread_join(workers[j].thread, NULL);
        if (workers[j].failed) {
            ++result->failed_workers;
            if (!first_failed)
                first_failed = &workers[j];
        }
    }
    result->done = counts.done;
    result->wall_s = bs_platform_seconds() - start;
    if (result->failed_workers > 0 || result->done < o->count) {
        char ran[160];
        snprintf(ran, sizeof ran, "%d worker(s) failed; %ld of %ld cases were run (rerun the command to go on)",
                 result->failed_workers, result->done, o->count);
        if (first_failed)
            snprintf(err, size, "%s%s%s; %s", first_failed->path, *first_failed->path ? ": " : "",
                     first_failed->err, ran);
        else if (!*err)
            snprintf(err, size, "%s", ran);
        free(workers);
        return -1;
    }
    free(workers);
    return 0;
}
