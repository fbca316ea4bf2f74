#!/usr/bin/env python3
"""Work-precision study: error of a boundary's final mean radius against wall time, first and second order.

Runs SCENE with scheme.order = 1 and 2 at each mesh size and prints, per run, the cells, steps, wall time, cell-steps
per second and the relative error of summary.json's boundary_mean_radius[BOUNDARY] against R_EXACT. Extra --set
options (e.g. a cheaper geometry) go after the sizes. A benchmark, not a test: it prints figures and asserts nothing.

usage: work_precision.py UNILAG SCENE BOUNDARY R_EXACT WORKDIR SIZE[,SIZE...] [--set KEY=VALUE ...]
example (Be shell, wedge, one core):
  OMP_NUM_THREADS=1 apps/work_precision.py build/release/apps/unilag inputs/be_shell2d.yaml inner 0.05 /tmp/wp \\
      0.0014,0.001,0.0007,0.0005 --set mesh.geometry=geometry/shell_wedge2d.geo
"""
import json
import os
import subprocess
import sys


def main():
    if len(sys.argv) < 7:
        sys.exit(__doc__)
    unilag, scene, boundary, r_exact, work, sizes = sys.argv[1:7]
    extra = sys.argv[7:]
    r_exact = float(r_exact)
    scene = os.path.abspath(scene)
    print(f"{'order':>5} {'h':>8} {'cells':>7} {'steps':>7} {'wall s':>8} {'cell-steps/s':>13} {'error':>9}")
    for order in (1, 2):
        for h in sizes.split(","):
            out = os.path.join(work, f"o{order}_h{h}")
            subprocess.run([unilag, "run", scene, "--quiet", "--set", f"scheme.order={order}", "--set",
                            f"mesh.size={h}", "--set", "output.interval=0", "--output", out] + extra,
                           check=True, stdout=subprocess.DEVNULL)
            with open(os.path.join(out, "summary.json")) as f:
                s = json.load(f)
            r = s["boundary_mean_radius"][boundary]
            print(f"{order:>5} {h:>8} {s['cells']:>7} {s['steps']:>7} {s['wall_seconds']:>8.1f} "
                  f"{s['cell_steps_per_second']:>13.3g} {(r - r_exact) / r_exact:>+9.2%}", flush=True)


if __name__ == "__main__":
    main()
