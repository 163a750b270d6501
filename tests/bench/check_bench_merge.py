#!/usr/bin/env python3
"""Checks that a merged sharded bench (tests/bench/shard_smoke.cmake) holds what one unsharded run
of the same matrix wrote: the same columns, the same configurations in the same order, the same
context, and the same figures wherever they do not depend on timing (the direct renderer's errors
and memory; the path tracer's samples per frame follow measured time, so its errors may differ).

    check_bench_merge.py WHOLE_DIR MERGED_DIR
"""
import csv
import json
import os
import sys


def fail(message):
    print(f"check_bench_merge: {message}", file=sys.stderr)
    sys.exit(1)


def read(directory):
    with open(os.path.join(directory, "bench.csv"), newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        columns = reader.fieldnames
    with open(os.path.join(directory, "bench.json")) as f:
        report = json.load(f)
    return columns, rows, report


def main():
    whole_columns, whole, whole_json = read(sys.argv[1])
    merged_columns, merged, merged_json = read(sys.argv[2])
    if whole_columns != merged_columns:
        fail(f"columns differ: {merged_columns} against {whole_columns}")
    key = lambda r: (r["scene"], r["technique"], r["preset"])
    if [key(r) for r in whole] != [key(r) for r in merged]:
        fail(f"rows differ: {[key(r) for r in merged]} against {[key(r) for r in whole]}")
    if [key(r) for r in whole_json["runs"]] != [key(r) for r in merged_json["runs"]]:
        fail("bench.json's runs are not in one run's order")
    for field in ("commit", "device", "driver", "api", "reference_spp"):
        if whole_json["context"][field] != merged_json["context"][field]:
            fail(f"context {field}: {merged_json['context'][field]} against {whole_json['context'][field]}")
    for w, m in zip(whole, merged):
        if w["technique"] == "direct":
            for column in ("relmse_frame1", "relmse_converged", "flip_converged", "gpu_memory_mib"):
                if w[column] != m[column]:
                    fail(f"{key(w)}: {column} {m[column]} against {w[column]}")
    print(f"check_bench_merge: {len(merged)} rows as one run writes them")


if __name__ == "__main__":
    main()
