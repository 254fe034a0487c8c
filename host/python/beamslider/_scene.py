"""Scenes, runs, sweeps and maps: libbeamslider-host's calls
(host/include/beamslider_host.h) as Python sees them (docs/python.md)."""

import json
import numbers
import os
import tempfile

import numpy

from beamslider._backend import Hook
from beamslider._columns import ROW_COLUMNS, TRANSDUCER_COLUMNS
from beamslider._errors import ArgumentError
from beamslider._table import Map

_MODELS = ("free", "pcs")


def _value_text(value):
    """A value as the scene reader reads it (floats: the shortest text that
    reads back exactly)."""
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        raise TypeError("%r: give a scene field a number or a text, not a bool" % value)
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    raise TypeError("%r: give a scene field a number or a text" % (value,))


def overrides_text(overrides):
    """Keyword overrides as "section.key=value" texts: a keyword holding a dot
    is a field (**{"excitation.frequency": 120}); any other names a section
    and takes a dict of its keys (excitation={"frequency": 120})."""
    texts = []
    for name, value in overrides.items():
        if "." in name:
            texts.append("%s=%s" % (name, _value_text(value)))
        elif isinstance(value, dict):
            texts += ["%s.%s=%s" % (name, key, _value_text(v)) for key, v in value.items()]
        else:
            raise TypeError("override %s=%r: give a field as **{'section.key': value} or a section as "
                            "section={'key': value}" % (name, value))
    return texts


def _number(text):
    """A field's canonical text as a number where it is one."""
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


class Scene:
    """A scene as read and built (bs_host_scene): the file or text, with its
    [scene] base, and the overrides. Immutable: replace() makes another.

    scene["section.key"] reads a field by its INI name (a number, or the text
    of a choice or name); name, model, s0, t_end, dt, steps, frequency,
    acceleration and has_schedule are the scene's run (bs_host_setup).
    """

    _b = None

    def __init__(self, *args, **kwargs):
        raise TypeError("make a Scene with Scene.load(path, **overrides) or Scene.from_text(text, ...)")

    @classmethod
    def load(cls, path, **overrides):
        """The scene file at path (relative: from the working folder; a
        [scene] base relative to the file) with overrides, each checked as
        `beamslider run --set` checks it. Raises SceneError."""
        return cls._make(os.fspath(path), None, tuple(overrides_text(overrides)))

    @classmethod
    def from_text(cls, text, name="scene.ini", **overrides):
        """The scene in text (an INI file's contents); name stands for the file
        in messages and locates a [scene] base. Raises SceneError."""
        return cls._make(os.fspath(name), text, tuple(overrides_text(overrides)))

    @classmethod
    def _make(cls, path, text, overrides):
        b = cls._b
        ffi, lib = b.ffi, b.lib
        texts, keep = b.cstrings(overrides)
        out = ffi.new("bs_host_scene **")
        error = ffi.new("bs_host_error *")
        status = lib.bspy_scene_load(path.encode(), text.encode() if text is not None else ffi.NULL, texts,
                                     len(overrides), out, error)
        del keep
        if status != lib.BS_HOST_OK:
            raise b.host_error(status, error)
        self = object.__new__(cls)
        self._ptr = ffi.gc(out[0], lib.bs_host_scene_free)
        self._source = (path, text)
        self.overrides = overrides
        setup = ffi.new("bs_host_setup *")
        lib.bs_host_scene_setup(self._ptr, setup)
        self.name = ffi.string(setup.name).decode()
        self.model = _MODELS[setup.model]
        self.s0, self.t_end, self.dt = setup.s0, setup.t_end, setup.dt
        self.steps = int(setup.steps)
        self.frequency, self.acceleration = setup.frequency, setup.acceleration
        self.has_schedule = bool(setup.has_schedule)
        self.transducer = self["transducer.load"] != "none"
        return self

    def replace(self, **overrides):
        """This scene with more overrides (the later of two wins)."""
        path, text = self._source
        return self._make(path, text, self.overrides + tuple(overrides_text(overrides)))

    def __getitem__(self, field):
        ffi, lib = self._b.ffi, self._b.lib
        out = ffi.new("char[]", 4096)
        error = ffi.new("bs_host_error *")
        status = lib.bs_host_scene_value(self._ptr, field.encode(), out, 4096, error)
        if status != lib.BS_HOST_OK:
            raise KeyError(ffi.string(error.text).decode())
        return _number(ffi.string(out).decode())

    def get(self, field, default=None):
        try:
            return self[field]
        except KeyError:
            return default

    @property
    def hash(self):
        """bs_scene_hash of the core scene, as the summaries' scene_hash."""
        return "%08x" % self._b.lib.bs_scene_hash(self._b.lib.bs_host_scene_core(self._ptr))

    def modes(self):
        """The modal precomputation (bs_host_modes): n, and arrays of the n
        modes frequency [Hz], lambda, gamma, phi_sensor; kappa, width,
        k_axial, shape_pieces, fit_error_phi, fit_error_slope."""
        ffi, lib = self._b.ffi, self._b.lib
        m = ffi.new("bs_host_modes *")
        lib.bs_host_scene_modes(self._ptr, m)
        n = m.n
        out = {"n": n}
        for name in ("frequency", "lambda", "gamma", "phi_sensor"):
            out[name] = numpy.array(list(getattr(m, name))[:n])
        for name in ("kappa", "width", "k_axial", "shape_pieces", "fit_error_phi", "fit_error_slope"):
            out[name] = getattr(m, name)
        return out

    def attached_frequency(self, s):
        """The first natural frequency [Hz] with the slider attached at s."""
        return self._b.lib.bs_host_attached_frequency(self._ptr, s)

    def attached_position(self, frequency):
        """The s in [B/2L, 1/2] where attached_frequency is frequency, or None."""
        s = self._b.lib.bs_host_attached_position(self._ptr, frequency)
        return None if s < 0 else s

    def sim(self, s0=None, model=None):
        """A Sim of this scene (its s0 and model unless given)."""
        return self._b.Sim(self, s0=s0, model=model)

    def twin_gains(self, noise, **options):
        """The observer's design for this scene (Gains.design)."""
        return self._b.Gains.design(self, noise, **options)

    # ---- runs -----------------------------------------------------------------

    def run(self, t_end=None, every=20, progress=None, **overrides):
        """Runs the scene from rest as `beamslider run` does (its [excitation]
        schedule included): a Run with a row at t = 0 and after every every-th
        step (every=1: every step) and the summary `beamslider run` prints.
        t_end and overrides change the scene for this run. progress: None or
        a callable(fraction, detail), called a few times a second; an
        exception from it stops the run and is raised. Raises SceneError,
        RunError (a step failed: its .result holds the rows up to it)."""
        b = self._b
        ffi, lib = b.ffi, b.lib
        if t_end is not None:
            overrides["run.t_end"] = t_end
        scene = self.replace(**overrides) if overrides else self
        if not isinstance(every, numbers.Integral) or every < 1:
            raise ArgumentError("every = %r: allowed: an integer >= 1" % (every,))
        columns = [c for c in ROW_COLUMNS if scene.transducer or c not in TRANSDUCER_COLUMNS]
        trace = b.Trace(scene.steps // every + 1, columns)
        trace._reset(0)
        hook = Hook(b, progress)
        result = ffi.new("bs_host_run_result *")
        summary = ffi.new("char **")
        error = ffi.new("bs_host_error *")
        status = lib.bspy_run(scene._ptr, every, trace._c, lib.bspy_progress, hook.handle, hook.stop, result,
                              summary, error)
        text = ffi.string(summary[0]).decode() if summary[0] != ffi.NULL else None
        lib.bspy_free(summary[0])
        run = b.Run(scene, trace, result, json.loads(text) if text else None)
        hook.raise_error()
        if status != lib.BS_HOST_OK:
            raise b.host_error(status, error, run)
        return run

    def sweep(self, direction="up", start=0.0, stop=0.5, step=0.005, hold=100, record=25, progress=None):
        """The quasi-static PCS sweep of `beamslider sweep` (docs/model.md 6)
        over s~ = start, start + step, ..., stop, taken from start up
        (direction "up") or from stop down ("down"); each point holds hold
        excitation periods, then records record. A Sweep. Raises SceneError,
        RunError."""
        b = self._b
        ffi, lib = b.ffi, b.lib
        if direction not in ("up", "down"):
            raise ArgumentError("direction %r: allowed: 'up' or 'down'" % (direction,))
        n = lib.bspy_sweep_points(start, stop, step)
        points = ffi.new("bs_host_sweep_point[]", max(n, 1))
        done = ffi.new("int *")
        summary = ffi.new("char **")
        error = ffi.new("bs_host_error *")
        hook = Hook(b, progress)
        status = lib.bspy_sweep(self._ptr, start, stop, step, direction == "down", hold, record, points,
                                max(n, 0), lib.bspy_progress, hook.handle, done, summary, error)
        text = ffi.string(summary[0]).decode() if summary[0] != ffi.NULL else None
        lib.bspy_free(summary[0])
        sweep = b.Sweep(self, [points[i] for i in range(done[0])], json.loads(text) if text else None)
        hook.raise_error()
        if status != lib.BS_HOST_OK:
            raise b.host_error(status, error, sweep)
        return sweep

    def map(self, vary, repeat=1, jobs=None, dir=None, shard=None, progress=None):
        """The map of `beamslider map` (docs/maps.md): vary is a dict of
        field -> values, each a (from, to, step) tuple (a range), a list of
        values, or the text of --vary ("90:140:1", "10,14"); the last field
        varies fastest. repeat: starts per grid point, 1e-5 apart; jobs:
        worker threads (None: every core); dir: the map's folder, resumable
        (None: a temporary one, removed once read); shard: (i, n). A Map with
        the tables. Raises SceneError (a bad --vary: nothing is written),
        RunError."""
        b = self._b
        ffi, lib = b.ffi, b.lib
        specs = _vary_texts(vary)
        fields = [spec.split("=", 1)[0] for spec in specs]
        with tempfile.TemporaryDirectory(prefix="beamslider-map-") as scratch:
            directory = os.fspath(dir) if dir is not None else os.path.join(scratch, "map")
            options = ffi.new("bs_host_map_options *")
            lib.bs_host_map_defaults(options)
            texts, keep = b.cstrings(specs)
            folder = ffi.new("char[]", directory.encode())
            options.dir = folder
            options.vary = texts
            options.vary_count = len(specs)
            options.repeat = repeat
            options.jobs = jobs if jobs is not None else (os.cpu_count() or 1)
            if shard is not None:
                options.shard_index, options.shard_count = shard
            hook = Hook(b, progress)
            options.progress = lib.bspy_progress
            options.progress_context = hook.handle
            result = ffi.new("bs_host_map_result *")
            error = ffi.new("bs_host_error *")
            status = lib.bs_host_map(self._ptr, options, result, error)
            del keep
            hook.raise_error()
            if status != lib.BS_HOST_OK:
                raise b.host_error(status, error)
            counts = {"points_total": result.points, "cases": result.cases, "shard_cases": result.shard_cases,
                      "skipped": result.skipped, "run": result.run, "done": result.done,
                      "complete": result.complete, "jobs": result.jobs, "wall_s": result.wall_s,
                      "warnings": ffi.string(result.warnings).decode()}
            return Map(directory, fields, counts, keep=dir is not None)

    def __repr__(self):
        path, text = self._source
        return "<%s %s from %s%s%s>" % (type(self).__module__ + ".Scene", self.name,
                                        "text " if text is not None else "", path,
                                        " with " + ", ".join(self.overrides) if self.overrides else "")


def _vary_texts(vary):
    """The --vary texts of scene.map's vary."""
    if isinstance(vary, (list, tuple)) and all(isinstance(v, str) for v in vary):
        return list(vary)
    if not isinstance(vary, dict) or not vary:
        raise TypeError("vary: a dict of field -> values, such as {'excitation.frequency': (100, 130, 10)}")
    texts = []
    for field, values in vary.items():
        if isinstance(values, str):
            spec = values
        elif isinstance(values, tuple) and len(values) == 3:
            spec = ":".join(_value_text(v) for v in values)
        else:
            spec = ",".join(_value_text(v) for v in numpy.asarray(values).ravel().tolist())
        texts.append("%s=%s" % (field, spec))
    return texts


class Run:
    """What scene.run() did: the rows (t, w_sensor, s, z_r, beta, contacts,
    sweeps, residual; v, p, v_s with a transducer: numpy arrays, as the
    columns of `beamslider run --out`), summary (the dict `beamslider run`
    prints as JSON), hash (the final state's, as the summary's), steps,
    s_final and scene."""

    _b = None

    def __init__(self, scene, trace, result, summary):
        self.scene = scene
        self.trace = trace
        self.summary = summary
        self.steps = int(result.steps)
        self.hash = "%08x" % result.hash
        self.s_final = result.s_final
        self._core_status = result.status

    def __getattr__(self, name):
        trace = self.__dict__.get("trace")
        if trace is not None and name in trace.columns:
            return trace[name]
        raise AttributeError(name)

    def __repr__(self):
        return "<Run %s: %d steps, s_final %.6g, hash %s>" % (self.scene.name, self.steps, self.s_final, self.hash)


class Sweep:
    """What scene.sweep() did: s (the prescribed positions, in sweep order),
    amp_h (mean half peak-to-peak of w(4L/7) / h) and v_mean (x_C drift per
    period / L, positive toward the centre) as numpy arrays; summary, the
    dict `beamslider sweep` prints."""

    _b = None

    def __init__(self, scene, points, summary):
        self.scene = scene
        self.summary = summary
        self.s = numpy.array([p.s for p in points])
        self.amp_h = numpy.array([p.amp_h for p in points])
        self.v_mean = numpy.array([p.v_mean for p in points])

    def __len__(self):
        return len(self.s)

    def __repr__(self):
        return "<Sweep %s: %d points>" % (self.scene.name, len(self))
