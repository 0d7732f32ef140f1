#!/usr/bin/env bash
# The cost of running the experiment through a Slurm job array instead of in
# one process, measured on this machine (so the point is overhead, not
# speed-up):
#
#   (a) `lowdisc experiment [EXPERIMENT OPTIONS]` on one machine;
#   (b) the same experiment through scripts/slurm/experiment.sh on a
#       single-node Slurm brought up here (local-cluster.sh): the plan, one
#       job array of units, C cores each, and the merge job;
#
# each in its own folder, so each renders its references into a fresh
# cache. Prints both wall times (b: from the plan to the merge job's end,
# polled each second), the sum of the units' own wall times, the load
# average around each run, and checks with same_results.py that the merged
# results.json and images equal the one-machine run's. Exits non-zero on
# any failure; stops the daemons it started.
#
#   scripts/slurm/overhead.sh [--lowdisc BIN] [--cpus-per-task C] [EXPERIMENT OPTIONS]
#
# Without EXPERIMENT OPTIONS it runs the README's default experiment
# (`lowdisc experiment --out ...`: 10 samplers, 256x144, 16 spp, 8 runs).
# LOWDISC_KEEP_WORK=1 keeps both runs' outputs (the folder is printed).
# C defaults to every core (`nproc`): one unit at a time on the whole
# machine, as the one-machine run renders. The binary is BIN, else $LOWDISC,
# else this checkout's target/release/lowdisc. Needs root (as test_local.sh).
# LOWDISC_SLURM_TEST_TIMEOUT (default 7200) bounds the wait for the jobs, in
# seconds.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
timeout_s="${LOWDISC_SLURM_TEST_TIMEOUT:-7200}"
lowdisc="${LOWDISC:-$root/target/release/lowdisc}"
cpus=$(nproc)
exp_opts=()
while [ $# -gt 0 ]; do
  case "$1" in
  --lowdisc)
    lowdisc=${2:?--lowdisc needs a value}
    shift 2
    ;;
  --cpus-per-task)
    cpus=${2:?--cpus-per-task needs a value}
    shift 2
    ;;
  -h | --help)
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
    exit 0
    ;;
  *)
    exp_opts+=("$1")
    shift
    ;;
  esac
done

fail() {
  echo "overhead: FAIL: $*" >&2
  exit 1
}
step() { echo "== overhead: $*"; }

case "$lowdisc" in /*) ;; *) lowdisc="$(pwd)/$lowdisc" ;; esac
[ -x "$lowdisc" ] || fail "no lowdisc binary at $lowdisc (build it: cargo build --release -p lowdisc-cli, or pass --lowdisc BIN)"

work=$(mktemp -d "${TMPDIR:-/tmp}/lowdisc-overhead.XXXXXX")
# shellcheck source=jobs.sh
. "$here/jobs.sh"

step "packages and cluster"
local_cluster_up

load() { cut -d' ' -f1-3 /proc/loadavg; }
# Seconds since `start`, to the millisecond.
since() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }

step "(a) one machine: lowdisc experiment ${exp_opts[*]}"
mkdir -p "$work/single"
load_a0=$(load)
start=$EPOCHREALTIME
"$lowdisc" experiment "${exp_opts[@]}" --quiet --out "$work/single/out"
single_s=$(since "$start")
load_a1=$(load)
echo "one machine: $single_s s"

step "(b) Slurm job array: experiment.sh --cpus-per-task $cpus ${exp_opts[*]}"
mkdir -p "$work/slurm"
load_b0=$(load)
start=$EPOCHREALTIME
"$here/experiment.sh" --lowdisc "$lowdisc" --cpus-per-task "$cpus" \
  --out "$work/slurm/out" "${exp_opts[@]}" | tee "$work/slurm/submit.log"
array=$(sed -n 's/^ARRAY_JOBS=//p' "$work/slurm/submit.log")
merge=$(sed -n 's/^MERGE_JOB=//p' "$work/slurm/submit.log")
if [ -z "$array" ] || [ -z "$merge" ]; then fail "experiment.sh printed no job ids"; fi
wait_jobs "$array,$merge"
slurm_s=$(since "$start")
load_b1=$(load)
echo "Slurm array: $slurm_s s"

step "merged results equal the one-machine run's"
python3 "$here/same_results.py" "$work/single/out" "$work/slurm/out" ||
  fail "the merged results differ from the one-machine run's"

units_s=$(python3 - "$work/slurm/out/units" <<'PY'
import json, pathlib, sys
records = [json.loads(p.read_text()) for p in pathlib.Path(sys.argv[1]).glob("*.json")]
print(f"{len(records)} units, {sum(r['wall_time_s'] for r in records):.1f}")
PY
)
echo "overhead: one machine ${single_s} s (load ${load_a0} -> ${load_a1});" \
  "Slurm array ${slurm_s} s (load ${load_b0} -> ${load_b1}; ${units_s%%,*} of" \
  "--cpus-per-task ${cpus}, their own wall times adding up to ${units_s#*, } s);" \
  "merged results equal"
