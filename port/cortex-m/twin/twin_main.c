/* twin_main.c - the digital twin as a firmware (README.md here): a bs_sim of
 * the compiled scene (BS_SCENE_CONFIG), corrected by the observer
 * (core/include/bs_observer.h) from the measured base acceleration and beam
 * signal, which arrive one sample per dt through a FIFO.
 *
 *   producer  twin_produce(), once per sample period (the clock's interrupt):
 *             one sample from the source's current block into the FIFO, a
 *             new block from the source when the last one is used up
 *   consumer  main(): takes samples out of the FIFO and steps the observer
 *             (and the twin in it), one step per sample; steps through the
 *             gap before a sample without measurement when the producer had
 *             to drop samples (twin_fifo.h, "Overrun policy")
 *   reports   every 0.1 s of the twin's time: s, s_sigma, amplitude and
 *             power, the FIFO's queue and losses, the state hashes; at the
 *             end the counts of everything
 *
 * Build switches (-D): TWIN_STREAM (the stream file, twin_stream.h),
 * TWIN_COST (1: every producer call and every observer step bracketed by
 * bs_board_mark() for the instruction counter, and the stack measured),
 * TWIN_CONSTANTS_IN_RAM (1: the scene and the gains copied to RAM before the
 * run, so that a step reads no constant from flash), TWIN_FIFO_SAMPLES,
 * TWIN_BLOCK_SAMPLES, TWIN_FRICTION_GAIN (the observer's friction_gain: 0,
 * the default, no friction estimate), TWIN_FRICTION_SIGMA,
 * TWIN_FRICTION_AMPLITUDE, TWIN_FRICTION_CLIMB and TWIN_FRICTION_DEADBAND (its gates and
 * deadband; a cost image opens the gates and widens the deadband so that
 * the estimate runs every update without changing mu, and so the
 * trajectory: docs/twin.md, "Friction"), TWIN_FRICTION_WALK (friction_walk:
 * the walk's cost image runs it at a gain too small to move mu: "The
 * walk"), and those
 * of the clock (twin_clock_*.c). The gains come
 * from twin_gains.h on the include path: `beamslider twin-gains SCENE.ini
 * --noise SIGMA --name twin_gains > twin_gains.h`.
 */
#include <stdio.h>
#include <string.h>
#include "beamslider.h"
#include "bs_observer.h"
#include BS_SCENE_CONFIG
#include "twin_gains.h"
#include "bs_board.h"
#include "twin_board.h"
#include "twin_fifo.h"

#ifndef TWIN_STREAM
#define TWIN_STREAM "twin.stream"
#endif
#ifndef TWIN_COST
#define TWIN_COST 0
#endif
#ifndef TWIN_CONSTANTS_IN_RAM
#define TWIN_CONSTANTS_IN_RAM 0
#endif
/* Samples the producer takes from the source at a time: the size of an
 * ADC's DMA block on a board (8 bytes a sample). */
#ifndef TWIN_BLOCK_SAMPLES
#define TWIN_BLOCK_SAMPLES 256u
#endif
#ifndef TWIN_FRICTION_GAIN
#define TWIN_FRICTION_GAIN 0.0
#endif
#ifndef TWIN_FRICTION_SIGMA
#define TWIN_FRICTION_SIGMA BS_OBSERVER_DEFAULT_FRICTION_SIGMA
#endif
#ifndef TWIN_FRICTION_AMPLITUDE
#define TWIN_FRICTION_AMPLITUDE BS_OBSERVER_DEFAULT_FRICTION_AMPLITUDE
#endif
#ifndef TWIN_FRICTION_CLIMB
#define TWIN_FRICTION_CLIMB BS_OBSERVER_DEFAULT_FRICTION_CLIMB
#endif
#ifndef TWIN_FRICTION_DEADBAND
#define TWIN_FRICTION_DEADBAND BS_OBSERVER_DEFAULT_FRICTION_DEADBAND
#endif
#ifndef TWIN_FRICTION_WALK
#define TWIN_FRICTION_WALK BS_OBSERVER_DEFAULT_FRICTION_WALK
#endif

static bs_sim twin;
static bs_observer obs;
static twin_fifo fifo;
#if TWIN_CONSTANTS_IN_RAM
static bs_scene scene_in_ram;
static bs_observer_gains gains_in_ram;
#endif

/* The producer's state (written in the interrupt only). */
static twin_stream_sample block[TWIN_BLOCK_SAMPLES];
static uint32_t block_size, block_next;
static volatile int source_done; /* the source has no more samples */

/* What the consumer counts. */
typedef struct twin_tally {
    uint32_t steps;     /* twin steps: measured + predicted */
    uint32_t measured;  /* samples the observer got */
    uint32_t predicted; /* steps through gaps, without measurement */
    uint32_t gaps;      /* gaps met */
    uint32_t longest;   /* the longest gap [samples] */
} twin_tally;

/* A report, taken in the step path when due, printed by the main loop. */
typedef struct twin_report {
    int due;
    uint32_t tenths; /* the twin's time [0.1 s] */
    bs_observer_estimate estimate;
    uint32_t queued;  /* samples in the FIFO */
    uint32_t lag;     /* samples the twin is behind the plant: arrived (stored or dropped), not yet stepped */
    uint32_t dropped;
    uint32_t hash, estimate_hash;
} twin_report;

static twin_tally tally;
static twin_report pending;
static uint32_t report_steps;  /* steps in 0.1 s */
static uint32_t report_in;     /* steps to the next report (a countdown: no division a step) */
static bs_real last_accel;     /* the last sample's base acceleration */

static void produce(void)
{
    if (block_next == block_size) {
        if (source_done)
            return;
        block_size = twin_source_read(block, TWIN_BLOCK_SAMPLES);
        block_next = 0;
        if (block_size == 0) {
            source_done = 1;
            return;
        }
    }
    twin_fifo_push(&fifo, block[block_next].base_accel, block[block_next].signal);
    ++block_next;
}

void twin_produce(void)
{
    if (TWIN_COST)
        bs_board_mark();
    produce();
    if (TWIN_COST)
        bs_board_mark();
}

/* FNV-1a over the estimate's bytes: equal hashes, bit-identical estimates. */
static uint32_t estimate_hash(const bs_observer_estimate *estimate)
{
    const unsigned char *byte = (const unsigned char *)estimate;
    uint32_t hash = 2166136261u;
    size_t i;
    for (i = 0; i < sizeof *estimate; ++i)
        hash = (hash ^ byte[i]) * 16777619u;
    return hash;
}

/* Takes the report due after this step (once in report_steps). */
static void take_report(void)
{
    report_in = report_steps;
    pending.due = 1; /* a second report due before the first is printed (a gap over 0.1 s) replaces it */
    pending.tenths = tally.steps / report_steps;
    bs_observer_get(&obs, &pending.estimate);
    pending.queued = twin_fifo_queued(&fifo);
    pending.dropped = fifo.dropped;
    pending.lag = fifo.head + pending.dropped - tally.steps;
    pending.hash = bs_sim_hash(&twin);
    pending.estimate_hash = estimate_hash(&pending.estimate);
}

/* The bookkeeping after every step: inline, its rare part a call (the
 * whole of it as a call: 23 estimated cycles a sample more, flash;
 * tests/qemu/twin_probe.sh on twin-cost-friction-off 2592.4 -> 2569.4). */
static inline void after_step(void)
{
    ++tally.steps;
    if (--report_in == 0)
        take_report();
}

/* One sample out of the FIFO: the gap before it, then its observer step. A
 * gap is stepped through on the base acceleration interpolated between the
 * samples either side (a straight line: fig6's period is 400 samples), with
 * no measurement (bs_observer_predict), so that the twin's time stays the
 * plant's and the observer's delay line stays aligned. */
static bs_status consume(const twin_fifo_entry *sample)
{
    const bs_real accel = (bs_real)sample->base_accel;
    bs_status status;
    uint32_t j;

    if (sample->gap > 0) {
        tally.gaps += 1;
        if (sample->gap > tally.longest)
            tally.longest = sample->gap;
    }
    for (j = 1; j <= sample->gap; ++j) {
        const bs_real part = (bs_real)j / (bs_real)(sample->gap + 1u);
        status = bs_observer_predict(&obs, &twin, last_accel + (accel - last_accel) * part);
        if (status != BS_OK)
            return status;
        ++tally.predicted;
        after_step();
    }
    if (TWIN_COST)
        bs_board_mark();
    status = bs_observer_step(&obs, &twin, accel, (bs_real)sample->signal);
    if (TWIN_COST)
        bs_board_mark();
    if (status != BS_OK)
        return status;
    ++tally.measured;
    last_accel = accel;
    after_step();
    twin_clock_spent(sample->gap + 1u);
    return BS_OK;
}

static void print_report(const twin_report *r)
{
    const bs_observer_estimate *e = &r->estimate;
    /* s, s_sigma, amplitude, power, outliers, health as `beamslider twin` writes them (--out) */
    printf("t %lu.%lu s %.9g s_sigma %.4g amplitude %.6g power %.6g outliers %lu health %d queued %lu lag %lu "
           "dropped %lu hash %08lx est %08lx\n", (unsigned long)(r->tenths / 10u), (unsigned long)(r->tenths % 10u),
           (double)e->s, (double)e->s_sigma, (double)e->amplitude, (double)e->power, (unsigned long)e->outliers,
           e->health, (unsigned long)r->queued, (unsigned long)r->lag, (unsigned long)r->dropped,
           (unsigned long)r->hash, (unsigned long)r->estimate_hash);
}

/* The twin and its observer on scene and gains. */
static bs_status start(const bs_scene *scene, const bs_observer_gains *gains)
{
    bs_solver_options solver;
    bs_observer_options options = bs_observer_defaults();
    bs_status status = bs_sim_init(&twin, scene, BS_MODEL_FREE, BS_SCENE_START);
    if (status != BS_OK)
        return status;
    options.friction_gain = (bs_real)TWIN_FRICTION_GAIN;
    options.friction_sigma = (bs_real)TWIN_FRICTION_SIGMA;
    options.friction_amplitude = (bs_real)TWIN_FRICTION_AMPLITUDE;
    options.friction_climb = (bs_real)TWIN_FRICTION_CLIMB;
    options.friction_deadband = (bs_real)TWIN_FRICTION_DEADBAND;
    options.friction_walk = (bs_real)TWIN_FRICTION_WALK;
    solver.max_sweeps = BS_SCENE_SOLVER_MAX_SWEEPS;
    solver.tol_rel = BS_SCENE_SOLVER_TOL_REL;
    solver.tol_abs = BS_SCENE_SOLVER_TOL_ABS;
    /* The solve's residual is a diagnostic the firmware neither reports nor
     * acts on (the health flag is the observer's outliers): not measured,
     * whatever the scene says. The twin's state is the same bit for bit. */
    solver.measure_residual = 0;
    status = bs_sim_set_solver(&twin, &solver);
    return status != BS_OK ? status : bs_observer_init(&obs, &twin, gains, &options);
}

int main(void)
{
    const bs_scene *scene = &bs_compiled_scene;
    const bs_observer_gains *gains = &twin_gains;
    twin_stream_header header;
    bs_status status = BS_OK;
    unsigned stack = 0;
    int stack_full = 0; /* the loop wrote the whole painted region: its use is not known */
    bs_real rate_dt;

    if (bs_build_check() != BS_OK) {
        printf("twin: this program and the core were built differently\n");
        return 1;
    }
#if TWIN_CONSTANTS_IN_RAM
    memcpy(&scene_in_ram, scene, sizeof scene_in_ram);
    memcpy(&gains_in_ram, gains, sizeof gains_in_ram);
    scene = &scene_in_ram;
    gains = &gains_in_ram;
#endif
    if (twin_source_open(TWIN_STREAM, &header) != 0 || header.version != TWIN_STREAM_VERSION) {
        printf("twin: %s: cannot open, or not a stream of version %u\n", TWIN_STREAM, TWIN_STREAM_VERSION);
        return 1;
    }
    printf("twin %s %s: %s, %lu samples at %lu Hz, signal %lu, fifo %u samples, clock %s\n", BS_SCENE_NAME,
           BS_REAL_NAME, TWIN_STREAM, (unsigned long)header.samples, (unsigned long)header.sample_rate,
           (unsigned long)header.signal, (unsigned)TWIN_FIFO_SAMPLES, twin_clock_describe());
    rate_dt = (bs_real)header.sample_rate * scene->dt;
    if (!(rate_dt > BS_R(0.9999) && rate_dt < BS_R(1.0001)) || header.signal != (uint32_t)gains->signal) {
        printf("twin: the stream is not for this scene and gains (sample rate 1/dt, signal %d)\n", gains->signal);
        return 1;
    }
    if (start(scene, gains) != BS_OK) {
        printf("twin: init refused\n");
        return 1;
    }
    report_steps = (uint32_t)(BS_R(0.1) / scene->dt + BS_R(0.5));
    report_in = report_steps;
    twin_fifo_init(&fifo);
    if (TWIN_COST)
        bs_board_stack_paint();
    twin_clock_start();
    for (;;) {
        const int done = source_done; /* read before the pop: a sample pushed after it is still taken */
        twin_fifo_entry sample;
        if (!twin_fifo_pop(&fifo, &sample)) {
            if (done)
                break;
            twin_clock_wait();
            continue;
        }
        status = consume(&sample);
        if (status != BS_OK)
            break;
        if (pending.due) { /* printed here, out of the step path (and its stack measured without it) */
            if (TWIN_COST) {
                const unsigned used = bs_board_stack_used();
                stack = used > stack ? used : stack;
                stack_full |= used >= bs_board_stack_painted();
            }
            print_report(&pending);
            pending.due = 0;
            if (TWIN_COST)
                bs_board_stack_paint();
        }
    }
    twin_clock_stop();
    if (TWIN_COST) {
        const unsigned used = bs_board_stack_used();
        stack = used > stack ? used : stack;
        stack_full |= used >= bs_board_stack_painted();
    }
    {
        bs_observer_estimate e;
        bs_observer_get(&obs, &e);
        printf("end status %d samples %lu steps %lu measured %lu predicted %lu dropped %lu gaps %lu longest-gap %lu "
               "most-queued %lu s %.9g hash %08lx est %08lx",
               (int)status, (unsigned long)(tally.measured + fifo.dropped), (unsigned long)tally.steps,
               (unsigned long)tally.measured, (unsigned long)tally.predicted, (unsigned long)fifo.dropped,
               (unsigned long)tally.gaps, (unsigned long)tally.longest, (unsigned long)fifo.most, (double)e.s,
               (unsigned long)bs_sim_hash(&twin), (unsigned long)estimate_hash(&e));
        if (TWIN_COST)
            printf(" stack %u", stack);
        printf("\n");
    }
    if (stack_full) {
        printf("twin: the main loop used all %u bytes of stack painted: raise BS_BOARD_STACK_PAINT_BYTES\n",
               bs_board_stack_painted());
        return 1;
    }
    return status != BS_OK || tally.measured + fifo.dropped != header.samples;
}
