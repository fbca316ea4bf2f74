#!/usr/bin/env bash
# expect_restart.sh WORK MODE RANKS_A RANKS_B PYTHON COMPARE -- UNILAG SCENE [--set ...]: checkpoint and restart
# (README "Checkpoint and restart") end bit for bit where the uninterrupted run ends.
#   interval:T:N: the run on RANKS_A ranks writes checkpoints every T (output.checkpoint_interval) and is stopped
#             by time.max_steps = N after its first checkpoint (exit 5, status max_steps);
#   signal:   every rank of the run on RANKS_A ranks gets SIGTERM once its second dump exists: exit 6, status
#             interrupted, a checkpoint (the end of the step it was in).
# Then the run restarts from WORK/run/checkpoint.h5 on RANKS_B ranks and must end equal (RTOL 0, compare_runs.py) to
# the uninterrupted run on one rank, steps.csv included. RANKS 1 runs without mpirun.
set -u
work=$1; mode=$2; ra=$3; rb=$4; python=$5; compare=$6; shift 7
unilag=$1; shift
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
launch() { local n=$1; shift; if [ "$n" -eq 1 ]; then "$unilag" "$@"; else mpirun --oversubscribe -np "$n" "$unilag" "$@"; fi; }
rm -rf "$work"; mkdir -p "$work"
launch 1 run "$@" --quiet --output "$work/full" || { echo "FAIL: the uninterrupted run"; exit 1; }
if [ "${mode%%:*}" = interval ]; then
    IFS=: read -r _ every cap <<< "$mode"
    launch "$ra" run "$@" --quiet --set output.checkpoint_interval="$every" --set time.max_steps="$cap" --output "$work/run"
    rc=$?; want=5; status=max_steps
else
    if [ "$ra" -eq 1 ]; then
        "$unilag" run "$@" --quiet --output "$work/run" & pid=$!
    else
        mpirun --oversubscribe -np "$ra" "$unilag" run "$@" --quiet --output "$work/run" & pid=$!
    fi
    for _ in $(seq 600); do [ -e "$work/run/unilag_000002.xmf" ] && break; sleep 0.1; done
    # every rank gets the signal, as from a batch system (mpirun itself would end the job at once)
    if [ "$ra" -eq 1 ]; then kill -TERM "$pid"; else pkill -TERM -P "$pid"; fi
    wait "$pid"; rc=$?; want=6; status=interrupted
fi
echo "first run: exit $rc"
[ "$rc" -eq "$want" ] || { echo "FAIL: expected exit $want"; exit 1; }
grep -q "\"status\": \"$status\"" "$work/run/summary.json" || { echo "FAIL: status is not $status"; exit 1; }
[ -f "$work/run/checkpoint.h5" ] || { echo "FAIL: no checkpoint"; exit 1; }
[ ! -e "$work/run/checkpoint.h5.tmp" ] || { echo "FAIL: a temporary checkpoint was left"; exit 1; }
launch "$rb" run "$@" --quiet --restart "$work/run/checkpoint.h5" --output "$work/run" || { echo "FAIL: restart"; exit 1; }
cmp "$work/full/steps.csv" "$work/run/steps.csv" || { echo "FAIL: steps.csv differs"; exit 1; }
# balance.csv (written on several ranks) keeps no row of the first run past the checkpoint: its steps rise, and a
# restart on one rank (which checks nothing) ends them at the checkpoint's step (summary.json's restarted_from)
if [ -f "$work/run/balance.csv" ]; then
    from=$("$python" -c "import json, sys; print(json.load(open(sys.argv[1]))['restarted_from']['step'])" \
           "$work/run/summary.json") || { echo "FAIL: no restarted_from in summary.json"; exit 1; }
    awk -F, -v from="$from" -v rb="$rb" '(NR > 2 && $1 <= last) || (NR > 1 && rb == 1 && $1 > from) { bad = 1 }
        { last = $1 } END { exit bad }' "$work/run/balance.csv" || { echo "FAIL: balance.csv past step $from"; exit 1; }
fi
"$python" "$compare" 0 "$work/full" "$work/run" | tail -n 1
[ "${PIPESTATUS[0]}" -eq 0 ] || { echo "FAIL: the restarted run differs"; exit 1; }
echo "expect_restart: PASS"
