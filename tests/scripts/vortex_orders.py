#!/usr/bin/env python3
"""Observed orders of the isentropic vortex's L2 errors (docs/gpr-model.md 3.1) between two meshes, each run with
--check: fails if an order is below its bound. Bounds are given per error as NAME=MIN (specific_volume, velocity,
energy); floor=MAX bounds the fine mesh's specific-volume error by MAX times the mesh's geometric floor
(apps/vortex_floor.py: its cells moved exactly). The other arguments after the sizes are passed to unilag (--set ...).

usage: vortex_orders.py UNILAG SCENE WORKDIR COARSE_SIZE FINE_SIZE NAME=MIN [NAME=MIN ...] [--set KEY=VALUE ...]
"""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps"))
from vortex_floor import floor  # noqa: E402

unilag, scene, work, coarse, fine = sys.argv[1:6]
bounds, extra = {}, []
for a in sys.argv[6:]:
    if extra or a.startswith("--"):
        extra.append(a)
    else:
        name, value = a.split("=")
        bounds[name] = float(value)
rows = []
for size in (coarse, fine):
    out = f"{work}/vortex_h{size}"
    subprocess.run([unilag, "run", scene, "--quiet", "--check", "--set", f"mesh.size={size}", "--set",
                    "output.interval=1e30", "--output", out] + extra, check=True) # dumps at t = 0 and the end
    with open(f"{out}/summary.json") as f:
        s = json.load(f)
    rows.append(s["l2_error"])
    geometric = floor(f"{out}/unilag_000000.h5", s["t_final"])[0]
    print(f"size {size}: cells {s['cells']}, h_final {s['l2_error']['h_final']:.4f}, " +
          ", ".join(f"L2 {k} {s['l2_error'][k]:.4e}" for k in ("specific_volume", "velocity", "energy")) +
          f", geometric floor of specific_volume {geometric:.4e}")
ok = True
if "floor" in bounds:
    ratio, limit = rows[1]["specific_volume"] / geometric, bounds.pop("floor")
    ok = ratio <= limit
    print(f"specific_volume / geometric floor on the fine mesh: {ratio:.3f} (bound {limit}) {'ok' if ok else 'FAIL'}")
for name, low in bounds.items():
    order = math.log(rows[0][name] / rows[1][name]) / math.log(rows[0]["h_final"] / rows[1]["h_final"])
    passed = order >= low
    ok = ok and passed
    print(f"order of {name}: {order:.2f} (bound {low}) {'ok' if passed else 'FAIL'}")
print("vortex_orders:", "PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
