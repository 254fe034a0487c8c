# host/reports/reports.mk - the report targets: each regenerates a page of docs/
# from the code (README.md, "Reports"). Included by the top-level Makefile.
#
#   make fig6-report    the signature move in numbers -> docs/validation.md section 5
#   make accuracy       error against run time vs the reference -> docs/accuracy.md
#   make stability      the stiff and extreme cases -> docs/stability.md
#   make bench [BENCH_BASELINE=COMMIT]
#                       steps per CPU second, paired runs of this tree and the commit
#                       (0.7.0's by default) -> docs/performance.md
#   make twin-report    the twin in closed loop against the independent reference as
#                       plant (perturbed, noisy signals) -> docs/twin.md, "Closed loop"
#   make twin-ceiling-maps  the fig8 ceiling once more with its response maps designed at
#                       the plant's friction -> docs/twin.md, "The ceiling with its maps"
#   make twin-step      the high branch's climb against friction at two steps, and the fig8
#                       plants with the twin at 2e-5 s and 1e-5 s -> docs/twin.md,
#                       "The twin's step under friction"
#   make twin-fast      the first fig6 plants with the twin at 2e-5 s and at 3.125e-5 s
#                       prewarped (the step that keeps pace on a 168 MHz M4F) ->
#                       docs/twin.md, "The twin at a coarser step"
#   make twin-walk-cost the walk's cost on the Cortex-M4F (pessimistic cycles a sample:
#                       host/reports/friction_cost.sh) -> docs/twin.md, "Cost"
#   make harvester-report  harvested power over a load sweep, self-tuning under
#                       electrical damping, a moving ambient frequency -> docs/harvester.md
#   make baseline-check [BASELINE=COMMIT|this] [THIS_ARGS='run options'] [OUT=docs/x.md] [TOLERANCE=2]
#                       the slow dynamics of fig6 over 512-run ensembles, this tree
#                       (with THIS_ARGS) against the commit (0.7.0's by default) or,
#                       BASELINE=this, against itself without THIS_ARGS
#                       -> docs/baseline.md
#   make maps           the operating map over f_ex x a (1,530 runs of 120 s, 3 starts per
#                       point; about 30-50 min on 2 cores; resumable) -> docs/maps.md and
#                       docs/figures/map_*.png (host/reports/maps_report.sh; the map in
#                       build/maps/mssp2023)
#   make figures        PCS sweeps and free runs of the papers' figures (double,
#                       all cores) -> docs/figures/*.png and the tables of
#                       docs/validation.md section 7 (host/reports/figures/figures.sh;
#                       CSVs in build/figures/); JOBS=1 gives the same on one core
#
# `make test` also runs sweep-check (host/reports/figures/check_sweep.sh).

.PHONY: fig6-report accuracy stability bench baseline-check harvester-report twin-report twin-ceiling-maps twin-step twin-fast twin-walk-cost figures \
        sweep-check deps-figures \
        provenance-builds

# Every report stamps what it writes with the state hashes of both precisions'
# CLI (host/reports/provenance.sh), and a page of measured cost with the compiler
# and flags, which make passes to the scripts here.
REPORTS := fig6-report accuracy stability bench baseline-check harvester-report twin-report twin-ceiling-maps twin-step twin-fast figures maps \
           embedded-report twin-firmware-report
export PROVENANCE_CC := $(strip $(CC))
export PROVENANCE_CFLAGS := $(strip $(CFLAGS))
export PROVENANCE_CORE_OPT := $(strip $(CORE_OPT) $(CORE_LTO))
export PROVENANCE_CM_CC := $(strip $(CM_CC))
export PROVENANCE_CM_OPT := $(strip $(CM_OPT))
$(REPORTS): provenance-builds
provenance-builds:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider

fig6-report:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/reports/fig6_report.sh

$(OBJ)/bs-stability: host/reports/stability.c $(HOST_LIB_OBJ) $(CORE_OBJ)
	$(CC) $(CFLAGS) $(HOST_CFLAGS) -o $@ $^ $(HOST_LIBS)

accuracy: $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/reports/accuracy.sh

stability:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/bs-stability
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/bs-stability
	sh host/reports/stability_report.sh $(BUILD)/double/bs-stability $(BUILD)/float/bs-stability

bench:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	$(MAKE) --no-print-directory python
	$(if $(BENCH_BASELINE),BENCH_BASELINE=$(BENCH_BASELINE)) sh host/reports/bench.sh

harvester-report: deps-figures
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/reports/harvester_report.sh

twin-report: deps-figures $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	sh host/reports/twin_report.sh

twin-ceiling-maps: $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/reports/twin_ceiling_maps.sh

twin-step: $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/reports/twin_step.sh

twin-fast: $(BUILD)/bs-reference
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	sh host/reports/twin_fast.sh

BASELINE ?= 2326ca8
baseline-check:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	$(MAKE) --no-print-directory REAL=float $(BUILD)/float/beamslider
	$(if $(OUT),OUT=$(OUT)) $(if $(THIS_ARGS),THIS_ARGS='$(THIS_ARGS)') $(if $(TOLERANCE),TOLERANCE=$(TOLERANCE)) \
	    sh host/reports/baseline_check.sh $(BASELINE)

figures: deps-figures
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	BIN=$(BUILD)/double/beamslider DATA=$(BUILD)/figures $(if $(JOBS),JOBS=$(JOBS)) sh host/reports/figures/figures.sh

maps: deps-figures
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	BIN=$(BUILD)/double/beamslider DIR=$(BUILD)/maps/mssp2023 $(if $(JOBS),JOBS=$(JOBS)) sh host/reports/maps_report.sh

# The walk's cost, as make twin-friction-cost counts the law's (tests/embedded/twin.mk):
# the twin firmware on the 1 s fig6 stream with the walk (k = 4) running at every update,
# its gates open, at a gain (1e-30 /s) that leaves mu, and so the trajectory, as without
# it: mu (1 + gain e dt) rounds to mu in float. Here rather than beside the law's image,
# whose makefile is among the sources of docs/embedded.md's step report.
$(call twin_image,twin-cost-friction-walk,cortex-m4f,fig6,float,fig6-1s,sim,$(TWIN_COST_FLAGS) -DTWIN_FRICTION_GAIN=1e-30 \
    -DTWIN_FRICTION_WALK=4 -DTWIN_FRICTION_SIGMA=1.5 -DTWIN_FRICTION_AMPLITUDE=0 -DTWIN_FRICTION_CLIMB=0)
twin-walk-cost: $(if $(CM_TOOLS_OK),$(call cm_elf,twin-cost-friction-off,cortex-m4f) \
        $(call cm_elf,twin-cost-friction-walk,cortex-m4f) $(TWIN_DIR)/fig6-1s.stream)
	$(if $(CM_TOOLS_OK),@sh host/reports/friction_cost.sh $(call cm_elf,twin-cost-friction-off,cortex-m4f) \
	    $(call cm_elf,twin-cost-friction-walk,cortex-m4f),@echo "$(CM_TOOLS_MSG)")

deps-figures:
	@sh host/deps.sh gnuplot-nox

sweep-check:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	@sh host/reports/figures/check_sweep.sh $(BUILD)/double/beamslider

TEST_EXTRA += sweep-check
