# tests/robustness.mk - robustness checks (docs/robustness.md), included by
# the Makefile:
#
#   make fuzz             every libFuzzer target for FUZZ_SECONDS (60) each,
#                         corpus kept in $(BUILD)/fuzz/corpus; prints executions
#                         and coverage per target
#   make fuzz-coverage    line coverage of host/ and core/ reached by the
#                         seed and work corpora (llvm-cov)
#   make robustness-asan  the test suite (test-one, double) under
#                         AddressSanitizer + UndefinedBehaviorSanitizer
#   make robustness-valgrind  the test programs and the CLI under valgrind
#                         memcheck (test_sim: all but its two long runs)
#   make fuzz-short       a smoke run: every fuzz target for FUZZ_TEST_SECONDS (3)
#                         each, FUZZ_JOBS (2) at a time
#   make robustness-cli   regression checks of the CLI fixes and every real field
#                         at tiny and huge values, float and double
#
# `make test` runs robustness-cli, robustness-asan and fuzz-short (TEST_EXTRA);
# `make test-long` robustness-valgrind and fuzz (TEST_LONG). Knobs: FUZZ_CC (clang), ASAN_CC (gcc), FUZZ_SECONDS,
# FUZZ_TEST_SECONDS.

FUZZ_CC ?= clang
ASAN_CC ?= gcc
FUZZ_SECONDS ?= 60
FUZZ_TEST_SECONDS ?= 3
FUZZ_JOBS ?= 2
FUZZ_BUILD := $(BUILD)/fuzz
# fuzz_step_fig6_1mode, fuzz_step_fig6_frictionless: the core compiled against
# configs/NAME.h as in an embedded build (FUZZ_COMPILED: NAME:PRECISION)
FUZZ_COMPILED := fig6_1mode:float fig6_frictionless:double
FUZZ_TARGETS := fuzz_scene fuzz_step fuzz_step_float $(foreach c,$(FUZZ_COMPILED),fuzz_step_$(firstword $(subst :, ,$c)))
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZ_COV_PACKAGES := $(FUZZ_PACKAGES) llvm-14
ROBUSTNESS_PACKAGES := valgrind

# ---- libFuzzer targets ------------------------------------------------------
# Everything is built with clang, -fsanitize=fuzzer-no-link (coverage) plus
# ASan and UBSan (every UB check fatal); the harnesses with the project's
# warnings as errors. The libraries' own warnings are not errors here: clang
# warns where gcc does not (e.g. -Wdouble-promotion on INFINITY), and the
# project's warning gate is the gcc build.
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
FUZZ_BASE := -std=c99 -O1 -g -ffp-contract=off -fno-math-errno $(FUZZ_SAN) \
             -Icore/include -Icore/src -Iport -Iport/host $(HOST_INC) -Itests/fuzz -DFUZZ_CONFIGS='"$(CURDIR)/configs"'
FUZZ_LIB_WARNINGS := -Wall -Wextra -Wno-double-promotion
FUZZ_SRC := $(CORE_SRC) $(HOST_LIB_SRC)
FUZZ_HEADERS = $(wildcard core/*/*.h port/*.h port/host/*.h tests/fuzz/*.h) $(HOST_HEADERS)
# the build configuration of a precision (the host build's, Makefile)
fuzz_real_flag = -I$(BUILD)/$1/include

# fuzz_objects PRECISION: the library objects of one precision
fuzz_objects = $(FUZZ_SRC:%.c=$(FUZZ_BUILD)/$1/%.o)

define fuzz_precision_rules
$(FUZZ_BUILD)/$1/%.o: %.c $$(FUZZ_HEADERS) $(BUILD)/$1/include/bs_build_config.h | fuzz-deps
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) $$(FUZZ_BASE) $$(FUZZ_LIB_WARNINGS) $(call fuzz_real_flag,$1) -fsanitize=fuzzer-no-link -c -o $$@ $$<

$(FUZZ_BUILD)/$1/tests/fuzz/%.o: tests/fuzz/%.c $$(FUZZ_HEADERS) $(BUILD)/$1/include/bs_build_config.h | fuzz-deps
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) $$(FUZZ_BASE) $$(WARNINGS) $(call fuzz_real_flag,$1) -fsanitize=fuzzer-no-link -c -o $$@ $$<
endef
$(eval $(call fuzz_precision_rules,double))
$(eval $(call fuzz_precision_rules,float))

$(FUZZ_BUILD)/fuzz_scene: $(FUZZ_BUILD)/double/tests/fuzz/fuzz_scene.o $(call fuzz_objects,double)
	$(FUZZ_CC) $(FUZZ_BASE) -fsanitize=fuzzer -o $@ $^ $(HOST_LIBS)
$(FUZZ_BUILD)/fuzz_step: $(FUZZ_BUILD)/double/tests/fuzz/fuzz_step.o $(call fuzz_objects,double)
	$(FUZZ_CC) $(FUZZ_BASE) -fsanitize=fuzzer -o $@ $^ $(HOST_LIBS)
$(FUZZ_BUILD)/fuzz_step_float: $(FUZZ_BUILD)/float/tests/fuzz/fuzz_step.o $(call fuzz_objects,float)
	$(FUZZ_CC) $(FUZZ_BASE) -fsanitize=fuzzer -o $@ $^ $(HOST_LIBS)

# fuzz_compiled_rules SCENE PRECISION: the core and fuzz_step.c for one compiled scene
define fuzz_compiled_rules
$(FUZZ_BUILD)/$1-$2/%.o: %.c $$(FUZZ_HEADERS) configs/$1.h $(call emb_config_h,$1,$2,subspace) | fuzz-deps
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) -I$(EMB_CONFIG)/$1.$2.subspace $$(FUZZ_BASE) $$(FUZZ_LIB_WARNINGS) -I. \
	    -fsanitize=fuzzer-no-link -c -o $$@ $$<

$(FUZZ_BUILD)/$1-$2/tests/fuzz/%.o: tests/fuzz/%.c $$(FUZZ_HEADERS) configs/$1.h $(call emb_config_h,$1,$2,subspace) | fuzz-deps
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) -I$(EMB_CONFIG)/$1.$2.subspace $$(FUZZ_BASE) $$(WARNINGS) -I. \
	    -fsanitize=fuzzer-no-link -c -o $$@ $$<

$(FUZZ_BUILD)/fuzz_step_$1: $(FUZZ_BUILD)/$1-$2/tests/fuzz/fuzz_step.o $(CORE_SRC:%.c=$(FUZZ_BUILD)/$1-$2/%.o)
	$$(FUZZ_CC) $$(FUZZ_BASE) -fsanitize=fuzzer -o $$@ $$^ -lm
endef
$(foreach c,$(FUZZ_COMPILED),$(eval $(call fuzz_compiled_rules,$(firstword $(subst :, ,$c)),$(lastword $(subst :, ,$c)))))

# corpus/seed folder and dictionary of each target
fuzz_seeds = tests/fuzz/corpus/$(if $(filter fuzz_scene,$1),fuzz_scene,fuzz_step)
fuzz_dict = $(if $(filter fuzz_scene,$1),-dict=tests/fuzz/scene.dict)

# fuzz_run TARGET SECONDS: one bounded run; new inputs go to the work corpus
# in $(FUZZ_BUILD)/corpus, crashes to $(FUZZ_BUILD)/artifacts.
fuzz_run = sh tests/fuzz/run_fuzz.sh $(FUZZ_BUILD)/$1 $2 $(FUZZ_BUILD)/corpus/$1 $(call fuzz_seeds,$1) $(FUZZ_BUILD)/artifacts $(call fuzz_dict,$1)

.PHONY: fuzz fuzz-short fuzz-minute fuzz-build fuzz-coverage fuzz-deps robustness-asan robustness-valgrind robustness-deps \
        robustness-cli

fuzz-deps:
	@sh host/deps.sh $(FUZZ_PACKAGES)

fuzz-build: $(FUZZ_TARGETS:%=$(FUZZ_BUILD)/%)

fuzz: fuzz-build
	@set -e; $(foreach t,$(FUZZ_TARGETS),$(call fuzz_run,$t,$(FUZZ_SECONDS));)

# fuzz-short with FUZZ_SECONDS per target (`make test-long`)
fuzz-minute: fuzz-build
	@$(MAKE) --no-print-directory FUZZ_TEST_SECONDS=$(FUZZ_SECONDS) fuzz-short

fuzz-short: fuzz-build
	@$(MAKE) --no-print-directory -j$(FUZZ_JOBS) $(FUZZ_TARGETS:%=fuzz-short-%)

# one target's run of fuzz-short (each has its own corpus and artifacts)
fuzz-short-%: fuzz-build
	@$(call fuzz_run,$*,$(FUZZ_TEST_SECONDS))

# Line coverage of what the corpora reach: the targets rebuilt with clang's
# source-based coverage (no sanitizers), each corpus replayed once.
FUZZ_COV := $(BUILD)/fuzz-cov
FUZZ_COV_FLAGS := -std=c99 -O0 -g -ffp-contract=off -fno-math-errno -fprofile-instr-generate -fcoverage-mapping \
                  -Icore/include -Icore/src -Iport -Iport/host $(HOST_INC) -Itests/fuzz -DFUZZ_CONFIGS='"$(CURDIR)/configs"' -Wno-double-promotion
fuzz-coverage: $(BUILD)/double/include/bs_build_config.h
	@sh host/deps.sh $(FUZZ_COV_PACKAGES)
	@mkdir -p $(FUZZ_COV)
	$(FUZZ_CC) $(FUZZ_COV_FLAGS) -I$(BUILD)/double/include -fsanitize=fuzzer -o $(FUZZ_COV)/fuzz_scene tests/fuzz/fuzz_scene.c $(FUZZ_SRC) $(HOST_LIBS)
	$(FUZZ_CC) $(FUZZ_COV_FLAGS) -I$(BUILD)/double/include -fsanitize=fuzzer -o $(FUZZ_COV)/fuzz_step tests/fuzz/fuzz_step.c $(FUZZ_SRC) $(HOST_LIBS)
	@set -e; for t in fuzz_scene fuzz_step; do \
	    seeds=tests/fuzz/corpus/fuzz_step; [ $$t = fuzz_scene ] && seeds=tests/fuzz/corpus/fuzz_scene; \
	    mkdir -p $(FUZZ_BUILD)/corpus/$$t; \
	    LLVM_PROFILE_FILE=$(FUZZ_COV)/$$t.profraw $(FUZZ_COV)/$$t -runs=0 $(FUZZ_BUILD)/corpus/$$t $$seeds >/dev/null 2>&1; \
	    llvm-profdata-14 merge -sparse -o $(FUZZ_COV)/$$t.profdata $(FUZZ_COV)/$$t.profraw; \
	    echo "== $$t: line coverage of the sources it exercises (seed + work corpus)"; \
	    llvm-cov-14 report $(FUZZ_COV)/$$t -instr-profile=$(FUZZ_COV)/$$t.profdata \
	        $$( [ $$t = fuzz_scene ] && echo host/lib/scene/scene_ini.c host/lib/scene/scene_build.c host/lib/scene/modal.c host/lib/scene/shape_fit.c core/src/bs_scene.c core/src/bs_sim.c \
	                              || echo core/src/*.c ); \
	done

# ---- the test suite under ASan + UBSan -------------------------------------
# A separate build tree ($(BUILD)/asan); test-one runs the CMocka programs and
# the shell checks on the instrumented binaries. check_core_symbols reads the
# objects through tests/fuzz/nm_sanitized.sh, which hides the sanitizer
# run-time's own symbols (__asan_*, __ubsan_*).
ASAN_CFLAGS := -O1 -g -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer
ASAN_ENV := ASAN_OPTIONS=detect_leaks=1:fast_unwind_on_malloc=0:strict_string_checks=1:detect_stack_use_after_return=1 \
            UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 NM='sh $(CURDIR)/tests/fuzz/nm_sanitized.sh'

robustness-asan:
	@echo "== robustness-asan: test-one (double) under -fsanitize=address,undefined ($(ASAN_CC))"
	@$(ASAN_ENV) $(MAKE) --no-print-directory BUILD=$(BUILD)/asan CC=$(ASAN_CC) CFLAGS='$(ASAN_CFLAGS)' REAL=double test-one
	@echo "robustness-asan: ok"

# ---- valgrind memcheck -----------------------------------------------------
# The double test programs of the normal build and a few CLI runs.
# test_sim runs as tests/fuzz/vg_test_sim.c (the same source, without the
# 30e6-step phase test and the 1e6-step drift test, about 150 s under
# valgrind); everything else runs whole.
VG := valgrind -q --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible
VG_TESTS := $(filter-out test_sim,$(TESTS))
VG_OBJ := $(BUILD)/double

$(VG_OBJ)/tests/fuzz/vg_test_sim: tests/fuzz/vg_test_sim.c tests/test_sim.c $(VG_OBJ)/tests/support.o \
        $(HOST_LIB_SRC:%.c=$(VG_OBJ)/%.o) $(CORE_SRC:%.c=$(VG_OBJ)/%.o) | deps-test
	@mkdir -p $(dir $@)
	$(CC) -O2 -g $(BASE_CFLAGS) -I$(VG_OBJ)/include -Icore/include -Icore/src -Iport -Iport/host $(HOST_INC) -Itests \
	    -o $@ tests/fuzz/vg_test_sim.c $(filter %.o,$^) $(TEST_LIBS)

robustness-deps:
	@sh host/deps.sh $(ROBUSTNESS_PACKAGES)

robustness-valgrind: robustness-deps
	@$(MAKE) --no-print-directory REAL=double $(VG_TESTS:%=$(VG_OBJ)/tests/%) $(VG_OBJ)/beamslider \
	    $(VG_OBJ)/tests/fuzz/vg_test_sim
	@echo "== robustness-valgrind: valgrind memcheck ($(words $(VG_TESTS)) test programs + test_sim subset + CLI)"
	@set -e; for t in $(VG_TESTS:%=$(VG_OBJ)/tests/%) $(VG_OBJ)/tests/fuzz/vg_test_sim; do \
	    start=$$(date +%s); \
	    $(VG) --log-file=$(VG_OBJ)/valgrind.log ./$$t >$(VG_OBJ)/valgrind.out 2>&1 \
	        || { cat $(VG_OBJ)/valgrind.out $(VG_OBJ)/valgrind.log; echo "robustness-valgrind: FAIL: $$t"; exit 1; }; \
	    [ ! -s $(VG_OBJ)/valgrind.log ] || { cat $(VG_OBJ)/valgrind.log; echo "robustness-valgrind: FAIL: $$t"; exit 1; }; \
	    echo "ok   - valgrind $$t ($$(( $$(date +%s) - start )) s)"; \
	done
	@sh tests/fuzz/valgrind_cli.sh $(VG_OBJ)/beamslider
	@echo "robustness-valgrind: ok"

# ---- regression checks of the CLI fixes (docs/robustness.md) -----------------
robustness-cli:
	@$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	@$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	@sh tests/fuzz/check_robustness_cli.sh $(BUILD)/double/beamslider
	@sh tests/fuzz/check_robustness_cli.sh $(BUILD)/float/beamslider
	@sh tests/fuzz/check_extreme_values.sh $(BUILD)/double/beamslider
	@sh tests/fuzz/check_extreme_values.sh $(BUILD)/float/beamslider

TEST_EXTRA += robustness-cli robustness-asan fuzz-short
TEST_LONG += robustness-valgrind fuzz-minute
