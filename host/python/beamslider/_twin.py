"""The digital twin from Python: the observer's design (Gains), the observer
on a Sim (Observer) and the measured-signals format (Measured)
(core/include/bs_observer.h; docs/twin.md; docs/python.md, "The twin")."""

import numbers
import os

import numpy

from beamslider._backend import Hook
from beamslider._errors import ArgumentError, RunError
from beamslider._sim import _PROGRESS_CHUNK

_SIGNALS = ("deflection", "voltage")

ESTIMATE_DEFAULT = ("t", "s", "s_sigma", "amplitude", "innovation")


def _map_values(lib, name, values, slots):
    """values (1 to BS_OBSERVER_MAPS of them) into the C array slots; their
    count. Raises ArgumentError naming the option."""
    values = list(values)
    if not 1 <= len(values) <= lib.BS_OBSERVER_MAPS:
        raise ArgumentError("%s: %d values, allowed: 1 to %d" % (name, len(values), lib.BS_OBSERVER_MAPS))
    for i, v in enumerate(values):
        slots[i] = v
    return len(values)


class Gains:
    """The observer's constants for one scene, signal chain and noise
    (bs_observer_gains), designed by scene.twin_gains() or
    Gains.design(scene, noise, ...)."""

    _b = None

    def __init__(self, *args, **kwargs):
        raise TypeError("make Gains with Gains.design(scene, noise, ...)")

    @classmethod
    def design(cls, scene, noise, signal="deflection", force_noise=None, accel_noise=None, latency=0.0,
               map_frequencies=None, map_frictions=None, progress=None):
        """Designs the observer of `beamslider twin-gains` (bs_host_twin_design):
        noise, the signal's noise standard deviation [m or V]; signal
        "deflection" (w(4L/7) [m]) or "voltage" (the patch's [V], resistor
        load); force_noise [N/sqrt(Hz)], accel_noise [m/s^2], latency [s]
        (None: the library's defaults); map_frequencies: the response maps'
        excitation frequencies [Hz] (None: the scene's); map_frictions: mu
        at which each is made, followed at the twin's mu (None: the scene's
        mu; docs/twin.md, "Maps that follow mu"). Raises SceneError
        (an option out of range), RunError."""
        b = cls._b
        ffi, lib = b.ffi, b.lib
        if not isinstance(scene, b.Scene):
            raise TypeError("Gains.design(scene, ...): a %s.Scene, not %r" % (b.name, scene))
        if signal not in _SIGNALS:
            raise ArgumentError("signal %r: allowed: 'deflection' or 'voltage'" % (signal,))
        options = ffi.new("bs_host_twin_options *")
        lib.bs_host_twin_defaults(options, noise)
        options.signal = lib.BS_SIGNAL_VOLTAGE if signal == "voltage" else lib.BS_SIGNAL_DEFLECTION
        if force_noise is not None:
            options.force_noise = force_noise
        if accel_noise is not None:
            options.accel_noise = accel_noise
        options.latency = latency
        if map_frequencies is not None:
            options.map_count = _map_values(lib, "map_frequencies", map_frequencies, options.map_frequency)
        if map_frictions is not None:
            options.friction_count = _map_values(lib, "map_frictions", map_frictions, options.map_friction)
        hook = Hook(b, progress)
        options.progress = lib.bspy_progress
        options.progress_context = hook.handle
        self = object.__new__(cls)
        self._gains = ffi.new("bs_observer_gains *")
        error = ffi.new("bs_host_error *")
        status = lib.bspy_twin_design(scene._ptr, options, self._gains, error)
        hook.raise_error()
        if status != lib.BS_HOST_OK:
            raise b.host_error(status, error)
        self.scene = scene
        g = self._gains
        self.signal = _SIGNALS[g.signal]
        self.n_modes, self.latency, self.noise = g.n_modes, g.latency, float(g.noise)
        self.map_frequency = [float(g.map_frequency[i]) for i in range(g.map_count)]
        self.map_accel = [float(g.map_accel[i]) for i in range(g.map_count)]
        self.map_friction = [float(g.map_friction[i]) for i in range(g.map_count)]
        return self

    def __repr__(self):
        return "<Gains %s: %s, noise %g, latency %d steps, maps at %s Hz>" % (
            self.scene.name, self.signal, self.noise, self.latency, ", ".join("%g" % f for f in self.map_frequency))


class Observer:
    """The observer (bs_observer) correcting a Sim, the twin, from
    measurements: Observer(sim, gains, **options), options those of
    bs_observer_options (correct_beam, correct_position, lockin_time,
    position_gain, position_rate, position_deadband, sigma_hold,
    excitation_tolerance, settle_time, outlier_gate; the rest at their
    defaults). The sim's state is the first estimate."""

    _b = None

    def __init__(self, sim, gains, **options):
        b = self._b
        ffi, lib = b.ffi, b.lib
        if not isinstance(sim, b.Sim) or not isinstance(gains, b.Gains):
            raise TypeError("Observer(sim, gains): a %s.Sim and %s.Gains" % (b.name, b.name))
        settings = ffi.new("bs_observer_options *", lib.bs_observer_defaults())
        for name, value in options.items():
            if not hasattr(settings, name):
                raise TypeError("Observer: no option %r" % name)
            setattr(settings, name, value)
        self.sim = sim
        self.gains = gains
        self._obs = ffi.new("bs_observer *")
        b.check(lib.bspy_observer_init(self._obs, sim._sim, gains._gains, settings), "Observer")

    def step(self, accel, measurement, every=1, out=None, columns=ESTIMATE_DEFAULT, progress=None):
        """len(accel) steps: step i under the mean base acceleration accel[i]
        [m/s^2], corrected by measurement[i] (the signal of gains: [m] or
        [V]; NaN: a lost sample, the step predicts only). An Estimates row
        after every every-th step (out: Estimates to write into again).
        Raises RunError when a step fails."""
        b = self._b
        ffi, lib = b.ffi, b.lib
        accel = numpy.ascontiguousarray(accel, dtype=numpy.float64)
        measurement = numpy.ascontiguousarray(measurement, dtype=numpy.float64)
        if accel.ndim != 1 or accel.shape != measurement.shape:
            raise ArgumentError("accel and measurement: two 1-d arrays of one length, not shapes %s and %s"
                                % (accel.shape, measurement.shape))
        if not isinstance(every, numbers.Integral) or every < 1:
            raise ArgumentError("every = %r: allowed: an integer >= 1" % (every,))
        n = len(accel)
        estimates = out if out is not None else b.Estimates(n // every, columns)
        estimates._reset(n // every)
        a = ffi.cast("double *", accel.ctypes.data)
        y = ffi.cast("double *", measurement.ctypes.data)
        sim = self.sim
        chunk = n if progress is None else max(every, _PROGRESS_CHUNK // every * every)
        start = 0
        while True:
            k = min(chunk, n - start)
            if not sim._lock.acquire(blocking=False):
                raise RuntimeError("this Observer's Sim is stepping in another thread")
            try:
                status = lib.bspy_observer_steps(self._obs, sim._sim, a + start, y + start, k, sim.dt, every,
                                                 estimates._c, sim._done)
            finally:
                sim._lock.release()
            start += int(sim._done[0])
            if status != lib.BS_OK:
                text = b.status_text(status)
                raise RunError("%s: observer step %d: %s" % (sim.scene.name, sim.steps + 1, text), text, estimates)
            if progress is not None:
                progress(start / n if n else 1.0, None)
            if start >= n:
                return estimates

    def estimate(self):
        """The latest estimate (bs_observer_estimate) as a dict."""
        ffi, lib = self._b.ffi, self._b.lib
        e = ffi.new("bs_observer_estimate *")
        lib.bs_observer_get(self._obs, e)
        out = {name: float(getattr(e, name)) for name in
               ("s", "s_sigma", "s_error", "amplitude", "power", "phase_error", "frequency", "measurement",
                "prediction", "innovation", "innovation_rms")}
        out.update(outliers=int(e.outliers), health=int(e.health))
        return out


class Measured:
    """A measured-signals file (docs/twin.md, "Measured signals file") read by
    the library's reader: rate [Hz], signal ("deflection" or "voltage"),
    noise, accel_noise, latency (NaN: not given), has_truth; and the columns
    t [s], base_accel [m/s^2], signal (name clash: the column is `y`),
    s_true (NaN without truth) as numpy arrays."""

    _b = None

    def __init__(self, *args, **kwargs):
        raise TypeError("read a measured-signals file with read_measured(path)")

    @classmethod
    def read(cls, path):
        """Reads path whole. Raises SceneError (a malformed file: FILE:LINE)."""
        b = cls._b
        ffi, lib = b.ffi, b.lib
        header = ffi.new("bs_host_measured_header *")
        rows = ffi.new("double **")
        count = ffi.new("uint64_t *")
        error = ffi.new("bs_host_error *")
        status = lib.bspy_measured_read(os.fspath(path).encode(), header, rows, count, error)
        if status != lib.BS_HOST_OK:
            raise b.host_error(status, error)
        n = int(count[0])
        try:
            table = numpy.frombuffer(ffi.buffer(rows[0], n * 4 * 8), dtype=numpy.float64).reshape(n, 4).copy() \
                if n else numpy.empty((0, 4))
        finally:
            lib.bspy_free(rows[0])
        self = object.__new__(cls)
        self.path = os.fspath(path)
        self.rate = header.rate
        self.signal = _SIGNALS[header.signal]
        self.noise, self.accel_noise, self.latency = header.noise, header.accel_noise, header.latency
        self.has_truth = bool(header.has_truth)
        self.t, self.base_accel, self.y, self.s_true = (table[:, i].copy() for i in range(4))
        return self

    def __len__(self):
        return len(self.t)

    def __repr__(self):
        return "<Measured %s: %d rows at %g Hz, %s>" % (self.path, len(self), self.rate, self.signal)
