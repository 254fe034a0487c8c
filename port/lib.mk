# port/lib.mk - the core as a static library, and its installation. Included by
# the top-level Makefile after tests/embedded/embedded.mk (it uses BUILD, REAL,
# TARGET, SCENE, CONFIG, PREFIX, VERSION, CC, CFLAGS, BASE_CFLAGS, NO_LOOP_CALLS,
# CORE_SRC, CORE_OBJ and the CM_* variables of port/cortex-m/cortex-m.mk).
#
#   make lib        build/lib/libbeamslider-double.a and libbeamslider-float.a:
#                   the core objects the tests link ($(BUILD)/REAL/core/src/*.o:
#                   host port, run-time scenes, CFLAGS)
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
#                   for P in double, float: PREFIX/lib/libbeamslider-P.a, the
#                   headers in PREFIX/include/beamslider-P/ (core/include and
#                   P's bs_build_config.h), PREFIX/lib/pkgconfig/beamslider-P.pc;
#                   the CMake package PREFIX/lib/cmake/beamslider/ (targets
#                   beamslider::double, beamslider::float); the licence in
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
# ---- host: both precisions, from the objects the tests use ------------------
lib_host = $(LIB_DIR)/libbeamslider-$1.a

lib:
	@set -e; for real in $(LIB_REALS); do \
	    $(MAKE) --no-print-directory REAL=$$real $(LIB_DIR)/libbeamslider-$$real.a; done

$(call lib_host,$(REAL)): $(CORE_OBJ)
	@mkdir -p $(@D)
	@rm -f $@
	$(AR) rcs $@ $^

# ---- install ------------------------------------------------------------------
# PREFIX goes into the pkg-config files, so a relative one is made absolute.
LIB_PREFIX := $(abspath $(PREFIX))
LIB_DEST := $(DESTDIR)$(LIB_PREFIX)
LIB_HEADERS := $(wildcard core/include/*.h)
# The pointer size of the host libraries: the CMake package refuses a project
# that builds for another (a 32-bit or cross build).
LIB_POINTER_SIZE = $(shell printf '__SIZEOF_POINTER__\n' | $(CC) -E -P -x c - | tail -n 1)

install: lib
	@set -e; for real in $(LIB_REALS); do \
	    install -d '$(LIB_DEST)/lib/pkgconfig' '$(LIB_DEST)/include/beamslider-'$$real; \
	    install -m 644 $(LIB_DIR)/libbeamslider-$$real.a '$(LIB_DEST)/lib/'; \
	    install -m 644 $(LIB_HEADERS) $(BUILD)/$$real/include/bs_build_config.h '$(LIB_DEST)/include/beamslider-'$$real/; \
	    sed -e 's|@PREFIX@|$(LIB_PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e "s|@REAL@|$$real|g" \
	        port/pkgconfig/beamslider.pc.in > '$(LIB_DEST)/lib/pkgconfig/beamslider-'$$real.pc; \
	    echo "install: $(LIB_DEST)/lib/libbeamslider-$$real.a, include/beamslider-$$real/, lib/pkgconfig/beamslider-$$real.pc"; \
	done
	@install -d '$(LIB_DEST)/lib/cmake/beamslider' '$(LIB_DEST)/share/doc/beamslider'
	@install -m 644 port/cmake/beamsliderConfig.cmake '$(LIB_DEST)/lib/cmake/beamslider/'
	@sed -e 's|@VERSION@|$(VERSION)|g' -e 's|@POINTER_SIZE@|$(LIB_POINTER_SIZE)|g' \
	    port/cmake/beamsliderConfigVersion.cmake.in > '$(LIB_DEST)/lib/cmake/beamslider/beamsliderConfigVersion.cmake'
	@install -m 644 LICENSE '$(LIB_DEST)/share/doc/beamslider/'
	@echo "install: $(LIB_DEST)/lib/cmake/beamslider/ (find_package(beamslider)), share/doc/beamslider/LICENSE"

uninstall:
	@set -e; for real in $(LIB_REALS); do \
	    rm -f '$(LIB_DEST)/lib/libbeamslider-'$$real.a '$(LIB_DEST)/lib/pkgconfig/beamslider-'$$real.pc; \
	    rm -rf '$(LIB_DEST)/include/beamslider-'$$real; done
	@rm -rf '$(LIB_DEST)/lib/cmake/beamslider' '$(LIB_DEST)/share/doc/beamslider'
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
