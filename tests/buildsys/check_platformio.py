#!/usr/bin/python3
"""check_platformio.py LIB_DIR PROJECT_DIR OUT_DIR [CC] - the beamslider
PlatformIO library (port/platformio) and its example project read and built
as PlatformIO would, without PlatformIO (tests/check_embedded_build_systems.sh
runs it):

  library.json   parses; only build fields PlatformIO knows; its version is
                 the core's (BS_VERSION_STRING); srcDir and includeDir are
                 folders (includeDir with beamslider.h and every "headers"
                 entry); srcFilter selects exactly core/src/*.c; flags carry
                 the core's rounding and math flags and no relative -I (its
                 meaning changed between PlatformIO releases); extraScript
                 exists and, run with a stand-in of PlatformIO's Import(),
                 adds the folder of bs_build_config.h to the shared include
                 path and the port's (bs_port.h) to the library's own flags;
                 the generated header's template has only the fill-ins that
                 include/bs_build_config.h stands in for
  platformio.ini the example's: lib_deps takes the library by symlink://
                 and the path leads to LIB_DIR; build_flags select the
                 precision (BS_REAL_FLOAT) and a scene header that exists
  with CC (a cross compiler, e.g. arm-none-eabi-gcc): the library built as
                 PlatformIO builds it for a Cortex-M4F: every source srcFilter
                 selects, compiled with the platform's flags (here the M4F's,
                 -Os), the project's build_flags, then the library's flags and
                 what extraScript added, on its include path includeDir, srcDir
                 and the extraScript's; into OUT_DIR/libbeamslider.a. The
                 example's main.c compiled as the project's source (build_flags
                 and the library's shared include path only, run for
                 EXAMPLE_TENTHS=3) and linked with port/cortex-m's startup for
                 QEMU's mps2-an386: OUT_DIR/example.elf. A program without
                 BS_REAL_FLOAT in its flags stops at bs_build_config.h's #error.

Stricter than PlatformIO: the repository's warnings, as errors. Prints
"ok - ..." / "FAIL - ..." per check; exit status 0 when all pass, 1 when one
fails.
"""
import concurrent.futures
import configparser
import glob
import json
import os
import re
import shlex
import subprocess
import sys

passed = 0
failed = 0


def check(description, condition, detail=""):
    global passed, failed
    if condition:
        passed += 1
        print("ok   - " + description)
    else:
        failed += 1
        print("FAIL - " + description + (("\n       " + detail.replace("\n", "\n       ")) if detail else ""))
    return condition


# library.json "build" fields PlatformIO's library builder reads.
BUILD_FIELDS = {"srcDir", "srcFilter", "includeDir", "flags", "unflags", "extraScript", "libArchive",
                "libLDFMode", "libCompatMode", "builder"}
CORE_FLAGS = ("-std=c99", "-ffp-contract=off", "-fno-math-errno")
M4F = ["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"]
# What a platform puts on every compile line (PlatformIO's embedded platforms
# build at -Os with one section per function), and the repository's warnings.
PLATFORM = ["-Os", "-ffunction-sections", "-fdata-sections"]
STRICT = ["-Wall", "-Wextra", "-Werror", "-Wdouble-promotion", "-Wfloat-conversion", "-Wundef", "-Wshadow", "-Wvla"]


def as_list(value):
    if value is None:
        return []
    return value if isinstance(value, list) else [value]


def src_filter_match(src_dir, patterns):
    """The files a srcFilter selects: +<glob> adds, -<glob> removes, in order;
    a folder stands for every file under it (PlatformIO's rules, as far as this
    library needs them)."""
    selected = []
    for token in re.findall(r"([+-])<([^>]*)>", " ".join(as_list(patterns))):
        sign, pattern = token
        found = []
        for path in glob.glob(os.path.join(src_dir, pattern), recursive=True):
            if os.path.isdir(path):
                found += [os.path.join(d, f) for d, _, files in os.walk(path) for f in files]
            else:
                found.append(path)
        found = [os.path.realpath(p) for p in found]
        if sign == "+":
            selected += [p for p in found if p not in selected]
        else:
            selected = [p for p in selected if p not in found]
        yield sign + "<" + pattern + ">", found, selected


class StandinEnv:
    """What the extraScript may call on PlatformIO's (SCons) environment."""

    def __init__(self):
        self.added = {}

    def Append(self, **scopes):  # noqa: N802 (SCons's name)
        for scope, values in scopes.items():
            self.added.setdefault(scope, []).extend(as_list(values))


class StandinLibBuilder:
    def __init__(self, path):
        self.path = path


def run_extra_script(script, lib_dir):
    env = StandinEnv()
    namespace = {"__name__": "extra_script"}

    def standin_import(*names):
        exported = {"env": env, "pio_lib_builder": StandinLibBuilder(lib_dir)}
        for name in names:
            namespace[name] = exported[name]

    namespace["Import"] = standin_import
    cwd = os.getcwd()
    os.chdir(lib_dir)  # PlatformIO runs it from the library's folder
    try:
        with open(script, encoding="utf-8") as f:
            exec(compile(f.read(), script, "exec"), namespace)  # noqa: S102 (the repository's own script)
    finally:
        os.chdir(cwd)
    return env.added


def check_library(lib_dir, root):
    path = os.path.join(lib_dir, "library.json")
    with open(path, encoding="utf-8") as f:
        manifest = json.load(f)
    check("library.json parses (%s)" % path, isinstance(manifest, dict))
    version = re.search(r'#define BS_VERSION_STRING "([^"]*)"',
                        open(os.path.join(root, "core", "include", "beamslider.h"), encoding="utf-8").read()).group(1)
    check("library.json: name beamslider, version %s (BS_VERSION_STRING)" % version,
          manifest.get("name") == "beamslider" and manifest.get("version") == version,
          "name %r, version %r" % (manifest.get("name"), manifest.get("version")))
    build = manifest.get("build", {})
    check("library.json build: only fields PlatformIO knows", set(build) <= BUILD_FIELDS,
          "unknown: %s" % (set(build) - BUILD_FIELDS))

    src_dir = os.path.realpath(os.path.join(lib_dir, build.get("srcDir", "src")))
    include_dir = os.path.realpath(os.path.join(lib_dir, build.get("includeDir", "include")))
    check("srcDir %s is the repository" % build.get("srcDir"), src_dir == os.path.realpath(root), src_dir)
    check("includeDir %s holds beamslider.h" % build.get("includeDir"),
          os.path.isfile(os.path.join(include_dir, "beamslider.h")), include_dir)
    for header in as_list(manifest.get("headers")):
        check("headers: %s is in includeDir" % header, os.path.isfile(os.path.join(include_dir, header)))

    selected = []
    for rule, found, selected in src_filter_match(src_dir, build.get("srcFilter", "+<*>")):
        check("srcFilter %s matches files" % rule, len(found) > 0)
    core = sorted(os.path.realpath(p) for p in glob.glob(os.path.join(root, "core", "src", "*.c")))
    check("srcFilter selects exactly core/src/*.c (%d files)" % len(core), sorted(selected) == core,
          "selected: %s" % sorted(os.path.relpath(p, root) for p in selected))

    flags = [word for entry in as_list(build.get("flags")) for word in shlex.split(entry)]
    for flag in CORE_FLAGS:
        check("flags carry %s" % flag, flag in flags, repr(flags))
    check("flags name no relative -I (extraScript gives absolute ones)",
          not [f for f in flags if f.startswith("-I") and not os.path.isabs(f[2:] or "/")], repr(flags))

    script = os.path.join(lib_dir, build.get("extraScript", ""))
    added = {}
    if check("extraScript %s exists" % build.get("extraScript"), "extraScript" in build and os.path.isfile(script)):
        try:
            added = run_extra_script(script, lib_dir)
        except Exception as error:  # noqa: BLE001 (any failure of the script is the finding)
            check("extraScript runs", False, "%s: %s" % (type(error).__name__, error))
    cpppath = [str(p) for p in added.get("CPPPATH", [])]
    ccflags = [str(f) for f in added.get("CCFLAGS", [])]
    check("extraScript: the folder of bs_build_config.h on the shared include path (CPPPATH)",
          any(os.path.isfile(os.path.join(p, "bs_build_config.h")) for p in cpppath), repr(cpppath))
    # include/bs_build_config.h stands in for the generated header: it covers
    # the template's two fill-ins (BS_REAL_FLOAT from build_flags, the switches
    # as build_flags' defines); a new fill-in needs it updated.
    template = open(os.path.join(root, "core", "include", "bs_build_config.h.in"), encoding="utf-8").read()
    check("bs_build_config.h.in has the fill-ins include/bs_build_config.h stands in for",
          sorted(set(re.findall(r"@[A-Z_]+@", template))) == ["@BS_CONFIG_LINES@", "@BS_REAL_FLOAT@"],
          repr(sorted(set(re.findall(r"@[A-Z_]+@", template)))))
    private = [f[2:] for f in ccflags if f.startswith("-I")]
    check("extraScript: the port's folder (bs_port.h) on the library's own flags only",
          any(os.path.isfile(os.path.join(p, "bs_port.h")) for p in private)
          and not any(os.path.isfile(os.path.join(p, "bs_port.h")) for p in cpppath), repr(added))
    return {"src_dir": src_dir, "include_dir": include_dir, "sources": core, "flags": flags,
            "cpppath": cpppath, "ccflags": ccflags}


def check_project(project_dir, lib_dir, root):
    ini = os.path.join(project_dir, "platformio.ini")
    config = configparser.ConfigParser(interpolation=None, inline_comment_prefixes=(";",))
    config.read(ini, encoding="utf-8")
    check("platformio.ini parses, with an [env] section (%s)" % ini, config.has_section("env"))
    env = config["env"] if config.has_section("env") else {}
    deps = [d.strip() for d in env.get("lib_deps", "").splitlines() if d.strip()]
    links = [d.split("symlink://", 1)[1] for d in deps if "symlink://" in d]
    check("lib_deps takes the library by symlink:// (%s)" % deps, len(links) == 1)
    if links:
        target = os.path.realpath(os.path.join(project_dir, links[0]))
        check("symlink://%s leads to the library (%s)" % (links[0], lib_dir),
              target == os.path.realpath(lib_dir), target)
    # each line split as a shell would (PlatformIO passes a define's value to
    # the compiler as written, quotes included); "-D NAME" joined to "-DNAME"
    flags = []
    words = iter([word for line in env.get("build_flags", "").splitlines() for word in shlex.split(line)])
    for word in words:
        flags.append("-D" + next(words, "") if word == "-D" else word)
    defines = dict(f[2:].partition("=")[::2] for f in flags if f.startswith("-D"))
    check("build_flags select the precision: BS_REAL_FLOAT=0 or 1", defines.get("BS_REAL_FLOAT") in ("0", "1"),
          repr(defines))
    scene = defines.get("BS_SCENE_CONFIG", "")
    check("build_flags select the scene: BS_SCENE_CONFIG is a quoted header name that exists (%s)" % scene,
          len(scene) > 2 and scene[0] == scene[-1] == '"' and os.path.isfile(os.path.join(root, scene[1:-1])))
    return flags


def up_to_date(output, argv, inputs):
    """output exists, is newer than every input and was made by argv (OUTPUT.cmd)."""
    try:
        with open(output + ".cmd", encoding="utf-8") as f:
            same = f.read() == "\n".join(argv)
        return same and os.path.getmtime(output) > max(os.path.getmtime(i) for i in inputs)
    except OSError:
        return False


def compile_all(jobs, inputs):
    """jobs: (output, argv, source); compiled two at a time unless up to date
    (a second run rebuilds what changed); returns the failures."""
    class Done:
        returncode = 0
        stdout = ""

    def run(job):
        if up_to_date(job[0], job[1], inputs + [job[2]]):
            return job, Done()
        result = subprocess.run(job[1], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if result.returncode == 0:
            with open(job[0] + ".cmd", "w", encoding="utf-8") as f:
                f.write("\n".join(job[1]))
        return job, result
    failures = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for job, result in pool.map(run, jobs):
            if result.returncode != 0:
                failures.append("%s\n%s" % (" ".join(job[1]), result.stdout))
    return failures


def build(cc, lib, project_flags, project_dir, root, out_dir):
    ar = re.sub(r"gcc$", "ar", cc)
    obj_dir = os.path.join(out_dir, "lib")
    os.makedirs(obj_dir, exist_ok=True)
    includes = ["-I" + d for d in [lib["include_dir"], lib["src_dir"]] + lib["cpppath"]]
    lib_argv = [cc] + M4F + PLATFORM + STRICT + project_flags + lib["flags"] + lib["ccflags"] + includes
    jobs = [(os.path.join(obj_dir, os.path.basename(src)[:-2] + ".o"),
             lib_argv + ["-c", src, "-o", os.path.join(obj_dir, os.path.basename(src)[:-2] + ".o")], src)
            for src in lib["sources"]]
    main_o = os.path.join(out_dir, "main.o")
    main_c = os.path.join(project_dir, "src", "main.c")
    jobs.append((main_o, [cc] + M4F + PLATFORM + STRICT + project_flags + includes +
                 ["-DEXAMPLE_TENTHS=3", "-c", main_c, "-o", main_o], main_c))
    headers = [h for d in [lib["include_dir"], os.path.join(root, "core", "src"), os.path.join(root, "configs")]
               + lib["cpppath"] + [f[2:] for f in lib["ccflags"] if f.startswith("-I")]
               for h in glob.glob(os.path.join(d, "*.h"))]
    failures = compile_all(jobs, headers)
    if not check("the library's %d sources and the example's main.c compile for the Cortex-M4F" % len(lib["sources"]),
                 not failures, "%d failed; the first:\n%s" % (len(failures), failures[0]) if failures else ""):
        return
    archive = os.path.join(out_dir, "libbeamslider.a")
    if os.path.exists(archive):
        os.remove(archive)
    result = subprocess.run([ar, "rcs", archive] + [job[0] for job in jobs[:-1]],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    check("archive %s" % archive, result.returncode == 0, result.stdout)
    startup = os.path.join(root, "port", "cortex-m", "startup.c")
    link = [cc] + M4F + PLATFORM + STRICT + ["-nostartfiles", "-T" + os.path.join(root, "port", "cortex-m", "cm.ld"),
            "-Wl,--gc-sections", "--specs=nano.specs", "--specs=rdimon.specs", "-u", "_printf_float",
            "-Wl,--defsym=CODE_BASE=0x00000000,--defsym=CODE_SIZE=0x400000,"
            "--defsym=DATA_BASE=0x20000000,--defsym=DATA_SIZE=0x400000",
            "-o", os.path.join(out_dir, "example.elf"), startup, main_o, archive, "-lm"]
    result = subprocess.run(link, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    check("the example links with the library for QEMU's mps2-an386 (example.elf)", result.returncode == 0,
          " ".join(link) + "\n" + result.stdout)

    # Without the precision in build_flags: the header's message, not a silent default.
    probe = [cc] + M4F + includes + ["-fsyntax-only", "-x", "c", "-"]
    result = subprocess.run(probe, input='#include "beamslider.h"\n', stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    check("without BS_REAL_FLOAT in build_flags the build stops and says what to add",
          result.returncode != 0 and "add -D BS_REAL_FLOAT=1 (float) or -D BS_REAL_FLOAT=0 (double) to build_flags"
          in result.stdout, result.stdout)


def main():
    if len(sys.argv) not in (4, 5):
        print("usage: check_platformio.py LIB_DIR PROJECT_DIR OUT_DIR [CC]", file=sys.stderr)
        return 2
    lib_dir, project_dir, out_dir = (os.path.abspath(a) for a in sys.argv[1:4])
    cc = sys.argv[4] if len(sys.argv) == 5 else ""
    root = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    os.makedirs(out_dir, exist_ok=True)
    lib = check_library(lib_dir, root)
    project_flags = check_project(project_dir, lib_dir, root)
    if cc and failed == 0:
        build(cc, lib, project_flags, project_dir, root, out_dir)
    print("check_platformio: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
