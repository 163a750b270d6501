#!/usr/bin/env python3
"""Plots `lumina bench` results: relMSE after the last frame against GPU time per frame, log-log,
one curve per technique (its presets in order of cost), one panel per scene.

The curves use frame_ms, the median over every frame of the run. Where a technique's frames
cost much less once it has settled (lumen: after its surface cache converged, radiosity stops),
a hollow marker joined by a dotted line shows that settled cost (settled_frame_ms) at the same
error: the error after the last frame is the settled state's.

    python3 scripts/plot_bench.py bench/bench.csv bench/bench.png

Needs python3-matplotlib (Debian). The title names the device, driver, API and commit that the
CSV records, so a figure always says where it came from.
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402


# A settled cost is drawn apart when it differs from the run's median by more than this factor.
SETTLED_APART = 1.25


def settled_ms(row):
    """settled_frame_ms when it is there and differs from frame_ms by SETTLED_APART, else None."""
    text = row.get("settled_frame_ms", "")
    if not text:
        return None
    value, frame = float(text), float(row["frame_ms"])
    if not (math.isfinite(value) and value > 0) or max(value, frame) < SETTLED_APART * min(value, frame):
        return None
    return value


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    csv_path, png_path = argv[1], argv[2]
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        print(f"plot_bench: {csv_path} holds no runs", file=sys.stderr)
        return 1

    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4.2), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        curves = defaultdict(list)
        for r in rows:
            if r["scene"] == scene:
                curves[r["technique"]].append(r)
        for technique, runs in curves.items():
            runs.sort(key=lambda r: float(r["frame_ms"]))
            x = [float(r["frame_ms"]) for r in runs]
            y = [max(float(r["relmse_converged"]), 1e-12) for r in runs]
            (line,) = ax.plot(x, y, marker="o", label=technique)
            settled_label = f"{technique}, settled frames"
            for r, xi, yi in zip(runs, x, y):
                ax.annotate(r["preset"], (xi, yi), textcoords="offset points", xytext=(4, 4), fontsize=7)
                settled = settled_ms(r)
                if settled is not None:
                    ax.plot([xi, settled], [yi, yi], linestyle=":", color=line.get_color(), linewidth=1)
                    ax.plot([settled], [yi], marker="o", markerfacecolor="none", linestyle="none",
                            color=line.get_color(), label=settled_label)
                    settled_label = None
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("GPU time per frame (ms)")
        ax.set_ylabel("relMSE vs reference after the last frame")
        ax.set_title(scene)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    first = rows[0]
    fig.suptitle(
        f"{first['device']} ({first['api']}, {first['driver']}), commit {first['commit'][:12]}, "
        f"{first['width']}x{first['height']}, reference {first['reference_spp']} spp",
        fontsize=9,
    )
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
