# Phase timer for the test scripts (sourced by tools/run-tests.sh and tools/run-sanitizers.sh).
#   phase NAME CMD...   runs CMD, appends "NAME wall_s cpu_s" to $ADCS_PHASE_LOG (created on
#                       first use) and returns CMD's exit status;
#   phase_table         prints every phase recorded so far, with the total, as a table.
# CPU is user + system time of CMD and all its children (bash's `time`), so on 2 cores a phase
# that kept both busy shows cpu ≈ 2 × wall. The log is shared by a script and the scripts it
# calls, so one table covers the whole test command.
: "${ADCS_PHASE_LOG:=$(mktemp "${TMPDIR:-/tmp}/adcs-phases.XXXXXX")}"
export ADCS_PHASE_LOG

phase() {
  local name=$1; shift
  local tf rc=0
  tf=$(mktemp "${TMPDIR:-/tmp}/adcs-phase.XXXXXX")
  local TIMEFORMAT='%R %U %S'
  # The command's own stderr goes to fd 3 (the caller's stderr); only `time` writes to $tf.
  { time "$@" 2>&3 3>&-; } 3>&2 2>"$tf" || rc=$?
  local wall user sys
  read -r wall user sys <"$tf" || true
  rm -f "$tf"
  awk -v n="$name" -v w="${wall:-0}" -v u="${user:-0}" -v s="${sys:-0}" \
    'BEGIN { printf "%s %.0f %.0f\n", n, w, u + s }' >>"$ADCS_PHASE_LOG"
  echo "== phase $name: $(tail -n 1 "$ADCS_PHASE_LOG" | awk '{ print $2 " s wall, " $3 " s CPU" }')$( [ "$rc" -eq 0 ] || echo ", FAILED (exit $rc)")"
  return "$rc"
}

phase_table() {
  [ -s "$ADCS_PHASE_LOG" ] || return 0
  awk 'BEGIN { printf "\n%-22s %9s %9s\n", "phase", "wall [s]", "CPU [s]" }
       { printf "%-22s %9d %9d\n", $1, $2, $3; w += $2; c += $3 }
       END { printf "%-22s %9d %9d\n", "total", w, c }' "$ADCS_PHASE_LOG"
}
