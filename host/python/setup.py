"""setup.py - the build of the package beamslider (pyproject.toml; docs/python.md,
"Install"): its version from core/include/beamslider.h, its two extension
modules from build_ffi.py (cffi in API mode), and, before they are compiled,
`make lib` when the archives they link are missing (BEAMSLIDER_BUILD: make's
build folder; BEAMSLIDER_NO_MAKE=1: fail instead of running make).

    python3 setup.py build_ext --inplace       # the modules beside the sources
    pip install --no-build-isolation --no-index host/python
"""

import os
import re
import subprocess
import sys

from setuptools import setup
from setuptools.command.build import build
from setuptools.command.build_ext import build_ext
from setuptools.command.egg_info import egg_info

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import build_ffi  # noqa: E402 - beside this file

with open(os.path.join(build_ffi.ROOT, "core", "include", "beamslider.h")) as header:
    VERSION = re.search(r'#define BS_VERSION_STRING "([^"]+)"', header.read()).group(1)


# Where setuptools works unless told (--build-base, --egg-base): make's build
# folder, so that a build or `pip install` leaves the sources as they are.
WORK = os.path.join(build_ffi.BUILD, "python", "setuptools")


class Build(build):
    """build into WORK by default."""

    def initialize_options(self):
        super().initialize_options()
        self.build_base = os.path.relpath(WORK)


class EggInfo(egg_info):
    """egg_info into WORK by default."""

    def initialize_options(self):
        super().initialize_options()
        os.makedirs(WORK, exist_ok=True)
        self.egg_base = os.path.relpath(WORK)


class BuildExt(build_ext):
    """build_ext that makes the library first when its archives are missing."""

    def run(self):
        missing = build_ffi.missing_files()
        if missing:
            if os.environ.get("BEAMSLIDER_NO_MAKE"):
                sys.exit("beamslider: missing %s: run `make lib` in %s first" % (", ".join(missing), build_ffi.ROOT))
            command = ["make", "-C", build_ffi.ROOT, "BUILD=" + build_ffi.BUILD, "lib"]
            print("beamslider: building the library: " + " ".join(command), flush=True)
            subprocess.check_call(command)
        super().run()


setup(
    version=VERSION,
    packages=["beamslider"],
    include_package_data=False,  # the shim's sources are compiled in, not installed
    cffi_modules=["build_ffi.py:ffi_double", "build_ffi.py:ffi_float32"],
    cmdclass={"build": Build, "build_ext": BuildExt, "egg_info": EggInfo},
    zip_safe=False,
)
