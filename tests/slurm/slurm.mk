# tests/slurm/slurm.mk - the Slurm job-array scripts of host/slurm/ against a
# real single-node Slurm (tests/slurm/check_slurm.sh; docs/maps.md section 6).
# Part of `make test-long` (TEST_LONG), never of `make test`: it starts
# daemons as root. Skips with a notice without root or where slurm-wlm and
# munge cannot be installed.
.PHONY: slurm-check

slurm-check:
	$(MAKE) --no-print-directory -j$(JOBS) REAL=double $(BUILD)/double/beamslider
	@sh tests/slurm/check_slurm.sh $(BUILD)/double/beamslider $(BUILD)

TEST_LONG += slurm-check
