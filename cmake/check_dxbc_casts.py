#!/usr/bin/env python3
"""Finds vkd3d-shader's merged-cast miscompile in a DXBC disassembly (docs/d3d12.md).

vkd3d-shader 2.1 merges casts of one value to two types into one conversion instruction: for
`float3(v)` beside `uint3(v)` (v an int3) it writes `itof r1.xyzw, r0.xyzx` and then reads lane w
(the float of v.x) as if it were v.x itself. The signature: a conversion whose write mask holds
two lanes converted from the same source lane, and an instruction of the other domain (an integer
instruction reading a lane an itof/utof wrote, a float instruction reading a lane ftoi/ftou wrote)
reading the duplicate, directly or through movs.

usage: check_dxbc_casts.py DISASSEMBLY.asm [NAME]; exits 1 and names each site found.
"""
import re
import sys

TO_FLOAT = {"itof", "utof"}
TO_INT = {"ftoi", "ftou"}
INT_OPS = {
    "iadd", "imul", "ineg", "imax", "imin", "umax", "umin", "ige", "ilt", "ieq", "ine", "uge", "ult",
    "ishl", "ishr", "ushr", "and", "or", "xor", "not", "itof", "utof", "udiv", "imad", "umad", "bfi",
    "ubfe", "ibfe", "countbits", "firstbit_hi", "firstbit_lo", "firstbit_shi", "bfrev", "ld",
    "ld_structured", "ld_raw", "store_structured", "store_raw", "store_uav_typed", "ld_uav_typed",
    "imm_atomic_iadd", "atomic_iadd", "switch",
}
FLOAT_OPS = {
    "add", "mul", "mad", "div", "min", "max", "lt", "ge", "eq", "ne", "frc", "round_ne", "round_ni",
    "round_pi", "round_z", "sqrt", "rsq", "exp", "log", "dp2", "dp3", "dp4", "ftoi", "ftou", "sincos",
    "rcp", "deriv_rtx", "deriv_rty", "sample", "sample_l", "sample_lz", "sample_d", "sample_b",
    "f32tof16",
}
# Instructions with two destination operands (imul writes the high and low halves, udiv the
# quotient and remainder, sincos both results); either may be null.
TWO_DESTINATIONS = {"imul", "umul", "udiv", "sincos", "swapc", "uaddc", "usubb"}
LANES = "xyzw"
OPERAND = re.compile(r"(-?\|?)(r\d+)\.([xyzw]+)")


def source_lanes(mask, swizzle):
    """The source lane each written lane reads (a one-lane swizzle broadcasts)."""
    if len(swizzle) == 1:
        return [swizzle] * len(mask)
    return [swizzle[LANES.index(c)] for c in mask]


def split(line):
    t = line.strip().split(None, 1)
    if len(t) < 2:
        return (t[0] if t else ""), []
    return t[0], [o.strip() for o in t[1].split(",")]


def reads_of(lines, start, reg, lane, depth=0):
    """(index, opcode, line) of each instruction reading reg.lane from `start` until it is
    rewritten; movs are followed to the lanes they copy it to."""
    found = []
    for j in range(start, len(lines)):
        op, ops = split(lines[j])
        if not ops:
            continue
        destinations = 2 if op in TWO_DESTINATIONS else 1
        written_regs = [m for m in (OPERAND.match(o) for o in ops[:destinations]) if m]
        dst = written_regs[0] if written_regs else None
        for src in ops[destinations:]:
            m = OPERAND.match(src)
            if not m or m.group(2) != reg:
                continue
            mask = dst.group(3) if dst else "x"
            for written, read in zip(mask, source_lanes(mask, m.group(3))):
                if read != lane:
                    continue
                if op == "mov" and dst and depth < 4:
                    found += reads_of(lines, j + 1, dst.group(2), written, depth + 1)
                elif op not in ("mov", "movc"):
                    found.append((j, op, lines[j].strip()))
        if any(d.group(2) == reg and lane in d.group(3) for d in written_regs):
            break
    return found


def check(lines):
    sites = []
    for i, line in enumerate(lines):
        op, ops = split(line)
        if op not in TO_FLOAT and op not in TO_INT or len(ops) < 2:
            continue
        dst, src = OPERAND.match(ops[0]), OPERAND.match(ops[1])
        if not dst or not src:
            continue
        seen = set()
        wrong = INT_OPS if op in TO_FLOAT else FLOAT_OPS
        for written, read in zip(dst.group(3), source_lanes(dst.group(3), src.group(3))):
            if read in seen:
                for j, reader, text in reads_of(lines, i + 1, dst.group(2), written):
                    if reader in wrong:
                        sites.append(f"line {i + 1}: {line.strip()}  ->  line {j + 1}: {text}")
            seen.add(read)
    return sites


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    with open(sys.argv[1]) as f:
        lines = f.read().splitlines()
    sites = check(lines)
    name = sys.argv[2] if len(sys.argv) > 2 else sys.argv[1]
    for s in sites:
        print(f"{name}: vkd3d-shader merged two casts of one value (docs/d3d12.md): {s}", file=sys.stderr)
    return 1 if sites else 0


if __name__ == "__main__":
    sys.exit(main())
