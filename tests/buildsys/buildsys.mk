# tests/buildsys/buildsys.mk - the embedded build systems (port/zephyr: the
# Zephyr module and its sample; port/platformio: the PlatformIO library and its
# example) checked without Zephyr or PlatformIO. Included by the Makefile
# (after tests/embedded/embedded.mk, whose host twin it uses).
#
#   make embedded-build-systems-test   (part of `make test-long`)
#       tests/check_embedded_build_systems.sh: module.yml, Kconfig
#       (kconfiglib), library.json and the example's platformio.ini read and
#       checked; the module's CMake logic through a stand-in of the Zephyr
#       functions and the library as PlatformIO builds it, both for a
#       Cortex-M4F (fig6, float); the sample and the example run under QEMU
#       to the state of the host twin of fig6 in float. Builds go to
#       $(BUILD)/buildsys and are kept: a second run rebuilds what changed.

# Python's yaml and kconfiglib, for the system python3 (make test installs them
# as root, or says what to install: host/deps.sh).
TEST_PACKAGES += python3-yaml python3-kconfiglib
BUILDSYS_HOST_RUN := $(if $(CM_TOOLS_OK),$(EMB_HOST)/fig6.float.20000)

.PHONY: embedded-build-systems-test
embedded-build-systems-test: deps-test $(BUILDSYS_HOST_RUN)
	@sh tests/check_embedded_build_systems.sh $(BUILD)/buildsys $(BUILDSYS_HOST_RUN)

# In make test-long: its two cross builds and QEMU runs cost some 20 CPU-s,
# a twentieth of a fresh clone's make test, for files that change seldom.
TEST_LONG += embedded-build-systems-test
