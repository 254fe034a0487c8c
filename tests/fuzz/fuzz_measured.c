/* fuzz_measured.c - libFuzzer target: the measured-signals reader
 * (host/lib/twin/measured_signals.c), the one reader of the format for `twin
 * --measured` and twin_pack.
 *
 * Input: the file's bytes, written to a file in a private temporary folder.
 * The contract checked:
 *   - nothing crashes, hangs, leaks or reads out of bounds;
 *   - measured_open and measured_next answer as documented (0 / -1, 1 / 0 /
 *     -1) with a message on every refusal;
 *   - an accepted header holds what the grammar allows: a rate in
 *     [MEASURED_RATE_MIN, MEASURED_RATE_MAX], a signal of the two, a noise
 *     > 0, an accel_noise and a latency >= 0 (or NaN: not given);
 *   - every row read is finite, has t within 1 % of a sample period of
 *     k / rate, and s_true exactly when the column line names it;
 *   - measured_rewind reads the same rows again, bit for bit, and the same
 *     ending (the end, or the same refusal).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, strnlen */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_check.h"
#include "fuzz_files.h"
#include "measured_signals.h"

#define MAX_ROWS 4096 /* an input of -max_len 4096 holds fewer rows */

static measured_row rows[MAX_ROWS];

/* Reads the rows (the first MAX_ROWS kept, or compared with those kept when
 * again): the status that ended them, the message in err. */
static int read_rows(measured_reader *m, int again, uint64_t *count, char *err, size_t size)
{
    measured_row row;
    int status;
    *count = 0;
    err[0] = '\0';
    while ((status = measured_next(m, &row, err, size)) == 1) {
        const uint64_t k = *count + 1;
        if (!isfinite(row.t) || !isfinite(row.base_accel) || !isfinite(row.signal)
            || (m->header.has_truth ? !isfinite(row.s_true) : !isnan(row.s_true)))
            fuzz_fail("measured_next gave a row that is not finite, or s_true not as the column line says");
        if (!(fabs(row.t - (double)k / m->header.rate) <= 0.01 / m->header.rate))
            fuzz_fail("measured_next gave a row whose t is not k / rate");
        if (m->rows != k)
            fuzz_fail("measured_next counted its rows wrongly");
        if (k <= MAX_ROWS) {
            if (!again)
                rows[k - 1] = row;
            else if (memcmp(&rows[k - 1], &row, sizeof row) != 0)
                fuzz_fail("measured_rewind read another row than the first pass");
        }
        *count = k;
    }
    if (status != 0 && status != -1)
        fuzz_fail("measured_next answered neither 1, 0 nor -1");
    fuzz_check_message(status, err, size);
    return status;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static measured_reader m;
    const char *path = fuzz_path("measured.csv");
    const measured_header *h = &m.header;
    char err[1024], first_err[1024];
    uint64_t first, second;
    int status, again;

    fuzz_write(path, data, size);
    err[0] = '\0';
    status = measured_open(&m, path, err, sizeof err);
    fuzz_check_message(status, err, sizeof err);
    if (status != 0) {
        if (m.file)
            fuzz_fail("measured_open refused and left the file open");
        return 0;
    }
    if (!(h->rate >= MEASURED_RATE_MIN && h->rate <= MEASURED_RATE_MAX)
        || (h->signal != MEASURED_DEFLECTION && h->signal != MEASURED_VOLTAGE)
        || !(isnan(h->noise) || (isfinite(h->noise) && h->noise > 0.0))
        || !(isnan(h->accel_noise) || (isfinite(h->accel_noise) && h->accel_noise >= 0.0))
        || !(isnan(h->latency) || (isfinite(h->latency) && h->latency >= 0.0)) || m.rows != 0)
        fuzz_fail("measured_open accepted a header outside the grammar");

    status = read_rows(&m, 0, &first, first_err, sizeof first_err);
    if (status == 0 && first == 0)
        fuzz_fail("measured_next ended a stream of no row without an error");
    if (measured_rewind(&m, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        fuzz_fail("measured_rewind refused a file");
    }
    again = read_rows(&m, 1, &second, err, sizeof err);
    if (again != status || second != first || strcmp(err, first_err) != 0) {
        fprintf(stderr, "first: %d after %llu rows (%s); again: %d after %llu rows (%s)\n", status,
                (unsigned long long)first, first_err, again, (unsigned long long)second, err);
        fuzz_fail("measured_rewind read the rows otherwise than the first pass");
    }
    measured_close(&m);
    if (m.file)
        fuzz_fail("measured_close left the file open");
    return 0;
}
