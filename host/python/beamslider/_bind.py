"""The package's classes bound to one precision's extension module.

The classes (_scene.py, _sim.py, _twin.py) are written once; bind() makes
each precision's own subclasses of them, whose _b is that precision's
Backend. So a float32 Scene cannot reach a double Sim by mistake, and the
module a user imports (beamslider.double, beamslider.float32) holds classes
of one precision only. (Apart from _backend.py, so that the classes, which
use its Hook, and _backend.py do not import each other.)
"""

from beamslider import _columns, _scene, _sim, _twin
from beamslider._backend import Backend


def bind(module, name):
    """The classes and figures of one precision: a dict for the module
    beamslider.<precision> to take."""
    backend = Backend(module, name)
    made = {}
    for base in (_scene.Scene, _scene.Run, _scene.Sweep, _sim.Sim, _twin.Observer, _twin.Gains,
                 _twin.Measured, _columns.Trace, _columns.Estimates):
        made[base.__name__] = type(base.__name__, (base,), {"_b": backend, "__module__": name,
                                                           "__doc__": base.__doc__})
        setattr(backend, base.__name__, made[base.__name__])
    made.update(version=backend.version, build_tag=backend.build_tag, precision=backend.precision,
                real=backend.real, checkpoint_size=backend.checkpoint_size, max_modes=backend.max_modes,
                read_measured=made["Measured"].read)
    return made
