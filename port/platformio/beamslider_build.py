# beamslider_build.py - the library's PlatformIO build script (library.json,
# "extraScript"; port/platformio/README.md). PlatformIO runs it with the
# library's build environment before compiling the core.
#
# The include folders are added here, as absolute paths, because a relative
# -I in library.json's "flags" has been resolved against the library in some
# PlatformIO releases and against the project in others. The library folder is
# taken from PlatformIO's library builder, through any symlink, so that the
# repository around it (core/, port/embedded/) is found however the project
# names the library (lib_deps = symlink://..., a symlink in lib/).
import os

Import("env", "pio_lib_builder")  # noqa: F821 (SCons provides Import)

lib_dir = os.path.realpath(pio_lib_builder.path)  # noqa: F821
port_dir = os.path.dirname(lib_dir)

# Public: bs_build_config.h, which reads the project's build_flags. PlatformIO
# passes a library's CPPPATH on to the program that uses it.
env.Append(CPPPATH=[os.path.join(lib_dir, "include")])  # noqa: F821
# Private: the port of the core (bs_port.h: compiler builtins, the C
# library's sinf/cosf), on the library's own compile lines only.
env.Append(CCFLAGS=["-I" + os.path.join(port_dir, "embedded")])  # noqa: F821
