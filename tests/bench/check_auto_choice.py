#!/usr/bin/env python3
"""Checks `lumina render --technique auto` against an explicit `lumina bench` run of the same
candidates, size, frames and reference (tests/bench/auto_technique_smoke.cmake).

    check_auto_choice.py budgets BENCH.csv             prints "ALL;SPLIT;NONE": error budgets that
        every candidate meets, that only some meet (after a cheaper one that misses), and none meets
    check_auto_choice.py check BENCH.csv TECHNIQUE PRESET E
        the choice meets E in the matrix, and no candidate that meets E is cheaper

The errors of the two runs are the same computation on the same reference, so they are compared
exactly (up to float printing); their times are two measurements of the same work, and lavapipe's
vary by tens of percent between runs on a shared machine, and by more under the sanitizers: in
the sanitizer step's run of the CI rehearsal, direct low took 2.4 ms a frame in the calibration
and 2.8 in the matrix while direct medium (the same image) took 3.9 and 1.1, a 2.5x swing. So
"cheaper" means under a quarter of the chosen's matrix time: the check can fail on the error,
never on timing noise.
"""
import csv
import sys

TIME_NOISE = 4.0  # a candidate counts as cheaper when it takes less than 1/TIME_NOISE the time


def fail(message):
    print(f"check_auto_choice: {message}", file=sys.stderr)
    sys.exit(1)


def read(path):
    with open(path, newline="") as f:
        return [{"name": f"{r['technique']} {r['preset']}", "ms": float(r["frame_ms"]),
                 "relmse": float(r["relmse_converged"])} for r in csv.DictReader(f)]


def budgets(rows):
    errors = sorted(r["relmse"] for r in rows)
    by_time = sorted(rows, key=lambda r: r["ms"])
    # A candidate clearly more accurate than everything clearly cheaper than it: the budget of
    # its error excludes those.
    split = next((r["relmse"] for i, r in enumerate(by_time)
                  if i and all(c["relmse"] > r["relmse"] * 1.001 for c in by_time[:i]
                               if c["ms"] * TIME_NOISE < r["ms"])
                  and any(c["ms"] * TIME_NOISE < r["ms"] for c in by_time[:i])), errors[-1])
    print(f"{errors[-1] * 1.001:.9g};{split * 1.000001:.9g};{errors[0] * 0.999:.9g}", end="")


def check(rows, technique, preset, budget):
    chosen = next((r for r in rows if r["name"] == f"{technique} {preset}"), None)
    if chosen is None:
        fail(f"the choice {technique} {preset} is not in the matrix")
    if chosen["relmse"] > budget * (1 + 1e-6):
        fail(f"{chosen['name']} has relMSE {chosen['relmse']} in the matrix, over the budget {budget}")
    for r in rows:
        if r["relmse"] <= budget and r["ms"] * TIME_NOISE < chosen["ms"]:
            fail(f"{r['name']} meets {budget} (relMSE {r['relmse']}) at {r['ms']} ms, far cheaper than "
                 f"the choice {chosen['name']} at {chosen['ms']} ms")
    print(f"check_auto_choice: {chosen['name']} (relMSE {chosen['relmse']}, {chosen['ms']} ms) meets {budget}"
          " and nothing clearly cheaper does")


def main():
    rows = read(sys.argv[2])
    if sys.argv[1] == "budgets":
        budgets(rows)
    else:
        check(rows, sys.argv[3], sys.argv[4], float(sys.argv[5]))


if __name__ == "__main__":
    main()
