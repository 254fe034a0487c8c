# zephyr_standin.cmake - a minimal stand-in for the CMake functions a Zephyr
# build gives a module (find_package(Zephyr) loads the real ones), enough to
# run port/zephyr's module CMakeLists.txt without Zephyr
# (tests/check_embedded_build_systems.sh). Written from Zephyr's documented
# behaviour, not its code:
#
#   zephyr_interface         the flags every Zephyr source gets (here: the
#                            CPU's from the toolchain file, Zephyr's default
#                            -Os, C99, -ffreestanding); zephyr_include_directories
#                            and zephyr_compile_* add to it
#   zephyr_library_named(N)  a static library linked with zephyr_interface,
#                            made current; zephyr_library() names it after its
#                            folder; every library goes into the image
#                            (ZEPHYR_LIBS, read by standin_link_libraries)
#   zephyr_library_*         sources, private include folders, definitions,
#                            options (placed after zephyr_interface's, as in
#                            Zephyr, so that they win), options the compiler
#                            takes (_cc_option), link libraries
#
# Any other zephyr_* call stops with CMake's "Unknown CMake command": the
# module uses nothing beyond this list.
include_guard(GLOBAL)
include(CheckCCompilerFlag)

add_library(zephyr_interface INTERFACE)
target_compile_options(zephyr_interface INTERFACE -Os -std=c99 -ffreestanding)
set_property(GLOBAL PROPERTY ZEPHYR_LIBS "")

function(zephyr_include_directories)
    target_include_directories(zephyr_interface INTERFACE ${ARGN})
endfunction()
function(zephyr_compile_definitions)
    target_compile_definitions(zephyr_interface INTERFACE ${ARGN})
endfunction()
function(zephyr_compile_options)
    target_compile_options(zephyr_interface INTERFACE ${ARGN})
endfunction()

macro(zephyr_library_named name)
    set(ZEPHYR_CURRENT_LIBRARY ${name})
    add_library(${name} STATIC)
    target_link_libraries(${name} PUBLIC zephyr_interface)
    set_property(GLOBAL APPEND PROPERTY ZEPHYR_LIBS ${name})
endmacro()
macro(zephyr_library)
    file(RELATIVE_PATH _standin_name "${CMAKE_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
    string(REGEX REPLACE "[/:.]" "_" _standin_name "${_standin_name}")
    zephyr_library_named(${_standin_name})
endmacro()

function(zephyr_library_sources)
    target_sources(${ZEPHYR_CURRENT_LIBRARY} PRIVATE ${ARGN})
endfunction()
function(zephyr_library_include_directories)
    target_include_directories(${ZEPHYR_CURRENT_LIBRARY} PRIVATE ${ARGN})
endfunction()
function(zephyr_library_compile_definitions)
    target_compile_definitions(${ZEPHYR_CURRENT_LIBRARY} PRIVATE ${ARGN})
endfunction()
function(zephyr_library_link_libraries)
    target_link_libraries(${ZEPHYR_CURRENT_LIBRARY} PUBLIC ${ARGN})
endfunction()
# A library's own options must come after zephyr_interface's on the command
# line: CMake puts a target's own options first and those of the libraries it
# links after, so they go through one more interface library, linked last.
function(zephyr_library_compile_options)
    string(MD5 _standin_hash "${ZEPHYR_CURRENT_LIBRARY};${ARGN}")
    set(_standin_lib standin_options_${_standin_hash})
    if(NOT TARGET ${_standin_lib})
        add_library(${_standin_lib} INTERFACE)
        target_compile_options(${_standin_lib} INTERFACE ${ARGN})
    endif()
    target_link_libraries(${ZEPHYR_CURRENT_LIBRARY} PRIVATE ${_standin_lib})
endfunction()
function(zephyr_library_cc_option)
    foreach(_standin_option ${ARGN})
        string(MAKE_C_IDENTIFIER "STANDIN_CC_HAS${_standin_option}" _standin_var)
        check_c_compiler_flag("${_standin_option}" ${_standin_var})
        if(${_standin_var})
            zephyr_library_compile_options(${_standin_option})
        endif()
    endforeach()
endfunction()

# The image links every Zephyr library (not a Zephyr function: the stand-in's).
function(standin_link_libraries target)
    get_property(_standin_libs GLOBAL PROPERTY ZEPHYR_LIBS)
    target_link_libraries(${target} PRIVATE zephyr_interface ${_standin_libs})
endfunction()
