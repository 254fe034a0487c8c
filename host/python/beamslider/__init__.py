"""beamslider from Python: the simulator of a clamped beam shaken at its base
with a slider creeping along it (README.md), through libbeamslider-host and
the core, compiled in (docs/python.md).

Precision is chosen at import:

    import beamslider.double as bs     # bs_real double
    import beamslider.float32 as bs    # bs_real float

`import beamslider` gives the double one's names (beamslider.Scene, ...);
the exceptions are shared by both.
"""

from beamslider._errors import ArgumentError, CheckpointError, Error, RunError, SceneError
from beamslider.double import (Estimates, Gains, Measured, Observer, Run, Scene, Sim, Sweep, Trace,
                               build_tag, checkpoint_size, max_modes, precision, read_measured, real, version)

__version__ = version

__all__ = ["ArgumentError", "CheckpointError", "Error", "RunError", "SceneError", "Estimates", "Gains",
           "Measured", "Observer", "Run", "Scene", "Sim", "Sweep", "Trace", "build_tag", "checkpoint_size",
           "max_modes", "precision", "read_measured", "real", "version"]
