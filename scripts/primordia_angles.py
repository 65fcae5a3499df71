#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Folded divergence angles of the primordia of one or more runs (docs/networks.md, "Phyllotaxis on a
growing dome"): for every primordia.csv given, the primordia after time `--after` (the first ring), the
divergence from the previous record folded to min(d, 360 - d); over all runs: count, how many came less
than --close time units after the previous one (and in the same solve), mean / median / s.d., and the
shares within 20 degrees of 137.5 and of 180 and below 90. Usage:
  scripts/primordia_angles.py [--after 1] run1/primordia.csv run2/primordia.csv ...
"""
import argparse
import csv
import math
import statistics


def folded(d):
    d = d % 360.0
    return min(d, 360.0 - d)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--after", type=float, default=1.0, help="take primordia after this time (default 1)")
    ap.add_argument("--close", type=float, default=0.35, help="a primordium this soon after the previous is close")
    args = ap.parse_args()
    angles, close, same = [], 0, 0
    for path in args.csv:
        with open(path) as f:
            rows = list(csv.DictReader(f))
        for prev, row in zip(rows, rows[1:]):
            t, tp = float(row["time"]), float(prev["time"])
            if t <= args.after:
                continue
            angles.append(folded(float(row["divergence_deg"])))
            close += (t - tp) < args.close
            same += t == tp
    n = len(angles)
    if n == 0:
        print(f"runs {len(args.csv)}: no primordia after t = {args.after}")
        return
    share = lambda pred: sum(1 for a in angles if pred(a)) / n
    sd = statistics.stdev(angles) if n > 1 else float("nan")
    print(f"runs {len(args.csv)} | after t = {args.after}: {n} | close {close} ({same}) | "
          f"{statistics.mean(angles):.0f} / {statistics.median(angles):.0f} / {sd:.0f} | "
          f"~137.5 {share(lambda a: abs(a - 137.5) <= 20):.2f} | ~180 {share(lambda a: a >= 160):.2f} | "
          f"<90 {share(lambda a: a < 90):.2f}")


if __name__ == "__main__":
    main()
