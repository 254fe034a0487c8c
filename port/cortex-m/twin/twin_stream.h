/* twin_stream.h - a recorded plant run as the twin firmware reads it: the
 * measured-signals CSV of `beamslider twin-plant` (docs/twin.md, "Measured
 * signals file") in binary, written on the host by twin_pack.c.
 *
 * Layout, little-endian (the host and the Cortex-M both are):
 *   twin_stream_header (24 bytes), then `samples` twin_stream_sample.
 * Sample k (k = 1, 2, ...; t = k dt) holds the mean base acceleration over
 * (t - dt, t] [m/s^2] and the beam signal at t [m or V], each an IEEE
 * float32: the twin computes in float on the M4F, and twin_pack rounds each
 * CSV value once, as `beamslider twin` does in a float build
 * ((float)strtod), so both twins see the same numbers. 8 bytes a sample:
 * 24 MB for fig6's 60 s.
 */
#ifndef TWIN_STREAM_H
#define TWIN_STREAM_H

#include <stdint.h>

#define TWIN_STREAM_MAGIC "BSTW"
#define TWIN_STREAM_VERSION 1u

typedef struct twin_stream_header {
    char magic[4];        /* TWIN_STREAM_MAGIC, no terminating zero */
    uint32_t version;     /* TWIN_STREAM_VERSION */
    uint32_t sample_rate; /* [Hz]: 1/dt of the twin's scene (the firmware refuses another) */
    uint32_t signal;      /* bs_observer_signal: 0 deflection w(4L/7) [m], 1 patch voltage [V] */
    uint32_t samples;     /* samples that follow */
    float noise;          /* the signal's noise standard deviation from the CSV, 0 if none (informative) */
} twin_stream_header;

typedef struct twin_stream_sample {
    float base_accel; /* [m/s^2] */
    float signal;     /* [m] or [V] */
} twin_stream_sample;

#endif
