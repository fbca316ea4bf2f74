#!/usr/bin/env bash
# expect_rerun_clears.sh OUTDIR "LONG ARGS" "SHORT ARGS" -- COMMAND...: runs COMMAND LONG ARGS into OUTDIR, adds
# files of the user's there, then COMMAND SHORT ARGS into the same OUTDIR. Asserts: the short run leaves exactly its
# own dumps (fewer than the long run's; no unilag_NNNNNN.h5/.xmf of the long run survives; every dump is in
# unilag.xmf), summary.json and steps.csv are the short run's, and the user's files (notes.txt, unilag_mine.h5, a
# folder keep/ holding unilag_000099.h5) are untouched: a run removes only its own outputs, by name.
set -u
out=$1; long=$2; short=$3; shift 4
rm -rf "$out"
# shellcheck disable=SC2086  # LONG and SHORT are word lists on purpose
"$@" $long --output "$out" >/dev/null || { echo "FAIL: the long run failed"; exit 1; }
nlong=$(ls "$out"/unilag_[0-9]*.h5 | wc -l)
echo "long run: $nlong dumps"
echo "my notes" > "$out/notes.txt"
echo "mine" > "$out/unilag_mine.h5"
mkdir -p "$out/keep" && echo "mine" > "$out/keep/unilag_000099.h5"
# shellcheck disable=SC2086
"$@" $short --output "$out" >/dev/null || { echo "FAIL: the short run failed"; exit 1; }
nshort=$(ls "$out"/unilag_[0-9]*.h5 | wc -l)
echo "short run: $nshort dumps"
[ "$nshort" -lt "$nlong" ] || { echo "FAIL: the short run should write fewer dumps than the long one"; exit 1; }
nxmf=$(ls "$out"/unilag_[0-9]*.xmf | wc -l)
[ "$nxmf" -eq "$nshort" ] || { echo "FAIL: $nxmf step .xmf files beside $nshort dumps"; exit 1; }
listed=$(grep -o 'unilag_[0-9]*\.xmf' "$out/unilag.xmf" | sort -u | wc -l)
[ "$listed" -eq "$nshort" ] || { echo "FAIL: unilag.xmf lists $listed dumps, the folder holds $nshort"; exit 1; }
rows=$(($(wc -l < "$out/steps.csv") - 1))
steps=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["steps"])' "$out/summary.json")
[ "$rows" -eq "$steps" ] || { echo "FAIL: steps.csv has $rows rows, summary.json says $steps steps"; exit 1; }
[ "$(cat "$out/notes.txt")" = "my notes" ] || { echo "FAIL: notes.txt was touched"; exit 1; }
[ -f "$out/unilag_mine.h5" ] && [ -f "$out/keep/unilag_000099.h5" ] || { echo "FAIL: a file of the user's was removed"; exit 1; }
echo "expect_rerun_clears: PASS"
