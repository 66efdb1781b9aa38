#!/usr/bin/env bash
# peloid sweep --slurm through a real Slurm: starts slurmctld + slurmd (Debian
# slurm-wlm) for one node on localhost from a minimal slurm.conf in a temp
# directory (AuthType=auth/none, CredType=cred/none: no munge; random ports;
# state, spool, logs and pid files in the temp directory), submits the
# 4-point array and its collect step with the submit.sh peloid wrote, waits,
# checks sweep.tsv, and stops the two daemons it started.  Where Slurm cannot
# start (not root, slurm-wlm missing, a daemon does not come up) it prints
# "skipped" with the reason and exits 0; it never says passed then.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
T=$(mktemp -d /tmp/peloid-slurm.XXXXXX)
echo "== sweep through Slurm"
skip() { echo "  skipped sweep through Slurm: $1"; stop; rm -rf "$T"; exit 0; }
stop() {
  for d in slurmd slurmctld; do
    [ -s "$T/$d.pid" ] && kill "$(cat "$T/$d.pid" 2> /dev/null)" 2> /dev/null
  done
  for _ in $(seq 50); do
    alive=0
    for d in slurmd slurmctld; do [ -s "$T/$d.pid" ] && kill -0 "$(cat "$T/$d.pid" 2> /dev/null)" 2> /dev/null && alive=1; done
    [ $alive = 0 ] && break; sleep 0.1
  done
}
trap 'stop; rm -rf "$T"' EXIT
[ "$(id -u)" = 0 ] || skip "not root (slurmd runs jobs as root here)"
command -v slurmctld > /dev/null && command -v slurmd > /dev/null && command -v sbatch > /dev/null \
  || skip "slurm-wlm is not installed (slurmctld, slurmd, sbatch)"
P=$((20000 + RANDOM % 20000))
mkdir -p "$T/state" "$T/spool"
cat > "$T/slurm.conf" <<EOF
ClusterName=peloidtest
SlurmctldHost=localhost
SlurmctldPort=$P
SlurmdPort=$((P + 1))
AuthType=auth/none
CredType=cred/none
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/slurmctld.log
SlurmdLogFile=$T/slurmd.log
ProctrackType=proctrack/pgid
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SlurmdParameters=config_overrides
NodeName=peloidnode NodeHostname=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=peloid Nodes=peloidnode Default=YES MaxTime=10 State=UP
EOF
export SLURM_CONF="$T/slurm.conf"
slurmctld -f "$SLURM_CONF" > "$T/ctld.out" 2>&1 || skip "slurmctld did not start: $(tail -1 "$T/ctld.out")"
slurmd -f "$SLURM_CONF" -N peloidnode > "$T/d.out" 2>&1 || skip "slurmd did not start: $(tail -1 "$T/d.out")"
up=0
for _ in $(seq 100); do
  sinfo -h -o %T 2> /dev/null | grep -q idle && { up=1; break; }; sleep 0.2
done
[ $up = 1 ] || skip "the node did not come up idle in 20 s: $(tail -1 "$T/slurmctld.log" 2> /dev/null)"

cd "$T"
cat > bd.cfg <<'CFG'
name = "bd";
seed = 11;
steps = 300;
box: { cells = [8, 8, 8]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 16; radius = 1.0; mass_density = 1.0; temperature = 1.0; init = "random";
  pairs = ""; integrator = "brownian"; bd_viscosity = 0.02; substeps = 1; max_overlap = 1.0; };
observe: { msd_interval = 1; };
CFG
cat > study.cfg <<'CFG'
name = "slurm4";
scene = "bd.cfg";
out = "out";
grid = ( { key = "colloids.bd_viscosity"; values = [0.02, 0.04]; }, { key = "seed"; values = [1, 2]; } );
CFG
t0=$(date +%s)
"$PELOID" sweep study.cfg --slurm --threads 1 2> slurm.err || { echo "  FAIL --slurm: $(cat slurm.err)"; exit 1; }
bash out/submit.sh > submit.out 2>&1 || { echo "  FAIL sbatch: $(cat submit.out)"; exit 1; }
for _ in $(seq 200); do
  [ -z "$(squeue -h 2> /dev/null)" ] && break; sleep 0.2
done
left=$(squeue -h 2> /dev/null | wc -l)
n_ok=$(grep -c '	ok	0	' out/sweep.tsv 2> /dev/null)
logs=$(ls out/logs/slurm-*_?.out 2> /dev/null | wc -l)
if [ "$left" = 0 ] && [ "$n_ok" = 4 ] && [ "$logs" = 4 ] && [ -s out/sweep.png ]; then
  echo "  ok   4-point array through slurmctld + slurmd (tasks 0-3 and the collect step, $(( $(date +%s) - t0 )) s): sweep.tsv 4 ok rows"
else
  echo "  FAIL Slurm array: $left jobs left, $n_ok ok rows, $logs task logs; $(cat submit.out | tr '\n' ' ')"
  tail -3 "$T/slurmctld.log" 2> /dev/null
  exit 1
fi
