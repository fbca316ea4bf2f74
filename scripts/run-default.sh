#!/usr/bin/env bash
# README command 1: set up, build, and run the default scene (2D Sedov, about 16k triangles) on all cores.
# Extra arguments go to `unilag run`, e.g. scripts/run-default.sh --set mesh.size=0.0072
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
./build/release/apps/unilag run inputs/sedov2d.yaml --output output/sedov2d "$@"
echo "open output/sedov2d/unilag.xmf in ParaView; the run's figures are in output/sedov2d/summary.json"
