# The helpers of the package tests (install_test.sh, wheel_test.sh), sourced by them: each step
# says when it started, and a failure says what failed and shows the log of the command.
script_start=$SECONDS

# Prints a step's title and the seconds since the script began.
step() { echo "== $* (at $((SECONDS - script_start)) s)"; }

# Fails the test with MESSAGE.
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Runs "$@" with its output to LOG; on failure shows the log and fails with MESSAGE.
logged() {
  local log=$1 message=$2
  shift 2
  "$@" >"$log" 2>&1 || {
    cat "$log" >&2
    fail "$message"
  }
}
