#!/usr/bin/env bash
# The Slurm backend against a real single-node Slurm: munged, slurmctld and slurmd started here, by
# hand, in a temporary folder (no systemd), and stopped at the end. A tiny check-exponent study runs
# once locally and once as a Slurm job array; every result must be the local one, bit for bit (only
# the wall-clock columns may differ). Also: a second call while the runs are still queued,
# a task that ended without a result is submitted again, and --wait. (Bad backend options, which
# need no Slurm: cli_test.sh backend_bad_input_exit_2.)
# Usage: slurm_test.sh DEMSCALE SOURCE_DIR. Exit 77 (CTest: skipped) where Slurm cannot start.
set -u
demscale=$1 src=$2
skip() { echo "SKIP: $* (tools/install-deps.sh --tests installs Slurm; the test starts it as root)"; exit 77; }
fail() { echo "FAIL [slurm]: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || skip "starting slurmctld, slurmd and munged needs root"
for tool in munged slurmctld slurmd sbatch squeue sinfo scancel; do
  command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] || skip "$tool is not installed"
done
export PATH="$PATH:/usr/sbin"

work=$(mktemp -d)
pids=()
stop_cluster() {
  scancel --user=root >/dev/null 2>&1
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  [ -s "$work/munged.pid" ] && kill "$(cat "$work/munged.pid")" 2>/dev/null
  wait 2>/dev/null
  rm -rf "$work"
}
trap stop_cluster EXIT

# The cluster: one node, this machine's cores, ports of our own so a real cluster is not disturbed.
node=$(hostname -s) cores=$(nproc) port=$((20000 + RANDOM % 4000 * 2))
mkdir -p "$work/munge" "$work/state" "$work/spool" && chmod 700 "$work/munge"
head -c 1024 /dev/urandom >"$work/munge.key" && chmod 400 "$work/munge.key"
munged --force --socket="$work/munge/sock" --key-file="$work/munge.key" --log-file="$work/munged.log" \
  --pid-file="$work/munged.pid" --seed-file="$work/munged.seed" || skip "munged did not start: $(tail -2 "$work/munged.log" 2>/dev/null)"
cat >"$work/slurm.conf" <<CONF
ClusterName=demscaletest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/munge/sock
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cores State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -D -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 & pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$work/slurmd.out" 2>&1 & pids+=($!)
for _ in $(seq 60); do
  [ "$(sinfo --noheader --format=%T 2>/dev/null)" = idle ] && break
  sleep 0.5
done
[ "$(sinfo --noheader --format=%T 2>/dev/null)" = idle ] ||
  skip "the node did not come up: $(tail -3 "$work/slurmctld.log" "$work/slurmd.log" 2>/dev/null | tr '\n' ' ')"
echo "single-node Slurm up: node $node, $cores CPUs, port $port"

# The wall-clock columns (wall_s, speedup_wall) dropped from every CSV table, and the cost line
# (cached runs and wall time differ by design); the rest kept as is.
physics() {
  awk -F, -v OFS=, '
    /^cost: / { next }
    /^#/ || NF == 0 { drop = ""; print; next }
    /(^|,)wall_s(,|$)/ { drop = ","; for (i = 1; i <= NF; i++) if ($i == "wall_s" || $i == "speedup_wall") drop = drop i "," }
    { line = ""; for (i = 1; i <= NF; i++) if (index(drop, "," i ",") == 0) line = line (line == "" ? "" : OFS) $i; print line }' "$1"
}
study=(check-exponent --exponent 1 --scene "$src/data/scenes/small_wet.toml" --sf 1.4 --seeds 2 --no-png --format csv)
cd "$work" || fail "no work folder"

"$demscale" "${study[@]}" --cache local --out local_out >local.csv 2>local.err
local_rc=$?
case $local_rc in 0 | 1 | 4) ;; *) cat local.err >&2; fail "the local study failed (exit $local_rc)" ;; esac

# First call: the eight runs (fine and S_f 1.4, two seeds each, and their dry control) go to Slurm, exit 5.
"$demscale" "${study[@]}" --cache slurm --out slurm_out --backend slurm >slurm.csv 2>slurm.err
rc=$?
[ $rc -eq 5 ] || { cat slurm.err >&2; fail "first slurm call: exit $rc, expected 5 (runs pending)"; }
grep -q 'submitted 8 run(s) as Slurm job array' slurm.err || { cat slurm.err >&2; fail "no submission line"; }
grep -q 'run the same command again to collect' slurm.err || fail "no hint how to collect"
[ ! -e slurm_out ] || fail "a pending call wrote outputs"
job=$(sed -n 's/.*as Slurm job array \([0-9]*\).*/\1/p' slurm.err)
# A second call at once: nothing new is submitted while the tasks are queued or running.
"$demscale" "${study[@]}" --cache slurm --out slurm_out --backend slurm >/dev/null 2>again.err
rc=$?
if [ $rc -eq 5 ]; then
  grep -q '0 run(s) submitted' again.err || { cat again.err >&2; fail "second call submitted again"; }
fi
for _ in $(seq 600); do
  [ -z "$(squeue --noheader --jobs="$job" 2>/dev/null)" ] && break
  sleep 1
done
[ -z "$(squeue --noheader --jobs="$job" 2>/dev/null)" ] || fail "job $job still queued after 10 minutes"

# Collecting: the same exit code and the same results as the local study.
"$demscale" "${study[@]}" --cache slurm --out slurm_out --backend slurm >slurm.csv 2>slurm.err
rc=$?
[ $rc -eq $local_rc ] || { cat slurm.err "$work"/slurm/slurm/logs/* >&2; fail "collecting call: exit $rc, the local study's $local_rc"; }
grep -q '8 cached, 0 to run' slurm.err || fail "collecting call did not read the 8 runs from the cache"
diff <(physics local.csv) <(physics slurm.csv) || fail "the study's tables differ from the local ones"
for f in local_out/*.csv; do
  diff <(physics "$f") <(physics "slurm_out/${f#local_out/}") || fail "$f differs"
done
n=0
for f in local/*.csv; do
  key=$(basename "$f" .csv)
  cmp "$f" "slurm/$key.csv" || fail "final particle state $key.csv differs"
  diff <(grep -v '"wall_s"\|"threads"' "local/$key.json") <(grep -v '"wall_s"\|"threads"' "slurm/$key.json") ||
    fail "cached result $key.json differs"
  n=$((n + 1))
done
[ $n -eq 8 ] || fail "expected 8 cached runs, found $n"
echo "8 runs on Slurm equal the local ones, bit for bit (wall times aside)"

# A run whose task ended without a result is submitted again; --wait then collects in one call.
lost=$(basename "$(ls slurm/*.json | head -1)" .json)
rm "slurm/$lost.json" "slurm/$lost.csv"
"$demscale" "${study[@]}" --cache slurm --out slurm_out --backend slurm --wait >slurm.csv 2>slurm.err
rc=$?
[ $rc -eq $local_rc ] || { cat slurm.err >&2; fail "--wait: exit $rc, expected $local_rc"; }
grep -q "run $lost left the queue without a result" slurm.err || { cat slurm.err >&2; fail "the lost run was not named"; }
grep -q 'submitted 1 run(s)' slurm.err || fail "the lost run was not submitted again"
diff <(physics local.csv) <(physics slurm.csv) || fail "tables differ after the lost run came back"
cmp "local/$lost.csv" "slurm/$lost.csv" || fail "the rerun's final state differs"

# LIGGGHTS as the array's tasks: each task settles its fill and runs mpirun -np 2 liggghts inside
# the task, and the study judges what comes back (the local trip: tests/cli/liggghts_test.sh).
# shellcheck source=../cli/need_liggghts.sh
. "$src/tests/cli/need_liggghts.sh"
if need_liggghts; then
  lig=("${study[@]}" --baseline none --engine liggghts --ranks 2 --cache lig --out lig_out --backend slurm --wait)
  "$demscale" "${lig[@]}" >lig.csv 2>lig.err
  rc=$?
  case $rc in 0 | 1 | 4) ;; *) cat lig.err lig/slurm/logs/* >&2; fail "the LIGGGHTS study on Slurm failed (exit $rc)" ;; esac
  grep -q 'submitted 4 run(s) as Slurm job array' lig.err || { cat lig.err >&2; fail "the 4 LIGGGHTS runs were not submitted"; }
  n=0
  for d in lig/liggghts/*/; do
    grep -q 'on 2 procs' "$d/log.liggghts" || fail "$d: LIGGGHTS did not run on 2 ranks in its task"
    n=$((n + 1))
  done
  [ $n -eq 4 ] || fail "expected 4 LIGGGHTS runs, found $n"
  echo "4 LIGGGHTS runs on 2 ranks each, as Slurm array tasks, judged"
else
  echo "note: no LIGGGHTS trip through Slurm: $why_no_liggghts"
fi

echo "ok"
