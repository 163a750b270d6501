#!/usr/bin/env python3
"""Tests of cmake/check_dxbc_casts.py on hand-written disassemblies.

usage: check_dxbc_casts_test.py PATH/TO/check_dxbc_casts.py
"""
import importlib.util
import sys
import unittest

spec = importlib.util.spec_from_file_location("check_dxbc_casts", sys.argv.pop(1))
checker = importlib.util.module_from_spec(spec)
spec.loader.exec_module(checker)


def sites(text):
    return checker.check(text.strip().splitlines())


class MergedCasts(unittest.TestCase):
    def test_integer_read_of_the_spare_lane_is_found(self):
        self.assertEqual(len(sites("""
            itof r1.xyzw, r0.xyzx
            iadd r2.x, r1.w, l(1)
        """)), 1)

    def test_a_read_through_movs_is_found(self):
        self.assertEqual(len(sites("""
            utof r1.zw, r0.x
            mov r3.y, r1.w
            ushr r2.x, r3.y, l(16)
        """)), 1)

    def test_imul_reading_the_spare_lane_is_found(self):
        self.assertEqual(len(sites("""
            utof r1.zw, r0.x
            imul null, r3.y, r1.w, l(3)
        """)), 1)

    def test_float_reads_are_not_a_site(self):
        self.assertEqual(sites("""
            itof r1.xyzw, r0.xyzx
            add r2.x, r1.w, l(1.0)
        """), [])

    def test_lanes_of_distinct_sources_are_not_a_site(self):
        self.assertEqual(sites("""
            itof r1.xy, r0.xy
            iadd r2.x, r1.y, l(1)
        """), [])

    def test_a_lane_rewritten_before_the_integer_read_is_not_a_site(self):
        self.assertEqual(sites("""
            utof r1.zw, r0.x
            mov r6.x, r1.w
            mov r6.x, l(0)
            iadd r2.x, r6.x, l(1)
        """), [])

    def test_the_second_destination_of_imul_is_written_not_read(self):
        # imul's operands are hi, lo, a, b: r6.x is overwritten here, as in the radiosity trace.
        self.assertEqual(sites("""
            utof r1.zw, r0.x
            mov r6.x, r1.w
            imul null, r6.x, r2.w, l(2146121005)
            ushr r2.w, r6.x, l(15)
        """), [])


if __name__ == "__main__":
    unittest.main()
