# Sourced by the tool's shell tests: their assertions, and the count of failures.
#   expect CODE DESCRIPTION [NEEDLE] -- command...
#     Runs the command (stdout in out.txt, stderr in err.txt) and checks its exit code. For
#     code 2 also: exactly one line "deepshadow: ..." on stderr, containing NEEDLE when given,
#     and no regular file left at the command's --out or --json (removed before it runs).
#   expect_kept CODE DESCRIPTION [NEEDLE] -- command...
#     The same for outputs that exist and must stay as they are (an input named as --out):
#     nothing is removed first, and nothing else is checked of them.
#   fail MESSAGE          counts a failure and prints it
#   skip_rest WHAT        what follows needs WHAT, which is missing: ends the test, failed if
#                         anything failed so far, else skipped (exit 77, ctest's SKIP_RETURN_CODE)
failures=0

fail() {
  echo "FAILED: $*"
  failures=$((failures + 1))
}

skip_rest() {
  if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s); the rest skipped: no $1"
    exit 1
  fi
  echo "skipped: no $1 (scripts/setup.sh installs it); every check before passed"
  exit 77
}

expect() {
  local code=$1 what=$2 needle=""
  shift 2
  if [ "$1" != "--" ]; then
    needle=$1
    shift
  fi
  shift # --
  local outputs=() previous=""
  for argument in "$@"; do
    if [ "$previous" = "--out" ] || [ "$previous" = "--json" ]; then
      outputs+=("$argument")
    fi
    previous=$argument
  done
  if [ -z "${keep_outputs:-}" ]; then
    for file in "${outputs[@]}"; do
      [ -f "$file" ] && rm -f "$file"
    done
  fi
  "$@" > out.txt 2> err.txt
  local got=$?
  if [ "$got" -ne "$code" ]; then
    fail "$what: exit $got, expected $code"
    head -c 2000 err.txt
    return
  fi
  if [ "$code" -eq 2 ]; then
    if [ "$(wc -l < err.txt)" -ne 1 ] || ! grep -q "^deepshadow: " err.txt; then
      fail "$what: expected one 'deepshadow: ...' line on stderr"
      head -c 2000 err.txt
      return
    fi
    if [ -n "$needle" ] && ! grep -qF -- "$needle" err.txt; then
      fail "$what: the error does not say '$needle'"
      cat err.txt
      return
    fi
    for file in "${outputs[@]}"; do
      if [ -z "${keep_outputs:-}" ] && [ -f "$file" ]; then
        fail "$what: exit 2 but $file was left behind"
        return
      fi
    done
  fi
  echo "ok: $what (exit $code)$( [ "$code" -eq 2 ] && echo ": $(cat err.txt)")"
}

expect_kept() {
  keep_outputs=1 expect "$@"
}

# Image checks with deepshadow-testkit (the sourcing script sets $kit).
#   not_flat FILE WHAT          FILE shows something: not one colour, more than 1 % covered
#   rmse_at_most A B LIMIT WHAT  A and B agree (RMSE in linear RGB [0, 1] at most LIMIT)
#   rmse_at_least A B LIMIT WHAT A and B differ (RMSE at least LIMIT)
not_flat() {
  if [ ! -s "$1" ]; then
    fail "$2: $1 was not written"
  elif "$kit" flat "$1" > kit.txt; then
    fail "$2: $1 is flat ($(cat kit.txt))"
  else
    echo "ok: $2: $1 is not flat ($(cat kit.txt))"
  fi
}

rmse_at_most() {
  if "$kit" compare "$1" "$2" --at-most "$3" > kit.txt; then
    echo "ok: $4: $(cat kit.txt) <= $3"
  else
    fail "$4: $1 against $2: $(cat kit.txt), expected RMSE <= $3"
  fi
}

rmse_at_least() {
  if "$kit" compare "$1" "$2" --at-least "$3" > kit.txt; then
    echo "ok: $4: $(cat kit.txt) >= $3"
  else
    fail "$4: $1 against $2: $(cat kit.txt), expected RMSE >= $3"
  fi
}
