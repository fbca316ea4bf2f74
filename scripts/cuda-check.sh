#!/usr/bin/env bash
# GPU compile check: are kernels/ and the tube launchers nvcc-clean? Compiles them with Debian's nvcc (CUDA 11.8,
# package nvidia-cuda-toolkit from bookworm's contrib / non-free) against Kokkos 3.4 from the same Trilinos 13.2
# source as scripts/setup.sh, built for CUDA (Ampere, sm_80) into a cached prefix. Needs no GPU; object files only.
# Opt-in (the toolkit is 1.6 GB of packages); where installed, ctest runs it too (--if-installed). Idempotent.
#
#   scripts/cuda-check.sh          install what is missing, build Kokkos for CUDA once, compile the check
#   scripts/cuda-check.sh --if-installed
#                                  only the check, where the toolkit and the CUDA Kokkos are already there; else
#                                  exit 77 (ctest's test cuda_compile_check: skipped on machines without them)
#   UNILAG_DEPS=/some/dir          the cache of scripts/setup.sh (default ~/.cache/unilag)
set -euo pipefail
IF_INSTALLED=0
if [ "${1:-}" = "--if-installed" ]; then IF_INSTALLED=1; fi

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEPS="${UNILAG_DEPS:-${XDG_CACHE_HOME:-$HOME/.cache}/unilag}"
KOKKOS_PREFIX="$DEPS/kokkos-3.4-cuda"
STAMP="$KOKKOS_PREFIX/.unilag-stamp"
STAMP_ID="kokkos-3.4 cuda-11.8 ampere80 serial v1"
log() { printf '[cuda-check] %s\n' "$*" >&2; }
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# Debian's toolkit, not another nvcc on PATH (a machine may carry /usr/local/cuda of another version); g++-11 is
# the newest host compiler CUDA 11.8 accepts.
export PATH="/usr/bin:$PATH" CUDA_ROOT=/usr NVCC_WRAPPER_DEFAULT_COMPILER=g++-11

TREE="$DEPS/src/tree"
WRAPPER="$TREE/packages/kokkos/bin/nvcc_wrapper"
toolkit_installed() { [ -x /usr/bin/nvcc ] && command -v g++-11 >/dev/null; }
kokkos_cached() { [ -x "$WRAPPER" ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$STAMP_ID" ]; }

# ---------------------------------------------------------------- 1. Debian's CUDA toolkit and g++-11
install_toolkit() {
  bash "$ROOT/scripts/setup.sh" >/dev/null # Debian packages, deb-src entry, Trilinos' source in the cache
  if toolkit_installed; then
    log "nvidia-cuda-toolkit installed"
  else
    if ! apt-cache policy nvidia-cuda-toolkit 2>/dev/null | grep -q "Candidate: [0-9]"; then
      log "adding bookworm's contrib and non-free components (nvidia-cuda-toolkit)"
      $SUDO tee /etc/apt/sources.list.d/unilag-nonfree.sources >/dev/null <<'SRC'
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: contrib non-free
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
      $SUDO apt-get update -qq
    fi
    log "installing nvidia-cuda-toolkit and g++-11 (about 1.6 GB)"
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends nvidia-cuda-toolkit g++-11 \
      >/dev/null
  fi
}

# ---------------------------------------------------------------- 2. Kokkos 3.4 for CUDA, from Trilinos' source
build_kokkos() {
  if [ ! -f "$TREE/packages/kokkos/CMakeLists.txt" ]; then
    log "unpacking Trilinos' source (Debian's package)"
    mkdir -p "$DEPS/src"
    (cd "$DEPS/src" && { ls trilinos_*.dsc >/dev/null 2>&1 || apt-get source --download-only trilinos >/dev/null; } \
      && rm -rf tree && dpkg-source --no-check -x trilinos_*.dsc tree >/dev/null)
  fi
  if kokkos_cached; then
    log "Kokkos for CUDA cached at $KOKKOS_PREFIX"
  else
    BUILD="$DEPS/kokkos-cuda-build"
    rm -rf "$BUILD" "$KOKKOS_PREFIX"
    log "building Kokkos 3.4 for CUDA (sm_80; about 2 minutes on 2 cores)"
    cmake -S "$TREE/packages/kokkos" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_INSTALL_PREFIX="$KOKKOS_PREFIX" -DCMAKE_CXX_COMPILER="$WRAPPER" -DCMAKE_CXX_STANDARD=17 \
      -DKokkos_ENABLE_CUDA=ON -DKokkos_ENABLE_CUDA_LAMBDA=ON -DKokkos_ENABLE_SERIAL=ON -DKokkos_ARCH_AMPERE80=ON \
      -DKokkos_ENABLE_TESTS=OFF > "$DEPS/kokkos-cuda-configure.log" 2>&1 \
      || { tail -30 "$DEPS/kokkos-cuda-configure.log"; exit 1; }
    cmake --build "$BUILD" > "$DEPS/kokkos-cuda-build.log" 2>&1 || { tail -30 "$DEPS/kokkos-cuda-build.log"; exit 1; }
    cmake --install "$BUILD" > /dev/null
    rm -rf "$BUILD"
    echo "$STAMP_ID" > "$STAMP"
  fi
}

if [ "$IF_INSTALLED" = 0 ]; then
  install_toolkit
  build_kokkos
elif ! { toolkit_installed && kokkos_cached; }; then
  log "skipped: no CUDA toolkit or CUDA Kokkos here (scripts/cuda-check.sh installs them)"
  exit 77
fi

# ---------------------------------------------------------------- 3. the check
CHECK="$ROOT/build/cuda-check"
cmake -S "$ROOT/tests/cuda" -B "$CHECK" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$WRAPPER" \
  -DKokkos_ROOT="$KOKKOS_PREFIX" > "$CHECK.configure.log" 2>&1 || { tail -30 "$CHECK.configure.log"; exit 1; }
t0=$(date +%s)
cmake --build "$CHECK" --target clean >/dev/null # every run compiles all: an object built with warnings stays built
if ! cmake --build "$CHECK" 2>&1 | tee "$CHECK.log" | grep -E "error|warning" | head -40; then :; fi
# A host call in device code is only a warning to nvcc (#20011-D), and a crash on a GPU: any warning fails.
if grep -q "FAILED:" "$CHECK.log" || grep -qi "warning" "$CHECK.log"; then
  log "FAILED: nvcc rejects or warns about the code above (full log: $CHECK.log)"
  exit 1
fi
version=$(nvcc --version | sed -n 's/.*release \([0-9.]*\).*/\1/p')
log "kernels/ and the tube launchers compile for CUDA sm_80 with nvcc $version ($(( $(date +%s) - t0 )) s)"
