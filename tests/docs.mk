# tests/docs.mk - the docs against the code, included last by the Makefile (so that
# its test runs after every other test of `make test`):
#
#   make docs-check   the report pages' provenance stamps against the tree
#                     (host/reports/docs_check.sh; builds both CLIs first): names
#                     every stale page and the command that regenerates it
#   make docs-test    (part of `make test`, after test-one has built both CLIs)
#                     the checker on stale copies (tests/check_docs_check.sh),
#                     README.md's commands as on a fresh clone (tests/check_readme.sh),
#                     then the pages as docs-check checks them
#   make readme-long  (part of `make test-long`) README.md's commands with the twin's:
#                     each designs an observer (3-9 CPU-s), which make test skips
.PHONY: docs-check docs-test
docs-check: provenance-builds
	@sh host/reports/docs_check.sh
docs-test:
	@sh tests/check_docs_check.sh
	@sh tests/check_readme.sh
	@sh host/reports/docs_check.sh
TEST_EXTRA += docs-test
readme-long:
	@sh tests/check_readme.sh --long
.PHONY: readme-long
TEST_LONG += readme-long
