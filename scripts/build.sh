#!/usr/bin/env bash
# Set up (idempotent) and build unilag with the release preset. Prints the build folder.
set -euo pipefail
cd "$(dirname "$0")/.."
PREFIX=$(bash scripts/setup.sh)
cmake --preset release -DCMAKE_PREFIX_PATH="$PREFIX" >/dev/null
cmake --build build/release -j "$(nproc)"
