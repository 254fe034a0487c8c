#!/bin/sh
# check_consumer.sh STAGE BUILD SCENE_LIB [CM_LIB] - beamslider taken as a
# library, the ways its users take it (`make consumer-test`, part of `make test`,
# which prepares the arguments):
#
#   STAGE      a fresh `make install PREFIX=STAGE` (absolute path)
#   BUILD      the build folder: the programs go to BUILD/consumer, the CMake
#              builds to BUILD/consumer-cmake, -cmake-scene, -cmake-m4f, -package
#   SCENE_LIB  the core compiled by make for configs/fig6_1mode.h in float
#              (build/lib/host/libbeamslider-float-fig6_1mode.a, the C++ test's)
#   CM_LIB     optional: `make TARGET=cortex-m4f SCENE=fig6_1mode REAL=float lib`
#
# Checks
#   (a) pkg-config: tests/consumer/consumer.c (C99) against beamslider-double and
#       beamslider-float, and tests/test_cxx.cpp (C++11) against beamslider-double,
#       compiled with warnings as errors, linked with `pkg-config --libs`, run;
#       the C and C++ programs reach the same state (hash)
#   (b) CMake, add_subdirectory(port/cmake): consumer.c with the core built by
#       CMake (run-time scenes, double: the same hash as (a), although CMake
#       compiles without -O); with BEAMSLIDER_SCENE=fig6_1mode, float: the same
#       hash as consumer.c linked with SCENE_LIB; cross-compiled for a
#       Cortex-M4F (library only: the embedded port by default, freestanding)
#   (c) CMake, find_package(beamslider MAJOR.MINOR) of this version: both imported
#       targets, the same hashes as (a); the next minor version is refused
#   (d) the consumer compiled against the float headers and linked with the
#       double library (and the reverse) stops with BS_E_BUILD, not a crash
#   (e) README.md's library program and CMakeLists.txt, as the README shows
#       them (between <!-- library-program --> and <!-- library-cmake -->
#       marks), built from the installed tree alone (no source tree on the
#       include path) in C and C++, with pkg-config (beamslider-host-double,
#       -float) and with find_package: they load the installed fig6.ini and
#       reach the state hash of the installed `beamslider run --t-end 1`
#   (f) every find_package(beamslider X.Y ...) of the repository's documents
#       asks for this tree's MAJOR.MINOR (core/include/beamslider.h), which
#       the installed package accepts
#   and CM_LIB references nothing but the port's math (check_core_symbols.sh).
#
# A missing tool (cc, c++, pkg-config, cmake) skips the checks that need it with
# a notice; any failed check fails the script.
# shellcheck disable=SC2086,SC2046 # compiler flags and pkg-config's output are lists of words
set -u
if [ $# -lt 3 ] || [ ! -f tests/consumer/consumer.c ]; then
    echo "usage (from the repository root): sh tests/check_consumer.sh STAGE BUILD SCENE_LIB [CM_LIB]" >&2
    exit 2
fi
stage=$1
build=$2
scene_lib=$3
cm_lib=${4:-}
root=$(pwd)
out=$build/consumer
mkdir -p "$out"
. tests/check_lib.sh

CC=${CC:-cc}
CXX=${CXX:-c++}
C_FLAGS="-std=c99 -O2 -Wall -Wextra -Werror -pedantic"
CXX_FLAGS="-std=c++11 -O2 -Wall -Wextra -Werror -pedantic"
export PKG_CONFIG_PATH="$stage/lib/pkgconfig"
version=$(sed -n 's/^#define BS_VERSION_STRING "\(.*\)"/\1/p' core/include/beamslider.h)

have() { command -v "$1" >/dev/null 2>&1; }
skip() { echo "skip - $1: needs $2 (apt-get install $3)"; }
hash_of() { sed -n 's/.*hash \([0-9a-f]*\).*/\1/p' "$1"; }

# run NAME EXPECTED_STATUS PROGRAM [ARGUMENTS...]: runs it, output in $out/NAME.txt
run() {
    name=$1
    expected=$2
    shift 2
    "$@" > "$out/$name.txt" 2>&1
    run_status=$?
    check_status "$name runs (exit status $expected): $(head -n 1 "$out/$name.txt")" "$expected" "$run_status" "$out/$name.txt"
    [ "$run_status" -eq "$expected" ]
}

# build DESCRIPTION COMMAND...: COMMAND's output in $out/build.txt on failure
build() {
    build_what=$1
    shift
    if "$@" > "$out/build.txt" 2>&1; then pass "$build_what"; return 0; fi
    fail "$build_what" "$(cat "$out/build.txt")"
    return 1
}

# same_hash DESCRIPTION FILE1 FILE2
same_hash() {
    h1=$(hash_of "$2")
    h2=$(hash_of "$3")
    if [ -n "$h1" ] && [ "$h1" = "$h2" ]; then pass "$1 (hash $h1)"; else fail "$1" "$2: '$h1', $3: '$h2'"; fi
}

# ---- (a) the installed library through pkg-config ---------------------------------
if have pkg-config && have "$CC"; then
    check "pkg-config finds beamslider-double $version" [ "$(pkg-config --modversion beamslider-double)" = "$version" ]
    check "pkg-config finds beamslider-float $version" [ "$(pkg-config --modversion beamslider-float)" = "$version" ]
    for real in double float; do
        build "C consumer against beamslider-$real (pkg-config --cflags --libs)" \
            "$CC" $C_FLAGS -I"$root" -o "$out/c-$real" tests/consumer/consumer.c \
            $(pkg-config --cflags --libs "beamslider-$real") &&
            run "c-$real" 0 "$out/c-$real"
    done
    if have "$CXX"; then
        build "C++ consumer tests/test_cxx.cpp against beamslider-double (pkg-config)" \
            "$CXX" $CXX_FLAGS -I"$root" -o "$out/cxx-double" tests/test_cxx.cpp \
            $(pkg-config --cflags --libs beamslider-double) &&
            run cxx-double 0 "$out/cxx-double" &&
            same_hash "C and C++ consumers reach the same state" "$out/c-double.txt" "$out/cxx-double.txt"
    else
        skip "C++ consumer" "$CXX" g++
    fi
    # (d) float headers, double library, and the reverse
    for pair in float:double double:float; do
        headers=${pair%:*}
        library=${pair#*:}
        build "C consumer with the $headers headers, linked with the $library library" \
            "$CC" $C_FLAGS -I"$root" -o "$out/mismatch-$headers-$library" tests/consumer/consumer.c \
            $(pkg-config --cflags "beamslider-$headers") $(pkg-config --libs "beamslider-$library") &&
            run "mismatch-$headers-$library" 3 "$out/mismatch-$headers-$library" &&
            check_has "mismatch ($headers headers, $library library) is reported as BS_E_BUILD" \
                "$out/mismatch-$headers-$library.txt" "BS_E_BUILD"
    done
else
    skip "pkg-config consumers" "pkg-config and $CC" "pkg-config gcc"
fi

# ---- (b), (c) CMake ------------------------------------------------------------------
# cmake_build DESCRIPTION DIR ARGS...: configure tests/consumer into DIR and build
cmake_build() {
    cmake_what=$1
    cmake_dir=$2
    shift 2
    rm -rf "$cmake_dir"
    build "$cmake_what: configure" cmake -S tests/consumer -B "$cmake_dir" "$@" &&
        build "$cmake_what: build" cmake --build "$cmake_dir"
}

if have cmake && have "$CC"; then
    cmake_build "CMake add_subdirectory(port/cmake), run-time scenes, double" "$build/consumer-cmake" &&
        run cmake-double 0 "$build/consumer-cmake/consumer" &&
        check_has "CMake's core: run-time scenes, double" "$out/cmake-double.txt" "double, run-time scenes" &&
        same_hash "the core built by CMake computes what make's computes" "$out/cmake-double.txt" "$out/c-double.txt"

    scene_include=${scene_lib%.a}.obj/include
    build "C consumer against make's core for fig6_1mode, float ($scene_lib)" \
        "$CC" $C_FLAGS -I"$scene_include" -Icore/include -I. -o "$out/make-scene-float" \
        tests/consumer/consumer.c "$scene_lib" -lm &&
        run make-scene-float 0 "$out/make-scene-float"
    cmake_build "CMake add_subdirectory(port/cmake), BEAMSLIDER_SCENE=fig6_1mode, float" "$build/consumer-cmake-scene" \
        -DBEAMSLIDER_SCENE=fig6_1mode -DBEAMSLIDER_REAL=float &&
        run cmake-scene-float 0 "$build/consumer-cmake-scene/consumer" &&
        check_has "CMake's core: compiled scene fig6_1mode, float" "$out/cmake-scene-float.txt" \
            "float, compiled scene fig6_1mode" &&
        same_hash "CMake's compiled-scene core computes what make's computes" \
            "$out/cmake-scene-float.txt" "$out/make-scene-float.txt"

    rm -rf "$build/consumer-cmake-bad"
    if cmake -S tests/consumer -B "$build/consumer-cmake-bad" -DBEAMSLIDER_REAL=half > "$out/cmake-bad.txt" 2>&1; then
        fail "CMake refuses BEAMSLIDER_REAL=half" "$(cat "$out/cmake-bad.txt")"
    else
        check_has "CMake refuses BEAMSLIDER_REAL=half with a message" "$out/cmake-bad.txt" \
            "BEAMSLIDER_REAL must be float or double, not 'half'"
    fi
    rm -rf "$build/consumer-cmake-bad"

    if have arm-none-eabi-gcc; then
        cmake_build "CMake add_subdirectory(port/cmake) cross-compiled for cortex-m4f, fig6_1mode, float" \
            "$build/consumer-cmake-m4f" -DCMAKE_TOOLCHAIN_FILE="$root/tests/consumer/cortex-m4f.cmake" \
            -DCMAKE_BUILD_TYPE=Release -DBEAMSLIDER_SCENE=fig6_1mode -DBEAMSLIDER_REAL=float &&
            check_has "cross-compiling selects the embedded port" "$build/consumer-cmake-m4f/CMakeCache.txt" \
                "BEAMSLIDER_PORT:STRING=embedded" &&
            check "the Cortex-M4F library built by CMake is freestanding" \
                env NM=arm-none-eabi-nm sh tests/check_core_symbols.sh float "$build/consumer-cmake-m4f/beamslider/libbeamslider.a"
    else
        skip "CMake cross build" arm-none-eabi-gcc "gcc-arm-none-eabi libnewlib-arm-none-eabi"
    fi

    minor=${version%.*}                                             # MAJOR.MINOR
    next=${version%%.*}.$((${minor#*.} + 1))                        # MAJOR.(MINOR+1)
    cmake_build "CMake find_package(beamslider $minor) in $stage" "$build/consumer-package" \
        -DCONSUMER_USE_PACKAGE=ON -DCMAKE_PREFIX_PATH="$stage" -DCONSUMER_PACKAGE_VERSION="$minor" &&
        run package-double 0 "$build/consumer-package/consumer-double" &&
        run package-float 0 "$build/consumer-package/consumer-float" &&
        same_hash "beamslider::double is the installed double library" "$out/package-double.txt" "$out/c-double.txt" &&
        same_hash "beamslider::float is the installed float library" "$out/package-float.txt" "$out/c-float.txt"
    rm -rf "$build/consumer-package-next"
    if cmake -S tests/consumer -B "$build/consumer-package-next" -DCONSUMER_USE_PACKAGE=ON \
        -DCMAKE_PREFIX_PATH="$stage" -DCONSUMER_PACKAGE_VERSION="$next" > "$out/package-next.txt" 2>&1; then
        fail "find_package(beamslider $next) refuses $version" "$(cat "$out/package-next.txt")"
    else
        check_has "find_package(beamslider $next) refuses $version" "$out/package-next.txt" "$version"
    fi
    rm -rf "$build/consumer-package-next"
else
    skip "CMake consumers" "cmake and $CC" "cmake gcc"
fi

# ---- (e) README.md's library program, from the installed tree alone ------------------
# readme_block NAME: the fenced block between <!-- NAME --> and <!-- /NAME --> of README.md
readme_block() {
    awk -v name="$1" '$0 == "<!-- " name " -->" { on = 1; next }
        $0 == "<!-- /" name " -->" { on = 0 }
        on && !/^```/' README.md
}
app=$out/readme-app
rm -rf "$app"
mkdir -p "$app/c" "$app/cxx"
readme_block library-program >"$app/c/app.c"
readme_block library-cmake >"$app/c/CMakeLists.txt"
cp "$app/c/app.c" "$app/cxx/app.cpp"
sed -e 's/^project(app C)$/project(app CXX)/' -e 's/app\.c)/app.cpp)/' "$app/c/CMakeLists.txt" >"$app/cxx/CMakeLists.txt"
scene=$stage/share/beamslider/scenes/fig6.ini
check "README.md holds the library program" grep -q 'bs_host_scene_load' "$app/c/app.c"
check "README.md holds its CMakeLists.txt" grep -q "find_package(beamslider" "$app/c/CMakeLists.txt"
"$stage/bin/beamslider" run "$scene" --t-end 1 >"$out/app-run.json" 2>"$out/app-run.err"
want=$(sed -n 's/.*"hash":"\([0-9a-f]*\)".*/\1/p' "$out/app-run.json")
check "the installed beamslider runs the installed fig6.ini" test -n "$want"
# same_run NAME PROGRAM: runs PROGRAM on the installed scene; it prints s ten
# times and the hash of beamslider run's state
same_run() {
    run "$1" 0 "$2" "$scene" &&
        check "$1 prints s every 0.1 s" test "$(grep -c '^t = ' "$out/$1.txt")" -eq 10 &&
        if [ "$(hash_of "$out/$1.txt")" = "$want" ]; then pass "$1 reaches beamslider run's state (hash $want)"
        else fail "$1 reaches beamslider run's state" "$(cat "$out/$1.txt"), beamslider run: $want"; fi
}
if have pkg-config && have "$CC"; then
    build "README program in C against beamslider-host-double (pkg-config, installed tree only)" \
        sh -c "cd '$app/c' && $CC $C_FLAGS -o app app.c \$(pkg-config --cflags --libs beamslider-host-double)" &&
        same_run readme-c "$app/c/app"
    build "README program in C against beamslider-host-float (pkg-config)" \
        sh -c "cd '$app/c' && $CC $C_FLAGS -o app-float app.c \$(pkg-config --cflags --libs beamslider-host-float)" &&
        run readme-c-float 0 "$app/c/app-float" "$scene" &&
        check "the float program prints s every 0.1 s" test "$(grep -c '^t = ' "$out/readme-c-float.txt")" -eq 10
    if have "$CXX"; then
        build "README program in C++ against beamslider-host-double (pkg-config)" \
            sh -c "cd '$app/cxx' && $CXX $CXX_FLAGS -o app app.cpp \$(pkg-config --cflags --libs beamslider-host-double)" &&
            same_run readme-cxx "$app/cxx/app"
    fi
    build "README program linked statically (libbeamslider-host-double.a, libbeamslider-double.a)" \
        sh -c "cd '$app/c' && $CC $C_FLAGS -o app-static app.c -I'$stage/include/beamslider-double' \
            '$stage/lib/libbeamslider-host-double.a' '$stage/lib/libbeamslider-double.a' -linih -lcjson -lm -pthread" &&
        same_run readme-static "$app/c/app-static"
else
    skip "README program with pkg-config" "pkg-config and $CC" "pkg-config gcc"
fi
if have cmake; then
    for language in c cxx; do
        rm -rf "$app/$language/build"
        build "README program in $language with find_package (its CMakeLists.txt): configure" \
            cmake -S "$app/$language" -B "$app/$language/build" -DCMAKE_PREFIX_PATH="$stage" &&
            build "README program in $language with find_package: build" cmake --build "$app/$language/build" &&
            same_run "readme-cmake-$language" "$app/$language/build/app"
    done
else
    skip "README program with CMake" cmake cmake
fi

# ---- (f) the find_package versions the documents ask for ------------------------------
for doc in README.md port/cmake/README.md port/cmake/beamsliderConfig.cmake; do
    asked=$(grep -o 'find_package(beamslider [0-9][0-9.]*' "$doc" | sed 's/.* //' | sort -u | tr '\n' ' ')
    if [ -n "$asked" ] && [ "$asked" = "${version%.*} " ]; then
        pass "$doc asks find_package for ${version%.*}, this version's"
    else
        fail "$doc asks find_package for this version's MAJOR.MINOR ${version%.*}" "it asks for: ${asked:-nothing}"
    fi
done

# ---- the cross-compiled library of make lib ------------------------------------------
if [ -n "$cm_lib" ]; then
    check "make lib for cortex-m4f ($cm_lib) is freestanding" \
        env NM=arm-none-eabi-nm sh tests/check_core_symbols.sh float "$cm_lib"
fi

echo "check_consumer: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
