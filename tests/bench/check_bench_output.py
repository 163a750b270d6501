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
        if r["technique"] == "direct" and not r["passes_ms"].count("gbuffer="):
            fail(f"{key}: no gbuffer pass timing in '{r['passes_ms']}'")
        if not r["device"] or not r["commit"]:
            fail(f"{key}: device or commit missing")
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
            elif abs(first - last) > 1e-6 * max(first, 1e-9):
                # The direct renderer is deterministic: frame 1 is already converged.
                fail(f"{scene}/direct/{r['preset']}: relMSE changed over frames ({first} -> {last})")
    print(f"check_bench_output: {len(rows)} configurations, all figures sane")


if __name__ == "__main__":
    main()
