/* observer_design.h - the constants of the twin's observer (core/include/
 * bs_observer.h), designed on the host in double: the steady-state Kalman
 * gains of the linear modal model and the slider table (docs/twin.md,
 * "Observer"). */
#ifndef OBSERVER_DESIGN_H
#define OBSERVER_DESIGN_H

#include <stddef.h>
#include <stdio.h>
#include "bs_observer.h"
#include "progress_hook.h"
#include "scene_build.h"

/* What the gains are designed for. */
typedef struct observer_design_options {
    int signal;           /* BS_SIGNAL_DEFLECTION or BS_SIGNAL_VOLTAGE (resistor load only) */
    double noise;         /* measurement noise standard deviation per sample [m or V], > 0 */
    double force_noise;   /* process noise: one-sided density of an unmodelled force acting at a
                             random point of the beam [N/sqrt(Hz)], >= 0 (the contacts the linear
                             model leaves out) */
    double accel_noise;   /* noise of the measured base acceleration, per sample [m/s^2], >= 0 */
    int latency;          /* the signal lags the base acceleration by this many steps,
                             0 .. BS_OBSERVER_MAX_LATENCY */
    int map_hold;         /* response map: excitation periods held at each point before ... (>= 0) */
    int map_record;       /* ... the first harmonic is taken over this many (>= 1) */
    int map_count;        /* response maps at map_frequency[], 1 .. BS_OBSERVER_MAPS; 0: from the
                             scene (observer_design) */
    double map_frequency[BS_OBSERVER_MAPS]; /* [Hz], > 0, ascending */
    int friction_count;   /* maps at each excitation, one per map_friction[], map_count (or the
                             scene's excitations) times friction_count at most BS_OBSERVER_MAPS;
                             0: one, at the scene's mu */
    double map_friction[BS_OBSERVER_MAPS]; /* mu, >= 0, ascending */
    progress_hook progress; /* NULL, or told the part done as the response maps are made */
    void *progress_context;
} observer_design_options;

/* The response maps may take at most this many steps of simulation in all
 * (under half a minute on a PC: fig6_shift's eight frequencies at three
 * frictions, 3.45e8 steps, take 15 CPU seconds): a map costs 2 x 48 x (hold
 * + record) excitation periods, and a period 1 / (f dt) steps, so maps at
 * low frequencies cost the most (one at 1 Hz with dt = 2e-5 s: 1.7e9 steps).
 * observer_design refuses more, with the estimate. */
#define OBSERVER_DESIGN_MAX_STEPS 4e8

/* Map frequencies are spaced by at most this ratio, so that every frequency
 * between the first and the last is within 1 % of one (the observer's
 * default frequency tolerance). */
#define OBSERVER_MAP_SPACING 1.02

/* Defaults (observer_design_defaults): deflection, no latency, no
 * acceleration noise, force noise OBSERVER_DEFAULT_FORCE_NOISE, map 150 + 200
 * periods per point (the high branch settles over ~140 periods after a step
 * of s: docs/twin.md, "Observer" 4; where the slider rattles, the first
 * harmonic over 40 periods scatters by ~2 % from point to point, over 200 by
 * ~1 %: "Quieter maps"), maps from the scene; noise has no default (the
 * caller states it). */
#define OBSERVER_DEFAULT_FORCE_NOISE 1e-3
#define OBSERVER_DEFAULT_MAP_HOLD 150
#define OBSERVER_DEFAULT_MAP_RECORD 200

/* The defaults, with noise as given. */
observer_design_options observer_design_defaults(double noise);

/* Designs the constants for scene, built from file (scene_build's model):
 * the linear modal model at the scene's dt (the core's own step without
 * contacts and stretching, with the patch and its resistor), the discrete
 * Riccati equation solved by the structure-preserving doubling algorithm,
 * K = P C^T / (C P C^T + R), gains = Phi^latency K; and a response map
 * over [stop_min / L, 1/2] from two PCS sweeps of scene at each map
 * frequency (about 2 x 48 x (hold + record) periods of simulation each).
 * The map frequencies are options->map_frequency[], or with map_count 0
 * the scene's excitation frequency, or, for a scene with an [excitation]
 * schedule, the fewest frequencies spaced by at most OBSERVER_MAP_SPACING
 * from its lowest to its highest (an error if more than BS_OBSERVER_MAPS
 * are needed). Each map's amplitude is that of the schedule point nearest
 * in frequency (of several, the strongest; without a schedule, the
 * scene's). With friction_count > 0 each excitation has a map at each of
 * options->map_friction[] (the sweeps' sim set to that mu, the scene's e_N),
 * which the observer interpolates at the twin's mu. Returns 0, or -1 with a
 * message in err. */
int observer_design(const scene_file *file, const scene_model *model, const bs_scene *scene,
                    const observer_design_options *options, bs_observer_gains *gains, char *err, size_t err_size);

/* Prints gains as a C header (`beamslider twin-gains`) through the C writer
 * (out_c.h): a static const bs_observer_gains named `name` (which must pass
 * out_c_identifier_check: else -1, nothing written), after a block comment
 * holding comment (any text). Returns 0, or -1 on a write error or a gain
 * that is not finite. */
int observer_print_gains(FILE *out, const bs_observer_gains *gains, const char *name, const char *comment);

#endif
