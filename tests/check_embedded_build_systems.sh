#!/bin/sh
# check_embedded_build_systems.sh OUT [HOST_RUN] - the Zephyr module
# (port/zephyr) and the PlatformIO library (port/platformio) checked without
# Zephyr, west or PlatformIO, which Debian does not have (`make
# embedded-build-systems-test`, part of `make test-long`; tests/buildsys/):
#
#   Zephyr      module.yml and every path it names, the Kconfig under
#               kconfiglib (defaults, the precision choice, the sample's
#               prj.conf: tests/buildsys/check_zephyr_module.py); the module's
#               CMakeLists.txt run by CMake with a stand-in of the Zephyr
#               functions (tests/buildsys/zephyr/) and the CONFIG_* values
#               Kconfig gave, cross-compiled for a Cortex-M4F: the core for
#               fig6 in float as a Zephyr library (bs_sim_step in it, no C
#               library call but the port's math: check_core_symbols.sh; the
#               module's -O3 after Zephyr's -Os; the generated configuration),
#               and the sample with a stand-in kernel, run under QEMU: it
#               reports s every 0.1 s and ends in the state the host computes
#               (HOST_RUN's hash at the same step); a bad CONFIG_BEAMSLIDER_SCENE
#               stops CMake with a message naming it, a scene given by a
#               header's path is included by that path
#   PlatformIO  library.json, its extraScript, the example's platformio.ini;
#               the core built as PlatformIO builds it for a Cortex-M4F, the
#               example linked with it and run under QEMU, the same state as
#               the host (tests/buildsys/check_platformio.py)
#
# OUT: the folder for the builds (kept, so that a second run rebuilds only
# what changed). HOST_RUN: optional, the host twin of tests/embedded for fig6
# in float (build/embhost/fig6.float.20000): its line for step 15000 holds the
# hash both images must reach. Python's yaml and kconfiglib are required (the
# check says what to install); without cmake, arm-none-eabi-gcc or
# qemu-system-arm the parts that need them are skipped with a notice.
set -u
if [ $# -lt 1 ] || [ ! -f port/zephyr/zephyr/module.yml ]; then
    echo "usage (from the repository root): sh tests/check_embedded_build_systems.sh OUT [HOST_RUN]" >&2
    exit 2
fi
out=$1
host_run=${2:-}
root=$(pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
. tests/check_lib.sh

# Debian's interpreter: a python3 earlier on PATH may lack Debian's packages.
python=/usr/bin/python3
[ -x "$python" ] || python=python3
have() { command -v "$1" >/dev/null 2>&1; }
skip() { echo "skip - $1: needs $2 (apt-get install $3)"; }
cross_packages="gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi"

# run_py NAME SCRIPT ARGS...: a Python check; its ok/FAIL lines count here.
run_py() {
    py_name=$1
    shift
    "$python" "$@" > "$out/$py_name.txt" 2>&1
    py_status=$?
    cat "$out/$py_name.txt"
    passed=$((passed + $(grep -c '^ok ' "$out/$py_name.txt")))
    failed=$((failed + $(grep -c '^FAIL ' "$out/$py_name.txt")))
    if [ "$py_status" -ne 0 ] && ! grep -q '^FAIL ' "$out/$py_name.txt"; then
        fail "$py_name ran (exit status $py_status)"
    fi
    [ "$py_status" -eq 0 ]
}

# defines_step ARCHIVE: bs_sim_step is defined in it
defines_step() { arm-none-eabi-nm --defined-only "$1" | grep -q ' T bs_sim_step$'; }
# config_is_fig6_float HEADER
config_is_fig6_float() {
    grep -q '^#define BS_REAL_FLOAT 1' "$1" && grep -q '^#define BS_SCENE_CONFIG "configs/fig6.h"' "$1"
}
# no_scene HEADER: a configuration for scenes given at run time
no_scene() { grep -q '^/\* none \*/' "$1" && ! grep -q BS_SCENE_CONFIG "$1"; }
# step_flags_ok COMPILE_COMMANDS: bs_step.c's line has the M4F's FPU, the
# core's flags, and -O3 after Zephyr's -Os
step_flags_ok() {
    grep '"command".*core/src/bs_step\.c' "$1" |
        grep -q -- '-mfloat-abi=hard -mfpu=fpv4-sp-d16 .*-Os .*-ffp-contract=off .*-fno-math-errno .*-O3 '
}

# the hash a run reached: "... hash H" in its last line
end_hash() { sed -n 's/.*done, [0-9]* steps, hash \([0-9a-f]*\).*/\1/p' "$1"; }
host_hash=
if [ -n "$host_run" ]; then
    host_hash=$("$host_run" | sed -n 's/^scene: step 15000 hash \([0-9a-f]*\) .*/\1/p')
    check "the host run $host_run gives the hash of step 15000 ($host_hash)" [ -n "$host_hash" ]
fi

# run_image NAME ELF: the image under QEMU, three blocks of 0.1 s, the host's state
run_image() {
    sh port/cortex-m/run.sh "$2" cortex-m4f 60 > "$out/$1.out" 2>&1
    check_status "$1: runs under QEMU (mps2-an386)" 0 $? "$out/$1.out"
    check_has "$1: prints the scene and the precision" "$out/$1.out" "scene fig6, float"
    blocks=$(grep -c '^t 0\.[123] s  s 0\.[0-9]\{6\}' "$out/$1.out")
    check "$1: prints s after each 0.1 s block ($blocks of 3)" [ "$blocks" -eq 3 ]
    check_has "$1: ends after 15000 steps" "$out/$1.out" "done, 15000 steps"
    if [ -n "$host_hash" ]; then
        check "$1: the state the host computes (hash $(end_hash "$out/$1.out"), host $host_hash)" \
            [ "$(end_hash "$out/$1.out")" = "$host_hash" ]
    fi
}

if ! "$python" -c 'import yaml, kconfiglib' 2>/dev/null; then
    fail "Python's yaml and kconfiglib for $python" \
        "missing: apt-get install python3-yaml python3-kconfiglib (make test installs them as root)"
    echo "check_embedded_build_systems: $passed passed, $failed failed"
    exit 1
fi

# ---- Zephyr -------------------------------------------------------------------------
zout=$out/zephyr
zbuild=$out/zephyr-build
run_py zephyr-module tests/buildsys/check_zephyr_module.py port/zephyr "$zout"
zephyr_ok=$?

# The shared CMake logic alone (cmake -P): a bad scene name, none, a scene by path.
if have cmake; then
    cat > "$out/scene.cmake" <<EOF
include("$root/port/cmake/beamslider_core.cmake")
beamslider_core_configure(REAL float SCENE "\${SCENE}" SCENE_BASE "$root/port/zephyr/samples/twin"
    WITH_SUBSPACE ON CONFIG_DIR "$out/scene" REAL_OPTION CONFIG_BEAMSLIDER_REAL_FLOAT/_DOUBLE
    SCENE_OPTION CONFIG_BEAMSLIDER_SCENE)
EOF
    cmake -DSCENE=nope -P "$out/scene.cmake" > "$out/scene-bad.txt" 2>&1
    check_status "CONFIG_BEAMSLIDER_SCENE=\"nope\" stops CMake" 1 $? "$out/scene-bad.txt"
    check_has "... with a message naming the option and the scenes there are" "$out/scene-bad.txt" \
        "CONFIG_BEAMSLIDER_SCENE 'nope' names no scene header"
    rm -f "$out/scene/bs_build_config.h"
    cmake -DSCENE= -P "$out/scene.cmake" > "$out/scene-none.txt" 2>&1
    check_status "an empty CONFIG_BEAMSLIDER_SCENE: scenes given at run time" 0 $? "$out/scene-none.txt"
    check "... no scene in the configuration" no_scene "$out/scene/bs_build_config.h"
    rm -f "$out/scene/bs_build_config.h"
    cmake -DSCENE=../../../../configs/fig6_1mode.h -P "$out/scene.cmake" > "$out/scene-path.txt" 2>&1
    check_status "a scene given by a header's path, relative to the application" 0 $? "$out/scene-path.txt"
    check_has "... is included by its absolute path" "$out/scene/bs_build_config.h" \
        "#define BS_SCENE_CONFIG \"$root/configs/fig6_1mode.h\""
fi

if [ "$zephyr_ok" -ne 0 ]; then
    fail "Zephyr stand-in build: not tried (the module's checks failed)"
elif ! have cmake; then
    skip "Zephyr stand-in build" cmake cmake
elif ! have arm-none-eabi-gcc; then
    skip "Zephyr stand-in build" arm-none-eabi-gcc "$cross_packages"
else
    if cmake -S tests/buildsys/zephyr -B "$zbuild" -DCMAKE_TOOLCHAIN_FILE="$root/tests/consumer/cortex-m4f.cmake" \
        -DSTANDIN_CONFIG="$zout/config.cmake" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON > "$out/zephyr-cmake.txt" 2>&1 &&
        cmake --build "$zbuild" -j2 >> "$out/zephyr-cmake.txt" 2>&1; then
        pass "the module's CMakeLists.txt and the sample build with the stand-in (cortex-m4f, fig6, float)"
    else
        fail "the module's CMakeLists.txt and the sample build with the stand-in" "$(tail -n 30 "$out/zephyr-cmake.txt")"
    fi
    zlib=$zbuild/modules/beamslider/libbeamslider.a
    if [ -f "$zlib" ]; then
        check "the Zephyr library $zlib defines bs_sim_step" defines_step "$zlib"
        check "the Zephyr library references no C library call but the port's math" \
            env NM=arm-none-eabi-nm sh tests/check_core_symbols.sh float "$zlib"
        check "its configuration: float, configs/fig6.h" \
            config_is_fig6_float "$zbuild/modules/beamslider/include/bs_build_config.h"
        check "bs_step.c compiled for the M4F's FPU, with the core's flags, -O3 after Zephyr's -Os" \
            step_flags_ok "$zbuild/compile_commands.json"
    fi
    if ! have qemu-system-arm; then
        skip "the sample under QEMU" qemu-system-arm qemu-system-arm
    elif [ -f "$zbuild/app.elf" ]; then
        run_image zephyr-sample "$zbuild/app.elf"
    fi
fi

# ---- PlatformIO ------------------------------------------------------------------------
pout=$out/platformio
if have arm-none-eabi-gcc; then
    run_py platformio tests/buildsys/check_platformio.py port/platformio port/platformio/example "$pout" arm-none-eabi-gcc
    if [ -f "$pout/libbeamslider.a" ]; then
        check "the PlatformIO library defines bs_sim_step" defines_step "$pout/libbeamslider.a"
        check "the PlatformIO library references no C library call but the port's math" \
            env NM=arm-none-eabi-nm sh tests/check_core_symbols.sh float "$pout/libbeamslider.a"
    fi
    if ! have qemu-system-arm; then
        skip "the PlatformIO example under QEMU" qemu-system-arm qemu-system-arm
    elif [ -f "$pout/example.elf" ]; then
        run_image platformio-example "$pout/example.elf"
    fi
else
    skip "the PlatformIO build" arm-none-eabi-gcc "$cross_packages"
    run_py platformio tests/buildsys/check_platformio.py port/platformio port/platformio/example "$pout"
fi

echo "check_embedded_build_systems: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
