# tests/embedded/twin.mk - the twin firmware (port/cortex-m/twin) under QEMU and on
# the host, included by tests/embedded/embedded.mk (which sets EMB_CONFIG, EMB_HOST,
# emb_config_h, emb_word and includes port/cortex-m/cortex-m.mk).
#
#   make twin-firmware-test    (part of `make embedded-test`, ~15 s when built) a 1 s
#                              fig6 stream through the M4F image and its host build, bit
#                              for bit (tests/check_embedded.sh), at a twin step that keeps
#                              pace and at one that does not (the overrun policy); the
#                              former against `beamslider twin` on the same CSV, and the
#                              SysTick build under QEMU with -icount (tests/check_twin.sh)
#   make twin-firmware-report  the firmware's cost on a whole 60 s fig6 stream ->
#                              docs/embedded.md, "Twin firmware" (~10 min;
#                              host/reports/twin_firmware_report.sh; also run by
#                              `make embedded-report`)
#
# Data, all generated in $(TWIN_DIR) (nothing committed): the plant run
# fig6-T.csv (`beamslider twin-plant`, float build, noise 40 dB below each signal,
# 12 bits, seed 1, T seconds), its stream fig6-T.stream (twin_pack), and the
# observer's constants for a twin scene on that stream, SCENE-fig6-T/twin_gains.h
# (`beamslider twin-gains` with the noise the CSV states, as `beamslider twin`
# designs them).
TWIN_SRC_DIR := port/cortex-m/twin
TWIN_DIR := $(BUILD)/twin
TWIN_CLI := $(BUILD)/float/beamslider
TWIN_PACK := $(TWIN_DIR)/twin_pack
TWIN_PLANT_ARGS := --snr 40 --bits 12 --seed 1
# The simulated clock's stated twin step in the two check images [cycles; a sample
# period is 3360]: one that keeps pace, and the firmware's mean over the whole 60 s
# stream as measured (pessimistic estimate, docs/embedded.md "Twin firmware")
TWIN_PACE_CYCLES := 3000
TWIN_OVERLOAD_CYCLES := 7200
# The SysTick build under QEMU: SysTick at 25 MHz, reload 499 (1/dt = 50 kHz of QEMU's
# virtual time), and -icount shift=3: 8 ns of virtual time per instruction, i.e. a
# core that executes 125 million instructions a second
TWIN_ICOUNT := -icount shift=3,align=off,sleep=off

ifneq ($(OBJ),$(BUILD)/float)
# the float CLI, whatever REAL this make has (the top-level Makefile builds it when REAL=float)
$(TWIN_CLI): .force
	@$(MAKE) --no-print-directory REAL=float $@
endif

# twin_pack reads the CSV with the one reader of its format (host/lib/twin/measured_signals.c)
TWIN_PACK_SRC := $(TWIN_SRC_DIR)/twin_pack.c host/lib/twin/measured_signals.c host/lib/io/input_file.c \
                 host/lib/io/out_text.c
$(TWIN_PACK): $(TWIN_PACK_SRC) $(TWIN_SRC_DIR)/twin_stream.h host/lib/twin/measured_signals.h host/lib/io/input_file.h
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(BASE_CFLAGS) -I$(TWIN_SRC_DIR) -Ihost/lib/twin -Ihost/lib/io -o $@ $(TWIN_PACK_SRC) -lm

$(TWIN_DIR)/fig6-%s.csv: configs/fig6.ini configs/mssp2023.ini $(TWIN_CLI)
	@mkdir -p $(dir $@)
	$(TWIN_CLI) twin-plant configs/fig6.ini $(TWIN_PLANT_ARGS) --t-end $* --out $@ > $@.json
$(TWIN_DIR)/%.stream: $(TWIN_DIR)/%.csv $(TWIN_PACK)
	$(TWIN_PACK) $< $@

# the noise a CSV states: twin_noise CSV KEY (noise or accel_noise)
twin_noise = $$(sed -n 's/^\# $2 = \([^ ]*\) .*/\1/p' $1)
# $(TWIN_DIR)/SCENE-STREAM/twin_gains.h: the observer's constants of twin scene SCENE for
# STREAM, written only when its text changes (twin_gains.stamp is what is remade): the CLI
# is relinked at every commit, its revision in it, and the firmware compiled against the
# header need not be (make reads the header's time again after its empty recipe)
$(TWIN_DIR)/%/twin_gains.stamp: $(TWIN_CLI)
	@mkdir -p $(dir $@)
	@set -e; scene=$(word 1,$(subst -, ,$*)); csv=$(TWIN_DIR)/$(patsubst $(word 1,$(subst -, ,$*))-%,%,$*).csv; \
	    header=$(dir $@)twin_gains.h; \
	    $(TWIN_CLI) twin-gains configs/$$scene.ini --noise $(call twin_noise,$$csv,noise) \
	        --accel-noise $(call twin_noise,$$csv,accel_noise) --name twin_gains > $$header.tmp; \
	    if cmp -s $$header.tmp $$header; then rm -f $$header.tmp; else mv $$header.tmp $$header; fi; touch $@
$(TWIN_DIR)/%/twin_gains.h: $(TWIN_DIR)/%/twin_gains.stamp ;
.PRECIOUS: $(TWIN_DIR)/%/twin_gains.stamp
$(TWIN_DIR)/fig6-fig6-1s/twin_gains.stamp: $(TWIN_DIR)/fig6-1s.csv configs/fig6.ini
$(TWIN_DIR)/fig6-fig6-60s/twin_gains.stamp: $(TWIN_DIR)/fig6-60s.csv configs/fig6.ini
$(TWIN_DIR)/fig6_1mode-fig6-60s/twin_gains.stamp: $(TWIN_DIR)/fig6-60s.csv configs/fig6_1mode.ini

TWIN_COMMON_SRC := $(TWIN_SRC_DIR)/twin_main.c $(TWIN_SRC_DIR)/twin_fifo.c
# twin_flags SCENE REAL STREAM EXTRA: the compile flags of a twin image or host build
# (the scenes' excitation keeps its frequency: room for one response map)
twin_flags = -fno-tree-loop-distribute-patterns -I$(EMB_CONFIG)/$1.$2.subspace -Icore/include -Icore/src -I. \
             -I$(TWIN_SRC_DIR) -I$(TWIN_DIR)/$1-$3 -DTWIN_STREAM=\"$(TWIN_DIR)/$3.stream\" -DBS_OBSERVER_MAPS=1 $4
# The firmware's globals (FIFO, tally, clock, source, twin and observer)
# addressed from a shared anchor, one literal from flash for several, not
# one each: -fdata-sections gives every variable a section of its own, which
# rules the anchors out (`sh tests/qemu/twin_probe.sh` on
# twin-cost-friction-off: 2569.4 -> 2515.4 estimated cycles a sample with
# the constants in flash, the same hashes). The step's images gain nothing
# from it (mid-fig6-float 2364.8 either way) and keep their sections.
TWIN_CM_FLAGS := -fno-data-sections -fsection-anchors
# $(call twin_image,NAME,TARGET,SCENE,REAL,STREAM,CLOCK,EXTRA): cm_image of the firmware
# (CLOCK: sim or systick) on the semihosting source
define twin__image
$(call cm_image,$1,$2,$(TWIN_COMMON_SRC) $(TWIN_SRC_DIR)/twin_source_semihost.c $(TWIN_SRC_DIR)/twin_clock_$6.c \
    $(CORE_SRC),-Iport/embedded $(TWIN_CM_FLAGS) $(call twin_flags,$3,$4,$5,$7))
$$(CM_OBJS_$2_$1): $(call emb_config_h,$3,$4,subspace) $(TWIN_DIR)/$3-$5/twin_gains.h
endef
twin_image = $(eval $(call twin__image,$1,$2,$3,$4,$5,$6,$7))
# $(call twin_host,NAME,SCENE,STREAM,EXTRA): $(EMB_HOST)/NAME, the same firmware built for
# the host (stdio source, simulated clock, the no-op board of tests/embedded)
define twin__host
$(EMB_HOST)/$1: $(TWIN_COMMON_SRC) $(TWIN_SRC_DIR)/twin_source_stdio.c $(TWIN_SRC_DIR)/twin_clock_sim.c \
        $(wildcard $(TWIN_SRC_DIR)/*.h) tests/embedded/bs_board_host.c $(CORE_SRC) $(wildcard core/*/*.h) \
        configs/$2.h $(call emb_config_h,$2,float,subspace) $(TWIN_DIR)/$2-$3/twin_gains.h
	@mkdir -p $$(dir $$@)
	$$(CC) -O2 $$(BASE_CFLAGS) -Iport/host -Iport/cortex-m $(call twin_flags,$2,float,$3,$4) -o $$@ \
	    $(TWIN_COMMON_SRC) $(TWIN_SRC_DIR)/twin_source_stdio.c $(TWIN_SRC_DIR)/twin_clock_sim.c \
	    tests/embedded/bs_board_host.c $(CORE_SRC) -lm
endef
twin_host = $(eval $(call twin__host,$1,$2,$3,$4))

# --- make test ---------------------------------------------------------------------
$(call twin_image,twin-pace,cortex-m4f,fig6,float,fig6-1s,sim,-DTWIN_STEP_CYCLES=$(TWIN_PACE_CYCLES))
$(call twin_image,twin-overload,cortex-m4f,fig6,float,fig6-1s,sim,-DTWIN_STEP_CYCLES=$(TWIN_OVERLOAD_CYCLES))
$(call twin_image,twin-systick,cortex-m4f,fig6,float,fig6-1s,systick,)
$(call twin_host,twin-pace,fig6,fig6-1s,-DTWIN_STEP_CYCLES=$(TWIN_PACE_CYCLES))
$(call twin_host,twin-overload,fig6,fig6-1s,-DTWIN_STEP_CYCLES=$(TWIN_OVERLOAD_CYCLES))
TWIN_CHECK_PAIRS := cortex-m4f:$(call cm_elf,twin-pace,cortex-m4f):$(EMB_HOST)/twin-pace \
                    cortex-m4f:$(call cm_elf,twin-overload,cortex-m4f):$(EMB_HOST)/twin-overload
TWIN_TEST_DEPS := $(foreach p,$(TWIN_CHECK_PAIRS),$(call emb_word,$p,2) $(call emb_word,$p,3)) \
                  $(call cm_elf,twin-systick,cortex-m4f) $(TWIN_DIR)/fig6-1s.stream $(TWIN_CLI)
twin-firmware-test: $(if $(CM_TOOLS_OK),$(TWIN_TEST_DEPS))
	$(if $(CM_TOOLS_OK),@sh tests/check_embedded.sh $(TWIN_CHECK_PAIRS),@echo "$(CM_TOOLS_MSG)")
	$(if $(CM_TOOLS_OK),@TWIN_ICOUNT='$(TWIN_ICOUNT)' sh tests/check_twin.sh $(TWIN_CLI) configs/fig6.ini \
	    $(TWIN_DIR)/fig6-1s.csv $(EMB_HOST)/twin-pace $(call cm_elf,twin-systick,cortex-m4f))

# --- cost (make twin-firmware-report) ----------------------------------------------
# the whole 60 s stream, every producer call and observer step bracketed (TWIN_COST=1);
# twin scenes fig6 and fig6_1mode, constants in flash and in RAM, and fig6 on the M7.
# The cost images measure the main loop's stack too, painting the stack below it again
# after each 10 Hz report: a window of 4 KiB (the loop uses under 1 KiB; the image stops
# with an error if it ever fills the window), not the 64 KiB default, whose painting and
# scanning the per-sample count carried though a firmware has none (tests/qemu/twin_probe.sh on
# twin-cost-friction-off: 2647.1 estimated cycles a sample with 64 KiB, 2591.8 with 4 KiB).
TWIN_COST_FLAGS := -DTWIN_COST=1 -DBS_BOARD_STACK_PAINT_BYTES=4096
TWIN_RAM_FLAGS := -DTWIN_CONSTANTS_IN_RAM=1 -mslow-flash-data
$(foreach s,fig6 fig6_1mode,\
    $(call twin_image,twin-cost-$s,cortex-m4f,$s,float,fig6-60s,sim,$(TWIN_COST_FLAGS))\
    $(call twin_image,twin-cost-$s-ram,cortex-m4f,$s,float,fig6-60s,sim,$(TWIN_COST_FLAGS) $(TWIN_RAM_FLAGS)))
$(call twin_image,twin-cost-fig6,cortex-m7,fig6,float,fig6-60s,sim,$(TWIN_COST_FLAGS))
# The fig6 twin at the coarser step of docs/design.md 4 ("Prewarped frequencies"):
# fig6 with [numerics] dt = TWIN_FAST_DT and prewarp = on, a scene generated here
# (TWIN_DIR/fig6_fast.ini, its header by `beamslider gen`), on its own 60 s stream
# (the same scene as the plant, noise and bits as above), constants in flash and in RAM.
# 1/32000 s: the stream (twin_stream.h) wants a whole number of samples a second.
TWIN_FAST_DT := 3.125e-5
$(TWIN_DIR)/fig6_fast.ini: configs/fig6.ini tests/embedded/twin.mk
	@mkdir -p $(dir $@)
	printf '[scene]\nbase = %s\ndescription = fig6 at dt = %s s with prewarped modal frequencies\n[numerics]\ndt = %s\nprewarp = on\n' \
	    $(abspath configs/fig6.ini) $(TWIN_FAST_DT) $(TWIN_FAST_DT) > $@
$(TWIN_DIR)/fig6_fast.h: $(TWIN_DIR)/fig6_fast.ini configs/mssp2023.ini $(TWIN_CLI)
	$(TWIN_CLI) gen $< > $@.tmp && mv $@.tmp $@
$(call emb_config_h,fig6_fast,float,subspace): core/include/bs_build_config.h.in port/build_config.sh $(TWIN_DIR)/fig6_fast.h
	@sh port/build_config.sh $@ float 'BS_SCENE_CONFIG="$(TWIN_DIR)/fig6_fast.h"'
$(TWIN_DIR)/fast-60s.csv: $(TWIN_DIR)/fig6_fast.ini configs/mssp2023.ini $(TWIN_CLI)
	$(TWIN_CLI) twin-plant $< $(TWIN_PLANT_ARGS) --t-end 60 --out $@ > $@.json
$(TWIN_DIR)/fig6_fast-fast-60s/twin_gains.h: $(TWIN_DIR)/fig6_fast.ini $(TWIN_DIR)/fast-60s.csv $(TWIN_CLI)
	@mkdir -p $(dir $@)
	$(TWIN_CLI) twin-gains $< --noise $(call twin_noise,$(TWIN_DIR)/fast-60s.csv,noise) \
	    --accel-noise $(call twin_noise,$(TWIN_DIR)/fast-60s.csv,accel_noise) --name twin_gains > $@.tmp && mv $@.tmp $@
$(call twin_image,twin-cost-fig6_fast,cortex-m4f,fig6_fast,float,fast-60s,sim,$(TWIN_COST_FLAGS))
$(call twin_image,twin-cost-fig6_fast-ram,cortex-m4f,fig6_fast,float,fast-60s,sim,$(TWIN_COST_FLAGS) $(TWIN_RAM_FLAGS))
# report arguments TARGET:SCENE:VARIANT:ELF[:DT] (DT: the stream's sample period, 2e-5 s
# when not given)
TWIN_COST_SPECS := cortex-m4f:fig6:flash:$(call cm_elf,twin-cost-fig6,cortex-m4f) \
                   cortex-m4f:fig6:ram:$(call cm_elf,twin-cost-fig6-ram,cortex-m4f) \
                   cortex-m4f:fig6_1mode:flash:$(call cm_elf,twin-cost-fig6_1mode,cortex-m4f) \
                   cortex-m4f:fig6_1mode:ram:$(call cm_elf,twin-cost-fig6_1mode-ram,cortex-m4f) \
                   cortex-m7:fig6:flash:$(call cm_elf,twin-cost-fig6,cortex-m7) \
                   cortex-m4f:fig6_fast:flash:$(call cm_elf,twin-cost-fig6_fast,cortex-m4f):$(TWIN_FAST_DT) \
                   cortex-m4f:fig6_fast:ram:$(call cm_elf,twin-cost-fig6_fast-ram,cortex-m4f):$(TWIN_FAST_DT)
# the friction estimate's cost (docs/twin.md, "Friction"): the 1 s stream without it and
# with it running at every update (gate open, deadband wide: mu, and so the trajectory, stay
# as without it, so that the brackets differ by the estimate alone)
$(call twin_image,twin-cost-friction-off,cortex-m4f,fig6,float,fig6-1s,sim,$(TWIN_COST_FLAGS))
$(call twin_image,twin-cost-friction-on,cortex-m4f,fig6,float,fig6-1s,sim,$(TWIN_COST_FLAGS) -DTWIN_FRICTION_GAIN=60 \
    -DTWIN_FRICTION_SIGMA=1.5 -DTWIN_FRICTION_AMPLITUDE=0 -DTWIN_FRICTION_CLIMB=0 -DTWIN_FRICTION_DEADBAND=1)
twin-friction-cost: $(if $(CM_TOOLS_OK),$(call cm_elf,twin-cost-friction-off,cortex-m4f) \
        $(call cm_elf,twin-cost-friction-on,cortex-m4f) $(TWIN_DIR)/fig6-1s.stream)
	$(if $(CM_TOOLS_OK),@sh host/reports/friction_cost.sh $(call cm_elf,twin-cost-friction-off,cortex-m4f) \
	    $(call cm_elf,twin-cost-friction-on,cortex-m4f),@echo "$(CM_TOOLS_MSG)")
twin-firmware-report-images: $(foreach c,$(TWIN_COST_SPECS),$(call emb_word,$c,4)) $(TWIN_DIR)/fig6-60s.stream \
        $(TWIN_DIR)/fast-60s.stream
twin-firmware-report:
	$(MAKE) --no-print-directory -j2 twin-firmware-report-images
	CM_OPT='$(CM_OPT)' CM_BUILD='$(CM_BUILD)' TWIN_FIFO_SAMPLES=1024 \
	    sh host/reports/twin_firmware_report.sh $(TWIN_DIR)/fig6-60s.csv $(TWIN_COST_SPECS)
.PHONY: twin-firmware-test twin-firmware-report twin-firmware-report-images
