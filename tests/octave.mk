# tests/octave.mk - the Octave / MATLAB bridge (host/octave: a MEX gateway over
# libbeamslider-host, docs/octave.md), included by the Makefile after
# port/lib.mk:
#
#   make octave        build/octave/double/beamslider_mex.mex and
#                      build/octave/float/...: host/octave/make.m run by
#                      octave-cli against the archives of `make lib` (built
#                      first: a sub-make per precision)
#   make test-octave   (part of `make test`) tests/check_octave.sh against the
#                      CLI of each precision: the fig6 60 s hash (double), a
#                      2 s run through 'set', errors naming the field, the
#                      stepping state's round trip, docs/octave.md's examples
#
# Octave comes from Debian (octave, liboctave-dev: about 130 packages, 250 MiB
# installed, 70 MiB download); make test installs them as root or says what
# to install (host/deps.sh). Everything built goes to $(BUILD)/octave.
OCTAVE_PACKAGES := octave liboctave-dev
TEST_PACKAGES += $(OCTAVE_PACKAGES)
OCTAVE_OUT := $(abspath $(BUILD))/octave
OCTAVE_SRC := $(wildcard host/octave/src/*.c host/octave/src/*.h) host/octave/make.m
OCTAVE_CLI := octave-cli --norc --quiet --no-history

.PHONY: octave octave-one test-octave deps-octave
deps-octave:
	@sh host/deps.sh $(BUILD_PACKAGES) $(OCTAVE_PACKAGES)

octave: deps-octave
	@set -e; for real in double float; do $(MAKE) --no-print-directory REAL=$$real octave-one; done

# Inside the sub-make: the gateway of this REAL (and its archives, the
# rules of port/lib.mk for this REAL).
octave-one: $(OCTAVE_OUT)/$(REAL)/beamslider_mex.mex
$(OCTAVE_OUT)/$(REAL)/beamslider_mex.mex: $(OCTAVE_SRC) $(LIB_DIR)/libbeamslider-host-$(REAL).a \
        $(LIB_DIR)/libbeamslider-$(REAL).a
	$(OCTAVE_CLI) --eval "addpath('$(abspath host/octave)'); \
	    make('outdir', '$(@D)', 'precision', '$(REAL)', 'library', 'build', 'builddir', '$(abspath $(BUILD))');"

# (a sub-make per precision: the gateway and the CLI that is its reference)
test-octave: deps-octave
	@set -e; for real in double float; do \
	    $(MAKE) --no-print-directory -s REAL=$$real octave-one $(BUILD)/$$real/beamslider; done
	@sh tests/check_octave.sh $(BUILD)/double/beamslider $(OCTAVE_OUT)/double double
	@sh tests/check_octave.sh $(BUILD)/float/beamslider $(OCTAVE_OUT)/float float short
TEST_EXTRA += test-octave
