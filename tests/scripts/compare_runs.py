#!/usr/bin/env python3
"""Compare the final cell fields of unilag runs (e.g. on 1, 2, 3 ranks), matched by global cell id.

usage: compare_runs.py RTOL DIR_A DIR_B [DIR_C ...]
       compare_runs.py RTOL DIR_A DIR_B [DIR_C ...] [-- DIR_D DIR_E [...] ...]
Exits 1 if any field differs by more than RTOL relative to its largest magnitude; prints the differences.

Every dataset of the last dump (unilag_NNNNNN.h5) is compared, not a fixed list: the runs must have the same last dump
(same NNNNNN) with the same set of datasets. Cell datasets are matched by global_id; the node coordinates (and any
node dataset) through each cell's corners (connectivity), since node and cell numbering depend on the partition;
`rank` must be present but its values are not compared (they are the partition). summary.json must agree too:
'status' and 'steps' exactly, 't_final' (and the dump's XDMF time, where there is one) within RTOL, and where it has
one its 'largest_density' (value and time within RTOL, the cell's id where they are equal).
RTOL = 0 asks for bitwise-identical results. `--` starts another group, compared within itself (one process for
several comparisons).
"""
import glob
import json
import os
import re
import sys

import h5py
import numpy as np

# datasets whose values are expected to differ between partitions: compared by presence only
PARTITION = {"rank"}


def fail(msg):
    print(f"compare_runs: FAIL, {msg}")
    sys.exit(1)


def last_dump(d):
    """The last dump of folder d: its name, time (from its .xmf, or None), datasets in a partition-free order."""
    files = sorted(glob.glob(f"{d}/unilag_*.h5"))
    if not files:
        sys.exit(f"compare_runs: no unilag_*.h5 in {d}")
    name = files[-1]
    with h5py.File(name, "r") as f:
        data = {k: f[k][...] for k in f if isinstance(f[k], h5py.Dataset)}
        groups = [k for k in f if not isinstance(f[k], h5py.Dataset)]
    if groups:
        fail(f"{name} has groups {groups}; this script compares flat dumps only")
    for k in ("global_id", "connectivity", "coordinates"):
        if k not in data:
            fail(f"{name} has no '{k}'")
    gid = data["global_id"][:, 0]
    order = np.argsort(gid, kind="stable")
    ncells, nnodes = len(gid), len(data["coordinates"])
    corners = data["connectivity"][order]
    fields = {"global_id": gid[order]}
    for k, a in data.items():
        if k in ("global_id", "connectivity"):
            continue
        if k in PARTITION:
            fields[k] = None
        elif len(a) == ncells and len(a) != nnodes:
            fields[k] = a[order]
        elif len(a) == nnodes and len(a) != ncells:
            fields[k] = a[corners]  # (cells, corners, components), in global cell order
        else:
            fail(f"{name}: dataset {k} has {len(a)} rows, neither the {ncells} cells nor the {nnodes} nodes alone")
    t = None
    xmf = name[:-3] + ".xmf"
    if os.path.exists(xmf):
        m = re.search(r'<Time Value="([^"]+)"', open(xmf).read())
        t = float(m.group(1)) if m else None
    return name, t, fields


def summary(d):
    try:
        with open(f"{d}/summary.json") as f:
            s = json.load(f)
    except (OSError, ValueError) as e:
        fail(f"cannot read {d}/summary.json: {e}")
    for k in ("status", "steps", "t_final"):
        if k not in s:
            fail(f"{d}/summary.json has no '{k}'")
    return s


def rel(a, b, scale):
    return abs(a - b) / max(abs(scale), 1e-300)


def compare(dirs):
    """The largest relative difference of dirs[1:] from dirs[0]; exits on a structural difference."""
    ref_dir = dirs[0]
    ref_name, ref_t, ref = last_dump(ref_dir)
    ref_sum = summary(ref_dir)
    worst = 0.0
    for d in dirs[1:]:
        name, t, other = last_dump(d)
        s = summary(d)
        if os.path.basename(name) != os.path.basename(ref_name):
            fail(f"last dump {name} vs {ref_name}: a different number of dumps")
        for k in ("status", "steps"):
            if s[k] != ref_sum[k]:
                fail(f"summary.json '{k}': {s[k]} in {d} vs {ref_sum[k]} in {ref_dir}")
        diff = rel(s["t_final"], ref_sum["t_final"], ref_sum["t_final"])
        if "largest_density" in ref_sum:  # the run's largest cell density, when and where: the same on any partition
            a, b = ref_sum["largest_density"], s.get("largest_density")
            if b is None:
                fail(f"summary.json has no 'largest_density' in {d}")
            peak = max(rel(b["value"], a["value"], a["value"]), rel(b["t"], a["t"], a["t"]))
            if peak == 0.0 and b["cell"] != a["cell"]:
                fail(f"summary.json 'largest_density': cell {b['cell']} in {d} vs {a['cell']} in {ref_dir}")
            diff = max(diff, peak)
        if ref_t is not None and t is not None:
            diff = max(diff, rel(t, ref_t, ref_t))
        worst = max(worst, diff)
        print(f"{d} vs {ref_dir}: steps {s['steps']}, final time relative difference {diff:.3e}")
        if set(other) != set(ref):
            fail(f"datasets differ: only in {ref_name}: {sorted(set(ref) - set(other))}, "
                 f"only in {name}: {sorted(set(other) - set(ref))}")
        for k in sorted(ref):
            if ref[k] is None:
                continue
            if other[k].shape != ref[k].shape:
                fail(f"{k}: shape {other[k].shape} in {name} vs {ref[k].shape} in {ref_name}")
            scale = max(float(np.abs(ref[k]).max(initial=0.0)), 1e-300)
            diff = float(np.abs(other[k].astype(np.float64) - ref[k]).max(initial=0.0)) / scale
            if np.isnan(diff) or np.isnan(other[k]).any() != np.isnan(ref[k]).any():
                diff = np.inf
            worst = max(worst, diff)
            print(f"{name} vs {ref_name}: {k} max relative difference {diff:.3e}")
    return worst


def main():
    args = sys.argv[1:]
    if len(args) < 3:
        sys.exit(__doc__)
    rtol = float(args[0])
    groups = [[]]
    for a in args[1:]:
        if a == "--":
            groups.append([])
        else:
            groups[-1].append(a)
    if any(len(g) < 2 for g in groups):
        sys.exit(__doc__)
    worst = max(compare(g) for g in groups)
    if not worst <= rtol:
        fail(f"{worst:.3e} > {rtol:.1e}")
    print(f"compare_runs: PASS ({worst:.3e} <= {rtol:.1e})")


if __name__ == "__main__":
    main()
