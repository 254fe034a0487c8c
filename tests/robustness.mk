# tests/robustness.mk - robustness checks (docs/robustness.md), included by
# the Makefile:
#
#   make fuzz             every libFuzzer target for FUZZ_SECONDS (60) each,
#                         corpus kept in $(BUILD)/fuzz/corpus; prints executions
#                         and coverage per target
#   make fuzz-short       a smoke run of five double targets: its seed corpus, then up
#                         to FUZZ_SHORT_RUNS (300) executions or
#                         FUZZ_TEST_SECONDS (1), FUZZ_JOBS (2) targets at a time
#   make fuzz-minute      every target for FUZZ_SECONDS (60), FUZZ_JOBS at a time
#   make fuzz-long        every target for FUZZ_LONG_RUNS (1000000) executions,
#                         FUZZ_JOBS at a time, under nice (not in CI: hours)
#   make fuzz-coverage    line coverage of host/ and core/ reached by the
#                         seed and work corpora (llvm-cov)
#   make robustness-asan  the test suite (test-one, double) under
#                         AddressSanitizer + UndefinedBehaviorSanitizer
#   make robustness-asan-smoke  the CLI on the crafted inputs of
#                         check_robustness_cli.sh, and the readers' unit tests,
#                         under the same sanitizers, linked from the fuzz
#                         build's objects (clang; one sanitized build in make test)
#   make robustness-valgrind  the test programs and the CLI under valgrind
#                         memcheck (test_sim, test_observer, test_contact:
#                         without their longest cases, VG_SUBSET)
#   make robustness-cli   regression checks of the CLI fixes (float and double)
#                         and every real field at tiny and huge values (double;
#                         robustness-cli-float: float, in make test-long)
#
# `make test` runs robustness-cli, robustness-asan-smoke and fuzz-short
# (TEST_EXTRA); `make test-long` robustness-asan, robustness-cli-float,
# robustness-valgrind and fuzz-minute (TEST_LONG). Knobs:
# FUZZ_CC (clang), ASAN_CC (gcc), FUZZ_SECONDS, FUZZ_TEST_SECONDS,
# FUZZ_SHORT_RUNS, FUZZ_LONG_RUNS, FUZZ_JOBS.

FUZZ_CC ?= clang
ASAN_CC ?= gcc
FUZZ_SECONDS ?= 60
FUZZ_TEST_SECONDS ?= 1
FUZZ_SHORT_RUNS ?= 300
FUZZ_LONG_RUNS ?= 1000000
FUZZ_JOBS ?= 2
FUZZ_BUILD := $(BUILD)/fuzz
FUZZ_OPT := -O1
# make test's sanitizer smoke (fuzz-short, robustness-asan-smoke): the same
# rules in a tree of their own at -O0, which compiles in half the time of
# -O1 (a fresh clone's budget), and with one copy of the core's loops over
# the modes (BS_UNROLL_MODES=0, core/src/bs_inline.h: bs_contact.c in 1.7
# CPU-s instead of 9); its runs are short, so their speed matters little.
# fuzz-minute and fuzz-long use $(FUZZ_BUILD) at -O1, unrolled as shipped.
SANITIZED := $(BUILD)/sanitized
SANITIZED_MAKE = $(MAKE) --no-print-directory FUZZ_BUILD=$(SANITIZED) FUZZ_OPT='-O0 -DBS_UNROLL_MODES=0'
# The targets on the host library and the core, tests/fuzz/NAME.c, in double,
# and those also built in float (NAME_float).
FUZZ_DOUBLE := fuzz_scene fuzz_scene_set fuzz_excitation fuzz_measured fuzz_map fuzz_step fuzz_api
FUZZ_FLOAT := fuzz_step fuzz_api
# fuzz_step_fig6_1mode, fuzz_step_fig6_frictionless: the core compiled against
# configs/NAME.h as in an embedded build (FUZZ_COMPILED: NAME:PRECISION)
FUZZ_COMPILED := fig6_1mode:float fig6_frictionless:double
FUZZ_TARGETS := $(FUZZ_DOUBLE) $(FUZZ_FLOAT:%=%_float) \
                $(foreach c,$(FUZZ_COMPILED),fuzz_step_$(firstword $(subst :, ,$c)))
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
FUZZ_BASE := -std=c99 $(FUZZ_OPT) -g -ffp-contract=off -fno-math-errno $(FUZZ_SAN) \
             -Icore/include -Icore/src -Iport -Iport/host $(HOST_INC) -Itests/fuzz -I$(FUZZ_BUILD)/include \
             -DFUZZ_CONFIGS='"$(CURDIR)/configs"'
FUZZ_LIB_WARNINGS := -Wall -Wextra -Wno-double-promotion
FUZZ_SRC := $(CORE_SRC) $(HOST_LIB_SRC)
FUZZ_HEADERS = $(wildcard core/*/*.h port/*.h port/host/*.h tests/fuzz/*.h) $(HOST_HEADERS)
# the build configuration of a precision (the host build's, Makefile)
fuzz_real_flag = -I$(BUILD)/$1/include

# fuzz_objects PRECISION: the library objects of one precision; the test and
# fuzz programs take the revision's order-only (fuzz_revision: a commit
# changes it, and they publish it nowhere; the Makefile's test programs alike)
fuzz_objects = $(FUZZ_SRC:%.c=$(FUZZ_BUILD)/$1/%.o)
fuzz_revision = $(FUZZ_BUILD)/$1/host/lib/scene/source_revision.o
fuzz_objects_but_revision = $(filter-out $(call fuzz_revision,$1),$(call fuzz_objects,$1))

# The source revision the host library states (host/lib/scene/source_revision.c), for
# both precisions: the Makefile makes it only for the REAL of the make.
$(FUZZ_BUILD)/include/bs_revision.h: .force
	@mkdir -p $(dir $@)
	@printf '/* generated by make: the source revision of this build */\n#define BS_REVISION "%s"\n' '$(REVISION)' > $@.tmp.$$$$; \
	    if cmp -s $@.tmp.$$$$ $@; then rm -f $@.tmp.$$$$; else mv $@.tmp.$$$$ $@; fi

define fuzz_precision_rules
$(FUZZ_BUILD)/$1/%.o: %.c $$(FUZZ_HEADERS) $(BUILD)/$1/include/bs_build_config.h | fuzz-deps
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) $$(FUZZ_BASE) $$(FUZZ_LIB_WARNINGS) $(call fuzz_real_flag,$1) -fsanitize=fuzzer-no-link -c -o $$@ $$<

$(FUZZ_BUILD)/$1/tests/fuzz/%.o: tests/fuzz/%.c $$(FUZZ_HEADERS) $(BUILD)/$1/include/bs_build_config.h | fuzz-deps
	@mkdir -p $$(dir $$@)
	$$(FUZZ_CC) $$(FUZZ_BASE) $$(WARNINGS) $(call fuzz_real_flag,$1) -fsanitize=fuzzer-no-link -c -o $$@ $$<

$(FUZZ_BUILD)/$1/host/lib/scene/source_revision.o: $(FUZZ_BUILD)/include/bs_revision.h
endef
$(eval $(call fuzz_precision_rules,double))
$(eval $(call fuzz_precision_rules,float))

# fuzz_link TARGET PRECISION SOURCE: tests/fuzz/SOURCE.c with the host library and the core
define fuzz_link
$(FUZZ_BUILD)/$1: $(FUZZ_BUILD)/$2/tests/fuzz/$3.o $(call fuzz_objects_but_revision,$2) | $(call fuzz_revision,$2)
	$$(FUZZ_CC) $$(FUZZ_BASE) -fsanitize=fuzzer -o $$@ $$^ $(call fuzz_revision,$2) $$(HOST_LIBS)
endef
$(foreach t,$(FUZZ_DOUBLE),$(eval $(call fuzz_link,$t,double,$t)))
$(foreach t,$(FUZZ_FLOAT),$(eval $(call fuzz_link,$t_float,float,$t)))

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

# The seed corpus of each target (tests/fuzz/corpus/NAME, committed): the
# step targets share fuzz_step's, a float target its double's. Dictionaries:
# tests/fuzz/dict/NAME.dict where there is one (the words of a format).
fuzz_seed_name = $(if $(filter fuzz_step%,$1),fuzz_step,$(if $(filter fuzz_scene%,$1),fuzz_scene,$(1:%_float=%)))
fuzz_seeds = tests/fuzz/corpus/$(if $(filter fuzz_scene_set,$1),fuzz_scene_set,$(call fuzz_seed_name,$1))
fuzz_dict = $(addprefix -dict=,$(wildcard tests/fuzz/dict/$(call fuzz_seed_name,$1).dict))

# fuzz_run TARGET SECONDS WORK [OPTION...]: one bounded run; new inputs go to
# the work corpus WORK, crashes to $(FUZZ_BUILD)/artifacts.
fuzz_run = sh tests/fuzz/run_fuzz.sh $(FUZZ_BUILD)/$1 $2 $3 $(call fuzz_seeds,$1) $(FUZZ_BUILD)/artifacts $(call fuzz_dict,$1) $4

.PHONY: fuzz fuzz-short fuzz-minute fuzz-long fuzz-build fuzz-coverage fuzz-deps robustness-asan robustness-asan-smoke robustness-valgrind \
        robustness-deps robustness-cli robustness-cli-float

fuzz-deps:
	@sh host/deps.sh $(FUZZ_PACKAGES)

fuzz-build: $(FUZZ_TARGETS:%=$(FUZZ_BUILD)/%)

fuzz: fuzz-build
	@set -e; $(foreach t,$(FUZZ_TARGETS),$(call fuzz_run,$t,$(FUZZ_SECONDS),$(FUZZ_BUILD)/corpus/$t);)

# The smoke run of `make test`: from the seeds alone (a fresh work corpus, so
# that its cost does not grow with the corpora of longer runs).
# Five double targets, one per kind of input (one build of the library for
# them; the others, and the float and compiled-scene builds, are fuzz-minute's
# in make test-long), to keep a fresh clone's make test within its budget.
FUZZ_SHORT := fuzz_scene fuzz_excitation fuzz_measured fuzz_step fuzz_api
fuzz-short:
	@$(SANITIZED_MAKE) -j$(JOBS) $(FUZZ_SHORT:%=$(SANITIZED)/%)
	@$(SANITIZED_MAKE) -j$(FUZZ_JOBS) $(FUZZ_SHORT:%=fuzz-short-%)

fuzz-short-%: $(FUZZ_BUILD)/%
	@rm -rf $(FUZZ_BUILD)/short/$*
	@$(call fuzz_run,$*,$(FUZZ_TEST_SECONDS),$(FUZZ_BUILD)/short/$*,-runs=$(FUZZ_SHORT_RUNS))

# FUZZ_SECONDS of every target, on the kept work corpus (`make test-long`)
fuzz-minute:
	@$(MAKE) --no-print-directory -j$(JOBS) fuzz-build
	@$(MAKE) --no-print-directory -j$(FUZZ_JOBS) $(FUZZ_TARGETS:%=fuzz-minute-%)

fuzz-minute-%: fuzz-build
	@$(call fuzz_run,$*,$(FUZZ_SECONDS),$(FUZZ_BUILD)/corpus/$*)

# FUZZ_LONG_RUNS executions of every target (a release's campaign, not in CI;
# docs/robustness.md reports its figures). The machine is shared: nice, and
# FUZZ_JOBS targets at a time, each to its end whatever the others find.
# fuzz_api's log ends with how often each of restore's rules decided, which
# is printed too.
fuzz-long: fuzz-build
	@echo "fuzz-long: $(words $(FUZZ_TARGETS)) targets x $(FUZZ_LONG_RUNS) executions, $(FUZZ_JOBS) at a time (hours)"
	@$(MAKE) --no-print-directory -k -j$(FUZZ_JOBS) $(FUZZ_TARGETS:%=fuzz-long-%)

fuzz-long-%: fuzz-build
	@FUZZ_SHOW_RULES=1 nice $(call fuzz_run,$*,0,$(FUZZ_BUILD)/corpus/$*,-runs=$(FUZZ_LONG_RUNS))

# Line coverage of what the corpora reach: the double targets rebuilt with
# clang's source-based coverage (no sanitizers), each corpus (seeds and work)
# replayed once, reported over the sources the target is about.
FUZZ_COV := $(BUILD)/fuzz-cov
FUZZ_COV_FLAGS := -std=c99 -O0 -g -ffp-contract=off -fno-math-errno -fprofile-instr-generate -fcoverage-mapping \
                  -Icore/include -Icore/src -Iport -Iport/host $(HOST_INC) -Itests/fuzz -I$(FUZZ_BUILD)/include \
                  -DFUZZ_CONFIGS='"$(CURDIR)/configs"' -Wno-double-promotion
FUZZ_COV_SCENE := host/lib/scene/scene_ini.c host/lib/scene/scene_build.c host/lib/scene/modal.c host/lib/scene/shape_fit.c \
                  core/src/bs_scene.c core/src/bs_sim.c
fuzz_cov_sources = $(strip \
    $(if $(filter fuzz_scene fuzz_scene_set,$1),$(FUZZ_COV_SCENE)) \
    $(if $(filter fuzz_excitation,$1),host/lib/run/excitation_file.c host/lib/io/input_file.c) \
    $(if $(filter fuzz_measured,$1),host/lib/twin/measured_signals.c host/lib/io/input_file.c) \
    $(if $(filter fuzz_map,$1),host/lib/map/map_store.c host/lib/map/map_case.c host/lib/map/map_table.c host/lib/io/input_file.c) \
    $(if $(filter fuzz_step fuzz_api,$1),core/src/*.c))

fuzz-coverage: $(BUILD)/double/include/bs_build_config.h $(FUZZ_BUILD)/include/bs_revision.h
	@sh host/deps.sh $(FUZZ_COV_PACKAGES)
	@mkdir -p $(FUZZ_COV)
	@set -e; $(foreach t,$(FUZZ_DOUBLE),\
	    $(FUZZ_CC) $(FUZZ_COV_FLAGS) -I$(BUILD)/double/include -fsanitize=fuzzer -o $(FUZZ_COV)/$t tests/fuzz/$t.c \
	        $(FUZZ_SRC) $(HOST_LIBS); \
	    mkdir -p $(FUZZ_BUILD)/corpus/$t; \
	    LLVM_PROFILE_FILE=$(FUZZ_COV)/$t.profraw $(FUZZ_COV)/$t -runs=0 $(FUZZ_BUILD)/corpus/$t $(call fuzz_seeds,$t) \
	        >/dev/null 2>&1; \
	    llvm-profdata-14 merge -sparse -o $(FUZZ_COV)/$t.profdata $(FUZZ_COV)/$t.profraw; \
	    echo "== $t: line coverage of the sources it is about (seed + work corpus)"; \
	    llvm-cov-14 report $(FUZZ_COV)/$t -instr-profile=$(FUZZ_COV)/$t.profdata $(call fuzz_cov_sources,$t);)

# ---- the test suite under ASan + UBSan -------------------------------------
# A separate build tree ($(BUILD)/asan); test-one runs the CMocka programs and
# the shell checks on the instrumented binaries. check_core_symbols reads the
# objects through tests/fuzz/nm_sanitized.sh, which hides the sanitizer
# run-time's own symbols (__asan_*, __ubsan_*). One copy of the core's loops
# over the modes (BS_UNROLL_MODES=0): instrumented at the core's -O3, the
# nine of bs_contact.c take 48 CPU-s to compile, one 2.3 (and the CLI's -flto
# link compiles them again); the fuzz targets run the unrolled copies
# (fuzz-minute).
ASAN_CFLAGS := -O1 -g -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer \
               -DBS_UNROLL_MODES=0
ASAN_ENV := ASAN_OPTIONS=detect_leaks=1:fast_unwind_on_malloc=0:strict_string_checks=1:detect_stack_use_after_return=1 \
            UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 NM='sh $(CURDIR)/tests/fuzz/nm_sanitized.sh'

ASAN_MAKE = $(MAKE) --no-print-directory BUILD=$(BUILD)/asan CC=$(ASAN_CC) CFLAGS='$(ASAN_CFLAGS)' REAL=double
robustness-asan:
	@echo "== robustness-asan: test-one (double) under -fsanitize=address,undefined ($(ASAN_CC)), with the long cases"
	@$(ASAN_ENV) BS_TEST_LONG=1 $(ASAN_MAKE) -j$(JOBS) test-one
	@echo "robustness-asan: ok"

# The smoke of `make test` (the whole suite under the sanitizers costs about
# 180 CPU-s: make test-long): the instrumented CLI on the crafted inputs of the
# regressions (exit status, message, no output, inputs unchanged, and now no
# sanitizer report), and the unit tests of the readers and of restore. Linked
# from the objects fuzz-short builds anyway ($(SANITIZED): clang, ASan +
# UBSan, -O0; the fuzzer's coverage hooks are no-ops without libFuzzer), so
# that make test compiles the host library under the sanitizers once, not
# twice; robustness-asan keeps gcc's sanitizers.
ASAN_SMOKE_TESTS := test_input_file test_excitation_file test_measured test_checkpoint test_out test_map test_api
ASAN_SMOKE := $(SANITIZED)/smoke
$(FUZZ_BUILD)/double/tests/%.o $(FUZZ_BUILD)/double/host/cli/%.o: FUZZ_BASE += -Itests -Ihost/cli
$(FUZZ_BUILD)/double/tests/%.o: $(wildcard tests/*.h) | deps-test
$(FUZZ_BUILD)/smoke/beamslider: $(HOST_CLI_SRC:%.c=$(FUZZ_BUILD)/double/%.o) $(call fuzz_objects,double)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_BASE) -o $@ $^ $(HOST_LIBS)
$(FUZZ_BUILD)/smoke/%: $(FUZZ_BUILD)/double/tests/%.o $(FUZZ_BUILD)/double/tests/support.o \
        $(call fuzz_objects_but_revision,double) | $(call fuzz_revision,double)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_BASE) -o $@ $^ $(call fuzz_revision,double) $(TEST_LIBS)
robustness-asan-smoke:
	@$(SANITIZED_MAKE) -j$(JOBS) $(ASAN_SMOKE)/beamslider $(ASAN_SMOKE_TESTS:%=$(ASAN_SMOKE)/%)
	@echo "== robustness-asan-smoke: the CLI's crafted inputs and the readers' tests under -fsanitize=address,undefined ($(FUZZ_CC))"
	@set -e; for t in $(ASAN_SMOKE_TESTS); do echo "== $$t (ASan)"; $(ASAN_ENV) $(ASAN_SMOKE)/$$t >/dev/null; done
	@$(ASAN_ENV) sh tests/fuzz/check_robustness_cli.sh $(ASAN_SMOKE)/beamslider
	@echo "robustness-asan-smoke: ok"

# ---- valgrind memcheck -----------------------------------------------------
# The double test programs of the normal build and a few CLI runs.
VG := valgrind -q --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible
# The test programs run under valgrind whole, but VG_SUBSET: those without
# their longest cases (tests/fuzz/vg_NAME.c, the same source without the
# cases it lists and says why; docs/robustness.md section 1). Each of those
# runs natively first, saving its observer designs, which its run under
# valgrind reads back (tests/fuzz/vg_short_maps.h).
VG_SUBSET := test_sim test_observer test_contact test_friction test_shape
VG_TESTS := $(filter-out $(VG_SUBSET),$(TESTS))
VG_OBJ := $(BUILD)/double

$(VG_OBJ)/tests/fuzz/vg_%: tests/fuzz/vg_%.c tests/%.c tests/fuzz/vg_subset.h tests/fuzz/vg_short_maps.h $(VG_OBJ)/tests/support.o \
        $(HOST_LIB_SRC:%.c=$(VG_OBJ)/%.o) $(CORE_SRC:%.c=$(VG_OBJ)/%.o) | deps-test
	@mkdir -p $(dir $@)
	$(CC) -O2 -g $(BASE_CFLAGS) -I$(VG_OBJ)/include -Icore/include -Icore/src -Iport -Iport/host $(HOST_INC) -Itests \
	    -o $@ $< $(filter %.o,$^) $(TEST_LIBS)

robustness-deps:
	@sh host/deps.sh $(ROBUSTNESS_PACKAGES)

robustness-valgrind: robustness-deps
	@$(MAKE) --no-print-directory -j$(JOBS) REAL=double $(VG_TESTS:%=$(VG_OBJ)/tests/%) $(VG_OBJ)/beamslider \
	    $(VG_SUBSET:%=$(VG_OBJ)/tests/fuzz/vg_%)
	@echo "== robustness-valgrind: valgrind memcheck ($(words $(VG_TESTS)) test programs + subsets of $(VG_SUBSET) + CLI)"
	@set -e; mkdir -p $(VG_OBJ)/vg_gains; \
	for t in $(VG_SUBSET:%=$(VG_OBJ)/tests/fuzz/vg_%) $(VG_TESTS:%=$(VG_OBJ)/tests/%); do \
	    start=$$(date +%s); gains=$(VG_OBJ)/vg_gains/$$(basename $$t); \
	    case $$t in */fuzz/vg_*) VG_GAINS_SAVE=$$gains ./$$t >$(VG_OBJ)/valgrind.out 2>&1 \
	        || { cat $(VG_OBJ)/valgrind.out; echo "robustness-valgrind: FAIL: $$t (natively, saving its designs)"; exit 1; } ;; \
	    *) gains= ;; esac; \
	    VG_GAINS_LOAD=$$gains $(VG) --log-file=$(VG_OBJ)/valgrind.log ./$$t >$(VG_OBJ)/valgrind.out 2>&1 \
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

# Every real field at tiny and huge values in float too (`make test-long`:
# about 10 CPU-s of process start-ups; the refusals are the host's, in double
# whatever the core's precision)
robustness-cli-float:
	@$(MAKE) --no-print-directory -j$(JOBS) REAL=float $(BUILD)/float/beamslider
	@sh tests/fuzz/check_extreme_values.sh $(BUILD)/float/beamslider

TEST_EXTRA += robustness-cli robustness-asan-smoke fuzz-short
TEST_LONG += robustness-asan robustness-cli-float robustness-valgrind fuzz-minute
