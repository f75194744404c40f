# tests/cli/expect.sh: the preamble and helpers of the shell tests of the ncsim command
# (tests/cli/*_test.sh, tests/golden/golden_cli_test.sh, report/cli_test.sh). Source it after
# setting `ncsim` (the binary). It makes `work`, a scratch folder removed at exit (unless the
# test set one), and counts in `checks` and `failures`; `summary NAME` ends the test.
if [[ -z ${work:-} ]]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
checks=${checks:-0}
failures=${failures:-0}

# expect NAME STATUS PATTERN_STDOUT PATTERN_STDERR -- ARGS...: runs ncsim, compares the exit
# status, and greps stdout/stderr for extended regular expressions ('' = no requirement).
expect() {
  local name=$1 want=$2 out_re=$3 err_re=$4
  shift 5
  "$ncsim" "$@" >"$work/out" 2>"$work/err" </dev/null
  expect_status=$?
  again "$name" "$want" "$out_re" "$err_re"
}

# again NAME STATUS PATTERN_STDOUT PATTERN_STDERR: the checks of expect on the last expect's
# run, without running ncsim again (several checks of one long run, e.g. a sweep).
again() {
  local name=$1 want=$2 out_re=$3 err_re=$4
  checks=$((checks + 1))
  local ok=1
  [[ $expect_status -eq $want ]] || ok=0
  if [[ -n $out_re ]] && ! grep -Eq -- "$out_re" "$work/out"; then ok=0; fi
  if [[ -n $err_re ]] && ! grep -Eq -- "$err_re" "$work/err"; then ok=0; fi
  if ((ok)); then
    echo "ok   $name"
  else
    failures=$((failures + 1))
    echo "FAIL $name: exit $expect_status (want $want)"
    sed 's/^/  stdout: /' "$work/out"
    sed 's/^/  stderr: /' "$work/err"
  fi
}

# same NAME FILE_A FILE_B: the two files are byte-identical.
same() {
  checks=$((checks + 1))
  if cmp -s "$2" "$3"; then
    echo "ok   $1"
  else
    failures=$((failures + 1))
    echo "FAIL $1"
    diff "$2" "$3" | head -20
  fi
}

# holds NAME COMMAND...: a condition on the files written (a command that succeeds).
holds() {
  local name=$1
  shift
  checks=$((checks + 1))
  if "$@"; then
    echo "ok   $name"
  else
    failures=$((failures + 1))
    echo "FAIL $name"
  fi
}

# no_temp FILE: no temporary file of FILE is left (core::OutputFile writes FILE.XXXXXX.tmp;
# the pattern also finds the FILE.tmp of old).
no_temp() {
  ! compgen -G "$1.*tmp" >/dev/null
}

# no_file FILE: neither FILE nor a temporary file of it exists.
no_file() {
  [[ ! -e $1 ]] && no_temp "$1"
}

# summary NAME: the last line of a test: the counts, and the status (0 when nothing failed).
summary() {
  echo "$1: $((checks - failures)) passed, $failures failed"
  ((failures == 0))
}
