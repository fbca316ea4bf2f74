#!/usr/bin/env python3
"""Check a tube stability run's output folder: stability.csv against tube.md 2.1's u_cf (0.5%), and the PNG.

Usage: tube_stability.py OUTPUT_DIR [--png]
"""
import csv
import json
import sys

REFERENCE = {0.0: 4.478, 0.2: 5.59, 0.5: 9.32}


def main():
    folder = sys.argv[1]
    with open(f"{folder}/stability.csv") as f:
        rows = list(csv.DictReader(f))
    ok = True
    for r in rows:
        beta, ucf = float(r["beta"]), float(r["u_cf"])
        if beta in REFERENCE:
            err = abs(ucf - REFERENCE[beta]) / REFERENCE[beta]
            good = err <= 0.005 and r["instability"] == "flutter"
            ok &= good
            print(f"beta {beta}: u_cf {ucf:.6f} omega_cf {float(r['omega_cf']):.4f} ({r['instability']}), "
                  f"reference {REFERENCE[beta]}, error {100 * err:.3f}% {'ok' if good else 'FAIL'}")
    summary = json.load(open(f"{folder}/summary.json"))
    print("summary u_cf:", summary["u_cf"])
    if "--png" in sys.argv:
        with open(f"{folder}/stability.png", "rb") as f:
            png = f.read(8) == b"\x89PNG\r\n\x1a\n"
        print("stability.png:", "ok" if png else "FAIL")
        ok &= png and summary["plot"] == "stability.png"
    print("tube_stability:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
