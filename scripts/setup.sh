#!/usr/bin/env bash
# unilag set-up: Debian packages + Trilinos 13.2 (Kokkos OpenMP+Serial, Teuchos, Tpetra, Zoltan2, MPI)
# built from Debian's source package into a cached prefix. Idempotent: a second call returns in seconds.
#
#   scripts/setup.sh            install what is missing, build Trilinos once
#   UNILAG_DEPS=/some/dir       where the Trilinos prefix and its build cache live (default ~/.cache/unilag)
#   UNILAG_JOBS=N               parallel compile jobs for Trilinos (default: nproc)
set -euo pipefail

DEPS="${UNILAG_DEPS:-${XDG_CACHE_HOME:-$HOME/.cache}/unilag}"
PREFIX="$DEPS/trilinos-13.2-omp"
STAMP="$PREFIX/.unilag-stamp"
STAMP_ID="trilinos-13.2 kokkos-openmp-serial tpetra-zoltan2 mpi v1"
JOBS="${UNILAG_JOBS:-$(nproc)}"

log() { printf '[setup] %s\n' "$*" >&2; }
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# ---------------------------------------------------------------- 1. Debian packages
PKGS=(build-essential cmake ninja-build pkg-config dpkg-dev xz-utils
      libopenmpi-dev openmpi-bin libhdf5-openmpi-dev libgmsh-dev gmsh
      libgtest-dev libbenchmark-dev liblapack-dev libblas-dev libmuparser-dev
      python3-matplotlib python3-h5py python3-numpy python3-scipy paraview python3-paraview)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# ---------------------------------------------------------------- 2. Trilinos 13.2 with Kokkos OpenMP
if [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$STAMP_ID" ]; then
  log "Trilinos cached at $PREFIX"
  echo "$PREFIX"
  exit 0
fi

t0=$(date +%s)
SRC_CACHE="$DEPS/src"
mkdir -p "$SRC_CACHE"
if ! ls "$SRC_CACHE"/trilinos_*.dsc >/dev/null 2>&1; then
  # Debian's source package: a deb-src entry for bookworm, then download only.
  if ! grep -rqs "^Types:.*deb-src" /etc/apt/sources.list.d/ && ! grep -qs "^deb-src" /etc/apt/sources.list; then
    log "adding a deb-src entry for bookworm"
    $SUDO tee /etc/apt/sources.list.d/unilag-deb-src.sources >/dev/null <<'SRC'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
    $SUDO apt-get update -qq
  fi
  log "downloading Debian's trilinos source package"
  (cd "$SRC_CACHE" && apt-get source --download-only trilinos >/dev/null)
fi
TREE="$SRC_CACHE/tree"
if [ ! -f "$TREE/CMakeLists.txt" ]; then
  log "unpacking source (with Debian's patches)"
  rm -rf "$TREE"
  (cd "$SRC_CACHE" && dpkg-source --no-check -x trilinos_*.dsc tree >/dev/null)
fi

BUILD="$DEPS/trilinos-build"
rm -rf "$BUILD" "$PREFIX"
mkdir -p "$BUILD"
log "configuring Trilinos (Kokkos OpenMP+Serial, Teuchos, Tpetra, Zoltan2, MPI)"
cmake -S "$TREE" -B "$BUILD" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$PREFIX" \
  -DBUILD_SHARED_LIBS=ON \
  -DCMAKE_C_COMPILER=mpicc -DCMAKE_CXX_COMPILER=mpicxx \
  -DCMAKE_CXX_STANDARD=17 \
  -DCMAKE_CXX_FLAGS="-w" -DCMAKE_C_FLAGS="-w" \
  -DTrilinos_ENABLE_Fortran=OFF \
  -DTrilinos_ENABLE_ALL_OPTIONAL_PACKAGES=OFF \
  -DTrilinos_ENABLE_ALL_PACKAGES=OFF \
  -DTrilinos_ENABLE_Kokkos=ON -DTrilinos_ENABLE_Teuchos=ON \
  -DTrilinos_ENABLE_Tpetra=ON -DTrilinos_ENABLE_Zoltan2=ON \
  -DTrilinos_ENABLE_OpenMP=ON -DKokkos_ENABLE_OPENMP=ON -DKokkos_ENABLE_SERIAL=ON \
  -DTpetra_INST_OPENMP=ON -DTpetra_INST_SERIAL=OFF -DTpetra_INST_INT_LONG_LONG=ON \
  -DTrilinos_ENABLE_EXPLICIT_INSTANTIATION=OFF -DKokkosKernels_ADD_DEFAULT_ETI=OFF \
  -DTPL_ENABLE_MPI=ON -DTPL_ENABLE_BLAS=ON -DTPL_ENABLE_LAPACK=ON \
  -DTrilinos_ENABLE_TESTS=OFF -DTrilinos_ENABLE_EXAMPLES=OFF \
  -DTrilinos_ENABLE_SECONDARY_TESTED_CODE=ON \
  > "$DEPS/trilinos-configure.log" 2>&1 || { tail -40 "$DEPS/trilinos-configure.log"; exit 1; }
log "building Trilinos with $JOBS jobs (about 9 minutes on 2 cores)"
cmake --build "$BUILD" -j "$JOBS" > "$DEPS/trilinos-build.log" 2>&1 || { tail -40 "$DEPS/trilinos-build.log"; exit 1; }
cmake --install "$BUILD" > "$DEPS/trilinos-install.log" 2>&1 || { tail -40 "$DEPS/trilinos-install.log"; exit 1; }
rm -rf "$BUILD"
echo "$STAMP_ID" > "$STAMP"
log "Trilinos installed in $PREFIX ($(( $(date +%s) - t0 )) s)"
echo "$PREFIX"
