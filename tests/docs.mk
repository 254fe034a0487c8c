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
.PHONY: docs-check docs-test
docs-check: provenance-builds
	@sh host/reports/docs_check.sh
docs-test:
	@sh tests/check_docs_check.sh
	@sh tests/check_readme.sh
	@sh host/reports/docs_check.sh
TEST_EXTRA += docs-test
