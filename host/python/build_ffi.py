"""build_ffi.py - the cffi builders of the package's two extension modules.

cffi in API mode, out of line: for each precision one module
(beamslider._double, beamslider._float32) compiled from the public headers
of that precision's build and the shim (beamslider/_shim.c), and linked with
the position-independent archives `make lib` makes (build/lib/
libbeamslider-host-P.a and libbeamslider-P.a). Linking the archives into the
module keeps it whole: no LD_LIBRARY_PATH, no rpath into the source tree,
and an installed package keeps working when build/ is cleaned. Their
symbols are kept inside the module (exports.map), so that both
precisions' modules, which hold two builds of the same bs_* names, can be
loaded by one process.

The structs whose layout belongs to the build (bs_sim, bs_scene,
bs_observer) are declared opaque with `...`: cffi asks the compiler for
their size and alignment, so ffi.new("bs_sim *") allocates what this build's
bs_sim needs. Structs whose members Python reads are declared with the
members it reads and `...`: the compiler places them. The macros that pass
sizes and the build tag (bs_sim_init, bs_observer_init, bs_host_scene_load,
bs_host_twin_design) are called through the shim's functions.

Used by setup.py (cffi_modules), or alone: `python3 build_ffi.py [DIR]`
compiles both modules into DIR (default: beamslider/ beside this file).

The repository root is two folders up; BEAMSLIDER_BUILD names the build
folder (default ROOT/build, make's BUILD).
"""

import os
import re
import sys

import cffi

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BUILD = os.path.abspath(os.environ.get("BEAMSLIDER_BUILD", os.path.join(ROOT, "build")))

# precision module name -> the REAL of make's build
PRECISIONS = {"double": "double", "float32": "float"}
EXPORTS = os.path.join(HERE, "exports.map")

# What Python calls of the core and the host library, as cffi reads them. The
# shim's declarations (_shim.h) are appended.
CDEF = """
typedef %(real)s bs_real;
typedef int... bs_status;
typedef int... bs_model;
typedef int... bs_host_status;

#define BS_OK ...
#define BS_E_ARGUMENT ...
#define BS_E_BUILD ...
#define BS_E_CHECKPOINT_SIZE ...
#define BS_E_CHECKPOINT_DAMAGED ...
#define BS_E_CHECKPOINT_BUILD ...
#define BS_E_CHECKPOINT_SCENE ...
#define BS_MODEL_FREE ...
#define BS_MODEL_PCS ...
#define BS_SIGNAL_DEFLECTION ...
#define BS_SIGNAL_VOLTAGE ...
#define BS_HOST_OK ...
#define BS_HOST_E_INPUT ...
#define BS_HOST_E_FAILED ...
#define BS_HOST_E_MEMORY ...
#define BS_HOST_E_BUILD ...
#define BS_HOST_E_NULL ...
#define BS_MAX_MODES ...
#define BS_OBSERVER_MAPS ...
#define BS_OBSERVER_MAX_LATENCY ...
#define BS_VERSION_MAJOR ...
#define BS_VERSION_MINOR ...
#define BS_VERSION_PATCH ...
static const char *const BS_VERSION_STRING;
static const char *const BS_REAL_NAME;
static const size_t BS_CHECKPOINT_SIZE;

typedef struct { ...; } bs_sim;
typedef struct { ...; } bs_scene;
typedef struct { ...; } bs_observer;
typedef struct bs_host_scene bs_host_scene;

typedef struct {
    int max_sweeps;
    bs_real tol_rel;
    bs_real tol_abs;
    int measure_residual;
    ...;
} bs_solver_options;

typedef struct {
    unsigned active;
    int sweeps;
    int systems;
    bs_real residual;
    int converged;
    ...;
} bs_step_report;

typedef struct {
    int present;
    bs_real voltage;
    bs_real storage_voltage;
    bs_real power;
    bs_real energy;
    ...;
} bs_transducer_output;

typedef struct {
    int n_modes;
    int signal;
    int latency;
    bs_real noise;
    int gain_count;
    int map_count;
    bs_real map_frequency[...];
    bs_real map_accel[...];
    bs_real map_friction[...];
    int table_count;
    ...;
} bs_observer_gains;

typedef struct {
    int correct_beam;
    int correct_position;
    bs_real lockin_time;
    bs_real position_gain;
    bs_real position_rate;
    bs_real position_deadband;
    bs_real sigma_hold;
    bs_real excitation_tolerance;
    bs_real settle_time;
    bs_real outlier_gate;
    ...;
} bs_observer_options;

typedef struct {
    bs_real s;
    bs_real s_sigma;
    bs_real s_error;
    bs_real amplitude;
    bs_real power;
    bs_real phase_error;
    bs_real frequency;
    bs_real measurement;
    bs_real prediction;
    bs_real innovation;
    bs_real innovation_rms;
    uint32_t outliers;
    int health;
    ...;
} bs_observer_estimate;

typedef struct {
    bs_host_status status;
    char text[...];
    ...;
} bs_host_error;

typedef void (*bs_host_progress)(void *context, double fraction, const char *detail);

typedef struct {
    const char *name;
    bs_model model;
    double s0;
    double t_end;
    double dt;
    uint64_t steps;
    double frequency;
    double acceleration;
    int has_schedule;
    bs_solver_options solver;
    ...;
} bs_host_setup;

typedef struct {
    int n;
    double frequency[...];
    double lambda[...];
    double gamma[...];
    double phi_sensor[...];
    double kappa;
    double width;
    double k_axial;
    int shape_pieces;
    double fit_error_phi;
    double fit_error_slope;
    ...;
} bs_host_modes;

typedef struct {
    bs_status status;
    int stopped;
    uint64_t steps;
    double t;
    double s_final;
    double s_min;
    double t_s_min;
    double amp_final_h;
    int amp_periods;
    uint32_t hash;
    int transducer;
    double energy;
    double power_mean;
    double power_last;
    uint64_t contact_steps;
    uint64_t unconverged_steps;
    int max_sweeps;
    int max_systems;
    double wall_s;
    ...;
} bs_host_run_result;

typedef struct {
    double s;
    double amp_h;
    double v_mean;
    ...;
} bs_host_sweep_point;

typedef struct {
    const char *dir;
    const char *const *vary;
    int vary_count;
    int repeat;
    int jobs;
    int shard_index;
    int shard_count;
    bs_host_progress progress;
    void *progress_context;
    ...;
} bs_host_map_options;

typedef struct {
    long points;
    long cases;
    long shard_cases;
    long skipped;
    long run;
    long done;
    int complete;
    int jobs;
    double wall_s;
    char warnings[...];
    ...;
} bs_host_map_result;

typedef struct {
    int signal;
    double noise;
    double force_noise;
    double accel_noise;
    double latency;
    int map_count;
    double map_frequency[...];
    int friction_count;
    double map_friction[...];
    bs_host_progress progress;
    void *progress_context;
    ...;
} bs_host_twin_options;

typedef struct {
    double rate;
    int signal;
    double noise;
    double accel_noise;
    double latency;
    int has_truth;
    ...;
} bs_host_measured_header;

const char *bs_version(void);
const char *bs_status_text(bs_status status);
const char *bs_host_status_text(bs_host_status status);

bs_status bs_sim_set_solver(bs_sim *sim, const bs_solver_options *options);
bs_status bs_sim_get_solver(const bs_sim *sim, bs_solver_options *options);
bs_status bs_sim_set_pcs_position(bs_sim *sim, bs_real s);
bs_status bs_sim_step(bs_sim *sim);
bs_status bs_sim_step_measured(bs_sim *sim, bs_real base_accel);
bs_status bs_sim_set_excitation(bs_sim *sim, bs_real frequency, bs_real amplitude);
bs_status bs_sim_get_excitation(const bs_sim *sim, bs_real *frequency, bs_real *amplitude);
bs_status bs_sim_set_contact_laws(bs_sim *sim, bs_real mu, bs_real e_n);
bs_status bs_sim_get_contact_laws(const bs_sim *sim, bs_real *mu, bs_real *e_n);
bs_real bs_sim_base_acceleration(const bs_sim *sim);
bs_status bs_sim_get_transducer(const bs_sim *sim, bs_transducer_output *out);
bs_status bs_sim_get_report(const bs_sim *sim, bs_step_report *report);
bs_real bs_sim_sensor(const bs_sim *sim);
bs_real bs_sim_position(const bs_sim *sim);
bs_status bs_sim_beam_at(const bs_sim *sim, bs_real x, bs_real *w, bs_real *w_slope);
bs_status bs_sim_get_state(const bs_sim *sim, bs_real *q_beam, bs_real *u_beam, bs_real *slider,
                           bs_real *slider_velocity);
bs_status bs_sim_set_state(bs_sim *sim, const bs_real *q_beam, const bs_real *u_beam,
                           const bs_real *slider, const bs_real *slider_velocity);
bs_real bs_sim_phase(const bs_sim *sim);
uint64_t bs_sim_steps(const bs_sim *sim);
bs_real bs_sim_time(const bs_sim *sim);
uint32_t bs_sim_hash(const bs_sim *sim);
uint32_t bs_scene_hash(const bs_scene *scene);
bs_status bs_sim_save(const bs_sim *sim, void *buffer, size_t size);
bs_status bs_sim_restore(bs_sim *sim, const void *buffer, size_t size);

bs_observer_options bs_observer_defaults(void);
bs_status bs_observer_step(bs_observer *obs, bs_sim *sim, bs_real base_accel, bs_real measurement);
bs_status bs_observer_predict(bs_observer *obs, bs_sim *sim, bs_real base_accel);
bs_status bs_observer_get(const bs_observer *obs, bs_observer_estimate *estimate);

void bs_host_scene_free(bs_host_scene *scene);
const bs_scene *bs_host_scene_core(const bs_host_scene *scene);
void bs_host_scene_setup(const bs_host_scene *scene, bs_host_setup *setup);
bs_host_status bs_host_scene_value(const bs_host_scene *scene, const char *field, char *out, size_t size,
                                   bs_host_error *error);
void bs_host_scene_modes(const bs_host_scene *scene, bs_host_modes *modes);
double bs_host_attached_frequency(const bs_host_scene *scene, double s);
double bs_host_attached_position(const bs_host_scene *scene, double frequency);
void bs_host_map_defaults(bs_host_map_options *options);
bs_host_status bs_host_map(const bs_host_scene *scene, const bs_host_map_options *options,
                           bs_host_map_result *result, bs_host_error *error);
void bs_host_twin_defaults(bs_host_twin_options *options, double noise);

/* the progress callback of runs, sweeps, maps and designs (beamslider/_api.py) */
extern "Python" void bspy_progress(void *context, double fraction, const char *detail);
"""


def shim_declarations():
    """_shim.h without its preprocessor lines: the shim's part of the cdef."""
    with open(os.path.join(HERE, "beamslider", "_shim.h")) as header:
        text = header.read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("#"))


def library_files(real):
    """The archives and include folders of make's build for real."""
    archives = [os.path.join(BUILD, "lib", "libbeamslider-host-%s.a" % real),
                os.path.join(BUILD, "lib", "libbeamslider-%s.a" % real)]
    includes = [os.path.join(BUILD, real, "include"), os.path.join(ROOT, "core", "include"),
                os.path.join(ROOT, "host", "include"), os.path.join(HERE, "beamslider")]
    return archives, includes


def missing_files():
    """The files of `make lib` not there yet."""
    missing = []
    for real in PRECISIONS.values():
        archives, includes = library_files(real)
        missing += [path for path in archives + [os.path.join(includes[0], "bs_build_config.h")]
                    if not os.path.exists(path)]
    return missing


def builder(precision, relative=True):
    """The FFI builder of beamslider._<precision>; its source path relative
    to the working folder (setuptools refuses an absolute one) or not (a
    compile in another folder)."""
    real = PRECISIONS[precision]
    archives, includes = library_files(real)
    ffi = cffi.FFI()
    ffi.cdef(CDEF % {"real": "float" if real == "float" else "double"} + shim_declarations())
    rel = os.path.relpath if relative else os.path.abspath
    ffi.set_source(
        "beamslider._" + precision,
        # the shim is compiled inside the module: one translation unit per precision
        '#include "_shim.c"\n',
        include_dirs=includes,
        extra_objects=archives,
        libraries=["inih", "cjson", "m"],
        # -ffp-contract=off as the library's build; the archives' symbols stay in the module
        extra_compile_args=["-std=c99", "-ffp-contract=off", "-Wall", "-Wextra", "-Wno-unused-parameter"],
        extra_link_args=["-pthread", "-Wl,--exclude-libs,ALL", "-Wl,--version-script=" + EXPORTS],
        # (the archives are not among the dependencies setuptools compares: `make python` forces a
        # build when they change; setuptools takes relative paths only)
        depends=[rel(os.path.join(HERE, "beamslider", name)) for name in ("_shim.c", "_shim.h")] + [rel(EXPORTS)],
    )
    return ffi


ffi_double = builder("double")
ffi_float32 = builder("float32")

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else HERE
    for name in PRECISIONS:
        builder(name, relative=False).compile(tmpdir=out, verbose=True)
