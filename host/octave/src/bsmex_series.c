/* bsmex_series.c - time series of a sim as columns (bsmex.h).
 *
 * The columns are those of `beamslider run --out` (host/lib/run/run.c),
 * read with the core's functions, in the same order and units: t [s],
 * w_sensor = w(4L/7) [m], s = x_C / L, z_r [m] and beta [rad] of the slider,
 * the active contacts, the sweeps and residual of the contact solve, and
 * with a transducer v [V], p [W] and v_s [V]. One table, read by the
 * writer of rows and the one of fields.
 */
#include "bsmex.h"

#include <string.h>

typedef struct row_source {
    const bs_sim *sim;
    double t;
    bs_step_report report;
    bs_transducer_output transducer;
    bs_real slider[3];
} row_source;

static double col_t(const row_source *r) { return r->t; }
static double col_w_sensor(const row_source *r) { return (double)bs_sim_sensor(r->sim); }
static double col_s(const row_source *r) { return (double)bs_sim_position(r->sim); }
static double col_z_r(const row_source *r) { return (double)r->slider[1]; }
static double col_beta(const row_source *r) { return (double)r->slider[2]; }
static double col_contacts(const row_source *r) { return (double)r->report.active; }
static double col_pgs_iters(const row_source *r) { return (double)r->report.sweeps; }
static double col_pgs_residual(const row_source *r) { return (double)r->report.residual; }
static double col_v(const row_source *r) { return (double)r->transducer.voltage; }
static double col_p(const row_source *r) { return (double)r->transducer.power; }
static double col_v_s(const row_source *r) { return (double)r->transducer.storage_voltage; }

/* The transducer's columns come last (BSMEX_PLAIN_COLUMNS before them). */
#define BSMEX_PLAIN_COLUMNS 8
static const struct column {
    const char *name;
    double (*read)(const row_source *r);
} columns[BSMEX_COLUMNS] = {
    { "t", col_t },
    { "w_sensor", col_w_sensor },
    { "s", col_s },
    { "z_r", col_z_r },
    { "beta", col_beta },
    { "contacts", col_contacts },
    { "pgs_iters", col_pgs_iters },
    { "pgs_residual", col_pgs_residual },
    { "v", col_v },
    { "p", col_p },
    { "v_s", col_v_s },
};

void bsmex_series_start(bsmex_series *series, size_t room, int transducer)
{
    int i;
    memset(series, 0, sizeof *series);
    series->room = room;
    series->columns = transducer ? BSMEX_COLUMNS : BSMEX_PLAIN_COLUMNS;
    for (i = 0; i < series->columns; ++i) {
        series->array[i] = mxCreateDoubleMatrix((mwSize)room, 1, mxREAL);
        series->column[i] = (double *)mxGetData(series->array[i]);
    }
}

void bsmex_series_add(bsmex_series *series, const bs_sim *sim, double t)
{
    row_source r;
    int i;
    if (series->rows >= series->room)
        return;
    r.sim = sim;
    r.t = t;
    bs_sim_get_report(sim, &r.report);
    bs_sim_get_transducer(sim, &r.transducer);
    bs_sim_get_state(sim, NULL, NULL, r.slider, NULL);
    for (i = 0; i < series->columns; ++i)
        series->column[i][series->rows] = columns[i].read(&r);
    series->rows++;
}

void bsmex_field(mxArray *out, const char *name, mxArray *value)
{
    int field = mxGetFieldNumber(out, name);
    if (field < 0)
        field = mxAddField(out, name);
    mxSetFieldByNumber(out, 0, field, value);
}

void bsmex_series_finish(bsmex_series *series, mxArray *out)
{
    int i;
    for (i = 0; i < series->columns; ++i) {
        mxSetM(series->array[i], (mwSize)series->rows);
        bsmex_field(out, columns[i].name, series->array[i]);
        series->array[i] = NULL;
    }
}
