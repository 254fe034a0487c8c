# tests/python.mk - the Python package beamslider (host/python, docs/python.md),
# included by the Makefile (after port/lib.mk, whose archives it links):
#
#   make python        `make lib`, then the package's extension modules (cffi,
#                      both precisions) and its Python files built into
#                      $(BUILD)/python/lib (PYTHONPATH=$(BUILD)/python/lib to
#                      use it): nothing is written into host/python
#   make test-python   (part of `make test`) the pytest tests of
#                      host/python/tests against that build and the
#                      `beamslider` program of each precision, but the slow ones
#   make test-python-long  (part of `make test-long`) the slow ones (marked
#                      slow: the map example, the observer)
#
# With Debian's python3 and its packages only (PYTHON: the system interpreter,
# not a python3 earlier on PATH that may lack numpy); make test installs them
# as root, or says what to install (host/deps.sh).
PYTHON ?= /usr/bin/python3
PYTHON_PACKAGES := python3-cffi python3-numpy python3-pytest python3-setuptools python3-dev python3-pip \
                   python3-matplotlib
TEST_PACKAGES += $(PYTHON_PACKAGES)
PYTHON_BUILD := $(abspath $(BUILD))/python
PYTHON_LIB := $(PYTHON_BUILD)/lib
PYTHON_SOURCES := $(wildcard host/python/*.py host/python/*.toml host/python/*.map $(addprefix host/python/beamslider/*.,py c h))
PYTHON_ARCHIVES = $(foreach real,double float,$(call python_archives,$(real)))
# what the tests need of the environment: no bytecode or cache written beside
# the sources, the repository and the programs to compare with, no display
PYTHON_TEST_ENV := PYTHONPATH=$(PYTHON_LIB) PYTHONDONTWRITEBYTECODE=1 MPLBACKEND=Agg BEAMSLIDER_ROOT=$(CURDIR) \
                   BEAMSLIDER_CLI_DOUBLE=$(abspath $(BUILD))/double/beamslider \
                   BEAMSLIDER_CLI_FLOAT=$(abspath $(BUILD))/float/beamslider

.PHONY: python test-python test-python-long deps-python
# The static libraries the package links (and, for the tests, the programs)
# of each precision, one sub-make a precision (each costs some 0.5 CPU-s),
# then the package. Not the shared library: the package does not load it, and
# its link optimises the core again (-flto, some 20 CPU-s a precision);
# tests/check_consumer.sh tests it (make test-long).
python_archives = $(LIB_DIR)/libbeamslider-$1.a $(LIB_DIR)/libbeamslider-host-$1.a
python: deps-python
	@set -e; for real in $(LIB_REALS); do \
	    $(MAKE) --no-print-directory REAL=$$real $(call python_archives,$$real); done
	@$(MAKE) --no-print-directory $(PYTHON_BUILD)/built

# setuptools does not see the archives change: the stamp does, and --force
# rebuilds the modules then (the old package removed first).
$(PYTHON_BUILD)/built: $(PYTHON_SOURCES) $(PYTHON_ARCHIVES)
	@rm -rf $(PYTHON_LIB)
	cd host/python && BEAMSLIDER_BUILD=$(abspath $(BUILD)) BEAMSLIDER_NO_MAKE=1 PYTHONDONTWRITEBYTECODE=1 \
	    $(PYTHON) setup.py -q build --force --build-base $(PYTHON_BUILD)/setuptools --build-lib $(PYTHON_LIB)
	@touch $@

test-python: deps-python
	@set -e; for real in $(LIB_REALS); do \
	    $(MAKE) --no-print-directory REAL=$$real $(call python_archives,$$real) $(BUILD)/$$real/beamslider; done
	@$(MAKE) --no-print-directory $(PYTHON_BUILD)/built
	cd $(PYTHON_BUILD) && $(PYTHON_TEST_ENV) $(PYTHON) -m pytest -q -p no:cacheprovider -m "not slow" \
	    $(CURDIR)/host/python/tests

test-python-long: python
	@set -e; for real in $(LIB_REALS); do $(MAKE) --no-print-directory REAL=$$real $(BUILD)/$$real/beamslider; done
	cd $(PYTHON_BUILD) && $(PYTHON_TEST_ENV) $(PYTHON) -m pytest -q -p no:cacheprovider -m slow $(CURDIR)/host/python/tests

deps-python:
	@sh host/deps.sh $(PYTHON_PACKAGES)

# docs/figures/python_map.png, drawn by the map example (docs/python.md), and
# its line in docs/figures/PROVENANCE (host/reports/provenance.sh)
python-figure: python provenance-builds
	PYTHONPATH=$(PYTHON_LIB) PYTHONDONTWRITEBYTECODE=1 MPLBACKEND=Agg $(PYTHON) host/python/examples/map_example.py \
	    --out docs/figures/python_map.png --jobs $(JOBS) --dir $(PYTHON_BUILD)/map_example
	@sh -c '. host/reports/provenance.sh && provenance_figures "$$(provenance_stamp "make python-figure")" docs/figures/python_map.png'
.PHONY: python-figure

# ~7 CPU-s with the libraries and the programs built (pytest ~5: the fig6 60 s
# run and the program's in each precision; the sub-makes ~2); ~4 more to
# build the modules. The tests marked slow (the map example with matplotlib,
# the observer's design: ~8 CPU-s with their make) are test-python-long's.
TEST_EXTRA += test-python
TEST_LONG += test-python-long
