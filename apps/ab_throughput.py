#!/usr/bin/env python3
"""Throughput of two builds compared by alternating runs (A B A B ...): the variant_step microbenchmarks (one whole
step per physics variant, 64k cells, 1 thread) and the 64k-cell 2D Sedov run at 1 and 2 threads. Prints the median
cells/s (or cell-steps/s) of each and the median of the A-B pairs' ratios B/A, and writes them as CSV.

usage: ab_throughput.py BUILD_A BUILD_B OUT.csv [ROUNDS] [BENCH_FILTER] [--no-sedov]
  BUILD_*: build folders holding apps/unilag and apps/unilag_bench (e.g. build/release of two checkouts)
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

import script_args

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEDOV = [os.path.join(ROOT, "inputs", "sedov2d.yaml"), "--quiet", "--set", "mesh.size=0.0072", "--set",
         "time.end=0.15", "--set", "output.enabled=false"]


def bench(build, flt):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
        subprocess.run([os.path.join(build, "apps", "unilag_bench"), f"--benchmark_filter={flt}",
                        f"--benchmark_out={out.name}", "--benchmark_out_format=json"], env=env, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return {b["name"]: b["cells/s"] for b in json.load(open(out.name))["benchmarks"]}


def sedov(build, threads):
    with tempfile.TemporaryDirectory() as d:
        env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false")
        subprocess.run([os.path.join(build, "apps", "unilag"), "run", *SEDOV, "--output", d], env=env, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return json.load(open(os.path.join(d, "summary.json")))["cell_steps_per_second"]


def main():
    args = script_args.positional(3, __doc__, 5, flags=("--no-sedov",))
    a, b, out = args[:3]
    rest = args[3:]
    rounds = int(rest[0]) if rest else 5
    flt = rest[1] if len(rest) > 1 else "variant_step/.*/64k"
    cases = [(f"^{n}$", n) for n in bench(a, flt)]  # one warm-up pass, which also lists the cases
    if "--no-sedov" not in sys.argv:
        cases += [(t, f"sedov2d_64k/{t}thread") for t in (1, 2)]
    rows = []
    # Each case is run A then B, round after round: a pair shares the machine's load of the moment, so the
    # median of the pairs' ratios resists the slow drifts a shared machine has.
    for key, name in cases:
        va, vb = [], []
        for _ in range(rounds):
            for build, values in ((a, va), (b, vb)):
                values.append(sedov(build, key) if name.startswith("sedov") else bench(build, key)[name])
        ratio = statistics.median(y / x for x, y in zip(va, vb))
        rows.append((name, statistics.median(va), statistics.median(vb), ratio, va, vb))
        print(f"{name:48s} {rows[-1][1] / 1e6:9.3f} {rows[-1][2] / 1e6:9.3f} {ratio:6.3f}", flush=True)
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "median_A", "median_B", "median_ratio_B_over_A", "A", "B"])
        for name, ma, mb, ratio, va, vb in rows:
            w.writerow([name, f"{ma:.6g}", f"{mb:.6g}", f"{ratio:.4f}", " ".join(f"{v:.4g}" for v in va),
                        " ".join(f"{v:.4g}" for v in vb)])


if __name__ == "__main__":
    main()
