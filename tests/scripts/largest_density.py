#!/usr/bin/env python3
"""summary.json's largest_density is the largest cell density of the whole run: 2D Sedov on 1k triangles to t = 0.12
at the fixed step 4e-4 (below every stable step there, as in hydro_limit.py) with a dump after each, so that every
accepted state is dumped. The record
must equal the largest density over all dumps, with that dump's time, the cell's global id and its centroid; and
--check with exact.max_density just below it must fail (exit 3) naming it, just above it pass.

usage: largest_density.py UNILAG SCENE WORKDIR
"""
import glob
import json
import os
import re
import subprocess
import sys

import h5py
import numpy as np


def fail(msg):
    print(f"largest_density: FAIL, {msg}")
    sys.exit(1)


def run(unilag, scene, out, bound=None):
    """The run; with a bound, --check against it alone (the shock radius bound is for t = 1)."""
    args = [unilag, "run", scene, "--quiet", "--output", out, "--set", "mesh.size=0.0577", "--set", "time.end=0.12",
            "--set", "time.initial_dt=4e-4", "--set", "time.max_growth=1", "--set", "output.interval=4e-4"]
    if bound is not None:
        args += ["--check", "--set", "exact.shock_radius_tolerance=0", "--set", "exact.max_density=%.17g" % bound]
    return subprocess.run(args, capture_output=True, text=True)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    unilag, scene, work = sys.argv[1:]
    out = os.path.join(work, "run")
    r = run(unilag, scene, out)
    if r.returncode != 0:
        fail(f"run exited {r.returncode}: {r.stderr.strip()}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    dumps = sorted(glob.glob(os.path.join(out, "unilag_*.h5")))
    if len(dumps) != s["steps"] + 1:
        fail(f"{len(dumps)} dumps for {s['steps']} steps: not every step was dumped")
    best = (-1.0, 0.0, -1, None)
    for name in dumps:
        with open(name[:-3] + ".xmf") as f:
            t = float(re.search(r'Time Value="([^"]+)"', f.read()).group(1))
        with h5py.File(name, "r") as h:
            rho = h["density"][:, 0]
            i = int(np.argmax(rho))
            if rho[i] > best[0]:
                xy = h["coordinates"][:][h["connectivity"][i]].mean(axis=0)[:2]
                best = (float(rho[i]), t, int(h["global_id"][i, 0]), xy)
    peak = s["largest_density"]
    print(f"summary {peak}; dumps: {best[0]} at t = {best[1]} in cell {best[2]} at {best[3]}")
    if abs(peak["value"] - best[0]) > 1e-9 * best[0] or peak["cell"] != best[2]:  # JSON keeps 10 digits
        fail("the record is not the dumps' largest density")
    if abs(peak["t"] - best[1]) > 1e-12 or np.abs(np.array(peak["centroid"]) - best[3]).max() > 1e-9:
        fail("the record's time or centroid is not its dump's")
    if peak["value"] <= 1.0 + 1e-9:
        fail("no compression recorded")
    below = run(unilag, scene, os.path.join(work, "below"), 0.999 * peak["value"])
    if below.returncode != 3 or "largest cell density" not in below.stderr:
        fail(f"--check below the record: exit {below.returncode}, {below.stderr.strip()}")
    above = run(unilag, scene, os.path.join(work, "above"), 1.001 * peak["value"])
    if above.returncode != 0:
        fail(f"--check above the record: exit {above.returncode}, {above.stderr.strip()}")
    print("largest_density: PASS")


if __name__ == "__main__":
    main()
