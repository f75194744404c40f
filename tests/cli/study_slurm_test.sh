#!/usr/bin/env bash
# study_slurm_test.sh NCSIM: a study through Slurm gives the table the local run gives, byte for
# byte (issue 37 step 5, docs/study.md "Slurm"). The test brings up its own single-node Slurm
# from Debian's packages (munge, slurmctld, slurmd; scripts/deps.sh installs them) in a
# temporary folder: its own munge key and socket, its own slurm.conf (this host as the one node,
# its CPUs, free ports, state in the folder, SlurmUser root), the daemons in the foreground in
# the background of this script, and stops them in a trap whatever happens. Every wait is
# bounded. Needs root (slurmd runs jobs as their user); as another user it is skipped (77).
set -uo pipefail
ncsim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d /tmp/ncsim-slurm.XXXXXX)
chmod 755 "$work"
pids=()
stop_all() {
  local p
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  for _ in $(seq 50); do
    local alive=0
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    ((alive)) || break
    sleep 0.1
  done
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done
  wait 2>/dev/null
  rm -rf "$work"
}
trap stop_all EXIT
trap 'exit 1' INT TERM HUP
source "$here/expect.sh"

if [[ $(id -u) -ne 0 ]]; then
  echo "study_slurm_test: skipped: slurmd needs root to run jobs (the CI runs the tests as root)"
  exit 77
fi
for tool in munged slurmctld slurmd sbatch sinfo; do
  if ! command -v "$tool" >/dev/null; then
    echo "FAIL study_slurm_test: $tool is not installed (bash scripts/deps.sh installs munge, slurmctld, slurmd, slurm-client)"
    exit 1
  fi
done

# Two free TCP ports for slurmctld and slurmd.
read -r port_ctld port_d < <(python3 -c "
import socket
ss = [socket.socket() for _ in range(2)]
for s in ss: s.bind(('127.0.0.1', 0))
print(*[s.getsockname()[1] for s in ss])")
host=$(hostname -s)
mkdir -p "$work"/{munge,state,spool,log}
chmod 700 "$work/munge"
head -c 1024 /dev/urandom >"$work/munge/munge.key"
chmod 400 "$work/munge/munge.key"
munged -F -f --key-file="$work/munge/munge.key" --socket="$work/munge/munge.sock" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
  --log-file="$work/log/munged.log" >"$work/log/munged.out" 2>&1 &
pids+=($!)
export SLURM_CONF=$work/slurm.conf
cat >"$SLURM_CONF" <<CONF
ClusterName=ncsimtest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.sock
CredType=cred/munge
SlurmctldPort=$port_ctld
SlurmdPort=$port_d
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=study Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
# munged must answer before the Slurm daemons start.
for _ in $(seq 100); do
  [[ -S $work/munge/munge.sock ]] && break
  sleep 0.1
done
slurmctld -D -f "$SLURM_CONF" >"$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$work/log/slurmd.out" 2>&1 &
pids+=($!)
idle=0
for _ in $(seq 120); do
  if [[ $(timeout 5 sinfo -h -N -o '%t' 2>/dev/null) == idle ]]; then
    idle=1
    break
  fi
  sleep 0.5
done
if ((!idle)); then
  echo "FAIL study_slurm_test: the node did not become idle in 60 s (sinfo: $(timeout 5 sinfo -h -N -o '%t' 2>&1))"
  tail -n 20 "$work"/log/*
  exit 1
fi
echo "ok   Slurm is up: node $host idle, $(nproc) CPUs"

cp -r "$here/study" "$work/study"
sed -i -e "s#\"\.\./\.\./\.\./#\"$(cd "$here/../.." && pwd)/#" -e "s#\"\.\./#\"$here/#" "$work"/study/*.toml
checks=$((checks + 1))
if timeout 300 "$ncsim" study submit "$work/study/pickers.toml" -o "$work/slurm" --chunk 2 \
  >"$work/out" 2>"$work/err"; then
  echo "ok   study submit: the job array ran and was merged"
else
  failures=$((failures + 1))
  echo "FAIL study submit: exit $?"
  sed 's/^/  /' "$work/out" "$work/err"
  tail -n 20 "$work"/log/slurmctld.log "$work"/slurm/logs/* 2>/dev/null
fi
holds "submit: three array tasks of two jobs each" grep -q '^#SBATCH --array=0-2$' "$work/slurm/study.sbatch"
holds "submit: every task logged" bash -c "[[ \$(ls '$work/slurm/logs' | wc -l) -eq 3 ]]"
expect "the same study on this machine" 0 '' '' -- study run "$work/study/pickers.toml" -o "$work/local" --jobs 2
same "Slurm and the local run give byte-identical tables" "$work/slurm/results.csv" "$work/local/results.csv"
holds "the table has its six jobs" bash -c "[[ \$(wc -l <'$work/slurm/results.csv') -eq 7 ]]"
checks=$((checks + 1))
timeout 60 "$ncsim" study submit "$work/study/pickers.toml" -o "$work/bad" --partition nowhere \
  >"$work/out" 2>"$work/err"
status=$?
if [[ $status -eq 2 ]] && grep -q 'sbatch --wait .* failed (exit status [0-9]*; .*\[NC7210\]' "$work/err"; then
  echo "ok   a submit that sbatch refuses (no such partition) is NC7210, exit 2"
else
  failures=$((failures + 1))
  echo "FAIL a submit that sbatch refuses: exit $status"
  sed 's/^/  /' "$work/out" "$work/err"
fi
holds "... and no table is written" test ! -e "$work/bad/results.csv"
summary study_slurm_test
