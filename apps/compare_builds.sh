#!/usr/bin/env bash
# Bitwise regression between two builds of unilag: runs every regression scene at order 1 and 2 (short end times)
# with one binary into DIR, or compares two such folders at 0 tolerance (every dataset of every dump, steps.csv,
# and the stderr of runs that stop).
#
#   apps/compare_builds.sh run UNILAG DIR        run the scene set with UNILAG, output under DIR
#   apps/compare_builds.sh compare DIR_A DIR_B   0-tolerance comparison; exit 1 on any difference
set -uo pipefail
cd "$(dirname "$0")/.."
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# name | scene | options (both orders are run unless the name ends in @1)
CASES=(
  "sedov2d|inputs/sedov2d.yaml|--set mesh.size=0.0288 --set time.end=0.3 --set output.interval=0.1"
  "sedov3d|inputs/sedov3d.yaml|--set time.end=0.15"
  "gpr3d|tests/scenes/sedov3d_viscous_heat.yaml|--set time.end=0.1"
  "kidder2d|inputs/kidder2d.yaml|--set mesh.size=0.02"
  "be_shell|inputs/be_shell2d.yaml|--set mesh.geometry=geometry/shell_wedge2d.geo --set mesh.size=0.0014 --set time.end=6e-6"
  "be_plate|inputs/be_plate2d.yaml|--set mesh.geometry=geometry/plate_half2d.geo --set boundaries.left.type=symmetry --set time.end=6e-6"
  "impact2d|inputs/impact2d.yaml|--set time.end=2e-6"
  "viscous_shock|inputs/viscous_shock2d.yaml|--set time.end=0.1"
  "heat|inputs/heat_conduction2d.yaml|--set time.end=0.05"
  "tau1_m14|tests/scenes/tau1_sweep.yaml|--set materials.gas.strain_relaxation.tau1=1e-14 --set time.end=0.1"
  "tau1_m6|tests/scenes/tau1_sweep.yaml|--set materials.gas.strain_relaxation.tau1=1e-6 --set time.end=0.1"
  "tau1_1|tests/scenes/tau1_sweep.yaml|--set materials.gas.strain_relaxation.tau1=1 --set time.end=0.1"
  "tau1_p14|tests/scenes/tau1_sweep.yaml|--set materials.gas.strain_relaxation.tau1=1e14 --set time.end=0.1"
  "traction|tests/scenes/traction_wave.yaml|--set time.end=0.1"
  "mg_piston|tests/scenes/mg_piston.yaml|"
  "free|tests/scenes/free_expansion.yaml|"
  "collapse@1|tests/scenes/piston_collapse.yaml|"
  "picard_cap@1|tests/scenes/traction_wave.yaml|--set scheme.picard_max_iterations=2 --set time.max_retries=3"
)
MPI_CASES=(
  "sedov2d_np3|inputs/sedov2d.yaml|--set mesh.size=0.0288 --set time.end=0.2"
  "impact2d_np3|inputs/impact2d.yaml|--set time.end=1e-6"
)

run_one() { # binary dir name scene order np options...
  local bin=$1 dir=$2 name=$3 scene=$4 order=$5 np=$6
  shift 6
  local out="$dir/${name}_o${order}"
  rm -rf "$out"
  if [ "$np" = 1 ]; then
    "$bin" run "$scene" --quiet --set scheme.order="$order" --output "$out" "$@" >/dev/null 2>"$out.stderr"
  else
    mpirun --oversubscribe -np "$np" "$bin" run "$scene" --quiet --set scheme.order="$order" --output "$out" "$@" \
      >/dev/null 2>"$out.stderr"
  fi
  echo "$?" >"$out.rc"
  echo "$name order $order: exit $(cat "$out.rc")"
}

case "${1:-}" in
run)
  bin=$(realpath "$2") dir=$3
  mkdir -p "$dir"
  for c in "${CASES[@]}"; do
    IFS='|' read -r name scene opts <<<"$c"
    orders="1 2"
    [[ $name == *@1 ]] && orders=1 && name=${name%@1}
    # shellcheck disable=SC2086
    for o in $orders; do run_one "$bin" "$dir" "$name" "$scene" "$o" 1 $opts; done
  done
  for c in "${MPI_CASES[@]}"; do
    IFS='|' read -r name scene opts <<<"$c"
    # shellcheck disable=SC2086
    for o in 1 2; do OMP_NUM_THREADS=1 run_one "$bin" "$dir" "$name" "$scene" "$o" 3 $opts; done
  done
  ;;
compare)
  /usr/bin/python3 - "$2" "$3" <<'PY'
import glob, os, sys
import h5py, numpy as np
a, b = sys.argv[1], sys.argv[2]
bad = 0

def cellwise(f, n):
    """A dataset in global-id order, so that runs whose (measured, timing-dependent) repartitions put the cells in
    another order compare equal: cells by global_id, each cell's nodes by their coordinates; the rank is skipped."""
    if "global_id" not in f:
        return f[n][...]
    order = np.argsort(f["global_id"][:, 0], kind="stable")
    if n == "rank":
        return None
    if n == "coordinates":  # compared through the connectivity
        return None
    if n == "connectivity":
        return f["coordinates"][...][f[n][...]][order]
    return f[n][...][order]
for rc in sorted(glob.glob(f"{a}/*.rc")):
    case = os.path.basename(rc)[:-3]
    da, db = f"{a}/{case}", f"{b}/{case}"
    diffs = []
    for ext in (".rc", ".stderr"):
        ta, tb = open(da + ext).read(), open(db + ext).read()
        if ta != tb:
            diffs.append(f"{ext}: {ta.strip()[:200]!r} vs {tb.strip()[:200]!r}")
    if os.path.exists(f"{da}/steps.csv"):
        if open(f"{da}/steps.csv").read() != open(f"{db}/steps.csv").read():
            diffs.append("steps.csv differs")
    ha, hb = sorted(glob.glob(f"{da}/*.h5")), sorted(glob.glob(f"{db}/*.h5"))
    if [os.path.basename(f) for f in ha] != [os.path.basename(f) for f in hb]:
        diffs.append(f"dumps {len(ha)} vs {len(hb)}")
    for fa in ha:
        fb = f"{db}/{os.path.basename(fa)}"
        if not os.path.exists(fb):
            continue
        with h5py.File(fa) as A, h5py.File(fb) as B:
            names = []
            A.visit(lambda n: names.append(n) if isinstance(A[n], h5py.Dataset) else None)
            for n in names:
                if n not in B:
                    diffs.append(f"{os.path.basename(fa)}:{n} missing")
                    continue
                va, vb = cellwise(A, n), cellwise(B, n)
                if va is not None and not np.array_equal(va, vb):
                    d = np.abs(va - vb).max() if va.shape == vb.shape else np.inf
                    diffs.append(f"{os.path.basename(fa)}:{n} max diff {d:.3e}")
    print(f"{case}: {'identical' if not diffs else 'DIFFERENT'} ({len(ha)} dumps)")
    for d in diffs[:8]:
        print("   ", d)
    bad += bool(diffs)
print(f"{bad} case(s) differ")
sys.exit(1 if bad else 0)
PY
  ;;
*)
  sed -n 2,7p "$0"
  exit 2
  ;;
esac
