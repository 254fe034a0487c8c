"""Sim: the core's bs_sim stepped from Python, many steps a call
(core/include/beamslider.h; docs/python.md, "Stepping")."""

import numbers
import threading

import numpy

from beamslider._errors import ArgumentError, RunError

STEP_COLUMNS = ("t", "s", "w_sensor", "contacts")

# steps a call when a progress callback wants to hear in between (some 20 ms)
_PROGRESS_CHUNK = 65536


class Sim:
    """A simulation of a scene from rest (bs_sim, in the precision of the
    module), owned by Python; the scene is kept alive with it.

    step(n) and step_measured(accel) run many steps in one C call, with the
    GIL released, writing rows into numpy arrays. A Sim is for one thread at
    a time (another thread's call while one runs raises RuntimeError);
    different Sims run in parallel.
    """

    _b = None

    def __init__(self, scene, s0=None, model=None):
        b = self._b
        if not isinstance(scene, b.Scene):
            raise TypeError("Sim(scene): a %s.Scene, not %r" % (b.name, scene))
        model = scene.model if model is None else model
        if model not in ("free", "pcs"):
            raise ArgumentError("model %r: allowed: 'free' or 'pcs'" % (model,))
        s0 = scene.s0 if s0 is None else s0
        self.scene = scene
        self.dt = scene.dt
        self.model = model
        self._sim = b.ffi.new("bs_sim *")
        self._done = b.ffi.new("uint64_t *")
        self._lock = threading.Lock()
        status = b.lib.bspy_sim_init(self._sim, scene._ptr, b.lib.BS_MODEL_PCS if model == "pcs" else
                                     b.lib.BS_MODEL_FREE, s0)
        b.check(status, "%s: the core refuses to start with model %s, s0 %g" % (scene.name, model, s0))
        self.n_modes = scene.modes()["n"]

    # ---- stepping -------------------------------------------------------------

    def step(self, n=1, every=1, out=None, columns=STEP_COLUMNS, progress=None):
        """n steps under the harmonic excitation (the scene's, or the last
        set_excitation's; a scene's [excitation] schedule is scene.run()'s),
        a row after every every-th step: a Trace of n // every rows of
        columns (Trace's; out: a Trace to write into again). progress: None,
        or a callable(fraction, None) called between chunks of steps. Raises
        RunError when a step fails (the sim keeps its last good state, the
        error's result holds the rows up to it)."""
        lib = self._b.lib
        return self._advance(n, every, out, columns, progress,
                             lambda start, k, rows: lib.bspy_sim_steps(self._sim, k, self.dt, every, rows,
                                                                       self._done))

    def step_measured(self, accel, every=1, out=None, columns=STEP_COLUMNS, progress=None):
        """len(accel) steps, step i under the measured mean base acceleration
        accel[i] [m/s^2] (bs_sim_step_measured; docs/twin.md); rows as step."""
        ffi, lib = self._b.ffi, self._b.lib
        accel = numpy.ascontiguousarray(accel, dtype=numpy.float64)
        if accel.ndim != 1:
            raise ArgumentError("accel: a 1-d array of base accelerations, not shape %s" % (accel.shape,))
        base = ffi.cast("double *", accel.ctypes.data)
        return self._advance(len(accel), every, out, columns, progress,
                             lambda start, k, rows: lib.bspy_sim_steps_measured(self._sim, base + start, k,
                                                                                self.dt, every, rows,
                                                                                self._done))

    def _advance(self, n, every, out, columns, progress, call):
        b = self._b
        if not isinstance(n, numbers.Integral) or n < 0:
            raise ArgumentError("n = %r: allowed: an integer >= 0" % (n,))
        if not isinstance(every, numbers.Integral) or every < 1:
            raise ArgumentError("every = %r: allowed: an integer >= 1" % (every,))
        trace = out if out is not None else b.Trace(n // every, columns)
        trace._reset(n // every)
        rows = trace._c if trace.columns else b.ffi.NULL
        chunk = n if progress is None else max(every, _PROGRESS_CHUNK // every * every)
        start = 0
        while True:
            k = min(chunk, n - start)
            if not self._lock.acquire(blocking=False):
                raise RuntimeError("this Sim is stepping in another thread")
            try:
                status = call(start, k, rows)
            finally:
                self._lock.release()
            start += int(self._done[0])
            if status != b.lib.BS_OK:
                text = b.status_text(status)
                raise RunError("%s: step %d (t = %.9g s): %s" % (self.scene.name, self.steps + 1,
                                                                  (self.steps + 1) * self.dt, text), text, trace)
            if progress is not None:
                progress(start / n if n else 1.0, None)
            if start >= n:
                return trace

    # ---- reading --------------------------------------------------------------

    @property
    def steps(self):
        """Steps since the start."""
        return int(self._b.lib.bs_sim_steps(self._sim))

    @property
    def t(self):
        """Simulated time [s]: steps * dt, in double."""
        return self.steps * self.dt

    @property
    def s(self):
        """The slider position x_C / L."""
        return float(self._b.lib.bs_sim_position(self._sim))

    @property
    def w_sensor(self):
        """w(4L/7) [m]."""
        return float(self._b.lib.bs_sim_sensor(self._sim))

    @property
    def phase(self):
        """The excitation phase as a part of a period, [0, 1)."""
        return float(self._b.lib.bs_sim_phase(self._sim))

    @property
    def base_acceleration(self):
        """The mean base acceleration of the last step [m/s^2]."""
        return float(self._b.lib.bs_sim_base_acceleration(self._sim))

    @property
    def hash(self):
        """bs_sim_hash of the state, as the summaries print it ("%08x")."""
        return "%08x" % self._b.lib.bs_sim_hash(self._sim)

    def state(self):
        """A copy of the state: q and u (modal coordinates and velocities,
        n_modes each), slider (x_C [m], z_r [m], beta [rad]) and
        slider_velocity, as numpy arrays of the module's precision."""
        ffi, lib = self._b.ffi, self._b.lib
        parts = {name: ffi.new("bs_real[]", size) for name, size in
                 (("q", self.n_modes), ("u", self.n_modes), ("slider", 3), ("slider_velocity", 3))}
        lib.bs_sim_get_state(self._sim, parts["q"], parts["u"], parts["slider"], parts["slider_velocity"])
        return {name: numpy.frombuffer(ffi.buffer(part), dtype=self._b.real).copy() for name, part in parts.items()}

    def set_state(self, q=None, u=None, slider=None, slider_velocity=None):
        """Overwrites parts of the state (None: kept; bs_sim_set_state's
        rules). Raises ArgumentError (nothing changes)."""
        ffi, lib = self._b.ffi, self._b.lib

        def part(values, size, name):
            if values is None:
                return ffi.NULL
            values = numpy.asarray(values, dtype=numpy.float64).ravel()
            if len(values) != size:
                raise ArgumentError("%s: %d values, not %d" % (name, size, len(values)))
            return ffi.new("bs_real[]", values.tolist())

        self._b.check(lib.bs_sim_set_state(self._sim, part(q, self.n_modes, "q"), part(u, self.n_modes, "u"),
                                           part(slider, 3, "slider"),
                                           part(slider_velocity, 3, "slider_velocity")), "set_state")

    def report(self):
        """The contact report of the last step (bs_step_report) as a dict."""
        ffi, lib = self._b.ffi, self._b.lib
        r = ffi.new("bs_step_report *")
        lib.bs_sim_get_report(self._sim, r)
        return {"active": r.active, "sweeps": r.sweeps, "systems": r.systems, "residual": float(r.residual),
                "converged": bool(r.converged)}

    def transducer(self):
        """What the transducer does (bs_transducer_output) as a dict."""
        ffi, lib = self._b.ffi, self._b.lib
        o = ffi.new("bs_transducer_output *")
        lib.bs_sim_get_transducer(self._sim, o)
        return {"present": bool(o.present), "voltage": float(o.voltage),
                "storage_voltage": float(o.storage_voltage), "power": float(o.power), "energy": float(o.energy)}

    def beam_at(self, x):
        """(w [m], w') of the beam at x [m]."""
        ffi, lib = self._b.ffi, self._b.lib
        w, slope = ffi.new("bs_real *"), ffi.new("bs_real *")
        self._b.check(lib.bs_sim_beam_at(self._sim, x, w, slope), "beam_at(%r)" % (x,))
        return float(w[0]), float(slope[0])

    # ---- settings ---------------------------------------------------------------

    @property
    def excitation(self):
        """(frequency [Hz], amplitude [m/s^2]) of the harmonic excitation."""
        ffi = self._b.ffi
        f, a = ffi.new("bs_real *"), ffi.new("bs_real *")
        self._b.lib.bs_sim_get_excitation(self._sim, f, a)
        return float(f[0]), float(a[0])

    def set_excitation(self, frequency, amplitude):
        """The harmonic excitation from the next step on (the phase goes on).
        Raises ArgumentError."""
        self._b.check(self._b.lib.bs_sim_set_excitation(self._sim, frequency, amplitude),
                      "set_excitation(%r, %r)" % (frequency, amplitude))

    @property
    def contact_laws(self):
        """(mu, e_n): Coulomb friction and normal restitution."""
        ffi = self._b.ffi
        mu, e_n = ffi.new("bs_real *"), ffi.new("bs_real *")
        self._b.lib.bs_sim_get_contact_laws(self._sim, mu, e_n)
        return float(mu[0]), float(e_n[0])

    def set_contact_laws(self, mu, e_n):
        """The contact laws from the next step on (part of a checkpoint).
        Raises ArgumentError."""
        self._b.check(self._b.lib.bs_sim_set_contact_laws(self._sim, mu, e_n),
                      "set_contact_laws(%r, %r)" % (mu, e_n))

    @property
    def solver(self):
        """The contact solve's settings (bs_solver_options) as a dict."""
        ffi = self._b.ffi
        o = ffi.new("bs_solver_options *")
        self._b.lib.bs_sim_get_solver(self._sim, o)
        return {"max_sweeps": o.max_sweeps, "tol_rel": float(o.tol_rel), "tol_abs": float(o.tol_abs),
                "measure_residual": o.measure_residual}

    def set_solver(self, **settings):
        """Changes settings of solver (max_sweeps, tol_rel, tol_abs,
        measure_residual). Raises ArgumentError."""
        ffi = self._b.ffi
        o = ffi.new("bs_solver_options *")
        self._b.lib.bs_sim_get_solver(self._sim, o)
        for name, value in settings.items():
            if name not in ("max_sweeps", "tol_rel", "tol_abs", "measure_residual"):
                raise TypeError("set_solver: no setting %r" % name)
            setattr(o, name, value)
        self._b.check(self._b.lib.bs_sim_set_solver(self._sim, o), "set_solver(%r)" % (settings,))

    def set_pcs_position(self, s):
        """PCS only: the prescribed position s~, the state kept."""
        self._b.check(self._b.lib.bs_sim_set_pcs_position(self._sim, s), "set_pcs_position(%r)" % (s,))

    # ---- checkpoints --------------------------------------------------------------

    def save(self):
        """The complete state as checkpoint_size bytes (bs_sim_save; docs/twin.md,
        "Checkpoints"): restore() on a Sim of the same scene and build
        continues bit for bit."""
        ffi, lib = self._b.ffi, self._b.lib
        buffer = ffi.new("unsigned char[]", self._b.checkpoint_size)
        self._b.check(lib.bs_sim_save(self._sim, buffer, len(buffer)), "save")
        return bytes(ffi.buffer(buffer))

    def restore(self, checkpoint):
        """Overwrites the state with a checkpoint of save() (bytes-like).
        Raises CheckpointError (damaged, another build or precision, another
        scene): the sim is unchanged."""
        ffi, lib = self._b.ffi, self._b.lib
        data = bytes(checkpoint)
        self._b.check(lib.bs_sim_restore(self._sim, ffi.from_buffer(data), len(data)), "restore")

    def __repr__(self):
        return "<%s.Sim %s: t = %.9g s, s = %.6g, hash %s>" % (self._b.name, self.scene.name, self.t, self.s,
                                                               self.hash)

