"""Rows the C loops write: numpy arrays allocated once, handed to C as the
columns of a bspy_rows or bspy_estimates (_shim.h). A Trace or Estimates
may be given back to the next call (out=...) to be written again without a
new allocation."""

import numpy

# column -> numpy dtype; the order of `beamslider run --out`'s CSV
ROW_COLUMNS = {"t": numpy.float64, "w_sensor": numpy.float64, "s": numpy.float64, "z_r": numpy.float64,
               "beta": numpy.float64, "contacts": numpy.uint32, "sweeps": numpy.int32,
               "residual": numpy.float64, "v": numpy.float64, "p": numpy.float64, "v_s": numpy.float64}
TRANSDUCER_COLUMNS = ("v", "p", "v_s")
ESTIMATE_COLUMNS = {"t": numpy.float64, "s": numpy.float64, "s_sigma": numpy.float64, "s_error": numpy.float64,
                    "amplitude": numpy.float64, "power": numpy.float64, "phase_error": numpy.float64,
                    "frequency": numpy.float64, "innovation": numpy.float64, "outliers": numpy.uint32,
                    "health": numpy.int32}

_C_TYPES = {numpy.float64: "double *", numpy.uint32: "uint32_t *", numpy.int32: "int32_t *"}


class _Columns:
    _b = None
    _struct = None
    _all = None

    def __init__(self, room, columns=None):
        """Room for room rows of columns (names; None: all)."""
        ffi = self._b.ffi
        names = list(self._all) if columns is None else list(columns)
        unknown = [name for name in names if name not in self._all]
        if unknown:
            raise ValueError("unknown column %s; columns: %s" % (", ".join(unknown), ", ".join(self._all)))
        self.room = int(room)
        if self.room < 0:
            raise ValueError("room %d: allowed: >= 0 rows" % self.room)
        self.columns = [name for name in self._all if name in names]
        self._arrays = {name: numpy.empty(self.room, dtype=self._all[name]) for name in self.columns}
        self._c = ffi.new(self._struct + " *")
        for name, array in self._arrays.items():
            setattr(self._c, name, ffi.cast(_C_TYPES[self._all[name]], array.ctypes.data))
        self._c.room = self.room

    @property
    def rows(self):
        """The rows written by the last call."""
        return int(self._c.rows)

    def _reset(self, rows_needed):
        if rows_needed > self.room:
            raise ValueError("out= has room for %d rows, the call writes %d" % (self.room, rows_needed))
        self._c.rows = 0

    def __getitem__(self, name):
        return self._arrays[name][:self.rows]

    def __getattr__(self, name):
        arrays = self.__dict__.get("_arrays")
        if arrays is not None and name in arrays:
            return arrays[name][:self.rows]
        raise AttributeError(name)

    def __len__(self):
        return self.rows

    def as_dict(self):
        """{column: array} of the rows written (views, not copies)."""
        return {name: self[name] for name in self.columns}

    def __repr__(self):
        return "<%s: %d of %d rows, columns %s>" % (type(self).__name__, self.rows, self.room, ", ".join(self.columns))


class Trace(_Columns):
    """A sim's rows: t [s], s, w_sensor [m], z_r [m], beta [rad], contacts (bit
    i: contact i took part), sweeps, residual [N s], and with a transducer v
    [V], p [W], v_s [V]; each a numpy array of the rows written (len(trace)).
    Trace(room, columns) allocates room rows of the columns named."""

    _struct = "bspy_rows"
    _all = ROW_COLUMNS


class Estimates(_Columns):
    """An observer's estimates after its steps: t [s], s, s_sigma, s_error,
    amplitude [m], power [W], phase_error [rad], frequency [Hz], innovation,
    outliers, health (bs_observer_estimate)."""

    _struct = "bspy_estimates"
    _all = ESTIMATE_COLUMNS
