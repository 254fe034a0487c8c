# tests/determinism.mk - the optimisation-level line of the determinism contract
# (docs/design.md section 11): the pinned state hashes of tests/test_golden.c
# from a core compiled at -O0 instead of CORE_OPT's -O3, in float, in a build tree
# of its own. (-O0 in double: tests/check_consumer.sh's CMake build of the core,
# in make test; -O2 and the Cortex-M's -O3: tests/check_embedded.sh.) The same
# core with one copy of its loops over the modes (BS_UNROLL_MODES=0,
# core/src/bs_inline.h, as the sanitizer builds compile it) must reach the
# same pins too. Part of `make test-long`: a build of the host library and
# the core, about 16 CPU-s.
DETERMINISM_BUILD := $(BUILD)/determinism-O0
.PHONY: determinism-opt
determinism-opt:
	@$(MAKE) --no-print-directory -j$(JOBS) BUILD=$(DETERMINISM_BUILD) REAL=float CORE_OPT='-O0 -DBS_UNROLL_MODES=0' \
	    $(DETERMINISM_BUILD)/float/tests/test_golden
	@echo "== determinism-opt: test_golden's pinned hashes from the core at -O0, its mode loops not unrolled (float)"
	@$(DETERMINISM_BUILD)/float/tests/test_golden
TEST_LONG += determinism-opt
