# shellcheck shell=bash
# Helpers shared by the scripts that run experiments on a single-node Slurm
# brought up on this machine (test_local.sh, overhead.sh). Source it after
# setting `here` (this folder), `work` (a fresh temporary folder) and
# `timeout_s`, and defining `fail MESSAGE` (prints and exits non-zero).
#
#   local_cluster_up   installs slurm-wlm, munge and parallel (apt-get) and
#                      starts the cluster (local-cluster.sh) with its state
#                      in $work/cluster; when the script exits, stops exactly
#                      the daemons it started and removes $work, or keeps it
#                      (outputs and daemon logs) if the script failed or
#                      LOWDISC_KEEP_WORK=1 is set
#   wait_jobs IDS      waits until every job of the comma-separated IDS has
#                      left the queue (polling each second, at most
#                      $timeout_s), then fails unless each one COMPLETED

local_cluster_up() {
  chmod 0755 "$work" # munged's socket lies below it
  export LOWDISC_SLURM_DIR="$work/cluster"
  export SLURM_CONF="$LOWDISC_SLURM_DIR/slurm.conf"
  "$here/local-cluster.sh" install
  trap local_cluster_down EXIT
  "$here/local-cluster.sh" start
}

local_cluster_down() {
  local status=$?
  "$here/local-cluster.sh" stop || status=1
  if [ "$status" -eq 0 ] && [ "${LOWDISC_KEEP_WORK:-0}" != 1 ]; then
    rm -rf "$work"
  else
    echo "outputs and daemon logs kept in $work" >&2
  fi
  exit "$status"
}

# scontrol keeps finished jobs for MinJobAge=300 s, long enough to read
# their final state here.
wait_jobs() {
  local jobs=$1 waited=0 id state
  while [ -n "$(squeue -h -j "$jobs" -o %i 2>/dev/null)" ]; do
    [ "$waited" -lt "$timeout_s" ] || fail "jobs $jobs still queued after ${timeout_s}s: $(squeue -j "$jobs")"
    sleep 1
    waited=$((waited + 1))
  done
  for id in ${jobs//,/ }; do
    state=$(scontrol -o show job "$id" | tr ' ' '\n' | sed -n 's/^JobState=//p' | sort -u)
    [ "$state" = COMPLETED ] || fail "job $id ended $state (logs: $work/*/out/slurm/)"
  done
}
