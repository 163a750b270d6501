#!/usr/bin/env python3
"""Checks `lumina render --technique auto` against an explicit `lumina bench` run of the same
candidates, size, frames and reference (tests/bench/auto_technique_smoke.cmake).

    check_auto_choice.py budgets BENCH.csv             prints "ALL;SPLIT;NONE": error budgets that
        every candidate meets, that only some meet (after a cheaper one that misses), and none meets
    check_auto_choice.py check BENCH.csv AUTO.txt E    AUTO.txt: what render --technique auto printed
        every candidate's calibration error is the matrix's, the choice is the cheapest candidate
        under E by the calibration's times, and it meets E in the matrix

The errors of the two runs are the same computation on the same reference, so they are compared
exactly (up to the table's four printed digits). Their times are two measurements of the same work,
and lavapipe's vary by far more than the candidates differ: in the CI rehearsal's sanitizer run,
direct medium took 3.9 ms a frame in the calibration and 1.1 in the matrix (the same image as
direct low); in a fresh-clone run with the other core busy, direct low took 7.7 ms in the matrix
and 0.55 in the calibration. So the times are checked within one run (the choice is the cheapest
by the calibration's own), never across the two: the check fails on an error or a wrong choice,
never on timing noise. On the lent GPU `lumina bench --check-auto` compares the choice with the
matrix's cheapest, times included (docs/measurement.md).
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


def read_calibration(path):
    """The candidate table render --technique auto prints: technique, preset, GPU ms, relMSE."""
    table = {}
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) >= 4 and fields[0] in ("direct", "lumen", "ddgi", "sh-grid"):
                try:
                    table[f"{fields[0]} {fields[1]}"] = {"ms": float(fields[2]), "relmse": float(fields[3])}
                except ValueError:
                    continue
    if not table:
        fail(f"no calibration table in {path}")
    return table


def chosen_name(path):
    with open(path) as f:
        for line in f:
            if line.startswith("auto: chose "):
                return " ".join(line[len("auto: chose "):].split(":")[0].split()[:2])
    fail(f"no 'auto: chose' line in {path}")


def check(rows, auto_path, budget):
    calibration = read_calibration(auto_path)
    name = chosen_name(auto_path)
    matrix = {r["name"]: r for r in rows}
    for candidate, c in calibration.items():
        if candidate not in matrix:
            fail(f"the calibration's {candidate} is not in the matrix")
        m = matrix[candidate]["relmse"]
        # Four significant digits printed: within half a unit of the fourth.
        if abs(c["relmse"] - m) > 5.01e-4 * abs(m):
            fail(f"{candidate}: relMSE {c['relmse']} in the calibration, {m} in the matrix (the same computation)")
    if name not in calibration:
        fail(f"the choice {name} is not in the calibration table")
    under = {n: c for n, c in calibration.items() if c["relmse"] <= budget}
    cheapest = min(under, key=lambda n: under[n]["ms"])
    if under[cheapest]["ms"] < calibration[name]["ms"]:
        fail(f"{cheapest} meets {budget} at {under[cheapest]['ms']} ms in the calibration, cheaper than the choice "
             f"{name} at {calibration[name]['ms']} ms")
    if matrix[name]["relmse"] > budget * (1 + 1e-6):
        fail(f"{name} has relMSE {matrix[name]['relmse']} in the matrix, over the budget {budget}")
    print(f"check_auto_choice: {name} meets {budget} in the matrix (relMSE {matrix[name]['relmse']}), "
          f"the cheapest under it in the calibration ({calibration[name]['ms']} ms), whose errors are the matrix's")


def main():
    rows = read(sys.argv[2])
    if sys.argv[1] == "budgets":
        budgets(rows)
    else:
        check(rows, sys.argv[3], float(sys.argv[4]))


if __name__ == "__main__":
    main()
