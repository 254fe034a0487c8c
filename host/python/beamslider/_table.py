"""The tables of a map (docs/maps.md section 5) as numpy columns."""

import csv

import numpy

# columns that hold text although they may look like numbers
_TEXT_COLUMNS = {"hash"}


class Table:
    """A CSV table with a header line: table["column"] is a numpy array
    (float64 where every value is a number, "nan" included; else str),
    table.columns the names in file order, len(table) the rows."""

    def __init__(self, path):
        with open(path, newline="") as stream:
            reader = csv.reader(stream)
            self.columns = next(reader)
            rows = list(reader)
        self._data = {}
        for i, name in enumerate(self.columns):
            values = [row[i] for row in rows]
            self._data[name] = _column(name, values)
        self.path = path

    def __getitem__(self, name):
        return self._data[name]

    def __contains__(self, name):
        return name in self._data

    def __iter__(self):
        return iter(self.columns)

    def __len__(self):
        return len(next(iter(self._data.values()))) if self._data else 0

    def __repr__(self):
        return "<Table %s: %d rows, columns %s>" % (self.path, len(self), ", ".join(self.columns))


def _column(name, values):
    if name not in _TEXT_COLUMNS:
        try:
            return numpy.array([float(v) for v in values], dtype=numpy.float64)
        except ValueError:
            pass
    return numpy.array(values, dtype=str)


class Map:
    """What scene.map() made: the per-point table (points, DIR/map.csv) and
    the per-run table (runs, DIR/runs.csv), None while the map is not
    complete (a shard); axes, the values of each varied field in grid order
    (the last varies fastest); the counts of the library's bs_host_map_result
    (points_total, cases, done, run, skipped, jobs, wall_s, warnings); dir,
    the map's folder (None when it was a temporary one, now removed)."""

    def __init__(self, directory, fields, result, keep):
        self.dir = directory if keep else None
        for key, value in result.items():
            setattr(self, key, value)
        self.complete = bool(result["complete"])
        self.points = Table(directory + "/map.csv") if self.complete else None
        self.runs = Table(directory + "/runs.csv") if self.complete else None
        self.fields = list(fields)
        self.axes = {}
        if self.points is not None:
            for field in self.fields:
                column = self.points[field]
                seen = []
                for value in column:
                    if not any(value == s for s in seen):
                        seen.append(value)
                self.axes[field] = numpy.array(seen)

    def grid(self, column):
        """The points table's column shaped as the grid: one axis per varied
        field, in the order they were given."""
        if self.points is None:
            raise ValueError("the map is not complete: no table of points")
        shape = tuple(len(self.axes[field]) for field in self.fields)
        return numpy.asarray(self.points[column]).reshape(shape)

    def __repr__(self):
        return "<Map %s: %d points, %d cases, complete %s>" % (
            self.dir or "(temporary)", self.points_total, self.cases, self.complete)
