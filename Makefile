# beamslider - plain GNU make.
#
#   make              build build/beamslider (REAL precision)
#   make run          build and run the fig6 scene (60 s), print its summary
#   make test         build and run the tests, float and double (budget: 150 CPU-s, build done)
#   make test-long    the slow checks: valgrind, minute-long fuzzing, whole runs under QEMU,
#                     a sharded map on a private single-node Slurm (as root; tests/slurm/), the
#                     observer's measured s on its own 60 s plant (twin-bias-long)
#   make lib          the libraries in both precisions: build/lib/libbeamslider-double.a
#                     and -float.a (the core), libbeamslider-host-double.a, -float.a and
#                     .so (libbeamslider-host: host/include/beamslider_host.h) (with
#                     TARGET=cortex-m4f SCENE=fig6 REAL=float: the core for that target
#                     and compiled scene, build/lib/cortex-m4f/; port/lib.mk)
#   make install [PREFIX=/usr/local] [DESTDIR=]   the libraries in both precisions,
#                     their headers, pkg-config files (beamslider-host-double, -float,
#                     beamslider-double, -float), the CMake package beamslider, the
#                     beamslider program, the scenes and the licence (make uninstall)
#   make octave       the Octave/MATLAB gateway in build/octave/ (host/octave, docs/octave.md;
#                     tests/octave.mk: make test-octave, part of make test)
#   make fields       docs/fields.md: every scene field (also `beamslider fields`)
#   make configs      regenerate the compile-time scene headers configs/*.h
#   make test-sweeps  the contact solve's tests built with BS_WITH_SUBSPACE=0
#   make python       the Python package in build/python/lib (docs/python.md; tests/python.mk)
#   make bench, fig6-report, accuracy, stability, figures, embedded-report, maps
#                     the reports of docs/ (README.md, "Reports")
#   make docs-check   whether the reports' pages still describe the code (tests/docs.mk)
#   make clean
#   make TARGET=cortex-m4f [SCENE=fig6] [REAL=float] [run]
#                     cross build (and QEMU run) of one compiled scene

# Every rule is written out here: GNU make's built-in rules only cost it the
# search for files like RCS/x.c,v for each name it considers (a third of
# the CPU time of a make with nothing to do, every sub-make of make test).
MAKEFLAGS += --no-builtin-rules
.SUFFIXES:

# Knobs (make VAR=value):
REAL ?= double        # float | double: the core's bs_real
CC ?= cc
BUILD ?= build
TARGET ?= host        # host, or a Cortex-M target: cortex-m4f cortex-m7 cortex-m3 cortex-m0plus
SCENE ?= fig6         # the compiled scene of a Cortex-M build (configs/SCENE.h)
STEPS ?= 20000        # steps the Cortex-M build runs
CONFIG ?=             # more switches of the core's build configuration: NAME=VALUE ...
PREFIX ?= /usr/local  # where `make install` puts the library
JOBS ?= $(shell nproc 2>/dev/null || echo 2)  # parallel builds of `make run` and `make test`

ifeq ($(filter $(strip $(REAL)),float double),)
$(error REAL must be float or double, not '$(REAL)')
endif
REAL := $(strip $(REAL))
TARGET := $(strip $(TARGET))
SCENE := $(strip $(SCENE))
STEPS := $(strip $(STEPS))
CONFIG := $(strip $(CONFIG))
PREFIX := $(strip $(PREFIX))
JOBS := $(strip $(JOBS))
OBJ := $(BUILD)/$(REAL)
VERSION := $(shell sed -n 's/^\#define BS_VERSION_STRING "\(.*\)"/\1/p' core/include/beamslider.h)

# The generated build configuration of this build (core/include/bs_build_config.h.in):
# the precision and CONFIG's switches. Everything that includes beamslider.h finds it first.
CONFIG_H := $(OBJ)/include/bs_build_config.h
# -std=c99 keeps fused multiply-add off (-ffp-contract=off made explicit);
# -fno-math-errno lets sqrt be one instruction and changes no result.
WARNINGS := -Wall -Wextra -Werror -Wdouble-promotion -Wfloat-conversion -Wundef -Wshadow \
            -Wstrict-prototypes -Wvla
CFLAGS ?= -O2 -g
# The core's objects at -O3 after CFLAGS: its loops over modes, corners and
# contact rows have short constant lengths (bs_inline.h: BS_MODES_SWITCH),
# which -O3 unrolls; fig6 runs in a quarter fewer instructions per step than
# at -O2 (docs/performance.md). CORE_OPT= keeps CFLAGS's level (a debug build).
CORE_OPT ?= -O3
# The CLI and the shared library link a second build of the core's objects,
# compiled with -flto (LTO/), as one unit: the step's stages, separate files,
# inlined across them (fig6 in double 0.85-0.95 of the CPU time of the plain
# link, the same results: docs/design.md 4). The tests and the static
# library keep the plain objects (GCC would optimise every link of objects
# carrying its intermediate code again, about 8 CPU s each). CORE_LTO= goes
# without; a compiler without -flto does.
ifeq ($(origin CORE_LTO),undefined)
CORE_LTO := $(shell $(CC) -flto -Werror -c -x c /dev/null -o /dev/null >/dev/null 2>&1 && echo -flto)
endif
# the link that uses them: in parallel where the compiler can
LINK_LTO := $(if $(CORE_LTO),$(shell $(CC) -flto=auto -Werror -x c /dev/null -fsyntax-only \
              >/dev/null 2>&1 && echo -flto=auto || echo -flto))
# The core's -flto objects are optimised once, into $(OBJ)/LTO/core.o, by a
# partial link that writes plain code (GCC's -flinker-output=nolto-rel): the
# CLI's link of it is a plain one. A commit changes the revision object the
# CLI links, and with the -flto objects in its link every commit optimised
# the core again, about 13 CPU-s a precision of `make test`; the partial link
# of a fresh build costs about 7 more (docs/testing.md). The same results
# (fig6's hash) and speed within the noise of paired runs (farm-bench, fig6 in
# double: the full -flto link took 0.98 and 1.01 of its CPU time in two series).
LTO_UNIT := $(if $(CORE_LTO),$(shell $(CC) -flinker-output=nolto-rel -E -x c /dev/null >/dev/null 2>&1 && echo yes))
# what a link of CORE_LINK_OBJ adds: nothing for the partial link's plain object
CORE_LINK_FLAGS := $(if $(LTO_UNIT),,$(LINK_LTO))
BASE_CFLAGS := -std=c99 -ffp-contract=off -fno-math-errno $(WARNINGS)
# Core: no libc calls; keep GCC from turning loops into memset/memcpy calls
# (a GCC flag: other compilers go without; check_core_symbols.sh still checks).
NO_LOOP_CALLS := $(shell $(CC) -fno-tree-loop-distribute-patterns -Werror -E -x c /dev/null >/dev/null 2>&1 \
                   && echo -fno-tree-loop-distribute-patterns)
CORE_INC := -I$(OBJ)/include -Icore/include
# Host objects are position-independent: the same objects make the CLI, the
# tests and the installed libraries (a shared one among them; port/lib.mk).
# -fno-semantic-interposition keeps calls within a file direct and
# inlinable, as in a program (the library's symbols are not interposed).
HOST_PIC := -fPIC -fno-semantic-interposition
CORE_CFLAGS := $(BASE_CFLAGS) $(HOST_PIC) $(NO_LOOP_CALLS) $(CORE_INC) -Icore/src -Iport/host
# The host library's wings (host/lib/README.md), each on the include path:
# a file includes another wing's header by its name.
HOST_WINGS := io scene run map twin api
HOST_INC := -Ihost/include $(HOST_WINGS:%=-Ihost/lib/%)
HOST_CFLAGS := $(BASE_CFLAGS) $(HOST_PIC) $(CORE_INC) -Iport -Iport/host $(HOST_INC) -Ihost/cli
# Tests also reach the core's internal headers (core/src) to test its parts.
# They are programs, not library code: no HOST_PIC (with it, GCC 12 takes
# opendir's own alias for another allocator: -Wmismatched-dealloc).
TEST_CFLAGS := $(filter-out $(HOST_PIC),$(HOST_CFLAGS)) -Icore/src -Itests

CORE_SRC := $(wildcard core/src/*.c)
HOST_CLI_SRC := $(wildcard host/cli/*.c)
HOST_LIB_SRC := $(foreach w,$(HOST_WINGS),$(wildcard host/lib/$w/*.c)) port/host/bs_platform_host.c
HOST_HEADERS := $(wildcard host/include/*.h host/lib/*/*.h host/cli/*.h)
CORE_OBJ := $(CORE_SRC:%.c=$(OBJ)/%.o)
# what the CLI and the shared library link: the -flto build of the core
# optimised as one unit into one plain object (a partial link, where the
# compiler can: LTO_UNIT), or its objects, or the plain build
CORE_LTO_OBJ := $(CORE_SRC:%.c=$(OBJ)/LTO/%.o)
CORE_LINK_OBJ := $(if $(CORE_LTO),$(if $(LTO_UNIT),$(OBJ)/LTO/core.o,$(CORE_LTO_OBJ)),$(CORE_OBJ))
HOST_CLI_OBJ := $(HOST_CLI_SRC:%.c=$(OBJ)/%.o)
HOST_LIB_OBJ := $(HOST_LIB_SRC:%.c=$(OBJ)/%.o)
HOST_LIBS := -linih -lcjson -lm -pthread

TESTS := $(basename $(notdir $(wildcard tests/test_*.c)))
# ... and the C++ one (tests/test_cxx.cpp, below)
TEST_BIN := $(TESTS:%=$(OBJ)/tests/%) $(OBJ)/tests/test_cxx
TEST_LIBS := -lcmocka $(HOST_LIBS)

BUILD_PACKAGES := gcc make libc6-dev libinih-dev libcjson-dev
TEST_PACKAGES := $(BUILD_PACKAGES) libcmocka-dev binutils g++ cmake pkg-config

.PHONY: all run test test-long test-one test-one-build embedded-long test-sweeps scenarios-long lib install uninstall configs fields accuracy-check clean deps-build deps-test .force
.SECONDARY:
.DEFAULT_GOAL := all

ifeq ($(TARGET),host)
# build/beamslider is the binary of the REAL of the last `make`.
all: $(OBJ)/beamslider
	@cmp -s $< $(BUILD)/beamslider || cp $< $(BUILD)/beamslider
endif

$(OBJ)/beamslider: $(HOST_CLI_OBJ) $(HOST_LIB_OBJ) $(CORE_LINK_OBJ)
	$(CC) $(CFLAGS) $(CORE_LINK_FLAGS) -o $@ $^ $(HOST_LIBS)

$(OBJ)/LTO/core.o: $(CORE_LTO_OBJ)
	$(CC) $(CFLAGS) $(LINK_LTO) -r -flinker-output=nolto-rel -o $@ $^

# The source revision the host tool reports (JSON summaries, --version).
REVISION := $(shell git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)
$(OBJ)/include/bs_revision.h: .force
	@mkdir -p $(dir $@)
	@printf '/* generated by make: the source revision of this build */\n#define BS_REVISION "%s"\n' '$(REVISION)' > $@.tmp.$$$$; \
	    if cmp -s $@.tmp.$$$$ $@; then rm -f $@.tmp.$$$$; else mv $@.tmp.$$$$ $@; fi
$(OBJ)/host/lib/scene/source_revision.o: $(OBJ)/include/bs_revision.h

# What the objects of $(OBJ) were compiled with: a change of compiler or
# flags (HOST_PIC, CFLAGS) rebuilds them, not only a change of sources.
BUILD_FLAGS := $(OBJ)/build.flags
$(BUILD_FLAGS): .force
	@mkdir -p $(@D)
	@printf '%s\n' '$(CC) $(CFLAGS) $(CORE_OPT) $(CORE_LTO) $(CORE_CFLAGS) $(HOST_CFLAGS)' | cmp -s - $@ \
	    || printf '%s\n' '$(CC) $(CFLAGS) $(CORE_OPT) $(CORE_LTO) $(CORE_CFLAGS) $(HOST_CFLAGS)' > $@

# (both precisions: the reference and the reports use the double one from any REAL)
$(BUILD)/double/include/bs_build_config.h $(BUILD)/float/include/bs_build_config.h: .force
	@sh port/build_config.sh $@ $(word 2,$(subst /, ,$(patsubst $(BUILD)/%,x/%,$@))) $(CONFIG)

$(OBJ)/core/%.o: core/%.c $(wildcard core/*/*.h) port/host/bs_port.h $(CONFIG_H) $(BUILD_FLAGS) | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(CORE_OPT) $(CORE_CFLAGS) -c -o $@ $<

$(OBJ)/LTO/core/%.o: core/%.c $(wildcard core/*/*.h) port/host/bs_port.h $(CONFIG_H) $(BUILD_FLAGS) | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(CORE_OPT) $(CORE_LTO) $(CORE_CFLAGS) -c -o $@ $<

$(OBJ)/host/%.o: host/%.c $(HOST_HEADERS) $(wildcard core/include/*.h) $(CONFIG_H) $(BUILD_FLAGS) | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -c -o $@ $<

$(OBJ)/port/host/%.o: port/host/%.c port/bs_platform.h $(CONFIG_H) $(BUILD_FLAGS) | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -c -o $@ $<

$(OBJ)/tests/%.o: tests/%.c $(wildcard tests/*.h core/*/*.h) $(HOST_HEADERS) $(CONFIG_H) $(BUILD_FLAGS) | deps-test
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(TEST_CFLAGS) -c -o $@ $<

# The test programs take the revision order-only: a commit changes it, and
# relinking every test program for a string they publish nowhere cost about
# 5 CPU-s a precision (test-one-build after an empty commit: 17.1 -> 12.4,
# the rest the CLI's -flto link; docs/testing.md); they state the revision
# of their last link.
REVISION_OBJ := $(OBJ)/host/lib/scene/source_revision.o
$(OBJ)/tests/test_%: $(OBJ)/tests/test_%.o $(OBJ)/tests/support.o $(filter-out $(REVISION_OBJ),$(HOST_LIB_OBJ)) \
        $(CORE_OBJ) | $(REVISION_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(REVISION_OBJ) $(TEST_LIBS)

# Fragments append test targets to TEST_EXTRA (part of `make test`, whose budget
# is 150 CPU-seconds with the build done: README.md) or TEST_LONG (`make
# test-long`: the slow checks, CI runs them too).
TEST_EXTRA := accuracy-check
TEST_LONG := test-sweeps

include tests/embedded/embedded.mk
include port/lib.mk

# C++: tests/test_cxx.cpp, the public headers and a scene header as C++11, linked
# with the core compiled for that scene in this REAL (host port, CFLAGS). CXXFLAGS
# follows CFLAGS (the sanitizer build sets CFLAGS only).
CXX ?= g++
CXXFLAGS ?= $(CFLAGS)
CXX_WARNINGS := -std=c++11 -Wall -Wextra -Werror -pedantic -Wundef -Wshadow
CXX_SCENE := fig6_1mode
CXX_CORE := $(BUILD)/lib/host/libbeamslider-$(REAL)-$(CXX_SCENE).a
$(call lib_archive,$(CXX_CORE),$(CC),$(CFLAGS) $(BASE_CFLAGS) $(NO_LOOP_CALLS) -Iport/host -I.,$(AR),$(REAL),\
    'BS_SCENE_CONFIG="configs/$(CXX_SCENE).h"')
$(OBJ)/tests/test_cxx: tests/test_cxx.cpp $(CXX_CORE) $(wildcard core/include/*.h) | deps-test
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(CXX_WARNINGS) -I$(CXX_CORE:.a=.obj)/include -Icore/include -I. -o $@ $< $(CXX_CORE) -lm

ifeq ($(TARGET),host)
run:
	@$(MAKE) --no-print-directory -j$(JOBS) all
	$(BUILD)/beamslider run configs/fig6.ini --out $(BUILD)/fig6.csv --every 20
endif

# Every test in this REAL, then the core symbol check. The CLI's checks of
# outputs, inputs and maps test the host (which computes in double whatever
# the core's precision): `make test` runs them on the double program, `make
# test-long` on the float one too (cli-float-long).
test-one: test-one-build step-diff-test
	@set -e; for t in $(TEST_BIN); do echo "== $$t"; ./$$t; done
	@sh tests/check_core_symbols.sh $(REAL) $(CORE_OBJ)
	@sh tests/check_core_includes.sh
	@sh tests/check_cli.sh $(OBJ)/beamslider
	@sh tests/check_configs.sh $(OBJ)/beamslider
	$(if $(filter double,$(REAL)),@$(MAKE) --no-print-directory cli-checks)

# What test-one runs (make test-long builds it in both precisions first).
test-one-build: $(TEST_BIN) $(OBJ)/beamslider $(TWIN_PACK)

cli-checks: $(OBJ)/beamslider $(TWIN_PACK)
	@sh tests/check_outputs.sh $(OBJ)/beamslider
	@sh tests/check_inputs.sh $(OBJ)/beamslider $(TWIN_PACK)
	@sh tests/check_map.sh $(OBJ)/beamslider

cli-float-long:
	@$(MAKE) --no-print-directory -j$(JOBS) REAL=float cli-checks
.PHONY: cli-checks cli-float-long
TEST_LONG += cli-float-long

# The contact solve built without its subspace step (BS_WITH_SUBSPACE=0, the
# real-time option of docs/porting.md): its unit tests in both precisions
# (`make test-long`).
SWEEPS_BUILD := $(BUILD)/sweeps
SWEEPS_FLAGS := CONFIG=BS_WITH_SUBSPACE=0 BUILD=$(SWEEPS_BUILD)
test-sweeps:
	@set -e; for real in double float; do \
	    $(MAKE) --no-print-directory -s -j$(JOBS) REAL=$$real $(SWEEPS_FLAGS) $(SWEEPS_BUILD)/$$real/tests/test_pgs; \
	    echo "== $(SWEEPS_BUILD)/$$real/tests/test_pgs (BS_WITH_SUBSPACE=0)"; $(SWEEPS_BUILD)/$$real/tests/test_pgs; done

# The outcome classes of the papers' six scenarios, both precisions (`make
# test-long`; make test classifies fig6 alone, in tests/check_map.sh).
scenarios-long:
	@set -e; for real in double float; do \
	    $(MAKE) --no-print-directory -s -j$(JOBS) REAL=$$real $(BUILD)/$$real/beamslider; \
	    sh tests/check_scenarios.sh $(BUILD)/$$real/beamslider; done
TEST_LONG += scenarios-long

# The observer's measured s on its own nominal plant: 60 s of fig6 in each
# precision (tests/check_twin_bias.sh, ~10 CPU-s each).
twin-bias-long:
	@$(MAKE) --no-print-directory -j$(JOBS) REAL=double $(BUILD)/double/beamslider
	@$(MAKE) --no-print-directory -j$(JOBS) REAL=float $(BUILD)/float/beamslider
	@set -e; for real in double float; do sh tests/check_twin_bias.sh $(BUILD)/$$real/beamslider; done
.PHONY: twin-bias-long
TEST_LONG += twin-bias-long

# The CMocka cases too slow for make test's CPU budget (support_long_only:
# skipped there), in both precisions: the test binaries that hold one, again
# with BS_TEST_LONG set (`make test-long`).
LONG_CASES := test_observer
tests-long-cases:
	@set -e; for real in double float; do for t in $(LONG_CASES); do \
	    echo "== $(BUILD)/$$real/tests/$$t (BS_TEST_LONG=1)"; BS_TEST_LONG=1 $(BUILD)/$$real/tests/$$t; done; done
.PHONY: tests-long-cases
TEST_LONG += tests-long-cases

# Fragments of the other tools (reports, reference, robustness) add their own
# targets and test targets (TEST_EXTRA, TEST_LONG, above).
-include host/reports/reports.mk tests/reference/reference.mk tests/robustness.mk
include tests/consumer/consumer.mk
include tests/buildsys/buildsys.mk
include tests/octave.mk
include tests/slurm/slurm.mk
include tests/determinism.mk
include tests/python.mk
include tests/docs.mk

# Builds run JOBS at a time (the prerequisites); the tests themselves in order.
test: deps-test
	$(MAKE) --no-print-directory -j$(JOBS) REAL=double test-one
	$(MAKE) --no-print-directory -j$(JOBS) REAL=float test-one
	$(MAKE) --no-print-directory -j$(JOBS) embedded-test
	$(if $(strip $(TEST_EXTRA)),$(MAKE) --no-print-directory $(TEST_EXTRA))
	@echo "make test: all tests passed (double and float)"

# make test-long: the packages and the double and float trees first, then
# its targets JOBS at a time (tests/run_parallel.sh: each line prefixed with
# its target; the slowest first, TEST_LONG_FIRST, so that the lanes end
# together; fuzz-minute's targets one at a time, a lane's share). Its targets
# build into trees of their own, or check the shared ones already built: no
# two makes build the same file.
TEST_LONG_FIRST := fuzz-minute robustness-valgrind robustness-asan consumer-test embedded-long step-diff-long scenarios-long embedded-more
test-long: deps-test robustness-deps fuzz-deps deps-python
	@set -e; for real in double float; do $(MAKE) --no-print-directory -j$(JOBS) REAL=$$real test-one-build lib-one; done
	@MAKE='$(MAKE)' FUZZ_JOBS=1 bash tests/run_parallel.sh $(JOBS) $(filter $(TEST_LONG),$(TEST_LONG_FIRST)) \
	    $(filter-out $(TEST_LONG_FIRST),$(TEST_LONG))
	@echo "make test-long: all long tests passed"

# The field reference docs/fields.md (checked for staleness by make test).
fields: all
	$(BUILD)/beamslider fields > docs/fields.md.tmp && mv docs/fields.md.tmp docs/fields.md

# Compile-time scene headers for embedded builds: every scenario file
# (mssp2023.ini is only a base).
SCENE_INIS := $(filter-out configs/mssp2023.ini,$(wildcard configs/*.ini))
configs: all
	@set -e; for ini in $(SCENE_INIS); do \
	    $(BUILD)/beamslider gen $$ini > $${ini%.ini}.h.tmp && mv $${ini%.ini}.h.tmp $${ini%.ini}.h; \
	    echo "configs: $${ini%.ini}.h"; done

accuracy-check: $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	@sh tests/check_accuracy.sh $(BUILD)/bs-reference

deps-build:
	@sh host/deps.sh $(BUILD_PACKAGES)

deps-test:
	@sh host/deps.sh $(TEST_PACKAGES)

clean:
	rm -rf $(BUILD)
