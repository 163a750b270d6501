#!/usr/bin/env python3
"""One Pareto plot per scene from `lumina bench` results: GPU time per frame against relMSE after
the last frame, log-log, every technique x preset (x image size, when several CSVs are given: hollow
markers for the smaller sizes) as a point, and the Pareto front of each size marked: the
configurations no other one at that size beats on both time and error, circled and joined by a
step line (sizes are not compared with each other: each has its own reference). Also writes
pareto.csv, the fronts, cheapest first.

    python3 scripts/plot_pareto.py OUT_DIR BENCH.csv [BENCH.csv ...]

Writes OUT_DIR/pareto_SCENE.png per scene and OUT_DIR/pareto.csv. Needs python3-matplotlib
(Debian). Each figure's title names the device, driver, API and commit the CSVs record.
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"direct": "s", "lumen": "o", "ddgi": "D", "sh-grid": "^", "pathtracer": "v"}


def pareto_front(points):
    """The points no other point dominates (no more time and no more error, one of them less),
    sorted by time. A point is a dict with float 'ms' and 'relmse'."""
    front = []
    for p in sorted(points, key=lambda p: (p["ms"], p["relmse"])):
        if not front or p["relmse"] < front[-1]["relmse"]:
            front.append(p)
    return front


def read_points(paths):
    points, first, first_of_scene = [], None, {}
    for path in paths:
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                first = first or r
                first_of_scene.setdefault(r["scene"], r)
                points.append({"scene": r["scene"], "technique": r["technique"], "preset": r["preset"],
                               "size": f"{r['width']}x{r['height']}", "ms": float(r["frame_ms"]),
                               "relmse": max(float(r["relmse_converged"]), 1e-12)})
    return points, first, first_of_scene


def plot_scene(scene, points, first, path):
    sizes = sorted({p["size"] for p in points}, key=lambda s: int(s.split("x")[0]) * int(s.split("x")[1]))
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    colors = {}
    for p in points:
        key = (p["technique"], p["size"])
        label = p["technique"] + (f" {p['size']}" if len(sizes) > 1 else "")
        filled = sizes.index(p["size"]) == len(sizes) - 1
        line = ax.plot([p["ms"]], [p["relmse"]], linestyle="none", marker=MARKERS.get(p["technique"], "x"),
                       color=colors.get(p["technique"]), markerfacecolor=None if filled else "none",
                       label=None if key in colors else label)[0]
        colors.setdefault(p["technique"], line.get_color())
        colors.setdefault(key, True)
        ax.annotate(p["preset"], (p["ms"], p["relmse"]), textcoords="offset points", xytext=(4, 3), fontsize=6)
    fronts = []
    for size in sizes:
        front = pareto_front([p for p in points if p["size"] == size])
        largest = size == sizes[-1]
        xs, ys = [p["ms"] for p in front], [p["relmse"] for p in front]
        ax.step(xs, ys, where="post", color="black" if largest else "grey", linestyle="-" if largest else "--",
                linewidth=1.2, alpha=0.7, label="Pareto front" + (f" {size}" if len(sizes) > 1 else ""))
        ax.plot(xs, ys, linestyle="none", marker="o", markersize=12, markerfacecolor="none",
                color="black" if largest else "grey")
        fronts += front
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("GPU time per frame (ms, median)")
    ax.set_ylabel("relMSE vs reference after the last frame")
    ax.set_title(f"{scene} ({', '.join(sizes)})")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.suptitle(f"{first['device']} ({first['api']}, {first['driver']})\ncommit {first['commit'][:12]}, "
                 f"reference {first['reference_spp']} spp", fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return fronts


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    out, paths = argv[1], argv[2:]
    points, first, first_of_scene = read_points(paths)
    if not points:
        print(f"plot_pareto: {', '.join(paths)} hold no runs", file=sys.stderr)
        return 1
    os.makedirs(out, exist_ok=True)
    by_scene = defaultdict(list)
    for p in points:
        by_scene[p["scene"]].append(p)
    with open(os.path.join(out, "pareto.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["scene", "technique", "preset", "size", "frame_ms", "relmse_converged"])
        for scene, scene_points in by_scene.items():
            path = os.path.join(out, f"pareto_{scene}.png")
            # The scene's own run names its device and commit (several calls may have made the CSVs).
            for p in plot_scene(scene, scene_points, first_of_scene.get(scene, first), path):
                writer.writerow([scene, p["technique"], p["preset"], p["size"], p["ms"], p["relmse"]])
            print(f"plot_pareto: wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
