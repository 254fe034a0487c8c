# figures.mk - `make figures` and the sweep's command-line checks; included
# by the top-level Makefile.
#
#   make figures        PCS sweeps and free runs of the papers' figures (double,
#                       all cores) -> docs/figures/*.png and the tables of
#                       docs/validation.md section 7 (host/figures/figures.sh;
#                       CSVs in build/figures/)
#   make figures JOBS=1 the same on one core (identical results)
#
# `make test` also runs sweep-check (host/figures/check_sweep.sh).

.PHONY: figures sweep-check deps-figures

figures: deps-figures
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	BIN=$(BUILD)/double/beamslider DATA=$(BUILD)/figures $(if $(JOBS),JOBS=$(JOBS)) sh host/figures/figures.sh

deps-figures:
	@sh host/deps.sh gnuplot-nox

sweep-check:
	$(MAKE) --no-print-directory REAL=double $(BUILD)/double/beamslider
	@sh host/figures/check_sweep.sh $(BUILD)/double/beamslider

TEST_EXTRA += sweep-check
