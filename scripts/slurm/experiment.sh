#!/usr/bin/env bash
# Runs `lowdisc experiment` on a cluster: plans it into independent units,
# runs the units on Slurm as one job array (or with GNU parallel) and merges
# them into the same report, results.json and images as the one-machine run.
#
#   scripts/slurm/experiment.sh [SCRIPT OPTIONS] --out DIR [EXPERIMENT OPTIONS]
#
# EXPERIMENT OPTIONS are those of `lowdisc experiment` (scene, --samplers,
# --runs, --paper, --quick, ...) and go to `lowdisc experiment plan ... --out
# DIR`. If DIR/plan.json exists already, it is reused when no experiment
# options are given or they make the same plan (lowdisc refuses another):
# units already done are skipped, so resubmitting after a failure runs only
# what is left.
#
# Slurm (the default runner): the units become one array job
#   sbatch --array=0-(N-1)%K ... lowdisc experiment unit DIR --index $SLURM_ARRAY_TASK_ID
# and the merge a job that starts when every unit succeeded
#   sbatch --dependency=afterok:ARRAY --kill-on-invalid-dep=yes ... lowdisc experiment merge DIR
# The script prints both job ids and returns; watch with
# `lowdisc experiment status DIR`. DIR and the lowdisc binary must be on a file
# system that every node sees. Slurm's logs go to DIR/slurm/.
#
# SCRIPT OPTIONS
#   --partition P       sbatch --partition=P for every job
#   --time T            sbatch --time=T (a unit's time limit; also the merge's)
#   --max-running K     at most K units at once (the array's %K; default: no limit)
#   --cpus-per-task C   cores per unit: sbatch --cpus-per-task=C and the
#                       unit's --threads C (default: Slurm's one core per
#                       task, and the unit renders on every core it may use)
#   --sbatch-arg ARG    one more sbatch argument for every job (repeatable),
#                       e.g. --sbatch-arg=--account=rendering
#   --lowdisc BIN       the lowdisc binary (default: $LOWDISC, else `lowdisc`
#                       on PATH, else this checkout's target/release/lowdisc)
#   --parallel          run the units here with GNU parallel instead of Slurm:
#                         parallel lowdisc experiment unit DIR --index {} ::: $(seq 0 N-1)
#                       then the merge; waits, and fails if any unit failed
#   --jobs J            GNU parallel: units at once (default 1; a unit uses
#                       every core unless --cpus-per-task is given)
#   --parallel-arg ARG  one more argument for GNU parallel (repeatable), e.g.
#                       --parallel-arg=--sshloginfile=nodes.txt to fan out over ssh
set -euo pipefail

die() {
  echo "experiment.sh: $*" >&2
  exit 1
}

partition="" time_limit="" max_running="" cpus="" out="" lowdisc="${LOWDISC:-}"
runner=slurm jobs=1
sbatch_extra=() parallel_extra=() exp_args=()
# Both `--opt value` and `--opt=value`.
while [ $# -gt 0 ]; do
  opt=$1
  case "$opt" in
  --*=*)
    val=${opt#*=}
    opt=${opt%%=*}
    shift
    set -- "$opt" "$val" "$@"
    continue
    ;;
  esac
  case "$opt" in
  --partition | --time | --max-running | --cpus-per-task | --sbatch-arg | --lowdisc | --jobs | --parallel-arg | --out)
    [ $# -ge 2 ] || die "$opt needs a value"
    val=$2
    shift 2
    case "$opt" in
    --partition) partition=$val ;;
    --time) time_limit=$val ;;
    --max-running) max_running=$val ;;
    --cpus-per-task) cpus=$val ;;
    --sbatch-arg) sbatch_extra+=("$val") ;;
    --lowdisc) lowdisc=$val ;;
    --jobs) jobs=$val ;;
    --parallel-arg) parallel_extra+=("$val") ;;
    --out) out=$val ;;
    esac
    ;;
  --parallel)
    runner=parallel
    shift
    ;;
  -h | --help)
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
    exit 0
    ;;
  *)
    exp_args+=("$opt")
    shift
    ;;
  esac
done

[ -n "$out" ] || die "--out DIR is required (the plan's folder)"
# `positive OPTION VALUE`: VALUE is empty (not given) or a positive integer.
positive() {
  case "$2" in
  '') ;;
  *[!0-9]* | 0*) die "$1 needs a positive integer, got '$2'" ;;
  esac
}
positive --max-running "$max_running"
positive --cpus-per-task "$cpus"
positive --jobs "$jobs"

# The binary, as an absolute path (jobs run in other folders, on other nodes).
if [ -z "$lowdisc" ]; then
  if command -v lowdisc >/dev/null 2>&1; then
    lowdisc=$(command -v lowdisc)
  else
    lowdisc="$(cd "$(dirname "$0")/../.." && pwd)/target/release/lowdisc"
  fi
fi
case "$lowdisc" in /*) ;; */*) lowdisc="$(pwd)/$lowdisc" ;; *) lowdisc=$(command -v "$lowdisc" || true) ;; esac
[ -x "$lowdisc" ] || die "no lowdisc binary at '$lowdisc' (build it: cargo build --release -p lowdisc-cli, or pass --lowdisc BIN)"

mkdir -p "$out"
dir="$(cd "$out" && pwd)"
plan="$dir/plan.json"
if [ -f "$plan" ] && [ ${#exp_args[@]} -eq 0 ]; then
  echo "experiment.sh: reusing $plan"
else
  # An existing plan.json is kept if these options make the same plan, and
  # refused (with an error) if they make another.
  "$lowdisc" experiment plan "${exp_args[@]}" --out "$dir"
  [ -f "$plan" ] || die "lowdisc experiment plan wrote no $plan"
fi

# The number of units: the length of plan.json's "units" list.
units=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["units"]))' "$plan") ||
  die "cannot read the unit list of $plan"
[ "$units" -gt 0 ] || die "$plan lists no units"
last=$((units - 1))
echo "experiment.sh: $units units in $plan"

q_lowdisc=$(printf %q "$lowdisc")
q_dir=$(printf %q "$dir")
threads=""
[ -z "$cpus" ] || threads=" --threads $cpus"

if [ "$runner" = parallel ]; then
  command -v parallel >/dev/null 2>&1 || die "GNU parallel is not installed (Debian: apt-get install parallel)"
  mapfile -t indices < <(seq 0 "$last")
  failed=0
  parallel --jobs "$jobs" "${parallel_extra[@]}" \
    "$q_lowdisc experiment unit $q_dir --index {}$threads" ::: "${indices[@]}" || failed=$?
  [ "$failed" -eq 0 ] || die "$failed unit(s) failed (see $dir/units/*.failed; rerun the same command to retry them)"
  "$lowdisc" experiment merge "$dir"
  exit 0
fi

command -v sbatch >/dev/null 2>&1 || die "sbatch not found (use --parallel to run without Slurm)"
common=(--chdir="$dir")
[ -z "$partition" ] || common+=(--partition="$partition")
[ -z "$time_limit" ] || common+=(--time="$time_limit")
common+=("${sbatch_extra[@]}")
unit_opts=()
[ -z "$cpus" ] || unit_opts+=(--cpus-per-task="$cpus")
mkdir -p "$dir/slurm"

# An array's indices stay below the cluster's MaxArraySize (1001 by default),
# so a larger plan goes in as several arrays, each with its offset.
max_array=$(scontrol show config 2>/dev/null | sed -n 's/^MaxArraySize *= *\([0-9]*\).*/\1/p')
chunk=$((${max_array:-1001} - 1))
throttle=""
[ -z "$max_running" ] || throttle="%$max_running"
array_jobs=()
for ((offset = 0; offset < units; offset += chunk)); do
  size=$((units - offset < chunk ? units - offset : chunk))
  job=$(sbatch --parsable "${common[@]}" "${unit_opts[@]}" \
    --job-name=lowdisc-unit --array="0-$((size - 1))$throttle" \
    --output="$dir/slurm/unit-%A_%a.out" \
    --wrap="exec $q_lowdisc experiment unit $q_dir --index \$((SLURM_ARRAY_TASK_ID + $offset))$threads")
  job=${job%%;*}
  array_jobs+=("$job")
  echo "experiment.sh: units $offset..$((offset + size - 1)): array job $job"
done

deps=$(
  IFS=:
  echo "${array_jobs[*]}"
)
merge=$(sbatch --parsable "${common[@]}" --job-name=lowdisc-merge \
  --dependency="afterok:$deps" --kill-on-invalid-dep=yes \
  --output="$dir/slurm/merge-%j.out" \
  --wrap="exec $q_lowdisc experiment merge $q_dir")
merge=${merge%%;*}
echo "experiment.sh: merge job $merge (after every unit succeeded)"
echo "experiment.sh: watch with: $q_lowdisc experiment status $q_dir   (or: squeue -j ${deps//:/,},$merge)"
echo "ARRAY_JOBS=${deps//:/,}"
echo "MERGE_JOB=$merge"
