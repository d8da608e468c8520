# Shared by the command-line test scripts (source it after reading the arguments): a scratch
# folder $work removed on exit, a failure count, and fail/ok lines in one format (a script may
# define its own).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }
