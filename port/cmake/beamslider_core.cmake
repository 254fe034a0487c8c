# beamslider_core.cmake - what every CMake build of the beamslider core shares:
# the checks of its options, the generated build configuration, its sources,
# include folders and compiler flags. Included by port/cmake/CMakeLists.txt
# (the core as a plain static library) and by the Zephyr module's
# port/zephyr/zephyr/CMakeLists.txt (a Zephyr library); they differ only in
# how they make the library and which port (bs_port.h) they give it.
#
#   include(<beamslider>/port/cmake/beamslider_core.cmake)
#   beamslider_core_configure(
#       REAL <float|double>          the type of bs_real
#       SCENE <text>                 empty: scenes given at run time; NAME: the
#                                    repository's configs/NAME.h; a path ending
#                                    in .h: a header written by `beamslider gen`
#                                    (absolute, or relative to SCENE_BASE)
#       SCENE_BASE <dir>             where a relative scene path starts
#       WITH_SUBSPACE <ON|OFF>       the contact solve's subspace step
#       CONFIG_DIR <dir>             where bs_build_config.h is written
#       REAL_OPTION <name>           the user's names of REAL and SCENE, for
#       SCENE_OPTION <name>          the error messages
#   )
#
# A bad value stops the configuration with a message naming the option and
# what it allows. Sets in the caller's scope:
#   BEAMSLIDER_ROOT              the repository (absolute)
#   BEAMSLIDER_CORE_SOURCES      core/src/*.c
#   BEAMSLIDER_CORE_PUBLIC_DIRS  what a program that includes beamslider.h needs:
#                                CONFIG_DIR, core/include and, for a NAME scene,
#                                the repository root (the configuration names
#                                "configs/NAME.h")
#   BEAMSLIDER_CORE_PRIVATE_DIRS core/src (the port's folder is the caller's)
#   BEAMSLIDER_CORE_C_FLAGS      flags the core's sources want where the compiler
#                                takes them: the Makefile's rounding (no fused
#                                multiply-add), sqrt as one instruction, no
#                                memset/memcpy calls made up from loops (GCC)
#   BEAMSLIDER_CORE_SUMMARY      one line for message(STATUS)
#
# bs_build_config.h comes from core/include/bs_build_config.h.in, the template
# port/build_config.sh fills for the Makefile: same text, same build tag.

get_filename_component(BEAMSLIDER_ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)

function(beamslider_core_configure)
    cmake_parse_arguments(ARG "" "REAL;SCENE;SCENE_BASE;WITH_SUBSPACE;CONFIG_DIR;REAL_OPTION;SCENE_OPTION" "" ${ARGN})
    set(root "${BEAMSLIDER_ROOT}")

    if(NOT "${ARG_REAL}" MATCHES "^(float|double)$")
        message(FATAL_ERROR "beamslider: ${ARG_REAL_OPTION} must be float or double, not '${ARG_REAL}'")
    endif()

    # The scene: none, a name in configs/, or a header's path.
    set(public_dirs "${ARG_CONFIG_DIR}" "${root}/core/include")
    set(scene_define "")
    if("${ARG_SCENE}" STREQUAL "")  # (an empty argument leaves ARG_SCENE undefined)
        set(summary "run-time scenes")
    elseif("${ARG_SCENE}" MATCHES "\\.h$")
        if(IS_ABSOLUTE "${ARG_SCENE}")
            set(header "${ARG_SCENE}")
        else()
            get_filename_component(header "${ARG_SCENE}" ABSOLUTE BASE_DIR "${ARG_SCENE_BASE}")
        endif()
        if(NOT EXISTS "${header}" OR IS_DIRECTORY "${header}")
            message(FATAL_ERROR "beamslider: ${ARG_SCENE_OPTION} '${ARG_SCENE}': no such header ${header} "
                    "(write it with `beamslider gen SCENE.ini > NAME.h`; a relative path starts at ${ARG_SCENE_BASE})")
        endif()
        if(header MATCHES "[\"\\\\]")
            message(FATAL_ERROR "beamslider: ${ARG_SCENE_OPTION} '${ARG_SCENE}': the path ${header} holds a quote "
                    "or a backslash, which an #include cannot name; move the header")
        endif()
        set(scene_define "#define BS_SCENE_CONFIG \"${header}\"")
        set(summary "compiled scene ${header}")
    elseif("${ARG_SCENE}" MATCHES "^[A-Za-z0-9_]+$" AND EXISTS "${root}/configs/${ARG_SCENE}.h")
        set(scene_define "#define BS_SCENE_CONFIG \"configs/${ARG_SCENE}.h\"")
        list(APPEND public_dirs "${root}")
        set(summary "compiled scene ${ARG_SCENE}")
    else()
        file(GLOB scenes RELATIVE "${root}/configs" "${root}/configs/*.h")
        string(REPLACE ".h" "" scenes "${scenes}")
        string(REPLACE ";" ", " scenes "${scenes}")
        message(FATAL_ERROR "beamslider: ${ARG_SCENE_OPTION} '${ARG_SCENE}' names no scene header "
                "${root}/configs/${ARG_SCENE}.h; one of: ${scenes} "
                "(`beamslider gen SCENE.ini > configs/NAME.h` writes one), the path of a header "
                "ending in .h, or empty for run-time scenes")
    endif()

    # The generated build configuration.
    if("${ARG_REAL}" STREQUAL "float")
        set(BS_REAL_FLOAT 1)
    else()
        set(BS_REAL_FLOAT 0)
    endif()
    set(lines "${scene_define}")
    if(NOT ARG_WITH_SUBSPACE)
        if(NOT lines STREQUAL "")
            string(APPEND lines "\n")
        endif()
        string(APPEND lines "#define BS_WITH_SUBSPACE 0")
    endif()
    if(lines STREQUAL "")
        set(lines "/* none */")
    endif()
    set(BS_CONFIG_LINES "${lines}")
    configure_file("${root}/core/include/bs_build_config.h.in" "${ARG_CONFIG_DIR}/bs_build_config.h" @ONLY)

    if(CMAKE_SCRIPT_MODE_FILE)  # cmake -P (a test of these checks): no build to re-glob for
        file(GLOB sources "${root}/core/src/*.c")
    else()
        file(GLOB sources CONFIGURE_DEPENDS "${root}/core/src/*.c")
    endif()
    set(BEAMSLIDER_CORE_SOURCES "${sources}" PARENT_SCOPE)
    set(BEAMSLIDER_CORE_PUBLIC_DIRS "${public_dirs}" PARENT_SCOPE)
    set(BEAMSLIDER_CORE_PRIVATE_DIRS "${root}/core/src" PARENT_SCOPE)
    set(BEAMSLIDER_CORE_C_FLAGS -ffp-contract=off -fno-math-errno -fno-tree-loop-distribute-patterns PARENT_SCOPE)
    if(ARG_WITH_SUBSPACE)
        set(subspace ON)
    else()
        set(subspace OFF)
    endif()
    set(BEAMSLIDER_CORE_SUMMARY "bs_real ${ARG_REAL}, ${summary}, subspace step ${subspace}" PARENT_SCOPE)
endfunction()
