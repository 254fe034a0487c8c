# tests/embedded/embedded.mk - the core compiled against one scene for Cortex-M,
# included by the top-level Makefile (which sets BUILD, REAL, TARGET, SCENE, STEPS,
# CORE_SRC, BASE_CFLAGS).
#
#   make embedded-test     every image of EMB_CHECKS under QEMU against its host
#                          twin, bit for bit (part of `make test`), the twin
#                          firmware, and the core symbol check of each image
#                          (embedded-more: the same for EMB_MORE_CHECKS and the
#                          QEMU harness self-test, embedded-long the whole runs,
#                          in `make test-long`)
#   make embedded-report   flash, RAM, stack, instructions and estimated cycles
#                          per step, backlog of whole runs -> docs/embedded.md
#                          (and make twin-firmware-report: the twin firmware, tests/embedded/twin.mk)
#   make TARGET=cortex-m4f [SCENE=fig6] [REAL=float] [STEPS=N] [run]
#                          one image of tests/embedded/scene_run.c (and its QEMU run)
#
# Embedded: the core compiled against one scene (configs/NAME.h) for Cortex-M
# targets, run under QEMU (port/cortex-m). Each image runs
# tests/embedded/scene_run.c; the same program built for the host must print
# the same lines (tests/check_embedded.sh).
include port/cortex-m/cortex-m.mk

# Every image is compiled against a generated build configuration naming its
# scene and precision (and BS_WITH_SUBSPACE=0 for the sweeps solve):
# $(EMB_CONFIG)/SCENE.REAL.SOLVE/bs_build_config.h, SOLVE = subspace | sweeps.
EMB_CONFIG := $(BUILD)/embconfig
emb_config_h = $(EMB_CONFIG)/$1.$2.$3/bs_build_config.h
$(EMB_CONFIG)/%/bs_build_config.h: core/include/bs_build_config.h.in port/build_config.sh
	@sh port/build_config.sh $@ $(word 2,$(subst ., ,$*)) 'BS_SCENE_CONFIG="configs/$(word 1,$(subst ., ,$*)).h"' \
	    $(if $(filter sweeps,$(word 3,$(subst ., ,$*))),BS_WITH_SUBSPACE=0)

# emb_flags SCENE REAL STEPS SOLVE EXTRA: an image's compile flags
emb_flags = -fno-tree-loop-distribute-patterns -I$(EMB_CONFIG)/$1.$2.$4 -Icore/include -Icore/src -Iport/embedded -I. \
            -DBS_RUN_STEPS=$3 $5
# $(call emb_image,NAME,TARGET,SCENE,REAL,STEPS,SOLVE,EXTRA): cm_image of scene_run.c and the core
define emb__image
$(call cm_image,$1,$2,$(EMB_SRC),$(call emb_flags,$3,$4,$5,$6,$7))
$$(CM_OBJS_$2_$1): $(call emb_config_h,$3,$4,$6)
endef
emb_image = $(eval $(call emb__image,$(strip $1),$(strip $2),$(strip $3),$(strip $4),$(strip $5),$(strip $6),$7))
EMB_SRC := tests/embedded/scene_run.c $(CORE_SRC)
# TARGET:SCENE:REAL:STEPS run in `make test` (soft-float targets: fewer steps): the
# twin's board in both scenes and a core without FPU ...
EMB_CHECKS := cortex-m4f:fig6:float:20000 cortex-m0plus:fig6_1mode:float:2000
# ... and in `make test-long` the other boards, scenes and switches (fig6_frictionless:
# the core compiled without friction, a switch no other image turns off)
EMB_MORE_CHECKS := cortex-m4f:fig6_1mode:float:20000 cortex-m4f:fig6_frictionless:float:20000 \
                   cortex-m7:fig6:double:20000 cortex-m7:fig6_1mode:float:20000 \
                   cortex-m3:fig6_1mode:float:2000
# ... and in `make test-long`, the scenes' whole runs (t_end / dt steps)
EMB_LONG_CHECKS := cortex-m4f:fig6_1mode:float:BS_SCENE_STEPS cortex-m4f:fig6:float:BS_SCENE_STEPS
# TARGET:REAL per scene for `make embedded-report`
EMB_COST_TARGETS := cortex-m4f:float cortex-m7:float cortex-m7:double cortex-m3:float cortex-m0plus:float
EMB_COST_SCENES := fig6 fig6_1mode fig6_frictionless
# ... and the contact solve without its subspace step (-DBS_WITH_SUBSPACE=0,
# a hard bound on the cost of a step), on the FPU targets' float builds
EMB_SWEEPS_TARGETS := cortex-m4f:float cortex-m7:float
EMB_SWEEPS_SCENES := fig6 fig6_1mode
# ... and the "ram" variant of the M4F float images of these scenes: the scene
# copied to RAM before the run (scene_run.c, BS_RUN_SCENE_IN_RAM) and no literal
# pools (-mslow-flash-data: constants built from MOVW/MOVT), so that a step reads
# no data from flash, whose wait states the cycle estimate charges per read
EMB_RAM_SCENES := fig6 fig6_1mode
EMB_RAM_FLAGS := -DBS_RUN_SCENE_IN_RAM=1 -mslow-flash-data
# ... and the scenes' whole runs (t_end / dt steps, no tight phase; default
# core), TARGET:SCENE:REAL on the boards of the real-time targets, and the M4F
# float ones once more in the ram variant
EMB_WHOLE := cortex-m4f:fig6:float cortex-m4f:fig6_1mode:float cortex-m4f:fig8:float \
             cortex-m7:fig6:double cortex-m7:fig6_1mode:double cortex-m7:fig8:double
EMB_WHOLE_RAM := fig6 fig6_1mode fig8
# ... and M4F float images at -O2 instead of CM_OPT's -O3 (a later -O wins), SCENE:SOLVE:
# what the optimisation level buys and costs
EMB_O2 := fig6:subspace fig6:sweeps fig6_1mode:subspace fig6_1mode:sweeps fig6_frictionless:subspace
emb_steps = $(if $(filter cortex-m3 cortex-m0plus,$1),2000,20000)
emb_whole_flags := -DBS_RUN_COST=1 -DBS_RUN_TIGHT_STEPS=0

emb_word = $(word $2,$(subst :, ,$1))
$(foreach c,$(EMB_CHECKS) $(EMB_MORE_CHECKS),$(call emb_image,check-$(call emb_word,$c,2)-$(call emb_word,$c,3),$(call emb_word,$c,1),\
    $(call emb_word,$c,2),$(call emb_word,$c,3),$(call emb_word,$c,4),subspace,))
$(foreach c,$(EMB_LONG_CHECKS),$(call emb_image,long-$(call emb_word,$c,2)-$(call emb_word,$c,3),$(call emb_word,$c,1),\
    $(call emb_word,$c,2),$(call emb_word,$c,3),$(call emb_word,$c,4),subspace,-DBS_RUN_EVERY=100000))
$(foreach s,$(EMB_COST_SCENES),$(foreach t,$(EMB_COST_TARGETS),$(call emb_image,cost-$s-$(call emb_word,$t,2),\
    $(call emb_word,$t,1),$s,$(call emb_word,$t,2),$(call emb_steps,$(call emb_word,$t,1)),subspace,-DBS_RUN_COST=1)))
$(foreach s,$(EMB_SWEEPS_SCENES),$(foreach t,$(EMB_SWEEPS_TARGETS),$(call emb_image,cost-$s-$(call emb_word,$t,2)-sweeps,\
    $(call emb_word,$t,1),$s,$(call emb_word,$t,2),20000,sweeps,-DBS_RUN_COST=1)))
$(foreach s,$(EMB_RAM_SCENES),$(call emb_image,cost-$s-float-ram,cortex-m4f,$s,float,20000,subspace,\
    -DBS_RUN_COST=1 $(EMB_RAM_FLAGS)))
$(foreach w,$(EMB_WHOLE),$(call emb_image,whole-$(call emb_word,$w,2)-$(call emb_word,$w,3),$(call emb_word,$w,1),\
    $(call emb_word,$w,2),$(call emb_word,$w,3),BS_SCENE_STEPS,subspace,$(emb_whole_flags)))
$(foreach s,$(EMB_WHOLE_RAM),$(call emb_image,whole-$s-float-ram,cortex-m4f,$s,float,BS_SCENE_STEPS,subspace,\
    $(emb_whole_flags) $(EMB_RAM_FLAGS)))
# ... and M4F float images counting 50 000 steps from 20 s into the scene's
# run (the high branch, most steps with two contacts), flash and ram: a quick
# probe of the cost where the whole runs spend it
EMB_MID_SCENES := fig6 fig6_1mode
emb_mid_flags := -DBS_RUN_COST=1 -DBS_RUN_SKIP=1000000 -DBS_RUN_TIGHT_STEPS=0
$(foreach s,$(EMB_MID_SCENES),$(call emb_image,mid-$s-float,cortex-m4f,$s,float,50000,subspace,$(emb_mid_flags)))
$(foreach s,$(EMB_MID_SCENES),$(call emb_image,mid-$s-float-ram,cortex-m4f,$s,float,50000,subspace,\
    $(emb_mid_flags) $(EMB_RAM_FLAGS)))
$(foreach c,$(EMB_O2),$(call emb_image,cost-$(call emb_word,$c,1)-float-$(call emb_word,$c,2)-O2,cortex-m4f,\
    $(call emb_word,$c,1),float,20000,$(call emb_word,$c,2),-DBS_RUN_COST=1 -O2))

# The host twin of a check image: $(EMB_HOST)/SCENE.REAL.STEPS, scene_run.c and the
# core compiled for the host against the same configuration.
EMB_HOST := $(BUILD)/embhost
define emb__host
$(EMB_HOST)/$1.$2.$3: tests/embedded/scene_run.c tests/embedded/bs_board_host.c $(CORE_SRC) \
        $(wildcard core/*/*.h) configs/$1.h $(call emb_config_h,$1,$2,subspace)
	@mkdir -p $$(dir $$@)
	$$(CC) -O2 $$(BASE_CFLAGS) -I$(EMB_CONFIG)/$1.$2.subspace -Icore/include -Icore/src -Iport/host \
	    -Iport/cortex-m -I. -DBS_RUN_STEPS=$3 $4 -o $$@ tests/embedded/scene_run.c tests/embedded/bs_board_host.c \
	    $(CORE_SRC) -lm
endef
EMB_HOST_TWINS := $(sort $(foreach c,$(EMB_CHECKS) $(EMB_MORE_CHECKS),$(call emb_word,$c,2):$(call emb_word,$c,3):$(call emb_word,$c,4)))
$(foreach c,$(EMB_LONG_CHECKS),$(eval $(call emb__host,$(call emb_word,$c,2),$(call emb_word,$c,3),$(call emb_word,$c,4),-DBS_RUN_EVERY=100000)))
$(foreach c,$(EMB_HOST_TWINS),$(eval $(call emb__host,$(call emb_word,$c,1),$(call emb_word,$c,2),$(call emb_word,$c,3))))

EMB_LONG_PAIRS := $(foreach c,$(EMB_LONG_CHECKS),$(call emb_word,$c,1):$(call cm_elf,long-$(call emb_word,$c,2)-$(call emb_word,$c,3),$(call emb_word,$c,1)):$(EMB_HOST)/$(call emb_word,$c,2).$(call emb_word,$c,3).$(call emb_word,$c,4))
emb_check_pairs = $(foreach c,$1,$(call emb_word,$c,1):$(call cm_elf,check-$(call emb_word,$c,2)-$(call emb_word,$c,3),$(call emb_word,$c,1)):$(EMB_HOST)/$(call emb_word,$c,2).$(call emb_word,$c,3).$(call emb_word,$c,4))
EMB_CHECK_PAIRS := $(call emb_check_pairs,$(EMB_CHECKS))
EMB_MORE_PAIRS := $(call emb_check_pairs,$(EMB_MORE_CHECKS))

# The step of a compiled scene against the run-time core's, bit for bit
# (tests/embedded/step_diff.c, docs/design.md "Determinism"): step_diff.c
# built against the core compiled for SCENE (as a firmware builds it, at -O3
# as the host core is) and against this build's own core objects with the
# scene header as data; their outputs must be equal (without friction: to a
# tolerance, below). `make test` runs
# STEP_DIFF_SCENES in each REAL (test-one), `make test-long` every scene with
# a header in configs/ in both precisions (step-diff-long).
STEP_DIFF_SCENES := fig6 fig6_1mode
STEP_DIFF_DIR := $(BUILD)/stepdiff
# A scene whose compiled core leaves friction out (fig6_frictionless) is
# compared value by value instead: the run-time core solves its contacts
# with tangential rows of mu = 0, another sequence of operations, whose
# results differ from the compiled core's only where the contact solve stops
# at its tolerance (three contacts, max_sweeps 2): within STEP_DIFF_TOLERANCE
# of each value's scale (measured: 1.5e-4 in both precisions).
STEP_DIFF_ALL := $(basename $(notdir $(wildcard configs/*.h)))
STEP_DIFF_NO_FRICTION := fig6_frictionless
STEP_DIFF_TOLERANCE := 5e-4
define step__diff
$(STEP_DIFF_DIR)/$1.$2.compiled: tests/embedded/step_diff.c $(CORE_SRC) $(wildcard core/*/*.h) configs/$1.h \
        $(call emb_config_h,$1,$2,subspace)
	@mkdir -p $$(dir $$@)
	$$(CC) -O3 $$(BASE_CFLAGS) -I$(EMB_CONFIG)/$1.$2.subspace -Icore/include -Icore/src -Iport/host -I. \
	    -o $$@ tests/embedded/step_diff.c $(CORE_SRC) -lm
$(STEP_DIFF_DIR)/$1.$2.runtime: tests/embedded/step_diff.c configs/$1.h $(BUILD)/$2/include/bs_build_config.h \
        $(CORE_SRC:%.c=$(BUILD)/$2/%.o)
	@mkdir -p $$(dir $$@)
	$$(CC) -O2 $$(BASE_CFLAGS) $$(filter -fsanitize%,$$(CFLAGS)) -I$(BUILD)/$2/include -Icore/include -Iport/host -I. \
	    -DDIFF_SCENE_HEADER='"configs/$1.h"' -o $$@ tests/embedded/step_diff.c $(CORE_SRC:%.c=$(BUILD)/$2/%.o) -lm
endef
$(foreach s,$(STEP_DIFF_ALL),$(foreach r,double float,$(eval $(call step__diff,$s,$r))))
step_diff_pairs = $(foreach s,$1,$(STEP_DIFF_DIR)/$s.$2.compiled:$(STEP_DIFF_DIR)/$s.$2.runtime$(if \
    $(filter $s,$(STEP_DIFF_NO_FRICTION)),:$(STEP_DIFF_TOLERANCE)))
.PHONY: step-diff-test step-diff-long
# in this REAL (test-one)
step-diff-test: $(foreach p,$(call step_diff_pairs,$(STEP_DIFF_SCENES),$(REAL)),$(filter-out $(STEP_DIFF_TOLERANCE),$(subst :, ,$p)))
	@sh tests/embedded/check_step_diff.sh $(call step_diff_pairs,$(STEP_DIFF_SCENES),$(REAL))
step-diff-long:
	@set -e; for real in double float; do \
	    $(MAKE) --no-print-directory -j$(JOBS) REAL=$$real STEP_DIFF_SCENES='$(STEP_DIFF_ALL)' step-diff-test; done
TEST_LONG += step-diff-long

# The twin firmware (port/cortex-m/twin): twin-firmware-test, twin-firmware-report.
include tests/embedded/twin.mk

embedded-test: $(if $(CM_TOOLS_OK),$(foreach p,$(EMB_CHECK_PAIRS),$(call emb_word,$p,2) $(call emb_word,$p,3)) $(TWIN_TEST_DEPS))
	$(if $(CM_TOOLS_OK),@sh tests/check_embedded.sh $(EMB_CHECK_PAIRS),@echo "$(CM_TOOLS_MSG)")
	$(if $(CM_TOOLS_OK),@$(MAKE) --no-print-directory twin-firmware-test)
	$(if $(CM_TOOLS_OK),@set -e; $(foreach c,$(EMB_CHECKS),NM=arm-none-eabi-nm sh tests/check_core_symbols.sh \
	    $(call emb_word,$c,3) $(CM_BUILD)/$(call emb_word,$c,1)/check-$(call emb_word,$c,2)-$(call emb_word,$c,3).obj/core/src/*.o;))

# The images of EMB_MORE_CHECKS against their host twins, and their core symbols
# (`make test-long`).
embedded-more:
	$(if $(CM_TOOLS_OK),@$(MAKE) --no-print-directory -j$(JOBS) $(foreach p,$(EMB_MORE_PAIRS),$(call emb_word,$p,2) $(call emb_word,$p,3)))
	$(if $(CM_TOOLS_OK),@sh tests/check_embedded.sh $(EMB_MORE_PAIRS),@echo "$(CM_TOOLS_MSG)")
	$(if $(CM_TOOLS_OK),@CM_BUILD=$(CM_BUILD) sh tests/qemu/selftest.sh)
	$(if $(CM_TOOLS_OK),@set -e; $(foreach c,$(EMB_MORE_CHECKS),NM=arm-none-eabi-nm sh tests/check_core_symbols.sh \
	    $(call emb_word,$c,3) $(CM_BUILD)/$(call emb_word,$c,1)/check-$(call emb_word,$c,2)-$(call emb_word,$c,3).obj/core/src/*.o;))
TEST_LONG += embedded-more

# The whole runs of EMB_LONG_CHECKS against their host twins (`make test-long`).
embedded-long:
	$(if $(CM_TOOLS_OK),@$(MAKE) --no-print-directory -j$(JOBS) $(foreach p,$(EMB_LONG_PAIRS),$(call emb_word,$p,2) $(call emb_word,$p,3)))
	$(if $(CM_TOOLS_OK),@CHECK_EMBEDDED_TIMEOUT=1800 sh tests/check_embedded.sh $(EMB_LONG_PAIRS),@echo "$(CM_TOOLS_MSG)")
TEST_LONG += embedded-long

# report arguments TARGET:SCENE:REAL:KIND:ELF, KIND = SOLVE[-ram][-O2|-whole] with
# SOLVE subspace (the default core) or sweeps: the per-phase cost images (no
# suffix), their ram variant (-ram), the -O2 images, the whole runs (-whole)
EMB_COST_SPECS := $(foreach s,$(EMB_COST_SCENES),$(foreach t,$(EMB_COST_TARGETS),\
    $(call emb_word,$t,1):$s:$(call emb_word,$t,2):subspace:$(call cm_elf,cost-$s-$(call emb_word,$t,2),$(call emb_word,$t,1)))) \
    $(foreach s,$(EMB_SWEEPS_SCENES),$(foreach t,$(EMB_SWEEPS_TARGETS),\
    $(call emb_word,$t,1):$s:$(call emb_word,$t,2):sweeps:$(call cm_elf,cost-$s-$(call emb_word,$t,2)-sweeps,$(call emb_word,$t,1)))) \
    $(foreach s,$(EMB_RAM_SCENES),cortex-m4f:$s:float:subspace-ram:$(call cm_elf,cost-$s-float-ram,cortex-m4f)) \
    $(foreach w,$(EMB_WHOLE),$(call emb_word,$w,1):$(call emb_word,$w,2):$(call emb_word,$w,3):subspace-whole:$(call cm_elf,\
    whole-$(call emb_word,$w,2)-$(call emb_word,$w,3),$(call emb_word,$w,1))) \
    $(foreach s,$(EMB_WHOLE_RAM),cortex-m4f:$s:float:subspace-ram-whole:$(call cm_elf,whole-$s-float-ram,cortex-m4f)) \
    $(foreach c,$(EMB_O2),cortex-m4f:$(call emb_word,$c,1):float:$(call emb_word,$c,2)-O2:$(call cm_elf,cost-$(call emb_word,$c,1)-float-$(call emb_word,$c,2)-O2,cortex-m4f))
# The images are built two at a time, then measured (the script runs QEMU two at a time).
embedded-report-images: $(foreach c,$(EMB_COST_SPECS),$(call emb_word,$c,5))
embedded-report:
	$(MAKE) --no-print-directory -j2 embedded-report-images
	CM_OPT='$(CM_OPT)' CM_BUILD='$(CM_BUILD)' sh host/reports/embedded_report.sh $(EMB_COST_SPECS)
	$(MAKE) --no-print-directory twin-firmware-report
.PHONY: embedded-report embedded-report-images embedded-test embedded-more


ifneq ($(TARGET),host)
# make TARGET=cortex-m4f [SCENE=fig6] [REAL=float] [STEPS=N] [run]: the firmware
# tests/embedded/scene_run.c for one target and scene; `run` runs it under QEMU.
ifeq ($(filter $(TARGET),$(CM_TARGETS)),)
$(error TARGET must be host or one of: $(CM_TARGETS))
endif
$(call emb_image,$(SCENE)-$(REAL)-$(STEPS),$(TARGET),$(SCENE),$(REAL),$(STEPS),subspace,)
all: $(call cm_elf,$(SCENE)-$(REAL)-$(STEPS),$(TARGET))
	@arm-none-eabi-size $<
run: all
	$(CM_RUN) $(call cm_elf,$(SCENE)-$(REAL)-$(STEPS),$(TARGET)) $(TARGET) 300
endif
