#!/usr/bin/env python3
"""Draws issue 20's scaling curves from scripts/gpu/scaling.sh's output: GPU ms of the GBuffer,
the GI and the whole frame against pixels, against triangles drawn and against rays per screen
probe. Usage: plot_scaling.py DIR OUT.png  (DIR holds the JSON files and scaling.log); prints
the figures as markdown tables too."""
import json
import pathlib
import re
import sys

from perf_tables import DEFERRED  # the deferred renderer's passes: the rest of a frame is GI


def figures(path: pathlib.Path):
    passes = {p["name"]: p["medianMs"] for p in json.loads(path.read_text()).get("passes", [])}
    if "frame" not in passes:
        return None
    gbuffer = passes.get("gbuffer visibility", 0.0) + passes.get("gbuffer resolve", 0.0)
    gi = max(0.0, passes["frame"] - sum(v for k, v in passes.items() if k in DEFERRED))
    probes = sum(v for k, v in passes.items() if k.startswith("screen probes"))
    return {"gbuffer": gbuffer, "gi": gi, "frame": passes["frame"], "probes": probes}


def triangle_counts(log: str):
    """Triangles drawn per run name, from the `scene: NAME, N triangles` line after `== NAME`."""
    counts, name = {}, None
    for line in log.splitlines():
        if line.startswith("== "):
            name = line[3:].strip()
        m = re.match(r"scene: .*?, (\d+) triangles", line)
        if m and name:
            counts[name] = int(m.group(1))
    return counts


def main(argv) -> int:
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    folder, png = pathlib.Path(argv[1]), argv[2]
    runs = {p.stem: f for p in sorted(folder.glob("*.json")) if (f := figures(p))}
    if not runs:
        print(f"plot_scaling: no timing JSON in {folder}", file=sys.stderr)
        return 1
    log = (folder / "scaling.log").read_text() if (folder / "scaling.log").exists() else ""
    triangles = triangle_counts(log)

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    ax = axes[0]
    print("| pixels | scene | GBuffer ms | GI ms | frame ms |\n|---:|---|---:|---:|---:|")
    for scene in ("cornell_box", "atrium"):
        points = []
        for name, f in runs.items():
            m = re.fullmatch(rf"pixels_{scene}_(\d+)x(\d+)", name)
            if m:
                points.append((int(m.group(1)) * int(m.group(2)) / 1e6, f))
        points.sort(key=lambda p: p[0])
        for mp, f in points:
            print(f"| {mp:.2f} M | `{scene}` | {f['gbuffer']:.3f} | {f['gi']:.3f} | {f['frame']:.3f} |")
        for key, style in (("gbuffer", ":"), ("gi", "--"), ("frame", "-")):
            ax.plot([p[0] for p in points], [p[1][key] for p in points], style, marker="o", label=f"{scene} {key}")
    ax.set(xscale="log", yscale="log", xlabel="megapixels", ylabel="GPU ms", title="lumen medium: time against pixels")
    ax.legend(fontsize=7)

    ax = axes[1]
    print("\n| triangles | GBuffer ms (direct) | GI ms (lumen) | frame ms (lumen) |\n|---:|---:|---:|---:|")
    rows = []
    for name, f in runs.items():
        m = re.fullmatch(r"triangles_lumen_(\d+)", name)
        direct = runs.get(name.replace("lumen", "direct"))
        if m and name in triangles:
            rows.append((triangles[name], f, direct))
    rows.sort(key=lambda r: r[0])
    for count, f, direct in rows:
        print(f"| {count / 1e6:.2f} M | {direct['gbuffer'] if direct else float('nan'):.3f} | {f['gi']:.3f} | {f['frame']:.3f} |")
    ax.plot([r[0] for r in rows], [r[2]["gbuffer"] if r[2] else float("nan") for r in rows], ":", marker="o", label="GBuffer")
    ax.plot([r[0] for r in rows], [r[1]["gi"] for r in rows], "--", marker="o", label="GI (lumen)")
    ax.plot([r[0] for r in rows], [r[1]["frame"] for r in rows], "-", marker="o", label="frame (lumen)")
    ax.set(xscale="log", yscale="log", xlabel="triangles drawn", ylabel="GPU ms", title="city, 1920x1080: time against triangles")
    ax.legend(fontsize=7)

    ax = axes[2]
    print("\n| rays per probe | screen probes ms | frame ms |\n|---:|---:|---:|")
    points = sorted((int(n.rsplit("_", 1)[1]), f) for n, f in runs.items() if n.startswith("rays_"))
    for rays, f in points:
        print(f"| {rays} | {f['probes']:.3f} | {f['frame']:.3f} |")
    ax.plot([p[0] for p in points], [p[1]["probes"] for p in points], "--", marker="o", label="screen probes")
    ax.plot([p[0] for p in points], [p[1]["frame"] for p in points], "-", marker="o", label="frame")
    ax.set(xscale="log", yscale="log", xlabel="rays per screen probe", ylabel="GPU ms",
           title="cornell_box lumen medium, 1920x1080")
    ax.legend(fontsize=7)
    commit = next((line.split()[1] for line in log.splitlines() if line.startswith("commit ")), "?")
    fig.suptitle(f"lent GPU, commit {commit}: median GPU ms over frames 100-200, no validation", fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
