# check_lib.sh - shared by the shell checks of the command line
# (tests/check_cli.sh, host/reports/figures/check_sweep.sh): sourced, not run.
#
# check_setup SCRIPT BIN: BIN must be an executable and the working folder the
# repository root; makes $tmp, removed on exit. Then pass/fail/check* count
# into $passed and $failed.

passed=0
failed=0

pass() {
    passed=$((passed + 1))
    echo "ok   - $1"
}

fail() {
    failed=$((failed + 1))
    echo "FAIL - $1"
    if [ -n "${2:-}" ]; then
        printf '%s\n' "$2" | sed 's/^/       /'
    fi
}

# check DESCRIPTION COMMAND...: passes when COMMAND succeeds.
check() {
    description=$1
    shift
    if "$@"; then pass "$description"; else fail "$description"; fi
}

# check_status DESCRIPTION EXPECTED ACTUAL STDERR_FILE
check_status() {
    if [ "$3" -eq "$2" ]; then
        pass "$1"
    else
        fail "$1" "exit status $3, expected $2; stderr: $(cat "$4")"
    fi
}

# check_has DESCRIPTION FILE STRING: FILE contains STRING (fixed string).
check_has() {
    if grep -q -F -e "$3" "$2"; then
        pass "$1"
    else
        fail "$1" "no \"$3\" in: $(cat "$2")"
    fi
}

check_setup() {
    if [ -z "$2" ] || [ ! -x "$2" ]; then
        echo "FAIL - usage: sh $1 PATH/TO/beamslider (got '$2', not executable)"
        exit 1
    fi
    if [ ! -f configs/fig6.ini ]; then
        echo "FAIL - run from the repository root (configs/fig6.ini not found)"
        exit 1
    fi
    tmp=$(mktemp -d) || exit 1
    trap 'rm -rf "$tmp"' EXIT
    trap 'rm -rf "$tmp"; exit 1' INT TERM
}
