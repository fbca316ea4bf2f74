#!/usr/bin/env python3
"""2D Sedov on about 1k, 4k and 16k triangles: L1(density) must decrease with h, and the shock radius on the
finest mesh must be within 3% of the exact 0.9988 (docs/gpr-model.md 3.3). Every run has --check (conservation,
node balance); the 4k run also the scene bounds L1_4K and SHOCK_4K (exact.max_l1_density, shock_radius_tolerance)
when they are given.

usage: sedov_convergence.py UNILAG SCENE WORKDIR [L1_4K SHOCK_4K]
"""
import json
import subprocess
import sys

unilag, scene, work = sys.argv[1:4]
bounds4k = []
if len(sys.argv) == 6:
    bounds4k = ["--set", f"exact.max_l1_density={sys.argv[4]}", "--set", f"exact.shock_radius_tolerance={sys.argv[5]}"]
sizes = [0.0577, 0.0288, 0.0144]
rows = []
for h in sizes:
    out = f"{work}/sedov2d_h{h}"
    subprocess.run([unilag, "run", scene, "--quiet", "--check", "--set", f"mesh.size={h}", "--set",
                    "output.enabled=false", "--output", out] + (bounds4k if h == 0.0288 else []), check=True)
    with open(f"{out}/summary.json") as f:
        s = json.load(f)
    rows.append((h, s["cells"], s["l1_density_error"], s["shock_radius"], s["steps"]))
    print(f"h={h:<7} cells={s['cells']:<6} steps={s['steps']:<5} L1(density)={s['l1_density_error']:.4e} "
          f"shock radius={s['shock_radius']:.4f}")
ok = True
for a, b in zip(rows, rows[1:]):
    if not b[2] < a[2]:
        print(f"FAIL: L1 does not decrease from {a[1]} to {b[1]} cells ({a[2]:.4e} -> {b[2]:.4e})")
        ok = False
    else:
        print(f"observed order {a[1]}->{b[1]} cells: {__import__('math').log(a[2] / b[2]) / __import__('math').log(a[0] / b[0]):.2f}")
err = abs(rows[-1][3] - 0.9988) / 0.9988
print(f"finest shock radius {rows[-1][3]:.4f}, relative error {err:.2%} (bound 3%)")
if err > 0.03:
    ok = False
print("sedov_convergence:", "PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
