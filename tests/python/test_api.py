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
        self.assertTrue(issubclass(magfem.InputError, ValueError))
        self.assertTrue(issubclass(magfem.SolveError, RuntimeError))


EXAMPLE = os.path.join(os.environ.get("MAGFEM_SOURCE_DIR", "."), "examples/2d/diametric_cylinder.yaml")


class CaseTest(unittest.TestCase):
    def test_load_example(self):
        case = magfem.Case.load(EXAMPLE)
        self.assertIn("diametrically magnetized cylinder", case.to_yaml())
        self.assertEqual(case.with_params().to_yaml(), case.to_yaml())

    def test_from_dict_wrong_key_names_the_field(self):
        import yaml
        with open(EXAMPLE, encoding="utf-8") as f:
            d = yaml.safe_load(f)
        d["no_such_key"] = 1
        with self.assertRaises(magfem.InputError) as ctx:
            magfem.Case.from_dict(d)
        self.assertIsInstance(ctx.exception, ValueError)
        self.assertEqual(ctx.exception.file, "<dict>")
        self.assertIn("no_such_key", str(ctx.exception.field) + str(ctx.exception))

    def test_from_dict_reads_axisymmetric_as_axi(self):
        # `axisymmetric` is a spelling of `axi` (issue 34): the same reader, so the same case
        # and bit for bit the same solve; a misspelling names the field and the choices.
        import yaml
        path = os.path.join(os.environ.get("MAGFEM_SOURCE_DIR", "."), "examples/axi/solenoid.yaml")
        with open(path, encoding="utf-8") as f:
            d = yaml.safe_load(f)
        self.assertEqual(d["dimension"], "axi")
        axi = magfem.Case.from_dict(d).solve(mesh_scale=4)
        d["dimension"] = "axisymmetric"
        spelled = magfem.Case.from_dict(d).solve(mesh_scale=4)
        self.assertEqual(spelled.dimension, "axi")
        self.assertEqual(spelled.energy, axi.energy)
        d["dimension"] = "axisymetric"
        with self.assertRaises(magfem.InputError) as ctx:
            magfem.Case.from_dict(d)
        self.assertEqual(ctx.exception.field, "dimension")
        self.assertIn("2 | 3 | axi | axisymmetric", str(ctx.exception))

    def test_yaml_syntax_error_carries_the_line(self):
        with self.assertRaises(magfem.InputError) as ctx:
            magfem.Case(text="dimension: 2\nregions: [\n  {a: 1\n", name="<text>")
        self.assertIsNotNone(ctx.exception.line)
        self.assertGreaterEqual(ctx.exception.line, 2)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
