#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Writes RUN_DIR/report.html: a run's configuration, plots and frames.

Run by `tessella report RUN_DIR` (render/src/run_report.cpp), which first
writes RUN_DIR/report/cells.csv (one row per cell per snapshot read),
RUN_DIR/report/divisions.csv (one row per division seen) and the frames
RUN_DIR/report/frames/frame_*.png. The plots are made with matplotlib
(Agg backend: no display needed) and saved beside them.
"""
import csv
import html
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def numbers(rows, key):
    return [float(r[key]) for r in rows]


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_counts(stats, out):
    t = numbers(stats, "time")
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.plot(t, numbers(stats, "cells"), marker="o", ms=3)
    ax.set_xlabel("time")
    ax.set_ylabel("cells")
    ax.set_title("Cell count")
    ax.grid(alpha=0.3)
    save(fig, out)


def plot_sizes(cells, measure, out):
    by_time = defaultdict(list)
    for r in cells:
        by_time[float(r["time"])].append(float(r["size"]))
    times = sorted(by_time)
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.boxplot([by_time[t] for t in times], positions=range(len(times)), widths=0.6, showfliers=False)
    step = max(1, len(times) // 8)
    ax.set_xticks(range(0, len(times), step))
    ax.set_xticklabels([f"{times[i]:.3g}" for i in range(0, len(times), step)])
    ax.set_xlabel("time")
    ax.set_ylabel(f"cell {measure}")
    ax.set_title(f"Cell {measure} distribution (box: quartiles, whiskers: 1.5 IQR)")
    ax.grid(alpha=0.3, axis="y")
    save(fig, out)


def plot_rose(divisions, out):
    # Axial data: a wall at angle a is the same wall at a + 180, so each
    # division is drawn in both directions.
    angles = [float(r["angle_deg"]) for r in divisions]
    bins = 12
    counts = [0] * bins
    for a in angles:
        counts[min(int(a // (180 / bins)), bins - 1)] += 1
    width = math.pi / bins
    theta = [(i + 0.5) * width for i in range(bins)]
    fig = plt.figure(figsize=(4.2, 4.2))
    ax = fig.add_subplot(projection="polar")
    ax.bar(theta + [t + math.pi for t in theta], counts + counts, width=width, edgecolor="k", alpha=0.8)
    ax.set_title(f"New walls in the xy plane ({len(angles)} divisions)", fontsize=10)
    ax.set_yticklabels([])
    save(fig, out)


def plot_fields(stats, out):
    fields = [k[: -len("_total")] for k in stats[0] if k.endswith("_total") and k not in ("area_total", "volume_total")]
    if not fields:
        return False
    t = numbers(stats, "time")
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for f in fields:
        ax.plot(t, numbers(stats, f + "_total"), label=f)
    ax.set_xlabel("time")
    ax.set_ylabel("total amount")
    ax.set_title("Solver fields and species")
    ax.legend()
    ax.grid(alpha=0.3)
    save(fig, out)
    return True


def main(run_dir):
    report = os.path.join(run_dir, "report")
    stats = read_csv(os.path.join(run_dir, "stats.csv"))
    if not stats:
        sys.exit(f"{run_dir}/stats.csv has no row")
    cells = read_csv(os.path.join(report, "cells.csv"))
    divisions = read_csv(os.path.join(report, "divisions.csv"))
    measure = "volume" if "volume_total" in stats[0] else "area"
    with open(os.path.join(run_dir, "run.yaml")) as f:
        config = f.read()

    plots = [("counts.png", "Cell count over time")]
    plot_counts(stats, os.path.join(report, "counts.png"))
    plot_sizes(cells, measure, os.path.join(report, "sizes.png"))
    plots.append(("sizes.png", f"Cell {measure}s over time"))
    if divisions:
        plot_rose(divisions, os.path.join(report, "divisions.png"))
        plots.append(("divisions.png", "Division orientations"))
    if plot_fields(stats, os.path.join(report, "fields.png")):
        plots.append(("fields.png", "Field totals"))
    frames = sorted(f for f in os.listdir(os.path.join(report, "frames")) if f.endswith(".png"))

    last = stats[-1]
    summary = (
        f"{len(stats)} output steps, time {stats[0]['time']} to {last['time']}; "
        f"{stats[0]['cells']} cells at the start, {last['cells']} at the end; "
        f"{len(divisions)} divisions seen between the snapshots read."
    )
    name = os.path.basename(os.path.abspath(run_dir))
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>Tessella run {html.escape(name)}</title>",
        "<style>body{font-family:sans-serif;margin:2em;max-width:1200px}"
        "figure{display:inline-block;margin:0.5em}img{max-width:100%}"
        "pre{background:#f4f4f4;padding:1em;overflow:auto;max-height:30em}</style>",
        "</head><body>",
        f"<h1>Tessella run {html.escape(name)}</h1>",
        f"<p>{html.escape(summary)}</p>",
        "<h2>Plots</h2>",
    ]
    for file, caption in plots:
        parts.append(
            f'<figure><img class="plot" src="report/{file}" alt="{html.escape(caption)}">'
            f"<figcaption>{html.escape(caption)}</figcaption></figure>"
        )
    parts.append("<h2>Tissue</h2>")
    for file in frames:
        parts.append(f'<figure><img class="frame" src="report/frames/{file}" alt="{file}" width="320"></figure>')
    parts.append("<h2>Configuration (run.yaml)</h2>")
    parts.append(f"<pre>{html.escape(config)}</pre>")
    # For checks in a browser: how many images loaded (tests/apps/cli_cases.sh).
    parts.append(
        "<script>window.addEventListener('load', () => { const all = [...document.images];"
        " const ok = all.filter(i => i.complete && i.naturalWidth > 0).length;"
        " document.body.dataset.imagesLoaded = ok + '/' + all.length; });</script>"
    )
    parts.append("</body></html>")
    with open(os.path.join(run_dir, "report.html"), "w") as f:
        f.write("\n".join(parts) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: tessella_report.py RUN_DIR")
    main(sys.argv[1])
