/* measured_signals.h - the measured-signals format (docs/twin.md, "Measured
 * signals file"): one grammar, one reader for every program that reads it
 * (`beamslider twin`, port/cortex-m/twin/twin_pack.c, libbeamslider-host)
 * and one writer for every program that writes it (`beamslider twin-plant`,
 * libbeamslider-host). The reader never prints: errors come back as
 * "FILE:LINE: what is wrong" in err.
 *
 * The grammar, line by line:
 *   1. "# beamslider measured signals", alone or followed by a blank and
 *      free text;
 *   2. header lines starting with '#': a line holding '=' is a field
 *      "# key = value" of a known key, each key at most once; a line
 *      without '=' is a free comment;
 *   3. the column line "t,base_accel,signal" or "t,base_accel,signal,s_true";
 *   4. one row per step k = 1, 2, ...: that many finite numbers separated by
 *      commas (blanks around them allowed), t within 1 % of a sample period
 *      of k / sample_rate.
 * Lines end in LF or CRLF and hold at most MEASURED_LINE - 1 characters. The
 * fields (value syntax; required or not):
 *   sample_rate      NUMBER Hz, 0.001 .. 1e10                     required
 *   signal           deflection | voltage                         required
 *   signal_unit      m (deflection) | V (voltage)                 optional
 *   base_accel_unit  m/s^2                                        optional
 *   latency          NUMBER s, >= 0 (informative)                 optional
 *   noise            NUMBER m | V (the signal's unit), > 0        optional
 *   accel_noise      NUMBER m/s^2, >= 0                           optional
 *   plant            free text: what produced the stream          optional
 */
#ifndef MEASURED_SIGNALS_H
#define MEASURED_SIGNALS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "input_file.h"

#define MEASURED_TITLE "# beamslider measured signals"
#define MEASURED_LINE 512
#define MEASURED_RATE_MIN 1e-3  /* [Hz], as a record's (excitation_file.h) */
#define MEASURED_RATE_MAX 1e10

/* The signal a stream measures (the values of bs_observer_signal and of
 * twin_stream.h). */
enum { MEASURED_DEFLECTION = 0, MEASURED_VOLTAGE = 1 };

typedef struct measured_header {
    double rate;         /* [Hz] */
    int signal;          /* MEASURED_DEFLECTION or MEASURED_VOLTAGE */
    double noise;        /* the signal's noise standard deviation [m or V]; NAN: not given */
    double accel_noise;  /* base_accel's [m/s^2]; NAN: not given */
    double latency;      /* [s], informative; NAN: not given */
    int has_truth;       /* the rows hold s_true */
} measured_header;

typedef struct measured_row {
    double t;            /* k / rate [s] */
    double base_accel;   /* the mean over (t - 1/rate, t] [m/s^2] */
    double signal;       /* at t, as delivered [m or V] */
    double s_true;       /* the plant's x_C / L; NAN without the column */
} measured_row;

/* A stream being read (members private, but header and rows may be read). */
typedef struct measured_reader {
    const char *path;    /* as given; "-": standard input */
    FILE *file;
    input_lines lines;
    measured_header header;
    uint64_t rows;       /* rows read */
    long rows_at;        /* the line of the column line */
    long long rows_offset; /* the byte after it (a file: where a second pass starts) */
    char text[MEASURED_LINE];
} measured_reader;

/* Opens path ("-": standard input, unbounded in length, bounded per line;
 * else a regular file, input_file.h) and reads its header through the
 * column line. 0, or -1 with err (nothing left open). */
int measured_open(measured_reader *m, const char *path, char *err, size_t err_size);

/* The next row: 1; 0 at the end (a stream with no row at all is an
 * error); -1 with err. */
int measured_next(measured_reader *m, measured_row *row, char *err, size_t err_size);

/* Back to the first row, for a second pass (a file, not standard input).
 * 0 or -1 with err. */
int measured_rewind(measured_reader *m, char *err, size_t err_size);

void measured_close(measured_reader *m);

/* "deflection" or "voltage". */
const char *measured_signal_name(int signal);

/* The writer: the title line, then the header of h (rate; signal with its
 * unit; the base acceleration's unit; latency, noise and accel_noise unless
 * NAN; plant unless NULL, made one line so that no text of it can forge a
 * field), then the column line (with s_true when h->has_truth). Numbers are
 * written with enough digits to read back what was meant (rate 12, the
 * others 9 significant digits). 0, or -1 on a write error. */
int measured_write_header(FILE *out, const measured_header *h, const char *plant);

/* One row: t (12 significant digits: long runs), base_accel, signal and,
 * when the header has truth, s_true (9 each). 0, or -1 on a write error. */
int measured_write_row(FILE *out, const measured_row *row, int has_truth);

#endif
