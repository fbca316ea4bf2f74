#!/usr/bin/env python3
"""Kidder's isentropic shell compression (gamma = 2, imposed boundary pressures) to h(t) = 1/2 on three meshes:
the error of the inner radius (exact 0.45) must fall at about first order, the outer radius (exact 0.5) must be
within 1%, and every run must conserve (--check).

usage: kidder_convergence.py UNILAG SCENE WORKDIR
"""
import json
import math
import subprocess
import sys

unilag, scene, work = sys.argv[1:4]
sizes = [0.01, 0.005, 0.0025]
rows = []
for h in sizes:
    out = f"{work}/kidder_h{h}"
    subprocess.run([unilag, "run", scene, "--quiet", "--check", "--set", "exact.radius_tolerance=0", "--set",
                    f"mesh.size={h}", "--set", "output.enabled=false", "--output", out], check=True)
    with open(f"{out}/summary.json") as f:
        s = json.load(f)
    r = s["boundary_mean_radius"]
    rows.append((h, s["cells"], abs(r["inner"] - 0.45) / 0.45, abs(r["outer"] - 0.5) / 0.5))
    print(f"h={h:<7} cells={s['cells']:<6} inner={r['inner']:.5f} (error {rows[-1][2]:.2%}) "
          f"outer={r['outer']:.5f} (error {rows[-1][3]:.2%})")
ok = True
for a, b in zip(rows, rows[1:]):
    order = math.log(a[2] / b[2]) / math.log(a[0] / b[0])
    print(f"inner-radius error order {a[1]}->{b[1]} cells: {order:.2f}")
    if order < 0.8:
        ok = False
for row in rows:
    if row[3] > 0.01:
        print(f"FAIL: outer radius error {row[3]:.2%} > 1% on {row[1]} cells")
        ok = False
print("kidder_convergence:", "PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
