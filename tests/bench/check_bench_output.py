#!/usr/bin/env python3
"""Checks what one `lumina bench` run wrote (tests/bench/CMakeLists.txt): the CSV, JSON and PNG
exist, every configuration of the matrix is there once, and every figure is finite and sane.

    check_bench_output.py DIR EXPECTED_RUNS
"""
import csv
import json
import math
import os
import sys


def fail(message):
    print(f"check_bench_output: {message}", file=sys.stderr)
    sys.exit(1)


def check_settled(key, r):
    """settled_after_frame: 1 for direct and the path tracer, the surface cache converging for lumen
    and ddgi, the grid baked for sh-grid (or empty: not within the run); settled_frame_ms for the
    frames after it."""
    frames = int(r["frames"])
    after = r["settled_after_frame"]
    if r["technique"] not in ("lumen", "ddgi", "sh-grid") and after != "1":
        fail(f"{key}: settled_after_frame {after!r}, expected 1")
    if after and not 1 <= int(after) <= frames:
        fail(f"{key}: settled_after_frame {after} outside 1..{frames}")
    settled = r["settled_frame_ms"]
    if bool(settled) != bool(after and int(after) < frames):
        fail(f"{key}: settled_frame_ms {settled!r} with settled_after_frame {after!r} of {frames} frames")
    if settled and not (math.isfinite(float(settled)) and float(settled) > 0):
        fail(f"{key}: settled_frame_ms {settled}")


def check_budget_bases(report):
    """The path tracer's budgets multiply lumen's frame where lumen ran, else direct's."""
    ran = {}
    for run in report["runs"]:
        ran.setdefault(run["scene"], set()).add(run["technique"])
    for run in report["runs"]:
        if run["technique"] != "pathtracer":
            continue
        expected = next((t for t in ("lumen", "direct") if t in ran[run["scene"]]), "pathtracer sample")
        budget = run.get("budget", {})
        if budget.get("of") != expected or not budget.get("base_ms", 0) > 0:
            fail(f"{run['scene']}/pathtracer/{run['preset']}: budget {budget}, "
                 f"expected multiples of {expected}")


def main():
    directory, expected = sys.argv[1], int(sys.argv[2])
    for name in ("bench.csv", "bench.json", "bench.png"):
        path = os.path.join(directory, name)
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            fail(f"{path} missing or empty")
    with open(os.path.join(directory, "bench.png"), "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            fail("bench.png is not a PNG")
    with open(os.path.join(directory, "bench.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(directory, "bench.json")) as f:
        report = json.load(f)
    if len(rows) != expected or len(report["runs"]) != expected:
        fail(f"{len(rows)} CSV rows and {len(report['runs'])} JSON runs, expected {expected}")
    for key in ("commit", "device", "driver", "api"):
        if not report["context"].get(key):
            fail(f"JSON context has no {key}")
    keys = set()
    for r in rows:
        key = (r["scene"], r["technique"], r["preset"])
        if key in keys:
            fail(f"configuration {key} twice")
        keys.add(key)
        for column in ("frame_ms", "relmse_frame1", "relmse_converged", "indirect_relmse_converged",
                       "flip_converged", "gpu_memory_mib"):
            value = float(r[column])
            if not math.isfinite(value) or value < 0:
                fail(f"{key}: {column} = {r[column]}")
        if float(r["frame_ms"]) <= 0:
            fail(f"{key}: no GPU time")
        if float(r["gpu_memory_mib"]) <= 0:
            fail(f"{key}: no GPU memory recorded")
        if int(r["non_finite_pixels"]) != 0:
            fail(f"{key}: non-finite pixels")
        if not 0 < int(r["frames_to_converge"]) <= int(r["frames"]):
            fail(f"{key}: frames_to_converge {r['frames_to_converge']}")
        if r["technique"] in ("direct", "lumen", "ddgi", "sh-grid") and not r["passes_ms"].count("gbuffer resolve="):
            fail(f"{key}: no gbuffer resolve pass timing in '{r['passes_ms']}'")
        if r["technique"] == "lumen":
            for prefix in ("sdf: ", "surface cache: ", "screen probes: "):
                if prefix not in r["passes_ms"]:
                    fail(f"{key}: no '{prefix}...' pass timing in '{r['passes_ms']}'")
        if r["technique"] == "ddgi":
            for prefix in ("sdf: ", "surface cache: ", "ddgi: trace", "ddgi: sample"):
                if prefix not in r["passes_ms"]:
                    fail(f"{key}: no '{prefix}...' pass timing in '{r['passes_ms']}'")
        if r["technique"] == "sh-grid":
            for prefix in ("sh grid: bake gbuffer", "sh grid: project", "sh grid: sample"):
                if prefix not in r["passes_ms"]:
                    fail(f"{key}: no '{prefix}...' pass timing in '{r['passes_ms']}'")
        check_settled(key, r)
        if not r["device"] or not r["commit"]:
            fail(f"{key}: device or commit missing")
    check_budget_bases(report)
    by_technique = {}
    for r in rows:
        by_technique.setdefault((r["scene"], r["technique"]), []).append(r)
    for (scene, technique), runs in by_technique.items():
        for r in runs:
            first, last = float(r["relmse_frame1"]), float(r["relmse_converged"])
            if technique == "pathtracer":
                # Accumulating samples must lower the error (noise falls as 1/spp in relMSE).
                if not last < first:
                    fail(f"{scene}/pathtracer/{r['preset']}: relMSE did not fall ({first} -> {last})")
                if int(r["spp_per_frame"]) < 1:
                    fail(f"{scene}/pathtracer: spp_per_frame {r['spp_per_frame']}")
            elif technique == "direct" and abs(first - last) > 1e-6 * max(first, 1e-9):
                # The direct renderer is deterministic: frame 1 is already converged.
                fail(f"{scene}/direct/{r['preset']}: relMSE changed over frames ({first} -> {last})")
    # The direct renderer's indirect term is black; the GI techniques' must not be.
    black = {(r["scene"], r["preset"]): float(r["indirect_relmse_converged"])
             for r in rows if r["technique"] == "direct"}
    for r in (r for r in rows if r["technique"] in ("lumen", "ddgi", "sh-grid")):
        if black.get((r["scene"], r["preset"])) == float(r["indirect_relmse_converged"]):
            fail(f"{r['scene']}/{r['technique']}/{r['preset']}: indirect error equals the direct renderer's (black)")
    print(f"check_bench_output: {len(rows)} configurations, all figures sane")


if __name__ == "__main__":
    main()
