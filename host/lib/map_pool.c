/* map_pool.c - a map's cases on worker processes (map_pool.h). */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS, nanosleep with -std=c99 */
#define _POSIX_C_SOURCE 200809L

#include "map_pool.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif
#include "bs_platform.h"
#include "map_case.h"
#include "map_store.h"
#include "progress.h"

/* What the processes share: the next case to take and the cases done. */
typedef struct shared_counts {
    volatile long next;
    volatile long done;
} shared_counts;

/* A worker: takes cases until none is left. Reports on err_fd (its stderr
 * before standard error was sent to /dev/null: run_scene draws a progress
 * bar of its own whenever stderr is a terminal). Returns the exit status. */
static int worker(const map_pool_options *o, shared_counts *counts, int err_fd)
{
    static char row[MAP_ROW];
    char err[1024];
    char path[4400] = "";
    off_t length = 0;
    int fd = -1;

    for (;;) {
        /* GCC's atomic builtin (also clang's): every case goes to one worker */
        const long i = __sync_fetch_and_add(&counts->next, 1);
        if (i >= o->count)
            break;
        if (map_case_run(o->grid, o->base, o->cases[i], row, sizeof row, err, sizeof err) != 0)
            goto failed;
        if (fd < 0) { /* the file is made with the first row: a worker without cases leaves none */
            if ((fd = map_results_create(o->dir, o->grid, path, sizeof path, err, sizeof err)) < 0)
                goto failed;
            length = lseek(fd, 0, SEEK_END);
        }
        if (map_results_append(fd, row, &length, err, sizeof err) != 0)
            goto failed;
        __sync_fetch_and_add(&counts->done, 1);
    }
    if (fd >= 0 && close(fd) != 0) {
        snprintf(err, sizeof err, "%s", strerror(errno));
        goto failed;
    }
    return 0;
failed:
    dprintf(err_fd, "beamslider: error: %s%s%s\n", path, *path ? ": " : "", err);
    return 1;
}

static void start_worker(const map_pool_options *o, shared_counts *counts, pid_t parent)
{
    int err_fd, quiet;
#if defined(__linux__)
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) /* the parent died before prctl */
        _exit(1);
#else
    (void)parent;
#endif
    err_fd = dup(STDERR_FILENO);
    quiet = open("/dev/null", O_WRONLY);
    if (err_fd < 0 || quiet < 0 || dup2(quiet, STDERR_FILENO) < 0)
        _exit(1);
    close(quiet);
    _exit(worker(o, counts, err_fd)); /* _exit: the parent's stdio buffers are not the child's to flush */
}

int map_pool_run(const map_pool_options *o, map_pool_result *result, char *err, size_t size)
{
    const double start = bs_platform_seconds();
    const pid_t parent = getpid();
    shared_counts *counts;
    progress bar;
    int alive = 0, j;

    memset(result, 0, sizeof *result);
    counts = mmap(NULL, sizeof *counts, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (counts == MAP_FAILED) {
        snprintf(err, size, "cannot share memory with the workers: %s", strerror(errno));
        return -1;
    }
    counts->next = counts->done = 0;
    fflush(stdout);
    fflush(stderr);
    for (j = 0; j < o->jobs; ++j) {
        const pid_t pid = fork();
        if (pid == 0)
            start_worker(o, counts, parent);
        if (pid < 0) {
            snprintf(err, size, "cannot start worker %d: %s", j + 1, strerror(errno));
            ++result->failed_workers;
            break;
        }
        ++alive;
    }
    progress_start(&bar, "map");
    bar.enabled &= o->show_progress;
    while (alive > 0) {
        int status;
        const pid_t pid = waitpid(-1, &status, WNOHANG);
        if (pid > 0) {
            --alive;
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
                ++result->failed_workers;
        } else if (pid < 0 && errno != EINTR) {
            break;
        } else {
            const struct timespec pause = { 0, 100000000L }; /* 0.1 s */
            char detail[64];
            snprintf(detail, sizeof detail, "%ld/%ld cases", (long)counts->done, o->count);
            progress_update(&bar, o->count ? (double)counts->done / (double)o->count : 1.0, detail);
            nanosleep(&pause, NULL);
        }
    }
    progress_end(&bar);
    result->done = counts->done;
    result->wall_s = bs_platform_seconds() - start;
    munmap(counts, sizeof *counts);
    if (result->failed_workers > 0 || result->done < o->count) {
        if (!result->failed_workers || !*err)
            snprintf(err, size, "%d worker(s) failed; %ld of %ld cases were run (rerun the command to go on)",
                     result->failed_workers, result->done, o->count);
        return -1;
    }
    return 0;
}
