# beamslider - plain GNU make.
#
#   make              build build/beamslider (REAL precision)
#   make run          build and run the fig6 scene (60 s), print its summary
#   make test         build and run every test, float and double
#   make bench        steps per second -> docs/performance.md
#   make fig6-report  the signature move in numbers -> docs/validation.md
#   make configs      regenerate the compile-time scene headers configs/*.h
#   make clean
#
# Knobs (make VAR=value):
REAL ?= double        # float | double: the core's bs_real
CC ?= cc
BUILD ?= build

ifeq ($(filter $(strip $(REAL)),float double),)
$(error REAL must be float or double, not '$(REAL)')
endif
REAL := $(strip $(REAL))
OBJ := $(BUILD)/$(REAL)
REAL_FLAG := -DBS_REAL_FLOAT=$(if $(filter float,$(REAL)),1,0)

# -std=c99 keeps fused multiply-add off (-ffp-contract=off made explicit);
# -fno-math-errno lets sqrt be one instruction and changes no result.
WARNINGS := -Wall -Wextra -Werror -Wdouble-promotion -Wfloat-conversion -Wundef -Wshadow \
            -Wstrict-prototypes -Wvla
CFLAGS ?= -O2 -g
BASE_CFLAGS := -std=c99 -ffp-contract=off -fno-math-errno $(WARNINGS) $(REAL_FLAG)
# Core: no libc calls; keep GCC from turning loops into memset/memcpy calls.
CORE_CFLAGS := $(BASE_CFLAGS) -fno-tree-loop-distribute-patterns -Icore -Iport/host
HOST_CFLAGS := $(BASE_CFLAGS) -Icore -Iport -Iport/host -Ihost

CORE_SRC := $(wildcard core/*.c)
HOST_CLI_SRC := host/main.c $(wildcard host/cli_*.c)
HOST_LIB_SRC := $(filter-out $(HOST_CLI_SRC),$(wildcard host/*.c)) port/host/bs_platform_host.c
CORE_OBJ := $(CORE_SRC:%.c=$(OBJ)/%.o)
HOST_CLI_OBJ := $(HOST_CLI_SRC:%.c=$(OBJ)/%.o)
HOST_LIB_OBJ := $(HOST_LIB_SRC:%.c=$(OBJ)/%.o)
HOST_LIBS := -linih -lm

TESTS := $(basename $(notdir $(wildcard tests/test_*.c)))
TEST_BIN := $(TESTS:%=$(OBJ)/tests/%)
TEST_LIBS := -lcmocka -lcjson $(HOST_LIBS)

BUILD_PACKAGES := gcc make libc6-dev libinih-dev
TEST_PACKAGES := $(BUILD_PACKAGES) libcmocka-dev libcjson-dev binutils

.PHONY: all run test test-one bench fig6-report configs clean deps-build deps-test
.SECONDARY:

# build/beamslider is the binary of the REAL of the last `make`.
all: $(OBJ)/beamslider
	@cmp -s $< $(BUILD)/beamslider || cp $< $(BUILD)/beamslider

$(OBJ)/beamslider: $(HOST_CLI_OBJ) $(HOST_LIB_OBJ) $(CORE_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(HOST_LIBS)

$(OBJ)/core/%.o: core/%.c $(wildcard core/*.h) port/host/bs_port.h | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(CORE_CFLAGS) -c -o $@ $<

$(OBJ)/host/%.o: host/%.c $(wildcard host/*.h core/*.h) | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -c -o $@ $<

$(OBJ)/port/host/%.o: port/host/%.c port/bs_platform.h | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -c -o $@ $<

$(OBJ)/tests/%.o: tests/%.c $(wildcard tests/*.h host/*.h core/*.h) | deps-test
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -Itests -c -o $@ $<

$(OBJ)/tests/test_%: $(OBJ)/tests/test_%.o $(OBJ)/tests/support.o $(HOST_LIB_OBJ) $(CORE_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(TEST_LIBS)

run: all
	$(BUILD)/beamslider run configs/fig6.ini --out $(BUILD)/fig6.csv --every 20

# Every test in this REAL, then the core symbol check.
test-one: $(TEST_BIN) $(OBJ)/beamslider
	@set -e; for t in $(TEST_BIN); do echo "== $$t"; ./$$t; done
	@sh tests/check_core_symbols.sh $(REAL) $(CORE_OBJ)
	@sh tests/check_cli.sh $(OBJ)/beamslider
	@sh tests/check_configs.sh $(OBJ)/beamslider

test: deps-test
	$(MAKE) --no-print-directory REAL=double test-one
	$(MAKE) --no-print-directory REAL=float test-one
	@echo "make test: all tests passed (double and float)"

# Compile-time scene headers for embedded builds: every scenario file
# (mssp2023.ini is only a base).
SCENE_INIS := $(filter-out configs/mssp2023.ini,$(wildcard configs/*.ini))
configs: all
	@set -e; for ini in $(SCENE_INIS); do \
	    $(BUILD)/beamslider gen $$ini > $${ini%.ini}.h.tmp && mv $${ini%.ini}.h.tmp $${ini%.ini}.h; \
	    echo "configs: $${ini%.ini}.h"; done

fig6-report:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/fig6_report.sh

bench:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/bench.sh

deps-build:
	@sh host/deps.sh $(BUILD_PACKAGES)

deps-test:
	@sh host/deps.sh $(TEST_PACKAGES)

clean:
	rm -rf $(BUILD)
