# reference.mk - the double-precision reference model (tests/reference/), the
# oracle against which core/ is checked. Included by the top-level Makefile.
#
#   make build/bs-reference   the reference command line (never links core/)
#   make reference-test       build and run tests/reference/test_reference (part of `make test`)
#   make reference-compare    fig6, 10 s: core vs reference (tests/reference/compare.sh)
#
# The reference is always double (REAL does not apply); it reads scenes with
# the project's INI reader: of HOST_LIB_OBJ only scene_ini.o, scene_fields.o,
# schedule.o (the [excitation] schedule's parser) and input_file.o (how a
# file is opened), the rest of the host library needs core objects.

REF_DIR := tests/reference
REF_BUILD := $(BUILD)/reference
REF_SRC := $(filter-out $(REF_DIR)/ref_main.c $(REF_DIR)/test_reference.c,$(wildcard $(REF_DIR)/*.c))
REF_OBJ := $(REF_SRC:%.c=$(REF_BUILD)/%.o)
REF_INI_OBJ := $(REF_BUILD)/host/lib/scene/scene_ini.o $(REF_BUILD)/host/lib/scene/scene_fields.o \
               $(REF_BUILD)/host/lib/scene/schedule.o $(REF_BUILD)/host/lib/io/input_file.o
REF_CONFIG_H := $(BUILD)/double/include/bs_build_config.h
REF_CFLAGS := $(BASE_CFLAGS) -I$(BUILD)/double/include -Icore/include -Iport -Iport/host $(HOST_INC) -I$(REF_DIR)
REF_HEADERS := $(wildcard $(REF_DIR)/*.h) $(HOST_HEADERS)

.PHONY: reference reference-test reference-compare

reference: $(BUILD)/bs-reference

$(REF_BUILD)/%.o: %.c $(REF_HEADERS) $(REF_CONFIG_H) | deps-build
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(REF_CFLAGS) -c -o $@ $<

$(BUILD)/bs-reference: $(REF_BUILD)/$(REF_DIR)/ref_main.o $(REF_OBJ) $(REF_INI_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(HOST_LIBS)

$(REF_BUILD)/test_reference: $(REF_BUILD)/tests/reference/test_reference.o $(REF_OBJ) $(REF_INI_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ -lcmocka -lcjson $(HOST_LIBS)

$(REF_BUILD)/tests/reference/test_reference.o: | deps-test

reference-test: $(REF_BUILD)/test_reference $(BUILD)/bs-reference
	@echo "== $(REF_BUILD)/test_reference"
	@./$(REF_BUILD)/test_reference
	@sh $(REF_DIR)/check_cli.sh $(BUILD)/bs-reference

reference-compare: $(BUILD)/bs-reference all
	sh $(REF_DIR)/compare.sh $(BUILD)/beamslider $(BUILD)/bs-reference configs/fig6.ini 10

TEST_EXTRA += reference-test
