# beamslider - plain GNU make.
#
#   make              build build/beamslider (REAL precision)
#   make run          build and run the fig6 scene (60 s), print its summary
#   make test         build and run every test, float and double
#   make test-sweeps  the contact solve's tests built with -DBS_WITH_SUBSPACE=0
#   make bench        steps per second -> docs/performance.md
#   make fig6-report  the signature move in numbers -> docs/validation.md
#   make configs      regenerate the compile-time scene headers configs/*.h
#   make embedded-report  flash, RAM, stack, instructions per step on Cortex-M -> docs/embedded.md
#   make stability    the stiff and extreme cases -> docs/stability.md
#   make accuracy     error against run time vs the reference -> docs/accuracy.md
#   make figures      the papers' figures and validation tables -> docs/figures, docs/validation.md
#   make clean
#   make TARGET=cortex-m4f [SCENE=fig6] [REAL=float] [run]
#                     cross build (and QEMU run) of one compiled scene
#
# Knobs (make VAR=value):
REAL ?= double        # float | double: the core's bs_real
CC ?= cc
BUILD ?= build
TARGET ?= host        # host, or a Cortex-M target: cortex-m4f cortex-m7 cortex-m3 cortex-m0plus
SCENE ?= fig6         # the compiled scene of a Cortex-M build (configs/SCENE.h)
STEPS ?= 20000        # steps the Cortex-M build runs

ifeq ($(filter $(strip $(REAL)),float double),)
$(error REAL must be float or double, not '$(REAL)')
endif
REAL := $(strip $(REAL))
TARGET := $(strip $(TARGET))
SCENE := $(strip $(SCENE))
STEPS := $(strip $(STEPS))
OBJ := $(BUILD)/$(REAL)
REAL_FLAG := -DBS_REAL_FLOAT=$(if $(filter float,$(REAL)),1,0)

# -std=c99 keeps fused multiply-add off (-ffp-contract=off made explicit);
# -fno-math-errno lets sqrt be one instruction and changes no result.
WARNINGS := -Wall -Wextra -Werror -Wdouble-promotion -Wfloat-conversion -Wundef -Wshadow \
            -Wstrict-prototypes -Wvla
CFLAGS ?= -O2 -g
BASE_CFLAGS := -std=c99 -ffp-contract=off -fno-math-errno $(WARNINGS) $(REAL_FLAG)
# Core: no libc calls; keep GCC from turning loops into memset/memcpy calls
# (a GCC flag: other compilers go without; check_core_symbols.sh still checks).
NO_LOOP_CALLS := $(shell $(CC) -fno-tree-loop-distribute-patterns -Werror -E -x c /dev/null >/dev/null 2>&1 \
                   && echo -fno-tree-loop-distribute-patterns)
CORE_CFLAGS := $(BASE_CFLAGS) $(NO_LOOP_CALLS) -Icore/include -Icore/src -Iport/host
HOST_CFLAGS := $(BASE_CFLAGS) -Icore/include -Icore/src -Iport -Iport/host -Ihost/lib -Ihost/cli

CORE_SRC := $(wildcard core/src/*.c)
HOST_CLI_SRC := $(wildcard host/cli/*.c)
HOST_LIB_SRC := $(wildcard host/lib/*.c) port/host/bs_platform_host.c
CORE_OBJ := $(CORE_SRC:%.c=$(OBJ)/%.o)
HOST_CLI_OBJ := $(HOST_CLI_SRC:%.c=$(OBJ)/%.o)
HOST_LIB_OBJ := $(HOST_LIB_SRC:%.c=$(OBJ)/%.o)
HOST_LIBS := -linih -lcjson -lm

TESTS := $(basename $(notdir $(wildcard tests/test_*.c)))
TEST_BIN := $(TESTS:%=$(OBJ)/tests/%)
TEST_LIBS := -lcmocka $(HOST_LIBS)

BUILD_PACKAGES := gcc make libc6-dev libinih-dev libcjson-dev
TEST_PACKAGES := $(BUILD_PACKAGES) libcmocka-dev libcjson-dev binutils

.PHONY: all run test test-one test-sweeps bench fig6-report configs embedded-test embedded-report stability accuracy accuracy-check clean deps-build deps-test
.SECONDARY:
.DEFAULT_GOAL := all

ifeq ($(TARGET),host)
# build/beamslider is the binary of the REAL of the last `make`.
all: $(OBJ)/beamslider
	@cmp -s $< $(BUILD)/beamslider || cp $< $(BUILD)/beamslider
endif

$(OBJ)/beamslider: $(HOST_CLI_OBJ) $(HOST_LIB_OBJ) $(CORE_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(HOST_LIBS)

$(OBJ)/core/%.o: core/%.c $(wildcard core/*/*.h) port/host/bs_port.h | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(CORE_CFLAGS) -c -o $@ $<

$(OBJ)/host/%.o: host/%.c $(wildcard host/*/*.h core/include/*.h) | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -c -o $@ $<

$(OBJ)/port/host/%.o: port/host/%.c port/bs_platform.h | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -c -o $@ $<

$(OBJ)/tests/%.o: tests/%.c $(wildcard tests/*.h host/*/*.h core/*/*.h) | deps-test
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -Icore/src -Itests -c -o $@ $<

$(OBJ)/tests/test_%: $(OBJ)/tests/test_%.o $(OBJ)/tests/support.o $(HOST_LIB_OBJ) $(CORE_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(TEST_LIBS)

include tests/embedded/embedded.mk

ifeq ($(TARGET),host)
run: all
	$(BUILD)/beamslider run configs/fig6.ini --out $(BUILD)/fig6.csv --every 20
endif

# Every test in this REAL, then the core symbol check.
test-one: $(TEST_BIN) $(OBJ)/beamslider
	@set -e; for t in $(TEST_BIN); do echo "== $$t"; ./$$t; done
	@sh tests/check_core_symbols.sh $(REAL) $(CORE_OBJ)
	@sh tests/check_cli.sh $(OBJ)/beamslider
	@sh tests/check_configs.sh $(OBJ)/beamslider

# The contact solve built without its subspace step (BS_WITH_SUBSPACE=0, the
# real-time option of docs/porting.md): its unit tests in both precisions.
SWEEPS_BUILD := $(BUILD)/sweeps
SWEEPS_FLAGS := CFLAGS="$(CFLAGS) -DBS_WITH_SUBSPACE=0" BUILD=$(SWEEPS_BUILD)
test-sweeps:
	@set -e; for real in double float; do \
	    $(MAKE) --no-print-directory -s REAL=$$real $(SWEEPS_FLAGS) $(SWEEPS_BUILD)/$$real/tests/test_pgs; \
	    echo "== $(SWEEPS_BUILD)/$$real/tests/test_pgs (-DBS_WITH_SUBSPACE=0)"; $(SWEEPS_BUILD)/$$real/tests/test_pgs; done

# Fragments of the other tools (figures, reference, robustness) add their own
# targets and append test targets to TEST_EXTRA.
TEST_EXTRA := test-sweeps accuracy-check
-include host/reports/reports.mk tests/reference/reference.mk tests/robustness.mk

test: deps-test
	$(MAKE) --no-print-directory REAL=double test-one
	$(MAKE) --no-print-directory REAL=float test-one
	$(MAKE) --no-print-directory embedded-test
	$(if $(strip $(TEST_EXTRA)),$(MAKE) --no-print-directory $(TEST_EXTRA))
	@echo "make test: all tests passed (double and float)"

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
