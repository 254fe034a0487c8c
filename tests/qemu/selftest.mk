# tests/qemu/selftest.mk - builds the self-test images (selftest.sh runs this); also the
# smallest example of using cortex-m.mk. From the repository root:
#     make -f tests/qemu/selftest.mk [-j2]
# -> build/cm/<target>/selftest{,-fault,-hang}.elf for every target in CM_TARGETS.
SELFTEST_DIR := $(patsubst %/,%,$(dir $(lastword $(MAKEFILE_LIST))))
include port/cortex-m/cortex-m.mk

.PHONY: cm-selftest
cm-selftest:

# -fno-lto: selftest.sh reads a frame's size from the compiler's .su file, which a
# link-time-optimised object does not have (its code is generated at the link).
ST_SRC := $(SELFTEST_DIR)/selftest.c
$(foreach t,$(CM_TARGETS),\
  $(call cm_image,selftest,$t,$(ST_SRC),-fno-lto)\
  $(call cm_image,selftest-fault,$t,$(ST_SRC),-fno-lto -DBS_SELFTEST_FAULT=1)\
  $(call cm_image,selftest-hang,$t,$(ST_SRC),-fno-lto -DBS_SELFTEST_HANG=1))

cm-selftest: $(foreach t,$(CM_TARGETS),$(foreach n,selftest selftest-fault selftest-hang,$(call cm_elf,$n,$t)))
