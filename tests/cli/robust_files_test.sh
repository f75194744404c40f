#!/usr/bin/env bash
# robust_files_test.sh NCSIM FIXTURES: issue 34's file, output and signal defects. Inputs that
# are no regular files are refused at once (a list that is a pipe or /dev/zero); outputs never
# replace a pipe, a device or a symlink and never share a temporary name; a signal or a closed
# pipe leaves no temporary file and ends with a message. Every ncsim call is bounded in time
# (a hang is a failure, exit 124), FIFOs and children are cleaned up at exit.
set -uo pipefail
real_ncsim=$1
fixtures=$2
root=$(cd "$fixtures/../.." && pwd)
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT
# Every call ends within 20 s (timeout's status 124 fails the check that expects another).
ncsim=$work/ncsim
printf '#!/usr/bin/env bash\nexec timeout -k 5 20 %q "$@"\n' "$real_ncsim" >"$ncsim"
chmod +x "$ncsim"

# expect, again, same, holds, summary: tests/cli/expect.sh.
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
long_line=$fixtures/long_line.nc

# ---- item 8: a list that is no regular file --------------------------------------------------
# machine_with NAME FILE: portal_3x in $work/NAME whose X list is FILE (a symlink to it).
machine_with() {
  cp -r "$root/machines/portal_3x" "$work/$1"
  rm "$work/$1/x.lis"
  ln -s "$2" "$work/$1/x.lis"
  echo "$work/$1"
}
mkfifo "$work/fifo.lis"
expect "an axis list that is a pipe is refused at once (NC3010), not read" 2 '' \
  "machine\.lis:4:1: error: cannot read list '.*x\.lis': not a regular file \(a pipe\) \[NC3010\]" -- \
  check --machine "$(machine_with m_fifo "$work/fifo.lis")" "$long_line"
expect "an axis list that is /dev/zero is refused at once (NC3010), memory stays flat" 2 '' \
  "cannot read list '.*x\.lis': not a regular file \(a device\) \[NC3010\]" -- \
  check --machine "$(machine_with m_zero /dev/zero)" "$long_line"
cp -r "$root/machines/portal_3x" "$work/m_chfifo"
rm "$work/m_chfifo/channel.lis"
mkfifo "$work/m_chfifo/channel.lis"
expect "a channel list that is a pipe is refused at once (NC3010)" 2 '' \
  "cannot read list '.*channel\.lis': not a regular file \(a pipe\) \[NC3010\]" -- \
  time --machine "$work/m_chfifo" "$long_line"
cp -r "$root/machines/portal_3x" "$work/m_big"
truncate -s 17M "$work/m_big/y.lis"
expect "a list over 16 MiB is refused (NC3010), not read" 2 '' \
  "cannot read list '.*y\.lis': 17825792 bytes, above the limit of 16 MiB \[NC3010\]" -- \
  check --machine "$work/m_big" "$long_line"
cp -r "$root/machines/portal_3x" "$work/m_idx"
rm "$work/m_idx/machine.lis"
mkfifo "$work/m_idx/machine.lis"
expect "a machine index that is a pipe is refused at once (NC3010)" 2 '' \
  "machine\.lis: error: cannot read the machine index: not a regular file \(a pipe\) \[NC3010\]" -- \
  check --machine "$work/m_idx" "$long_line"

summary robust_files_test
