#!/usr/bin/env bash
# A sweep on a Dask cluster whose machines are all this one: the steps of docs/guide/sweeps.md
# ("On a Dask cluster, step by step") with 127.0.0.1 for every machine.
#
#   studies/dask_local_cluster.sh SWEEP.toml [femgear sweep options ...]
#
# 1. starts `dask scheduler` (a free port, no dashboard) and reads its address from its log;
# 2. starts two `dask worker ADDRESS --nworkers 1 --nthreads 1` processes in this working directory
#    and waits until both have registered with the scheduler;
# 3. runs `femgear sweep SWEEP.toml --scheduler ADDRESS` and returns its exit status;
# 4. stops the workers and the scheduler (also on Ctrl-C or an error).
# Environment: DASK (the dask command, default `dask`), FEMGEAR (the femgear command, default `femgear`,
# e.g. "python -m femgear"), PORT (scheduler port, default 0: any free port), LOGS (folder of the three
# logs, default a new temporary folder).  Run it from the folder the sweep's relative paths start from.
set -euo pipefail
if [[ $# -lt 1 ]]; then
    echo "usage: $0 SWEEP.toml [femgear sweep options ...]" >&2
    exit 2
fi
sweep=$1
shift
DASK=${DASK:-dask}
FEMGEAR=${FEMGEAR:-femgear}
PORT=${PORT:-0}
LOGS=${LOGS:-$(mktemp -d)}
mkdir -p "$LOGS"
pids=()
stop() {
    local p
    for ((i = ${#pids[@]} - 1; i >= 0; i--)); do      # workers first, the scheduler last
        p=${pids[i]}
        kill "$p" 2>/dev/null || true
        wait "$p" 2>/dev/null || true
    done
}
trap stop EXIT

# step 1: the scheduler
$DASK scheduler --host 127.0.0.1 --port "$PORT" --no-dashboard >"$LOGS/scheduler.log" 2>&1 &
pids+=($!)
address=""
for _ in $(seq 1 120); do
    address=$(grep -o "Scheduler at: *tcp://[0-9.]*:[0-9]*" "$LOGS/scheduler.log" | grep -o "tcp://.*" || true)
    [[ -n $address ]] && break
    sleep 0.5
done
if [[ -z $address ]]; then
    echo "the scheduler did not start; see $LOGS/scheduler.log" >&2
    exit 1
fi
echo "scheduler at $address (logs in $LOGS)" >&2

# step 2: two workers, one thread each, started in this (shared) working directory
for n in 1 2; do
    $DASK worker "$address" --nworkers 1 --nthreads 1 --no-dashboard --name "worker-$n" >"$LOGS/worker-$n.log" 2>&1 &
    pids+=($!)
done
for _ in $(seq 1 240); do
    [[ $(grep -c "Register worker" "$LOGS/scheduler.log" || true) -ge 2 ]] && break
    sleep 0.5
done
echo "$(grep -c "Register worker" "$LOGS/scheduler.log" || true) workers registered" >&2

# step 3: the sweep
set +e
$FEMGEAR sweep "$sweep" --scheduler "$address" "$@"
status=$?
set -e
exit $status
