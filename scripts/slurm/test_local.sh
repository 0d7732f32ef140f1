#!/usr/bin/env bash
# The cluster path of the experiment, tested for real on this machine:
# brings up a single-node Slurm (local-cluster.sh), runs a small experiment
# through a job array and through GNU parallel (experiment.sh), and checks
# that both merged results.json equal the one-machine run's bit for bit,
# times aside, and that every EXR image is byte-identical. Stops the daemons
# it started; exits non-zero on any failure; every wait has a timeout.
#
#   scripts/slurm/test_local.sh [EXPERIMENT OPTIONS]   (default: --quick)
#
# Needs root (apt-get, SlurmUser=root). The binary is $LOWDISC, else this
# checkout's target/debug/lowdisc (what `cargo test` builds), else it is built
# with `cargo build --profile test -p lowdisc-cli`. LOWDISC_SLURM_TEST_TIMEOUT
# (default 600) bounds each wait for Slurm jobs, in seconds.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
timeout_s="${LOWDISC_SLURM_TEST_TIMEOUT:-600}"
exp_opts=("$@")
[ ${#exp_opts[@]} -gt 0 ] || exp_opts=(--quick)

fail() {
  echo "test_local: FAIL: $*" >&2
  exit 1
}
step() { echo "== test_local: $*"; }

lowdisc="${LOWDISC:-$root/target/debug/lowdisc}"
if [ ! -x "$lowdisc" ]; then
  step "building lowdisc (cargo build --profile test -p lowdisc-cli)"
  (cd "$root" && cargo build -q --profile test -p lowdisc-cli)
fi
[ -x "$lowdisc" ] || fail "no lowdisc binary at $lowdisc"

work=$(mktemp -d "${TMPDIR:-/tmp}/lowdisc-slurm-test.XXXXXX")
# shellcheck source=jobs.sh
. "$here/jobs.sh"

step "packages and cluster"
local_cluster_up
sinfo

step "a trivial array: sbatch --array=0-3 --wrap hostname"
mkdir -p "$work/hello"
hello=$(sbatch --parsable --chdir="$work/hello" --array=0-3 --output='%a.out' --wrap hostname)
wait_jobs "${hello%%;*}"
for i in 0 1 2 3; do
  [ "$(cat "$work/hello/$i.out")" = "$(hostname)" ] || fail "array task $i printed '$(cat "$work/hello/$i.out")'"
done

# Each run in its own folder: the reference cache goes beside --out, and a
# shared cache would let a run skip its reference render.
step "one machine: lowdisc experiment ${exp_opts[*]}"
mkdir -p "$work/single"
start=$SECONDS
"$lowdisc" experiment "${exp_opts[@]}" --quiet --out "$work/single/out"
echo "one machine: $((SECONDS - start)) s"

step "Slurm job array: experiment.sh --max-running 2 ${exp_opts[*]}"
mkdir -p "$work/slurm"
start=$SECONDS
"$here/experiment.sh" --lowdisc "$lowdisc" --max-running 2 --time 30 \
  --out "$work/slurm/out" "${exp_opts[@]}" | tee "$work/slurm/submit.log"
array=$(sed -n 's/^ARRAY_JOBS=//p' "$work/slurm/submit.log")
merge=$(sed -n 's/^MERGE_JOB=//p' "$work/slurm/submit.log")
if [ -z "$array" ] || [ -z "$merge" ]; then fail "experiment.sh printed no job ids"; fi
wait_jobs "$array,$merge"
echo "Slurm array: $((SECONDS - start)) s"
"$lowdisc" experiment status "$work/slurm/out"

step "GNU parallel: experiment.sh --parallel --jobs 2 ${exp_opts[*]}"
mkdir -p "$work/parallel"
start=$SECONDS
timeout "$timeout_s" "$here/experiment.sh" --parallel --jobs 2 --lowdisc "$lowdisc" \
  --out "$work/parallel/out" "${exp_opts[@]}"
echo "GNU parallel: $((SECONDS - start)) s"

step "resubmitting a finished plan reruns no unit"
touch "$work/parallel/before-resubmit"
sleep 1
timeout "$timeout_s" "$here/experiment.sh" --parallel --lowdisc "$lowdisc" --out "$work/parallel/out"
rerun=$(find "$work/parallel/out/units" -newer "$work/parallel/before-resubmit" -type f)
[ -z "$rerun" ] || fail "resubmitting a finished plan rewrote unit files: $rerun"

step "merged results equal the one-machine run's"
for run in slurm parallel; do
  python3 "$here/same_results.py" "$work/single/out" "$work/$run/out" ||
    fail "$run: merged results differ from the one-machine run"
done
echo "test_local: OK"
