"""A validation entry of the catalogue (validation/catalogue.yaml) run from Python with
magfem.validate: the published value, the FE and analytic ones and the verdict, as
`magfem validate --only ID` reports them, but as rows to compute with and nothing written.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/validate_entry.py
      [ID ...]   (default: harwin.t1.paper.max_ratio_4, seed 002's Table 1 ratio)
"""
import sys

import magfem


def main():
    ids = sys.argv[1:] or ["harwin.t1.paper.max_ratio_4"]
    result = magfem.validate(tier="quick", entries=ids, progress=True)
    for row in result.rows:
        print("%s (%s %s, %s): published %s, FE %s, analytic %s, tolerance %s %% -> %s" % (
            row["id"], row["source"], row["section"], row["unit"], row["published"],
            row["fe"], row["analytic"], row["tolerance_pct"], row["status"]))
    print(result.summary)
    return 1 if result.failed else 0


if __name__ == "__main__":
    sys.exit(main())
