"""What the tests of the package beamslider share (`make test-python`,
tests/python.mk): the repository, and the summary the `beamslider` program of
each precision prints, to compare with.

The package under test is the one `import beamslider` finds (make puts its
build first on PYTHONPATH). BEAMSLIDER_ROOT names the repository (default:
three folders up); BEAMSLIDER_CLI_DOUBLE and BEAMSLIDER_CLI_FLOAT the
programs (default: ROOT/build/double/beamslider and .../float/...).
"""

import json
import os
import subprocess

import pytest

ROOT = os.environ.get("BEAMSLIDER_ROOT") or os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.dirname(os.path.abspath(__file__)))))

# the module name of a precision -> the REAL of make's build
PRECISIONS = {"double": "double", "float32": "float"}


def config(name):
    """The path of configs/NAME.ini."""
    return os.path.join(ROOT, "configs", name + ".ini")


def cli_path(precision):
    real = PRECISIONS[precision]
    return os.environ.get("BEAMSLIDER_CLI_" + real.upper()) or os.path.join(ROOT, "build", real, "beamslider")


def cli(precision, *args):
    """What `beamslider ARGS...` prints on stdout."""
    return subprocess.run([cli_path(precision)] + list(args), check=True, stdout=subprocess.PIPE,
                          stderr=subprocess.DEVNULL, text=True).stdout


def cli_run(precision, scene, *overrides):
    """The JSON summary `beamslider run SCENE --set ...` prints, as a dict."""
    command = [cli_path(precision), "run", config(scene)]
    for override in overrides:
        command += ["--set", override]
    out = subprocess.run(command, check=True, stdout=subprocess.PIPE, text=True).stdout
    return json.loads(out)


@pytest.fixture(params=sorted(PRECISIONS))
def bs(request):
    """The package's module of each precision in turn (beamslider.double,
    beamslider.float32)."""
    return __import__("beamslider." + request.param, fromlist=["Scene"])


def pytest_configure(config):
    # `make test-python` runs the tests not marked slow, `make test-python-long` the slow ones
    config.addinivalue_line("markers", "slow: costs a CPU-second or more (make test-python-long)")
