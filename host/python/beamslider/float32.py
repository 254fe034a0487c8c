"""beamslider in single precision: the core's bs_real is float (numpy.float32).

    import beamslider.float32 as bs
    run = bs.Scene.load("configs/fig6.ini").run()

The same names as beamslider.double (docs/python.md), whose results differ:
float and double follow different trajectories and have different hashes.
"""

from beamslider import _float32
from beamslider._bind import bind

_made = bind(_float32, __name__)

Scene = _made["Scene"]
Sim = _made["Sim"]
Run = _made["Run"]
Sweep = _made["Sweep"]
Trace = _made["Trace"]
Observer = _made["Observer"]
Gains = _made["Gains"]
Estimates = _made["Estimates"]
Measured = _made["Measured"]
read_measured = _made["read_measured"]
version = _made["version"]
build_tag = _made["build_tag"]
precision = _made["precision"]
real = _made["real"]
checkpoint_size = _made["checkpoint_size"]
max_modes = _made["max_modes"]

del _made, bind
