/* ref_replay.h - a measured base acceleration to replay (docs/model.md 10):
 * a text file with the mean base acceleration of each outer step, one per
 * line, in m/s^2; '#' starts a comment (to the end of the line), blank lines
 * are skipped. */
#ifndef REF_REPLAY_H
#define REF_REPLAY_H

#include <stddef.h>
#include <stdint.h>

/* Reads path into *values (malloc'ed; the caller frees it) and *count, and
 * the number of lines into *lines (if not NULL). Refuses, with the file and
 * the line in err: a line that is not one finite number (text after it, NaN,
 * inf, out of range), a line longer than 4095 characters, a file that cannot
 * be read. Returns 0 or -1. */
int ref_replay_read(const char *path, double **values, uint64_t *count, unsigned long *lines, char *err,
                    size_t err_size);

#endif
