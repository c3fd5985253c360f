#!/usr/bin/python3
"""Checks docs/summary.schema.json against the summary.json that `magfem solve` writes.

usage: check_summary_schema.py MAGFEM SCHEMA SOURCE_DIR WORK_DIR [--all]

Solves examples and validates each summary.json against the schema, which forbids keys it
does not list: a key added to one dimension's summary and not documented, or a key one
dimension lost, fails here. The default set is every planar and axisymmetric example and the
3D examples that together write every optional block (coils with an inductance matrix,
forces, sections, nonlinear iron), all on a coarse mesh: the schema is about the keys, not the
numbers. --all solves every example (the long tier).

Before that, the schema must reject summaries with a key added, a key removed and a value of
the wrong type, so that a schema which accepts anything cannot pass.

Prints one OK/FAIL line per file and exits 1 on any unexpected result.
"""
import copy
import glob
import json
import os
import subprocess
import sys

import jsonschema

# 3D examples of the default set: coil + magnet (coils, inductance_H, forces), sections,
# forces on a magnet pair, nonlinear iron with a coil.
DEFAULT_3D = ["coil_and_magnet", "magnetized_sphere_sections", "two_spheres", "coil_over_plate"]
COARSE_3D = "3"   # --mesh-scale of the 3D examples: a few seconds each
COARSE_2D = "2"


# --all: the 3D examples whose coarse variant cannot run, with the scale they get instead.
SCALE_OF = {
    # Coarse already (its own mesh.scale 3): at 3 x 3 the magnets' facets, chords ~0.8 mm deep,
    # reach the stress sphere 0.5 mm from them, which then lies in a magnet (a clear error).
    "compensator_adaptive": "1",
}


def examples(source_dir, everything):
    files = sorted(glob.glob(os.path.join(source_dir, "examples", "*", "*.yaml")))
    chosen = []
    for f in files:
        dim = os.path.basename(os.path.dirname(f))
        name = os.path.splitext(os.path.basename(f))[0]
        if everything or dim in ("2d", "axi") or name in DEFAULT_3D:
            coarse = SCALE_OF.get(name, COARSE_3D) if dim == "3d" else COARSE_2D
            chosen.append((f, coarse))
    return chosen


def must_reject(validator, summary, what):
    errors = list(validator.iter_errors(summary))
    if not errors:
        print("FAIL schema accepts a summary with " + what)
        return False
    print("OK   schema rejects a summary with %s (%s)" % (what, errors[0].message[:80]))
    return True


def self_test(validator, summary):
    ok = True
    added = copy.deepcopy(summary)
    added["energy"] = summary["energy_J"]
    ok &= must_reject(validator, added, "an undocumented key")
    removed = copy.deepcopy(summary)
    del removed["energy_per"]
    ok &= must_reject(validator, removed, "energy_per missing")
    wrong = copy.deepcopy(summary)
    wrong["error_estimate"]["energy_error_pct"] = "0.1"
    ok &= must_reject(validator, wrong, "a number written as a string")
    return ok


def main():
    args = [a for a in sys.argv[1:] if a != "--all"]
    if len(args) != 4:
        print(__doc__)
        return 2
    magfem, schema_path, source_dir, work = args
    with open(schema_path) as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    ok = True
    first = None
    for case, scale in examples(source_dir, "--all" in sys.argv):
        name = os.path.relpath(case, source_dir)
        out = os.path.join(work, name.replace("/", "_").replace(".yaml", ""))
        run = subprocess.run([magfem, "solve", case, "--out", out, "--mesh-scale", scale],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if run.returncode != 0:
            print("FAIL %s: magfem solve exited %d: %s" % (name, run.returncode,
                                                          run.stderr.strip()[-300:]))
            ok = False
            continue
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        errors = sorted(validator.iter_errors(summary), key=lambda e: list(e.path))
        if errors:
            ok = False
            for e in errors[:5]:
                print("FAIL %s: %s: %s" % (name, "/".join(map(str, e.path)) or "(top)",
                                          e.message[:200]))
        else:
            print("OK   " + name)
        if first is None:
            first = summary
    if first is None:
        print("FAIL no example solved")
        return 1
    ok &= self_test(validator, first)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
