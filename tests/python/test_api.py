"""Tests of the Python module, run by ctest with /usr/bin/python3 and PYTHONPATH=build/python."""
import os
import sys
import unittest

import magfem


class PackageTest(unittest.TestCase):
    def test_version_matches_project(self):
        expected = os.environ.get("MAGFEM_EXPECTED_VERSION")
        if expected:
            self.assertEqual(magfem.__version__, expected)
        self.assertRegex(magfem.__version__, r"^\d+\.\d+\.\d+$")

    def test_exception_hierarchy(self):
        err = magfem.InputError("bad key", file="<dict>", line=3, field="regions[0].materal")
        self.assertIsInstance(err, ValueError)
        self.assertEqual((err.file, err.line, err.field), ("<dict>", 3, "regions[0].materal"))
        self.assertTrue(issubclass(magfem.SolveError, RuntimeError))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
