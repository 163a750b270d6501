#!/usr/bin/env python3
"""Turns the JSON of scripts/gpu/perf_tables.sh (one `lumina render --timings-json` file per
scene, technique, preset and size) into markdown tables: per scene and configuration, each pass's
median GPU ms at every size, and the frame. Usage: perf_tables.py DIR > tables.md"""
import json
import pathlib
import sys


# The deferred renderer's passes; everything else in a frame belongs to the GI technique.
DEFERRED = {"gbuffer visibility", "gbuffer resolve", "direct light", "composite", "sun shadow", "point shadows"}


def print_summary(runs, sizes) -> None:
    """One row per scene and configuration: the GBuffer, the GI and the whole frame at each size
    (GI: the frame less the deferred renderer's passes; medians of sums are not sums of
    medians, so the columns need not add up exactly)."""
    print("| scene | technique | preset | " + " | ".join(f"{s} GBuffer / GI / frame" for s in sizes) + " |")
    print("|---|---|---|" + "---:|" * len(sizes))
    for (scene, technique, preset), by_size in sorted(runs.items()):
        cells = []
        for size in sizes:
            passes = {p["name"]: p["medianMs"] for p in by_size.get(size, {}).get("passes", [])}
            if "frame" not in passes:
                cells.append("")
                continue
            gbuffer = passes.get("gbuffer visibility", 0.0) + passes.get("gbuffer resolve", 0.0)
            deferred = sum(v for k, v in passes.items() if k in DEFERRED)
            gi = max(0.0, passes["frame"] - deferred) if technique != "direct" else 0.0
            cells.append(f"{gbuffer:.2f} / {gi:.2f} / {passes['frame']:.2f}")
        print(f"| `{scene}` | {technique} | {preset} | " + " | ".join(cells) + " |")
    print()


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    folder = pathlib.Path(sys.argv[1])
    runs = {}
    context = None
    for path in sorted(folder.glob("*.json")):
        data = json.loads(path.read_text())
        c = data.get("context", {})
        context = context or c
        key = (c.get("scene"), c.get("technique"), path.stem.split("_")[-2])
        runs.setdefault(key, {})[c.get("size")] = data
    if not runs:
        print(f"no timing JSON in {folder}", file=sys.stderr)
        return 1
    print(f"Device {context.get('device')}, driver {context.get('driver')}, {context.get('api')}, "
          f"commit {context.get('commit')}; median GPU ms per pass over the frames after warm-up "
          f"(runs: how many of them the pass ran in).\n")
    sizes = sorted({s for r in runs.values() for s in r}, key=lambda s: int(s.split("x")[0]))
    print_summary(runs, sizes)
    for (scene, technique, preset), by_size in sorted(runs.items()):
        print(f"### `{scene}`, {technique}, {preset}\n")
        print("| pass | " + " | ".join(sizes) + " |")
        print("|---|" + "---:|" * len(sizes))
        names = []
        for size in sizes:
            for p in by_size.get(size, {}).get("passes", []):
                if p["name"] not in names:
                    names.append(p["name"])
        names.sort(key=lambda n: n == "frame")
        for name in names:
            cells = []
            for size in sizes:
                passes = {p["name"]: p for p in by_size.get(size, {}).get("passes", [])}
                p = passes.get(name)
                frames = by_size.get(size, {}).get("frames", 0)
                if p is None:
                    cells.append("")
                elif p["runs"] < frames:
                    cells.append(f"{p['medianMs']:.3f} ({p['runs']} runs)")
                else:
                    cells.append(f"{p['medianMs']:.3f}")
            label = f"**{name}**" if name == "frame" else name
            print(f"| {label} | " + " | ".join(cells) + " |")
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
