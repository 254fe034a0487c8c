# port/cortex-m/cortex-m.mk - bare-metal images for QEMU Cortex-M boards (GNU make fragment).
#
# Include it from a makefile whose working directory is the repository root:
#     include port/cortex-m/cortex-m.mk
#
# Interface
#   $(call cm_image,NAME,TARGET,SOURCES,CFLAGS)
#       Defines the rules for $(CM_BUILD)/TARGET/NAME.elf (e.g. build/cm/cortex-m4f/NAME.elf):
#       SOURCES (C files, paths relative to the repository root) + startup.c + bs_board.c,
#       each compiled with CM_CPU_TARGET, CM_CFLAGS, -Iport/cortex-m and CFLAGS (the image's own
#       -I and -D flags, may be empty), linked with CM_LDFLAGS and the target's memory map.
#       Also writes NAME.map beside the ELF, and per source NAME.obj/<path>.o, .su (stack use
#       per function, -fstack-usage) and .d. Objects are rebuilt when any flag changes.
#       Use it at the top level of a makefile: it $(eval)s its rules and expands to nothing.
#       It adds the ELF to no goal; depend on $(call cm_elf,NAME,TARGET). Each NAME/TARGET
#       pair may be defined once; variants with other -D flags need other NAMEs.
#   $(call cm_elf,NAME,TARGET)   the ELF's path
#   CM_TARGETS       cortex-m4f cortex-m7 cortex-m3 cortex-m0plus
#   CM_TOOLS_OK      1 if $(CM_CC) and $(CM_QEMU) are on PATH, else empty
#   CM_TOOLS_MSG     a one-line notice to print when skipping because CM_TOOLS_OK is empty
#   CM_RUN, CM_COUNT commands taking "ELF TARGET [TIMEOUT_S]" (run.sh here, tests/qemu/count.sh)
#   CM_CPU_<T>, CM_MACHINE_<T>, CM_MAP_<T>   per target: CPU flags, QEMU -M, memory map
#
# Example
#     include port/cortex-m/cortex-m.mk
#     $(call cm_image,bench,cortex-m4f,bench/main.c $(wildcard core/src/*.c),-Ibuild/mcu -Icore/include -Icore/src -Iport/embedded)
#     cm-bench: $(call cm_elf,bench,cortex-m4f)
#     	$(if $(CM_TOOLS_OK),$(CM_COUNT) $< cortex-m4f,@echo "$(CM_TOOLS_MSG)")
#
# Knobs: CM_BUILD (default $(BUILD)/cm, or build/cm), CM_CC, CM_QEMU, CM_OPT (-O3 -g -fno-schedule-insns -flto).
# The target table is repeated in run.sh (QEMU machine per target): keep both in step.

CM_DIR := $(patsubst %/,%,$(dir $(lastword $(MAKEFILE_LIST))))
CM_BUILD ?= $(if $(BUILD),$(BUILD),build)/cm
CM_CC ?= arm-none-eabi-gcc
CM_QEMU ?= qemu-system-arm
# -O3: with a compiled scene the loops over modes and contact rows have short, known
# lengths, which -O3 unrolls; the beamslider core then runs about 10 % (one mode) to 20 %
# (five modes) fewer instructions per step than at -O2, for 1.5-2.4 times the code
# (docs/embedded.md, "Optimisation level"). -fno-schedule-insns: GCC's scheduling before
# register allocation runs the unrolled sums of the contact problem out of the FPU's
# 32 registers (they spilled to the stack); without it the M4F step costs 4 % fewer
# estimated cycles (docs/embedded.md). -flto: the step's stages live in several files, and
# only at the link can GCC inline the contact problem, solve and application into the step,
# where their data stays in registers: 5.6 % fewer estimated cycles a step on the M4F
# (docs/design.md 4); the reports attribute the inlined code to its stage by its inline
# chain (tests/qemu/inline_names.sh)
CM_OPT ?= -O3 -g -fno-schedule-insns -flto

CM_TARGETS := cortex-m4f cortex-m7 cortex-m3 cortex-m0plus

# Single-precision FPU; double is software (libgcc).
CM_CPU_cortex-m4f := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
CM_MACHINE_cortex-m4f := mps2-an386
# Double-precision FPU.
CM_CPU_cortex-m7 := -mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16
CM_MACHINE_cortex-m7 := mps2-an500
# No FPU: float and double both in software.
CM_CPU_cortex-m3 := -mcpu=cortex-m3 -mthumb
CM_MACHINE_cortex-m3 := mps2-an385
# QEMU 7.2 has no M0+; ARMv6-M code runs unchanged on the AN385's Cortex-M3 (same counts as
# on the microbit's Cortex-M0, checked). The memory is the AN385's, far more than an M0+ has.
CM_CPU_cortex-m0plus := -mcpu=cortex-m0plus -mthumb
CM_MACHINE_cortex-m0plus := mps2-an385

# Memory map for cm.ld: CODE base/size (vector table at its base), DATA base/size.
cm__map = -Wl,--defsym=CODE_BASE=$1,--defsym=CODE_SIZE=$2,--defsym=DATA_BASE=$3,--defsym=DATA_SIZE=$4
# MPS2 AN385/AN386/AN500: 4 MiB SSRAM1 at 0 and 4 MiB SSRAM2/3 at 0x20000000.
CM_MAP_cortex-m4f := $(call cm__map,0x00000000,0x400000,0x20000000,0x400000)
CM_MAP_cortex-m7 := $(CM_MAP_cortex-m4f)
CM_MAP_cortex-m3 := $(CM_MAP_cortex-m4f)
CM_MAP_cortex-m0plus := $(CM_MAP_cortex-m4f)

# -std=c99 already implies -ffp-contract=off (no fused multiply-add): explicit, since
# host and target must round alike. -fno-math-errno makes sqrtf one vsqrt instruction.
CM_CFLAGS := -std=c99 $(CM_OPT) -Wall -Wextra -Werror -Wdouble-promotion -Wfloat-conversion \
             -Wundef -Wshadow -Wvla -ffunction-sections -fdata-sections -fno-math-errno \
             -ffp-contract=off -fstack-usage
# -nostartfiles: startup.c replaces rdimon's crt0. -u _printf_float: nano printf drops %f
# otherwise (prints nothing). rdimon: stdio, files and exit status over semihosting.
CM_LDFLAGS := -nostartfiles -T $(CM_DIR)/cm.ld -Wl,--gc-sections --specs=nano.specs \
              --specs=rdimon.specs -u _printf_float -lm
CM_PORT_SRC := $(CM_DIR)/startup.c $(CM_DIR)/bs_board.c

CM_TOOLS_OK := $(if $(and $(shell command -v $(CM_CC) 2>/dev/null),$(shell command -v $(CM_QEMU) 2>/dev/null)),1)
CM_TOOLS_MSG := cortex-m: skipped: needs $(CM_CC) and $(CM_QEMU) on PATH (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm)
CM_RUN = sh $(CM_DIR)/run.sh
CM_COUNT = CM_BUILD='$(CM_BUILD)' sh tests/qemu/count.sh

cm_elf = $(CM_BUILD)/$(strip $2)/$(strip $1).elf
cm_image = $(eval $(call cm__image,$(strip $1),$(strip $2),$(strip $3),$4))
cm__quote = '$(subst ','\'',$1)'

# $1 NAME, $2 TARGET, $3 SOURCES, $4 CFLAGS. The rules leave make's default goal as it was.
# The flags file holds every compile and link flag and is rewritten only when they change, so
# a changed flag rebuilds without `make clean`.
define cm__image
cm__saved_goal := $$(.DEFAULT_GOAL)
$(if $(CM_CPU_$2),,$(error cm_image: unknown TARGET '$2' for '$1' (one of: $(CM_TARGETS))))
$(if $(CM_FLAGS_$2_$1),$(error cm_image: $1 for $2 defined twice))
CM_OBJS_$2_$1 := $(patsubst %.c,$(CM_BUILD)/$2/$1.obj/%.o,$(CM_PORT_SRC) $3)
CM_FLAGS_$2_$1 := $(CM_CPU_$2) $(CM_CFLAGS) -I$(CM_DIR) $4
CM_LINK_$2_$1 := $(CM_LDFLAGS) $(CM_MAP_$2)

$(CM_BUILD)/$2/$1.elf: $$(CM_OBJS_$2_$1) $(CM_DIR)/cm.ld $(CM_BUILD)/$2/$1.obj/flags
	$$(CM_CC) $$(CM_FLAGS_$2_$1) -o $$@ $$(CM_OBJS_$2_$1) $$(CM_LINK_$2_$1) -Wl,-Map=$(CM_BUILD)/$2/$1.map

$$(CM_OBJS_$2_$1): $(CM_BUILD)/$2/$1.obj/%.o: %.c $(CM_BUILD)/$2/$1.obj/flags
	@mkdir -p $$(@D)
	$$(CM_CC) $$(CM_FLAGS_$2_$1) -MMD -MP -c -o $$@ $$<

$(CM_BUILD)/$2/$1.obj/flags: .cm_force
	@mkdir -p $$(@D)
	@printf '%s\n' $$(call cm__quote,$$(CM_FLAGS_$2_$1) $$(CM_LINK_$2_$1)) | cmp -s - $$@ || \
	 printf '%s\n' $$(call cm__quote,$$(CM_FLAGS_$2_$1) $$(CM_LINK_$2_$1)) > $$@

-include $$(CM_OBJS_$2_$1:.o=.d)
.DEFAULT_GOAL := $$(cm__saved_goal)
endef

.PHONY: .cm_force
.cm_force:
