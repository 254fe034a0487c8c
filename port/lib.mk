# port/lib.mk - the core as a static library, and its installation. Included by
# the top-level Makefile after tests/embedded/embedded.mk (it uses BUILD, REAL,
# TARGET, SCENE, CONFIG, PREFIX, VERSION, CC, CFLAGS, BASE_CFLAGS, NO_LOOP_CALLS,
# CORE_SRC, CORE_OBJ and the CM_* variables of port/cortex-m/cortex-m.mk).
#
#   make lib        for P in double, float: build/lib/libbeamslider-P.a (the
#                   core: host port, run-time scenes), libbeamslider-host-P.a
#                   (libbeamslider-host: host/lib, its public header
#                   host/include/beamslider_host.h) and the shared
#                   libbeamslider-host-P.so.VERSION (both in one), of the
#                   objects in $(BUILD)/P (position-independent: HOST_PIC)
#   make TARGET=cortex-m4f SCENE=NAME REAL=float lib   (any target of CM_TARGETS)
#                   build/lib/cortex-m4f/libbeamslider-float-NAME.a: the core
#                   compiled against configs/NAME.h (and CONFIG's switches) with
#                   the target's CPU flags, the embedded port and CM_CFLAGS
#                   (-O3, one section per function and object); link it with
#                   -Wl,--gc-sections and -lm, and compile the firmware against
#                   build/lib/cortex-m4f/libbeamslider-float-NAME.obj/include
#                   and the repository root (the build configuration names
#                   "configs/NAME.h")
#   make install [PREFIX=/usr/local] [DESTDIR=]
#                   for P in double, float: PREFIX/lib/ the libraries of make
#                   lib (the .so with its soname and development links), the
#                   headers in PREFIX/include/beamslider-P/ (core/include,
#                   beamslider_host.h and P's bs_build_config.h),
#                   PREFIX/lib/pkgconfig/beamslider-P.pc and
#                   beamslider-host-P.pc; the CMake package
#                   PREFIX/lib/cmake/beamslider/ (targets beamslider::double,
#                   beamslider::float, beamslider::host-double,
#                   beamslider::host-float); the program PREFIX/bin/beamslider
#                   (of REAL); the scenes configs/*.ini in
#                   PREFIX/share/beamslider/scenes/; the licence in
#                   PREFIX/share/doc/beamslider/
#   make uninstall  removes what install put there (same PREFIX and DESTDIR)

LIB_DIR := $(BUILD)/lib
LIB_REALS := double float

# $(call lib_archive,ARCHIVE,COMPILER,FLAGS,AR,REAL,SWITCHES): rules for ARCHIVE,
# every core source compiled by COMPILER with FLAGS into ARCHIVE's folder
# NAME.obj/ (NAME: ARCHIVE without .a) against its own generated build
# configuration NAME.obj/include/bs_build_config.h (REAL and the NAME=VALUE
# SWITCHES, port/build_config.sh). FLAGS name the port and whatever else the
# sources need. Objects are rebuilt when COMPILER or FLAGS change (NAME.obj/flags).
lib_archive = $(eval $(call lib__archive,$(strip $1),$(strip $2),$3,$(strip $4),$(strip $5),$6))
define lib__archive
LIB_OBJDIR_$1 := $(1:.a=.obj)
LIB_OBJ_$1 := $$(CORE_SRC:%.c=$$(LIB_OBJDIR_$1)/%.o)
LIB_FLAGS_$1 := $3 -I$$(LIB_OBJDIR_$1)/include -Icore/include -Icore/src

$1: $$(LIB_OBJ_$1)
	@rm -f $$@
	$4 rcs $$@ $$^

$$(LIB_OBJ_$1): $$(LIB_OBJDIR_$1)/%.o: %.c $$(LIB_OBJDIR_$1)/include/bs_build_config.h \
        $$(LIB_OBJDIR_$1)/flags $(wildcard core/*/*.h port/*/bs_port.h configs/*.h)
	@mkdir -p $$(@D)
	$2 $$(LIB_FLAGS_$1) -c -o $$@ $$<

$$(LIB_OBJDIR_$1)/include/bs_build_config.h: .force
	@sh port/build_config.sh $$@ $5 $6

$$(LIB_OBJDIR_$1)/flags: .force
	@mkdir -p $$(@D)
	@printf '%s\n' '$2 $$(LIB_FLAGS_$1)' | cmp -s - $$@ || printf '%s\n' '$2 $$(LIB_FLAGS_$1)' > $$@
endef

ifeq ($(TARGET),host)
# ---- host: both precisions, position-independent ---------------------------
# The libraries are made of the objects the CLI and the tests use
# ($(BUILD)/REAL/: HOST_PIC, the Makefile's, compiles them -fPIC: a shared
# library needs it, and the static archives have it too, so that another
# shared library, a Python or Octave module, may take them in): a sub-make
# per precision.
OBJCOPY ?= objcopy
VERSION_MINOR := $(basename $(VERSION))
# lib_names REAL: what `make lib` makes for one precision
lib_names = $(LIB_DIR)/libbeamslider-$1.a $(LIB_DIR)/libbeamslider-host-$1.a \
            $(LIB_DIR)/libbeamslider-host-$1.so.$(VERSION)

lib:
	@set -e; for real in $(LIB_REALS); do \
	    $(MAKE) --no-print-directory REAL=$$real lib-one; done

# Inside the sub-make: the libraries of this REAL.
.PHONY: lib-one
lib-one: $(call lib_names,$(REAL))

$(LIB_DIR)/libbeamslider-$(REAL).a: $(CORE_OBJ)
	@mkdir -p $(@D)
	@rm -f $@
	$(AR) rcs $@ $^

# The host library's archive: its objects as one, every symbol but the
# public ones (bs_*: beamslider_host.h's, the port's bs_platform_*) made
# local, so that its internal names (scene_load, run_scene, ...) cannot
# clash with a program's. It needs the core archive and -linih -lcjson -lm
# -pthread (pkg-config --static beamslider-host-REAL says so).
$(LIB_DIR)/libbeamslider-host-$(REAL).a: $(HOST_LIB_OBJ)
	@mkdir -p $(@D)
	@rm -f $@ $(@:.a=.o)
	$(LD) -r -o $(@:.a=.o) $^
	$(OBJCOPY) --wildcard --keep-global-symbol='bs_*' $(@:.a=.o)
	$(AR) rcs $@ $(@:.a=.o)
	@rm -f $(@:.a=.o)

# The shared library: the host library and the core in one (what a Python
# or Octave process loads), exporting the bs_* symbols only
# (port/libbeamslider-host.map); soname MAJOR.MINOR: until 1.0 a minor
# release may change the API.
$(LIB_DIR)/libbeamslider-host-$(REAL).so.$(VERSION): $(HOST_LIB_OBJ) $(CORE_LINK_OBJ) port/libbeamslider-host.map
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(CORE_LINK_FLAGS) -shared -Wl,-soname,libbeamslider-host-$(REAL).so.$(VERSION_MINOR) \
	    -Wl,--version-script=port/libbeamslider-host.map -Wl,-z,defs -o $@ $(HOST_LIB_OBJ) $(CORE_LINK_OBJ) $(HOST_LIBS)

# ---- install ------------------------------------------------------------------
# PREFIX goes into the pkg-config files, so a relative one is made absolute.
LIB_PREFIX := $(abspath $(PREFIX))
LIB_DEST := $(DESTDIR)$(LIB_PREFIX)
LIB_HEADERS := $(wildcard core/include/*.h) host/include/beamslider_host.h
# The pointer size of the host libraries: the CMake package refuses a project
# that builds for another (a 32-bit or cross build).
LIB_POINTER_SIZE = $(shell printf '__SIZEOF_POINTER__\n' | $(CC) -E -P -x c - | tail -n 1)
# The scenes `make install` puts in PREFIX/share/beamslider/scenes (with the
# bases they name) and the program: the CLI of this REAL.
LIB_SCENES := $(wildcard configs/*.ini)

# lib_pc REAL NAME: writes port/pkgconfig/NAME.pc.in for REAL to PREFIX/lib/pkgconfig/NAME-REAL.pc
lib_pc = sed -e 's|@PREFIX@|$(LIB_PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e "s|@REAL@|$1|g" \
             port/pkgconfig/$2.pc.in > '$(LIB_DEST)/lib/pkgconfig/$2-'$1.pc

install: lib $(OBJ)/beamslider
	@set -e; for real in $(LIB_REALS); do \
	    install -d '$(LIB_DEST)/lib/pkgconfig' '$(LIB_DEST)/include/beamslider-'$$real; \
	    install -m 644 $(LIB_DIR)/libbeamslider-$$real.a $(LIB_DIR)/libbeamslider-host-$$real.a '$(LIB_DEST)/lib/'; \
	    install -m 755 $(LIB_DIR)/libbeamslider-host-$$real.so.$(VERSION) '$(LIB_DEST)/lib/'; \
	    ln -sf libbeamslider-host-$$real.so.$(VERSION) '$(LIB_DEST)/lib/libbeamslider-host-'$$real.so.$(VERSION_MINOR); \
	    ln -sf libbeamslider-host-$$real.so.$(VERSION_MINOR) '$(LIB_DEST)/lib/libbeamslider-host-'$$real.so; \
	    install -m 644 $(LIB_HEADERS) $(BUILD)/$$real/include/bs_build_config.h '$(LIB_DEST)/include/beamslider-'$$real/; \
	    $(call lib_pc,$$real,beamslider); \
	    $(call lib_pc,$$real,beamslider-host); \
	    echo "install: $(LIB_DEST)/lib/libbeamslider{,-host}-$$real.a, libbeamslider-host-$$real.so, include/beamslider-$$real/, lib/pkgconfig/beamslider{,-host}-$$real.pc"; \
	done
	@install -d '$(LIB_DEST)/lib/cmake/beamslider' '$(LIB_DEST)/share/doc/beamslider' '$(LIB_DEST)/bin' \
	    '$(LIB_DEST)/share/beamslider/scenes'
	@install -m 644 port/cmake/beamsliderConfig.cmake '$(LIB_DEST)/lib/cmake/beamslider/'
	@sed -e 's|@VERSION@|$(VERSION)|g' -e 's|@POINTER_SIZE@|$(LIB_POINTER_SIZE)|g' \
	    port/cmake/beamsliderConfigVersion.cmake.in > '$(LIB_DEST)/lib/cmake/beamslider/beamsliderConfigVersion.cmake'
	@install -m 644 LICENSE '$(LIB_DEST)/share/doc/beamslider/'
	@install -m 755 $(OBJ)/beamslider '$(LIB_DEST)/bin/'
	@install -m 644 $(LIB_SCENES) '$(LIB_DEST)/share/beamslider/scenes/'
	@echo "install: $(LIB_DEST)/bin/beamslider ($(REAL)), share/beamslider/scenes/ ($(words $(LIB_SCENES)) scenes), lib/cmake/beamslider/ (find_package(beamslider $(VERSION_MINOR))), share/doc/beamslider/LICENSE"

uninstall:
	@set -e; for real in $(LIB_REALS); do \
	    rm -f '$(LIB_DEST)/lib/libbeamslider-'$$real.a '$(LIB_DEST)/lib/libbeamslider-host-'$$real.a \
	          '$(LIB_DEST)/lib/libbeamslider-host-'$$real.so '$(LIB_DEST)/lib/libbeamslider-host-'$$real.so.* \
	          '$(LIB_DEST)/lib/pkgconfig/beamslider-'$$real.pc '$(LIB_DEST)/lib/pkgconfig/beamslider-host-'$$real.pc; \
	    rm -rf '$(LIB_DEST)/include/beamslider-'$$real; done
	@rm -f '$(LIB_DEST)/bin/beamslider'
	@rm -rf '$(LIB_DEST)/lib/cmake/beamslider' '$(LIB_DEST)/share/doc/beamslider' '$(LIB_DEST)/share/beamslider'
	@echo "uninstall: removed beamslider from $(LIB_DEST)"

else
# ---- a Cortex-M target: one compiled scene --------------------------------------
LIB_CROSS := $(LIB_DIR)/$(TARGET)/libbeamslider-$(REAL)-$(SCENE).a
$(call lib_archive,$(LIB_CROSS),$(CM_CC),$(CM_CPU_$(TARGET)) $(CM_CFLAGS) -fno-tree-loop-distribute-patterns \
    -Iport/embedded -I.,$(patsubst %gcc,%ar,$(CM_CC)),$(REAL),'BS_SCENE_CONFIG="configs/$(SCENE).h"' $(CONFIG))

lib: lib-cross-check $(LIB_CROSS)
	@$(patsubst %gcc,%size,$(CM_CC)) -t $(LIB_CROSS) | tail -n 1 | \
	    awk '{ print "lib: $(LIB_CROSS): text " $$1 " B, data " $$2 " B, bss " $$3 " B (before --gc-sections)" }'

# Fails early, with the fix, on a missing scene header or compiler.
.PHONY: lib-cross-check
lib-cross-check:
	@test -f configs/$(SCENE).h || { echo "lib: no configs/$(SCENE).h (SCENE=NAME of a configs/NAME.h; make configs writes them)" >&2; exit 2; }
	@command -v $(CM_CC) >/dev/null || { echo "lib: needs $(CM_CC) (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi)" >&2; exit 2; }
$(LIB_CROSS:.a=.obj)/include/bs_build_config.h: | lib-cross-check

install uninstall:
	@echo "$@: installs the host libraries; run it without TARGET (TARGET=$(TARGET) builds with: make lib)" >&2; exit 2
endif
