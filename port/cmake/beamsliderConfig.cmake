# beamsliderConfig.cmake - find_package(beamslider) for an installation made
# by `make install` (installed as PREFIX/lib/cmake/beamslider/; this file is
# port/cmake/beamsliderConfig.cmake).
#
#   find_package(beamslider 0.8 REQUIRED)              # or COMPONENTS double float host-double host-float
#   target_link_libraries(app PRIVATE beamslider::host-double)
#
# Imported targets, two per precision (bs_real): beamslider::double and
# beamslider::float, the core with run-time scenes (static libraries, with
# the math library); beamslider::host-double and beamslider::host-float,
# libbeamslider-host (beamslider_host.h: scenes from INI files at run time,
# runs, sweeps, maps, the twin), a shared library that holds the core too.
# Each brings its own include folder (PREFIX/include/beamslider-P:
# beamslider.h, beamslider_host.h and the bs_build_config.h it was built
# with). A program links one of them; compiled against the other's headers
# it gets BS_E_BUILD. The version check (beamsliderConfigVersion.cmake)
# takes any request of this MAJOR.MINOR up to this patch.
#
# The installation is found relative to this file, so it can be moved as a
# whole. For the core built inside your project (an MCU, a compiled scene)
# use add_subdirectory(<beamslider>/port/cmake) instead (port/cmake/README.md).

get_filename_component(_beamslider_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)

set(_beamslider_reals double float)
set(_beamslider_components double float host-double host-float)
foreach(_beamslider_component IN LISTS beamslider_FIND_COMPONENTS)
    if(NOT _beamslider_component IN_LIST _beamslider_components)
        set(beamslider_FOUND FALSE)
        set(beamslider_NOT_FOUND_MESSAGE
            "beamslider: unknown component '${_beamslider_component}' (the components are double, float, host-double and host-float)")
        return()
    endif()
endforeach()

foreach(_beamslider_real IN LISTS _beamslider_reals)
    set(_beamslider_lib "${_beamslider_prefix}/lib/libbeamslider-${_beamslider_real}.a")
    set(_beamslider_include "${_beamslider_prefix}/include/beamslider-${_beamslider_real}")
    if(NOT EXISTS "${_beamslider_lib}" OR NOT EXISTS "${_beamslider_include}/bs_build_config.h")
        set(beamslider_FOUND FALSE)
        set(beamslider_NOT_FOUND_MESSAGE
            "beamslider: ${_beamslider_lib} or ${_beamslider_include}/bs_build_config.h is missing (reinstall with make install)")
        return()
    endif()
    if(NOT TARGET beamslider::${_beamslider_real})
        add_library(beamslider::${_beamslider_real} STATIC IMPORTED)
        set_target_properties(beamslider::${_beamslider_real} PROPERTIES
            IMPORTED_LOCATION "${_beamslider_lib}"
            IMPORTED_LINK_INTERFACE_LANGUAGES C
            INTERFACE_INCLUDE_DIRECTORIES "${_beamslider_include}"
            INTERFACE_LINK_LIBRARIES m)
    endif()
    set(beamslider_${_beamslider_real}_FOUND TRUE)

    set(_beamslider_host "${_beamslider_prefix}/lib/libbeamslider-host-${_beamslider_real}.so")
    if(NOT EXISTS "${_beamslider_host}" OR NOT EXISTS "${_beamslider_include}/beamslider_host.h")
        set(beamslider_FOUND FALSE)
        set(beamslider_NOT_FOUND_MESSAGE
            "beamslider: ${_beamslider_host} or ${_beamslider_include}/beamslider_host.h is missing (reinstall with make install)")
        return()
    endif()
    if(NOT TARGET beamslider::host-${_beamslider_real})
        get_filename_component(_beamslider_host_real "${_beamslider_host}" REALPATH)
        add_library(beamslider::host-${_beamslider_real} SHARED IMPORTED)
        set_target_properties(beamslider::host-${_beamslider_real} PROPERTIES
            IMPORTED_LOCATION "${_beamslider_host_real}"
            INTERFACE_INCLUDE_DIRECTORIES "${_beamslider_include}")
    endif()
    set(beamslider_host-${_beamslider_real}_FOUND TRUE)
endforeach()

unset(_beamslider_host)
unset(_beamslider_host_real)
unset(_beamslider_components)
unset(_beamslider_lib)
unset(_beamslider_include)
unset(_beamslider_real)
unset(_beamslider_reals)
unset(_beamslider_component)
unset(_beamslider_prefix)
