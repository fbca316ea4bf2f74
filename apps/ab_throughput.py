#!/usr/bin/env python3
"""Throughput of two builds compared by alternating runs (A B A B ...): the variant_step microbenchmarks (one whole
step per physics variant, 64k cells, 1 thread) and the 64k-cell 2D Sedov run at 1 and 2 threads. Prints the median
cells/s (or cell-steps/s) of each and the ratio B/A, and writes them as CSV.

usage: ab_throughput.py BUILD_A BUILD_B OUT.csv [ROUNDS] [BENCH_FILTER]
  BUILD_*: build folders holding apps/unilag and apps/unilag_bench (e.g. build/release of two checkouts)
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

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
    a, b, out = sys.argv[1:4]
    rounds = int(sys.argv[4]) if len(sys.argv) > 4 else 3
    flt = sys.argv[5] if len(sys.argv) > 5 else "variant_step/.*/64k"
    samples = {}
    for r in range(rounds):
        for label, build in (("A", a), ("B", b)):
            for name, v in bench(build, flt).items():
                samples.setdefault(name, {"A": [], "B": []})[label].append(v)
            for t in (1, 2):
                samples.setdefault(f"sedov2d_64k/{t}thread", {"A": [], "B": []})[label].append(sedov(build, t))
        print(f"round {r + 1} of {rounds} done", flush=True)
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "median_A", "median_B", "ratio_B_over_A", "samples"])
        print(f"{'case':48s} {'A (M/s)':>9s} {'B (M/s)':>9s} {'B/A':>6s}")
        for name, s in samples.items():
            ma, mb = statistics.median(s["A"]), statistics.median(s["B"])
            w.writerow([name, f"{ma:.6g}", f"{mb:.6g}", f"{mb / ma:.4f}", len(s["A"])])
            print(f"{name:48s} {ma / 1e6:9.3f} {mb / 1e6:9.3f} {mb / ma:6.3f}")


if __name__ == "__main__":
    main()
