# tests/consumer/consumer.mk - beamslider taken as a library, included by the
# Makefile (after port/lib.mk and tests/embedded/embedded.mk):
#
#   make consumer-test   (part of `make test-long`: about 30 CPU-s) a fresh `make install` into
#                        $(BUILD)/stage, then tests/check_consumer.sh: the
#                        programs of tests/consumer/ built against it with
#                        pkg-config (C and C++), with CMake (add_subdirectory
#                        of port/cmake, find_package), a float/double mismatch
#                        refused with BS_E_BUILD, README.md's library program
#                        from the installed tree alone (C, C++, pkg-config,
#                        find_package: the hash of the installed beamslider run),
#                        the find_package versions the documents ask for, and
#                        the cross-compiled library
#                        of `make lib` for a Cortex-M4F when its compiler is there
CONSUMER_STAGE := $(abspath $(BUILD))/stage
# the core compiled for fig6_1mode in float by make (the C++ test's, Makefile)
CONSUMER_SCENE_LIB := $(BUILD)/lib/host/libbeamslider-float-fig6_1mode.a
CONSUMER_CM_LIB := $(if $(shell command -v $(CM_CC) 2>/dev/null),$(BUILD)/lib/cortex-m4f/libbeamslider-float-fig6_1mode.a)

.PHONY: consumer-test
consumer-test: deps-test
	@rm -rf $(CONSUMER_STAGE)
	@$(MAKE) --no-print-directory -s TARGET=host install PREFIX=$(CONSUMER_STAGE) >/dev/null
	@$(MAKE) --no-print-directory -s -j$(JOBS) TARGET=host REAL=float $(CONSUMER_SCENE_LIB)
	$(if $(CONSUMER_CM_LIB),@$(MAKE) --no-print-directory -s -j$(JOBS) TARGET=cortex-m4f SCENE=fig6_1mode REAL=float lib >/dev/null)
	@sh tests/check_consumer.sh $(CONSUMER_STAGE) $(abspath $(BUILD)) $(CONSUMER_SCENE_LIB) $(CONSUMER_CM_LIB)

TEST_LONG += consumer-test
