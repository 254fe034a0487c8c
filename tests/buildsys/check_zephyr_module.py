#!/usr/bin/python3
"""check_zephyr_module.py MODULE_ROOT OUT_DIR - the beamslider Zephyr module
(port/zephyr) read as Zephyr would read it, without Zephyr
(tests/check_embedded_build_systems.sh runs it):

  module.yml   parses (python3-yaml); only keys Zephyr knows; every path it
               names exists: build.cmake a folder with CMakeLists.txt,
               build.kconfig a file, each sample a folder with CMakeLists.txt,
               prj.conf, sample.yaml (parses, names the sample and its tests)
               and src/main.c
  Kconfig      parses with kconfiglib (python3-kconfiglib) under a stand-in of
               the Zephyr symbols it refers to, without a warning; the
               defaults: the library off; once on, float on a part without a
               double-precision FPU and double on one with it, the FPU
               implied, a full C library required (sinf/cosf), no scene,
               the subspace step and -O3 on; the sample's prj.conf applies
               without a warning and gives fig6 in float
  OUT_DIR/config.cmake   the CONFIG_* values of the sample's configuration as
               Zephyr hands them to CMake (bool y, strings unquoted, n left
               unset), and the module's folders from module.yml, for the
               stand-in build (tests/buildsys/zephyr/CMakeLists.txt)

Prints "ok - ..." / "FAIL - ..." per check; exit status 0 when all pass, 1
when one fails, 2 when python3-yaml or python3-kconfiglib is missing.
"""
import os
import sys

try:
    import yaml
    import kconfiglib
except ImportError as missing:
    print("check_zephyr_module: needs %s (apt-get install python3-yaml python3-kconfiglib)" % missing.name)
    sys.exit(2)

passed = 0
failed = 0


def check(description, condition, detail=""):
    global passed, failed
    if condition:
        passed += 1
        print("ok   - " + description)
    else:
        failed += 1
        print("FAIL - " + description + (("\n       " + detail) if detail else ""))
    return condition


# The keys of zephyr/module.yml that Zephyr's module reader accepts (its
# documented schema: name, build{cmake, kconfig, ...}, samples, tests, boards,
# blobs); a key outside these is refused by Zephyr.
MODULE_KEYS = {"name", "build", "samples", "tests", "boards", "blobs"}
BUILD_KEYS = {"cmake", "kconfig", "cmake-ext", "kconfig-ext", "sysbuild-cmake", "sysbuild-kconfig",
              "sysbuild-cmake-ext", "sysbuild-kconfig-ext", "depends", "settings"}


def check_module_yml(root):
    path = os.path.join(root, "zephyr", "module.yml")
    with open(path, encoding="utf-8") as f:
        meta = yaml.safe_load(f)
    check("module.yml parses as a mapping (%s)" % path, isinstance(meta, dict), repr(meta))
    if not isinstance(meta, dict):
        return None
    check("module.yml has only keys Zephyr knows", set(meta) <= MODULE_KEYS, "unknown: %s" % (set(meta) - MODULE_KEYS))
    check("module.yml names the module beamslider (ZEPHYR_BEAMSLIDER_MODULE)", meta.get("name") == "beamslider")
    build = meta.get("build", {})
    check("module.yml build: has only keys Zephyr knows", isinstance(build, dict) and set(build) <= BUILD_KEYS,
          repr(build))
    cmake_dir = os.path.join(root, str(build.get("cmake", "zephyr")))
    kconfig = os.path.join(root, str(build.get("kconfig", "zephyr/Kconfig")))
    check("build.cmake %s holds a CMakeLists.txt" % cmake_dir, os.path.isfile(os.path.join(cmake_dir, "CMakeLists.txt")))
    check("build.kconfig %s is a file" % kconfig, os.path.isfile(kconfig))
    samples = meta.get("samples", [])
    check("module.yml lists the sample(s)", isinstance(samples, list) and len(samples) > 0, repr(samples))
    for sample in samples:
        sample_dir = os.path.join(root, sample)
        for name in ("CMakeLists.txt", "prj.conf", "sample.yaml", os.path.join("src", "main.c")):
            check("sample %s has %s" % (sample, name), os.path.isfile(os.path.join(sample_dir, name)))
        sample_yaml = os.path.join(sample_dir, "sample.yaml")
        if os.path.isfile(sample_yaml):
            with open(sample_yaml, encoding="utf-8") as f:
                described = yaml.safe_load(f)
            check("sample %s: sample.yaml names the sample and its tests" % sample,
                  isinstance(described, dict) and "name" in described.get("sample", {})
                  and isinstance(described.get("tests"), dict) and len(described["tests"]) > 0, repr(described))
    return {"cmake_dir": cmake_dir, "kconfig": kconfig, "samples": [os.path.join(root, s) for s in samples]}


# The Zephyr symbols the module's Kconfig refers to, as the stand-in defines
# them: the SoC's FPU, the FPU option, the C library choice (the minimal libc
# has no sinf/cosf), and two the sample's prj.conf sets. Then the module's
# Kconfig, sourced inside a menu with its ZEPHYR_<NAME>_MODULE symbol, as
# Zephyr's module glue does.
STANDIN_KCONFIG = """\
mainmenu "Zephyr Kconfig stand-in for the beamslider module"

config CPU_HAS_FPU
\tbool "stand-in: the part has a floating-point unit"

config CPU_HAS_FPU_DOUBLE_PRECISION
\tbool "stand-in: the unit does double precision"
\tdepends on CPU_HAS_FPU

config FPU
\tbool "stand-in: compile for the floating-point unit"
\tdepends on CPU_HAS_FPU

config REQUIRES_FULL_LIBC
\tbool

choice STANDIN_LIBC
\tprompt "stand-in: C library"
\tdefault STANDIN_FULL_LIBC if REQUIRES_FULL_LIBC
\tdefault MINIMAL_LIBC

config MINIMAL_LIBC
\tbool "minimal libc (string functions, sqrt; no sinf, cosf)"
\tdepends on !REQUIRES_FULL_LIBC

config STANDIN_FULL_LIBC
\tbool "a complete C library (picolibc, newlib)"

endchoice

config PRINTK
\tbool "stand-in: printk"
\tdefault y

config MAIN_STACK_SIZE
\tint "stand-in: main thread's stack [bytes]"
\tdefault 1024

menu "beamslider module"
source "{kconfig}"

config ZEPHYR_BEAMSLIDER_MODULE
\tbool
\tdefault y
endmenu
"""


def fresh(kconf, **board):
    """Every symbol back to its default, then the part's symbols set."""
    kconf.unset_values()
    for name, value in board.items():
        kconf.syms[name].set_value(value)


def chosen(kconf, choice):
    return kconf.named_choices[choice].selection.name if kconf.named_choices[choice].selection else None


def check_kconfig(kconfig, prj_conf, out_dir):
    top = os.path.join(out_dir, "Kconfig.standin")
    with open(top, "w", encoding="utf-8") as f:
        f.write(STANDIN_KCONFIG.format(kconfig=os.path.abspath(kconfig)))
    try:
        kconf = kconfiglib.Kconfig(top, warn_to_stderr=False)
    except kconfiglib.KconfigError as error:
        check("Kconfig parses (kconfiglib)", False, str(error))
        return None
    check("Kconfig parses (kconfiglib), no warnings", not kconf.warnings, "\n       ".join(kconf.warnings))

    expected = {"BEAMSLIDER": kconfiglib.BOOL, "BEAMSLIDER_REAL_FLOAT": kconfiglib.BOOL,
                "BEAMSLIDER_REAL_DOUBLE": kconfiglib.BOOL, "BEAMSLIDER_SCENE": kconfiglib.STRING,
                "BEAMSLIDER_WITH_SUBSPACE": kconfiglib.BOOL, "BEAMSLIDER_SPEED_OPTIMIZATIONS": kconfiglib.BOOL}
    for name, kind in expected.items():
        sym = kconf.syms.get(name)
        check("Kconfig defines %s (%s, with a prompt)" % (name, kconfiglib.TYPE_TO_STR[kind]),
              sym is not None and sym.type == kind and any(node.prompt for node in sym.nodes))
    if not check("Kconfig has the choice BEAMSLIDER_REAL of float and double",
                 "BEAMSLIDER_REAL" in kconf.named_choices
                 and {s.name for s in kconf.named_choices["BEAMSLIDER_REAL"].syms}
                 == {"BEAMSLIDER_REAL_FLOAT", "BEAMSLIDER_REAL_DOUBLE"}):
        return None

    fresh(kconf, CPU_HAS_FPU=2)
    check("CONFIG_BEAMSLIDER is off unless asked for", kconf.syms["BEAMSLIDER"].str_value == "n")
    kconf.syms["BEAMSLIDER"].set_value(2)
    values = {name: kconf.syms[name].str_value for name in
              ("BEAMSLIDER", "BEAMSLIDER_SCENE", "BEAMSLIDER_WITH_SUBSPACE", "BEAMSLIDER_SPEED_OPTIMIZATIONS", "FPU")}
    check("CONFIG_BEAMSLIDER=y can be set", values["BEAMSLIDER"] == "y")
    check("single-precision FPU (Cortex-M4F): float by default", chosen(kconf, "BEAMSLIDER_REAL") == "BEAMSLIDER_REAL_FLOAT",
          str(chosen(kconf, "BEAMSLIDER_REAL")))
    check("float implies the FPU", values["FPU"] == "y")
    check("defaults: no scene (run-time scenes), subspace step on, -O3 on",
          values["BEAMSLIDER_SCENE"] == "" and values["BEAMSLIDER_WITH_SUBSPACE"] == "y"
          and values["BEAMSLIDER_SPEED_OPTIMIZATIONS"] == "y", repr(values))
    check("CONFIG_BEAMSLIDER requires a full C library (the minimal one has no sinf, cosf)",
          chosen(kconf, "STANDIN_LIBC") == "STANDIN_FULL_LIBC" and kconf.syms["MINIMAL_LIBC"].str_value == "n")
    kconf.syms["MINIMAL_LIBC"].set_value(2)
    check("... and the minimal libc cannot be chosen with it", kconf.syms["MINIMAL_LIBC"].str_value == "n")
    kconf.syms["BEAMSLIDER_REAL_DOUBLE"].set_value(2)
    check("double can be chosen", chosen(kconf, "BEAMSLIDER_REAL") == "BEAMSLIDER_REAL_DOUBLE")

    fresh(kconf, CPU_HAS_FPU=2, CPU_HAS_FPU_DOUBLE_PRECISION=2, BEAMSLIDER=2)
    check("double-precision FPU (Cortex-M7): double by default",
          chosen(kconf, "BEAMSLIDER_REAL") == "BEAMSLIDER_REAL_DOUBLE")
    fresh(kconf, BEAMSLIDER=2)
    check("no FPU (Cortex-M3): float by default, no FPU",
          chosen(kconf, "BEAMSLIDER_REAL") == "BEAMSLIDER_REAL_FLOAT" and kconf.syms["FPU"].str_value == "n")

    # The sample's configuration on a Cortex-M4F part (the part's symbols,
    # then prj.conf, on a fresh parse, as a build reads them).
    kconf = kconfiglib.Kconfig(top, warn_to_stderr=False)
    board = os.path.join(out_dir, "board.conf")
    with open(board, "w", encoding="utf-8") as f:
        f.write("CONFIG_CPU_HAS_FPU=y\n")
    kconf.load_config(board)
    kconf.load_config(prj_conf, replace=False)
    check("the sample's prj.conf applies without a warning", not kconf.warnings, "\n       ".join(kconf.warnings))
    check("the sample's configuration: CONFIG_BEAMSLIDER=y, float, scene fig6",
          kconf.syms["BEAMSLIDER"].str_value == "y" and chosen(kconf, "BEAMSLIDER_REAL") == "BEAMSLIDER_REAL_FLOAT"
          and kconf.syms["BEAMSLIDER_SCENE"].str_value == "fig6")
    kconf.write_config(os.path.join(out_dir, ".config"), header="# the beamslider sample's configuration, stand-in\n")
    lines = []
    for sym in kconf.unique_defined_syms:
        if not sym.name.startswith(("BEAMSLIDER", "ZEPHYR_BEAMSLIDER")) and sym.name not in ("FPU", "PRINTK", "MAIN_STACK_SIZE"):
            continue
        if sym.type in (kconfiglib.BOOL, kconfiglib.TRISTATE):
            if sym.str_value != "n":
                lines.append('set(CONFIG_%s %s)' % (sym.name, sym.str_value))
        elif sym.type in (kconfiglib.INT, kconfiglib.HEX):
            lines.append('set(CONFIG_%s %s)' % (sym.name, sym.str_value))
        elif sym.type == kconfiglib.STRING:
            lines.append('set(CONFIG_%s "%s")' % (sym.name, sym.str_value.replace("\\", "\\\\").replace('"', '\\"')))
    return lines


def main():
    if len(sys.argv) != 3:
        print("usage: check_zephyr_module.py MODULE_ROOT OUT_DIR", file=sys.stderr)
        return 2
    root, out_dir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    os.makedirs(out_dir, exist_ok=True)
    module = check_module_yml(root)
    if module is None or not os.path.isfile(module["kconfig"]) or not module["samples"]:
        print("check_zephyr_module: %d passed, %d failed" % (passed, failed + (0 if failed else 1)))
        return 1
    sample = module["samples"][0]
    if not os.path.isfile(os.path.join(sample, "prj.conf")):
        print("check_zephyr_module: %d passed, %d failed" % (passed, failed))
        return 1
    lines = check_kconfig(module["kconfig"], os.path.join(sample, "prj.conf"), out_dir)
    if lines is not None:
        lines += ['set(STANDIN_MODULE_DIR "%s")' % root, 'set(STANDIN_MODULE_CMAKE_DIR "%s")' % module["cmake_dir"],
                  'set(STANDIN_APP_DIR "%s")' % sample]
        with open(os.path.join(out_dir, "config.cmake"), "w", encoding="utf-8") as f:
            f.write("# written by tests/buildsys/check_zephyr_module.py: the sample's CONFIG_* values\n")
            f.write("\n".join(lines) + "\n")
    print("check_zephyr_module: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
