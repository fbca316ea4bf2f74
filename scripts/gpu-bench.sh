#!/usr/bin/env bash
# The kernels on a GPU: builds apps/bench_portable.cpp for CUDA (Kokkos 3.4 from the same Trilinos 13.2 source as
# scripts/setup.sh, with the nvcc on PATH), and runs it where a GPU is. docs/parallel.md 7 has the figures.
#
#   scripts/gpu-bench.sh build        Kokkos for CUDA (cached) and build/gpu-bench/unilag_bench_portable; needs
#                                     scripts/setup.sh's source cache and nvcc (tested: CUDA 13.0), no GPU
#   scripts/gpu-bench.sh run OUTDIR   on the GPU machine (carry build/gpu-bench): for each physics variant the
#                                     self-check, the comparison with the CPU build and the throughput; then the
#                                     hydro step's against mesh size, numbered in order and shuffled; CSVs to OUTDIR
#   scripts/gpu-bench.sh resources    nvcc's registers and per-thread stack frame of each kernel (after build)
#   UNILAG_DEPS=/some/dir             the cache of scripts/setup.sh (default ~/.cache/unilag)
#
# Kokkos 3.4 predates CUDA 12 and 13 and Hopper: four patches, applied to a copy of its source, make it build
# and run there.
#  - nvcc_wrapper's default architecture sm_35 is gone from nvcc: sm_80 (its PTX runs on later GPUs, Hopper too).
#  - cuda_fp16.h's __half no longer converts as Kokkos 3.4's half_t expects: half_t falls back to float (unused).
#  - cudaMemPrefetchAsync takes a cudaMemLocation and flags since CUDA 13 (managed memory only; unused here).
#  - Kokkos refuses a GPU of another major compute capability than compiled for: a later one runs the PTX.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEPS="${UNILAG_DEPS:-${XDG_CACHE_HOME:-$HOME/.cache}/unilag}"
OUT_BIN="$ROOT/build/gpu-bench"
PHYSICS="hydro elastic plastic heat plastic_heat"
log() { printf '[gpu-bench] %s\n' "$*" >&2; }

build() {
  command -v nvcc >/dev/null || { log "no nvcc on PATH"; exit 1; }
  local cuda tree src prefix stamp id
  cuda=$(nvcc --version | sed -n 's/.*release \([0-9.]*\).*/\1/p')
  tree="$DEPS/src/tree"
  [ -f "$tree/packages/kokkos/CMakeLists.txt" ] || bash "$ROOT/scripts/setup.sh" >/dev/null
  prefix="$DEPS/kokkos-3.4-cuda$cuda-sm80"
  stamp="$prefix/.unilag-stamp"
  id="kokkos-3.4 cuda-$cuda sm80 serial patches-v2"
  src="$DEPS/kokkos-cuda$cuda-src"
  export NVCC_WRAPPER_DEFAULT_COMPILER=g++
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$id" ]; then
    log "Kokkos for CUDA $cuda cached at $prefix"
  else
    rm -rf "$src" "$prefix" "$src-build"
    cp -r "$tree/packages/kokkos" "$src"
    patch_kokkos "$src"
    log "building Kokkos 3.4 for CUDA $cuda (sm_80; about 5 minutes on 2 cores)"
    cmake -S "$src" -B "$src-build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
      -DCMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper" -DCMAKE_CXX_STANDARD=17 -DKokkos_ENABLE_CUDA=ON \
      -DKokkos_ENABLE_CUDA_LAMBDA=ON -DKokkos_ENABLE_SERIAL=ON -DKokkos_ARCH_AMPERE80=ON -DKokkos_ENABLE_TESTS=OFF \
      > "$src-build.log" 2>&1 || { tail -30 "$src-build.log"; exit 1; }
    cmake --build "$src-build" >> "$src-build.log" 2>&1 || { grep -A3 "error" "$src-build.log" | head -40; exit 1; }
    cmake --install "$src-build" > /dev/null
    rm -rf "$src-build"
    echo "$id" > "$stamp"
  fi
  mkdir -p "$OUT_BIN"
  cmake -S "$ROOT/tests/cuda" -B "$ROOT/build/gpu-bench-cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper" -DKokkos_ROOT="$prefix" > "$ROOT/build/gpu-bench-cmake.log" 2>&1 \
    || { tail -30 "$ROOT/build/gpu-bench-cmake.log"; exit 1; }
  cmake --build "$ROOT/build/gpu-bench-cmake" --target unilag_bench_portable 2>&1 | tail -5
  cp "$ROOT/build/gpu-bench-cmake/unilag_bench_portable" "$OUT_BIN/"
  # the CUDA runtime it links travels with it (the GPU machine's may not be on its library path)
  cp -L "$(ldd "$OUT_BIN/unilag_bench_portable" | awk '/libcudart/ {print $3}')" "$OUT_BIN/"
  # the CPU build's states after 20 steps of each physics variant, the references of `run`
  local cpu="$ROOT/build/release/apps/unilag_bench_portable" physics
  [ -x "$cpu" ] || bash "$ROOT/scripts/build.sh" >/dev/null
  rm -f "$OUT_BIN"/cpu*.bin
  for physics in $PHYSICS; do
    OMP_NUM_THREADS=2 "$cpu" --dim 2 --physics "$physics" --sizes 64 --dump "$OUT_BIN/cpu2d_$physics.bin" >/dev/null
    OMP_NUM_THREADS=2 "$cpu" --dim 3 --physics "$physics" --sizes 12 --dump "$OUT_BIN/cpu3d_$physics.bin" >/dev/null
  done
  log "built $OUT_BIN/unilag_bench_portable (CUDA $cuda, sm_80 code and PTX)"
}

patch_kokkos() {
  local k="$1"
  sed -i 's/^default_arch="sm_35"/default_arch="sm_80"/' "$k/bin/nvcc_wrapper"
  sed -i '0,/^#if !(defined(KOKKOS_COMPILER_CLANG)/s//#if 0 \&\& !(defined(KOKKOS_COMPILER_CLANG)/' \
    "$k/core/src/Cuda/Kokkos_Cuda_Half.hpp"
  python3 - "$k/core/src/Cuda/Kokkos_CudaSpace.cpp" <<'PY'
import sys
path = sys.argv[1]
text = open(path).read()
old = """    CUDA_SAFE_CALL(cudaMemPrefetchAsync(ptr, bytes, space.cuda_device(),
                                        space.cuda_stream()));"""
new = """#if CUDA_VERSION >= 13000
    CUDA_SAFE_CALL(cudaMemPrefetchAsync(ptr, bytes, cudaMemLocation{cudaMemLocationTypeDevice, space.cuda_device()},
                                        0, space.cuda_stream()));
#else
""" + old + "\n#endif"
assert old in text, "Kokkos_CudaSpace.cpp: the prefetch call to patch is not there"
open(path, "w").write(text.replace(old, new))
PY
  # the PTX of sm_80 runs on any later GPU (the driver compiles it at start); Kokkos 3.4 asks for the same major
  local same='if (compiled_major != cudaProp.major || compiled_minor > cudaProp.minor)'
  local later='if (compiled_major > cudaProp.major ||'
  later+=' (compiled_major == cudaProp.major \&\& compiled_minor > cudaProp.minor))'
  sed -i "s/$same/$later/" "$k/core/src/Cuda/Kokkos_Cuda_Instance.cpp"
  grep -q 'if (compiled_major > cudaProp.major' "$k/core/src/Cuda/Kokkos_Cuda_Instance.cpp" \
    || { log "the Kokkos patch of the architecture check did not apply"; exit 1; }
  grep -q '^default_arch="sm_80"' "$k/bin/nvcc_wrapper" \
    && grep -q '^#if 0 && !(defined(KOKKOS_COMPILER_CLANG)' "$k/core/src/Cuda/Kokkos_Cuda_Half.hpp" \
    || { log "a Kokkos patch did not apply"; exit 1; }
}

run() {
  local out="$1" bin="$OUT_BIN/unilag_bench_portable" rc=0
  export LD_LIBRARY_PATH="$OUT_BIN${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  mkdir -p "$out"
  nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem,memory.total --format=csv | tee "$out/gpu.txt"
  local physics
  # 1. Each physics variant: self-check, and the comparison with the CPU build's state after 20 steps (the dumps
  #    travel in build/gpu-bench), then the throughput on a mesh that fills the GPU.
  for physics in $PHYSICS; do
    "$bin" --dim 2 --physics "$physics" --sizes 64 --compare "$OUT_BIN/cpu2d_$physics.bin" || rc=1
    "$bin" --dim 3 --physics "$physics" --sizes 12 --compare "$OUT_BIN/cpu3d_$physics.bin" || rc=1
    "$bin" --dim 2 --physics "$physics" --sizes 1024 --steps 5 --csv "$out/gpu2d_$physics.csv" || rc=1
    "$bin" --dim 3 --physics "$physics" --sizes 64 --steps 5 --csv "$out/gpu3d_$physics.csv" || rc=1
  done
  # 2. The hydro step's throughput against mesh size, numbered in order and shuffled.
  "$bin" --dim 2 --sizes 128,256,512,1024,2048 --steps 5 --csv "$out/gpu2d.csv" || rc=1
  "$bin" --dim 2 --sizes 512,2048 --steps 5 --shuffle --csv "$out/gpu2d_shuffled.csv" || rc=1
  "$bin" --dim 3 --sizes 16,32,64,96 --steps 5 --csv "$out/gpu3d.csv" || rc=1
  "$bin" --dim 3 --sizes 64 --steps 5 --shuffle --csv "$out/gpu3d_shuffled.csv" || rc=1
  return $rc
}

# nvcc's resource report of every kernel of the benchmark (registers, per-thread stack frame: arrays indexed at run
# time live there, in local memory; spills), one line per launcher, variant and dimension. No GPU needed.
resources() {
  local dir="$ROOT/build/gpu-bench-ptxas" src prefix
  src=$(ls -d "$DEPS"/kokkos-cuda*-src | tail -1)
  prefix=$(ls -d "$DEPS"/kokkos-3.4-cuda*-sm80 | tail -1)
  [ -x "$src/bin/nvcc_wrapper" ] && [ -d "$prefix" ] || { log "run scripts/gpu-bench.sh build first"; exit 1; }
  NVCC_WRAPPER_DEFAULT_COMPILER=g++ cmake -S "$ROOT/tests/cuda" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper" -DKokkos_ROOT="$prefix" -DCMAKE_CXX_FLAGS="-Xptxas=-v" >/dev/null
  cmake --build "$dir" --target clean >/dev/null
  NVCC_WRAPPER_DEFAULT_COMPILER=g++ cmake --build "$dir" --target unilag_bench_portable > "$dir.log" 2>&1
  python3 - "$dir.log" <<'PY'
import re, subprocess, sys
rows, cur = [], None
for line in open(sys.argv[1]):
    m = re.search(r"Compiling entry function '(\S+)'", line)
    if m:
        cur = [m.group(1), 0, 0, 0]
        rows.append(cur)
    elif cur and (m := re.search(r"(\d+) bytes stack frame, (\d+) bytes spill stores", line)):
        cur[2], cur[3] = int(m.group(1)), int(m.group(2))
    elif cur and (m := re.search(r"Used (\d+) registers", line)):
        cur[1] = int(m.group(1))
names = subprocess.run(["c++filt"], input="\n".join(r[0] for r in rows), capture_output=True, text=True).stdout
seen = set()
for row, name in zip(rows, names.split("\n")):
    m = re.search(r"unilag::(\w+)<(\d), unilag::Physics<(\w+), (\w+), (\w+)>", name)
    if not m:
        continue
    kernel = m.group(1)
    if kernel == "MechanicalQuantities":  # the gradients' two kernels, named by their function
        kernel = "nodeSums" if "unilag::nodeSums<" in name else "limitedGradients"
    if re.search(r"MechanicalQuantities<\d, unilag::Physics<[^>]*> >, true>", name):  # the one with vertex bounds
        kernel += "+vertex"
    tag = "%s %sD strain,plastic,heat=%s" % (kernel, m.group(2), "".join("1" if b == "true" else "0"
                                                                         for b in m.groups()[2:]))
    if tag not in seen:
        seen.add(tag)
        print("%-51s registers %3d  stack %5d B  spill %d B" % (tag, row[1], row[2], row[3]))
PY
}

case "${1:-}" in
  build) build ;;
  resources) resources ;;
  run) run "${2:?scripts/gpu-bench.sh run OUTDIR}" ;;
  *) echo "usage: scripts/gpu-bench.sh build | run OUTDIR | resources" >&2; exit 2 ;;
esac
