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
CORE_CFLAGS := $(BASE_CFLAGS) $(NO_LOOP_CALLS) -Icore -Iport/host
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

# ---------------------------------------------------------------------------
# Embedded: the core compiled against one scene (configs/NAME.h) for Cortex-M
# targets, run under QEMU (port/cortex-m). Each image runs
# tests/embedded/scene_run.c; the same program built for the host must print
# the same lines (tests/check_embedded.sh).
include port/cortex-m/cortex-m.mk

# emb_flags SCENE REAL STEPS EXTRA
emb_flags = -fno-tree-loop-distribute-patterns -Icore -Iport/embedded -I. -DBS_REAL_FLOAT=$(if $(filter float,$2),1,0) \
            -DBS_SCENE_CONFIG='"configs/$1.h"' -DBS_RUN_STEPS=$3 $4
EMB_SRC := tests/embedded/scene_run.c $(CORE_SRC)
# TARGET:SCENE:REAL:STEPS run in `make test` (soft-float targets: fewer steps)
EMB_CHECKS := cortex-m4f:fig6:float:20000 cortex-m4f:fig6_1mode:float:20000 \
              cortex-m7:fig6:double:20000 cortex-m7:fig6_1mode:float:20000 \
              cortex-m3:fig6_1mode:float:2000 cortex-m0plus:fig6_1mode:float:2000
# TARGET:REAL per scene for `make embedded-report`
EMB_COST_TARGETS := cortex-m4f:float cortex-m7:float cortex-m7:double cortex-m3:float cortex-m0plus:float
EMB_COST_SCENES := fig6 fig6_1mode fig6_frictionless
# ... and the contact solve without its subspace step (-DBS_WITH_SUBSPACE=0,
# a hard bound on the cost of a step), on the FPU targets' float builds
EMB_SWEEPS_TARGETS := cortex-m4f:float cortex-m7:float
EMB_SWEEPS_SCENES := fig6 fig6_1mode
# ... and the scenes' whole runs (t_end / dt steps, no tight phase), both solves,
# TARGET:SCENE for the boards of the real-time targets
EMB_WHOLE := cortex-m4f:fig6 cortex-m4f:fig6_1mode cortex-m7:fig6
# ... and M4F float images at -O2 instead of CM_OPT's -O3 (a later -O wins), SCENE:SOLVE:
# what the optimisation level buys and costs
EMB_O2 := fig6:subspace fig6:sweeps fig6_1mode:subspace fig6_1mode:sweeps fig6_frictionless:subspace
emb_steps = $(if $(filter cortex-m3 cortex-m0plus,$1),2000,20000)

emb_word = $(word $2,$(subst :, ,$1))
$(foreach c,$(EMB_CHECKS),$(call cm_image,check-$(call emb_word,$c,2)-$(call emb_word,$c,3),$(call emb_word,$c,1),\
    $(EMB_SRC),$(call emb_flags,$(call emb_word,$c,2),$(call emb_word,$c,3),$(call emb_word,$c,4),)))
$(foreach s,$(EMB_COST_SCENES),$(foreach t,$(EMB_COST_TARGETS),$(call cm_image,cost-$s-$(call emb_word,$t,2),\
    $(call emb_word,$t,1),$(EMB_SRC),$(call emb_flags,$s,$(call emb_word,$t,2),$(call emb_steps,$(call emb_word,$t,1)),-DBS_RUN_COST=1))))
$(foreach s,$(EMB_SWEEPS_SCENES),$(foreach t,$(EMB_SWEEPS_TARGETS),$(call cm_image,cost-$s-$(call emb_word,$t,2)-sweeps,\
    $(call emb_word,$t,1),$(EMB_SRC),$(call emb_flags,$s,$(call emb_word,$t,2),20000,-DBS_RUN_COST=1 -DBS_WITH_SUBSPACE=0))))
$(foreach w,$(EMB_WHOLE),$(foreach v,subspace:1 sweeps:0,$(call cm_image,whole-$(call emb_word,$w,2)-float-$(call emb_word,$v,1),\
    $(call emb_word,$w,1),$(EMB_SRC),$(call emb_flags,$(call emb_word,$w,2),float,BS_SCENE_STEPS,\
    -DBS_RUN_COST=1 -DBS_RUN_TIGHT_STEPS=0 -DBS_WITH_SUBSPACE=$(call emb_word,$v,2)))))
$(foreach c,$(EMB_O2),$(call cm_image,cost-$(call emb_word,$c,1)-float-$(call emb_word,$c,2)-O2,cortex-m4f,$(EMB_SRC),\
    $(call emb_flags,$(call emb_word,$c,1),float,20000,-DBS_RUN_COST=1 -DBS_WITH_SUBSPACE=$(if $(filter sweeps,$(call emb_word,$c,2)),0,1) -O2)))

# The host twin of a check image: build/embhost/check-SCENE-REAL-STEPS
EMB_HOST := $(BUILD)/embhost
$(EMB_HOST)/check-%: tests/embedded/scene_run.c tests/embedded/bs_board_host.c $(CORE_SRC) $(wildcard core/*.h configs/*.h)
	@mkdir -p $(dir $@)
	$(CC) -O2 $(BASE_CFLAGS:-DBS_REAL_FLOAT%=) -Icore -Iport/host -Iport/cortex-m -I. \
	    -DBS_REAL_FLOAT=$(if $(filter float,$(word 2,$(subst -, ,$(subst fig6_1mode,fig6x1mode,$*)))),1,0) \
	    -DBS_SCENE_CONFIG='"configs/$(subst x1mode,_1mode,$(word 1,$(subst -, ,$(subst fig6_1mode,fig6x1mode,$*)))).h"' \
	    -DBS_RUN_STEPS=$(word 3,$(subst -, ,$*)) -o $@ tests/embedded/scene_run.c tests/embedded/bs_board_host.c $(CORE_SRC) -lm

EMB_CHECK_PAIRS := $(foreach c,$(EMB_CHECKS),$(call emb_word,$c,1):$(call cm_elf,check-$(call emb_word,$c,2)-$(call emb_word,$c,3),$(call emb_word,$c,1)):$(EMB_HOST)/check-$(call emb_word,$c,2)-$(call emb_word,$c,3)-$(call emb_word,$c,4))

embedded-test: $(if $(CM_TOOLS_OK),$(foreach p,$(EMB_CHECK_PAIRS),$(call emb_word,$p,2) $(call emb_word,$p,3)))
	$(if $(CM_TOOLS_OK),@sh tests/check_embedded.sh $(EMB_CHECK_PAIRS),@echo "$(CM_TOOLS_MSG)")
	$(if $(CM_TOOLS_OK),@CM_BUILD=$(CM_BUILD) sh port/cortex-m/selftest.sh)
	$(if $(CM_TOOLS_OK),@set -e; $(foreach c,$(EMB_CHECKS),NM=arm-none-eabi-nm sh tests/check_core_symbols.sh \
	    $(call emb_word,$c,3) $(CM_BUILD)/$(call emb_word,$c,1)/check-$(call emb_word,$c,2)-$(call emb_word,$c,3).obj/core/*.o;))

# report arguments TARGET:SCENE:REAL:SOLVE:ELF (whole runs: SOLVE is subspace-whole or
# sweeps-whole; -O2 images: subspace-O2 or sweeps-O2)
EMB_COST_SPECS := $(foreach s,$(EMB_COST_SCENES),$(foreach t,$(EMB_COST_TARGETS),\
    $(call emb_word,$t,1):$s:$(call emb_word,$t,2):subspace:$(call cm_elf,cost-$s-$(call emb_word,$t,2),$(call emb_word,$t,1)))) \
    $(foreach s,$(EMB_SWEEPS_SCENES),$(foreach t,$(EMB_SWEEPS_TARGETS),\
    $(call emb_word,$t,1):$s:$(call emb_word,$t,2):sweeps:$(call cm_elf,cost-$s-$(call emb_word,$t,2)-sweeps,$(call emb_word,$t,1)))) \
    $(foreach w,$(EMB_WHOLE),$(foreach v,subspace sweeps,\
    $(call emb_word,$w,1):$(call emb_word,$w,2):float:$v-whole:$(call cm_elf,whole-$(call emb_word,$w,2)-float-$v,$(call emb_word,$w,1)))) \
    $(foreach c,$(EMB_O2),cortex-m4f:$(call emb_word,$c,1):float:$(call emb_word,$c,2)-O2:$(call cm_elf,cost-$(call emb_word,$c,1)-float-$(call emb_word,$c,2)-O2,cortex-m4f))
embedded-report: $(foreach c,$(EMB_COST_SPECS),$(call emb_word,$c,5))
	CM_OPT='$(CM_OPT)' sh host/embedded_report.sh $(EMB_COST_SPECS)

ifeq ($(TARGET),host)
run: all
	$(BUILD)/beamslider run configs/fig6.ini --out $(BUILD)/fig6.csv --every 20
else
# make TARGET=cortex-m4f [SCENE=fig6] [REAL=float] [STEPS=N] [run]: the firmware
# tests/embedded/scene_run.c for one target and scene; `run` runs it under QEMU.
ifeq ($(filter $(TARGET),$(CM_TARGETS)),)
$(error TARGET must be host or one of: $(CM_TARGETS))
endif
$(call cm_image,$(SCENE)-$(REAL)-$(STEPS),$(TARGET),$(EMB_SRC),$(call emb_flags,$(SCENE),$(REAL),$(STEPS),))
all: $(call cm_elf,$(SCENE)-$(REAL)-$(STEPS),$(TARGET))
	@arm-none-eabi-size $<
run: all
	$(CM_RUN) $(call cm_elf,$(SCENE)-$(REAL)-$(STEPS),$(TARGET)) $(TARGET) 300
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
-include host/figures.mk host/reference/reference.mk tests/robustness.mk

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

fig6-report:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/fig6_report.sh

$(OBJ)/bs-stability: host/tools/stability.c $(HOST_LIB_OBJ) $(CORE_OBJ)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -o $@ $^ $(HOST_LIBS)

accuracy: $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	$(MAKE) --no-print-directory REAL=double $(SWEEPS_FLAGS) $(SWEEPS_BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(SWEEPS_FLAGS) $(SWEEPS_BUILD)/float/beamslider
	sh host/accuracy.sh

accuracy-check: $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	@sh tests/check_accuracy.sh $(BUILD)/bs-reference

stability:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/bs-stability
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/bs-stability
	sh host/stability_report.sh $(BUILD)/double/bs-stability $(BUILD)/float/bs-stability

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
