#!/usr/bin/python3
"""Checks docs/case.schema.json against the case files of the source tree.

usage: check_case_schema.py SCHEMA SOURCE_DIR

- the schema itself must be a valid JSON Schema (draft-07);
- its bundled-material names must match materials/library.yaml (names, aliases, kinds);
- every examples/**/*.yaml and validation/cases/*.yaml must parse as plain YAML (expressions
  quoted, "${..}") and validate;
- a few built-in snippets must validate (the axisymmetric mode, which has no example yet);
- every tests/schema/broken/*.yaml must fail validation, with a message containing the text of
  its `# expect-error: ...` line (so each file fails for the reason it was written for).

Prints one OK/FAIL line per file and exits 1 on any unexpected result.
Needs Debian's python3-jsonschema and python3-yaml.
"""
import glob
import json
import os
import re
import sys

import jsonschema
import jsonschema.exceptions
import yaml


class CaseLoader(yaml.SafeLoader):
    """PyYAML resolves YAML 1.1, where `1e-9` (no dot) is a string; magfem (yaml-cpp, std::stod)
    and the YAML language server (YAML 1.2) read it as a number. Resolve floats as YAML 1.2
    does, and reject duplicate keys."""


CaseLoader.yaml_implicit_resolvers = {
    ch: [(tag, rx) for tag, rx in resolvers if tag != "tag:yaml.org,2002:float"]
    for ch, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
CaseLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"""^(?:[-+]?(?:\.[0-9]+|[0-9]+\.[0-9]*)(?:[eE][-+]?[0-9]+)?
                   |[-+]?[0-9]+[eE][-+]?[0-9]+
                   |[-+]?\.(?:inf|Inf|INF)
                   |\.(?:nan|NaN|NAN))$""", re.X),
    list("-+0123456789."))


def construct_mapping(loader, node, deep=False):
    seen = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if key in seen:
            raise yaml.constructor.ConstructorError(
                None, None, "duplicate key %r" % (key,), key_node.start_mark)
        seen.add(key)
    return yaml.SafeLoader.construct_mapping(loader, node, deep)


CaseLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, construct_mapping)


def evaluate(text, lookup):
    """+ - * / parentheses, numbers and names, as casefile/parameter_expression.cpp."""
    import ast

    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            return float(node.value)
        if isinstance(node, ast.Name):
            return lookup(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = ev(node.operand)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub, ast.Mult, ast.Div)):
            a, b = ev(node.left), ev(node.right)
            return {ast.Add: a + b, ast.Sub: a - b, ast.Mult: a * b}.get(type(node.op)) \
                if not isinstance(node.op, ast.Div) else a / b
        raise ValueError("not a parameter expression: %r" % text)

    return ev(ast.parse(text, mode="eval"))


def substitute_parameters(data):
    """Replaces `${..}` by numbers as magfem's reader does (units are not converted: the schema
    checks kinds and signs, which positive unit factors keep)."""
    if not isinstance(data, dict) or "parameters" not in data:
        return data
    raw = data["parameters"] or {}
    values = {}

    def lookup(name):
        if name not in values:
            v = raw[name]["value"] if isinstance(raw[name], dict) else raw[name]
            values[name] = evaluate(v[2:-1], lookup) if isinstance(v, str) else float(v)
        return values[name]

    def walk(node):
        if isinstance(node, dict):
            return {k: walk(v) for k, v in node.items()}
        if isinstance(node, list):
            return [walk(v) for v in node]
        if isinstance(node, str) and "${" in node:
            if re.fullmatch(r"\$\{[^}]*\}", node):
                return evaluate(node[2:-1], lookup)
            return re.sub(r"\$\{([^}]*)\}", lambda m: "%g" % evaluate(m.group(1), lookup), node)
        return node

    return {k: (v if k == "parameters" else walk(v)) for k, v in data.items()}


def load_yaml(path):
    """Plain YAML, as an editor's YAML 1.2 parser reads it: no preprocessing (magfem quotes a
    bare `${..}` for itself, docs/case_format.md "Parameters"; the files checked here must not
    need that, so that every YAML tool reads them)."""
    with open(path, encoding="utf-8") as f:
        return substitute_parameters(yaml.load(f.read(), Loader=CaseLoader))


def where(error):
    path = "".join("[%d]" % p if isinstance(p, int) else ".%s" % p for p in error.absolute_path)
    return path.lstrip(".") or "(top level)"


def all_messages(errors):
    for e in errors:
        yield "%s: %s" % (where(e), e.message)
        yield from all_messages(e.context)


# Built-in snippets that must validate: the axisymmetric mode (no example file yet) is kept
# permissive: 2D keys with points [r, z], coils as regions with turns and current.
GOOD_SNIPPETS = {
    "axi coil and magnet": """
dimension: axi
unit: mm
materials: {pm: {kind: magnet, B_r: 1.2, mu_r: 1.05}}
regions:
  - {name: magnet, shape: rectangle, center: [2.5, 0], width: 5, height: 10, material: pm,
     magnetization: {type: axial}}
  - {name: coil, shape: rectangle, center: [8, 0], width: 2, height: 6, turns: 200, current: 1.5}
boundary: {type: open, radius: 40}
mesh: {size: 2}
probes:
  - {name: axis, type: line, start: [0, -20], end: [0, 20], points: 81}
""",
    "axisymmetric spelled out": """
dimension: axisymmetric
regions:
  - {name: coil, shape: rectangle, center: [8, 0], width: 2, height: 6, turns: 200, current: 1.5}
boundary: {type: open, radius: 40}
mesh: {size: 2}
""",
    "2d minimal with YAML 1.2 floats": """
regions: [{name: m, shape: disk, radius: 1, current_density: 2e6}]
boundary: {type: dirichlet, radius: 5}
mesh: {size: 0.5}
solver: {tolerance: 1e-9}
""",
}


def check_library(schema, source_dir):
    """The schema's `library` enums must be the bundled library's names and aliases, by kind."""
    lib = load_yaml(os.path.join(source_dir, "materials", "library.yaml"))["materials"]
    by_kind = {}
    for name, entry in lib.items():
        by_kind.setdefault(entry["kind"], set()).update([name] + list(entry.get("aliases", [])))
    material = schema["definitions"]["material"]
    expected_all = set().union(*by_kind.values())
    problems = []
    if set(material["properties"]["library"]["enum"]) != expected_all:
        problems.append("material.library enum %s != library.yaml %s"
                        % (sorted(material["properties"]["library"]["enum"]), sorted(expected_all)))
    for branch in material["else"]["allOf"]:
        names = set(branch["if"]["properties"]["library"]["enum"])
        allowed = set(branch["then"]["propertyNames"]["enum"])
        # The overridable law keys tell the kind: bh -> soft, B_r -> magnet, else linear.
        kind = "soft" if "bh" in allowed else "magnet" if "B_r" in allowed else "linear"
        if by_kind.get(kind, set()) != names:
            problems.append("library branch %s does not match the %s entries of library.yaml %s"
                            % (sorted(names), kind, sorted(by_kind.get(kind, set()))))
    return problems


def undocumented(schema):
    """Paths of properties (in `properties` maps) without a description, after $ref."""
    defs = schema.get("definitions", {})

    def resolve(s):
        while isinstance(s, dict) and "$ref" in s and "description" not in s:
            s = defs[s["$ref"].split("/")[-1]]
        return s

    out = []

    def walk(node, path):
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "properties" and isinstance(value, dict):
                    for name, sub in value.items():
                        target = resolve(sub)
                        # `true` and {"items": ...} entries in the dimension branches only
                        # refine a property documented at the top level.
                        refines = sub is True or sub is False or (path.startswith("allOf") and "$ref" not in sub)
                        if not refines and not (isinstance(target, dict) and "description" in target):
                            out.append("%s.properties.%s" % (path, name))
                        walk(sub, "%s.properties.%s" % (path, name))
                elif key not in ("if", "enum", "const", "default", "examples"):
                    walk(value, "%s.%s" % (path, key) if path else key)
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, "%s[%d]" % (path, i))

    walk(schema, "")
    return out


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    schema_path, source_dir = argv[1], argv[2]
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    failures = 0

    try:
        jsonschema.Draft7Validator.check_schema(schema)
        print("OK    schema is a valid draft-07 JSON Schema")
    except jsonschema.SchemaError as e:
        print("FAIL  schema is not a valid JSON Schema: %s" % e.message)
        return 1
    validator = jsonschema.Draft7Validator(schema)

    missing = undocumented(schema)
    for m in missing:
        print("FAIL  property without a description: %s" % m)
    if not missing:
        print("OK    every property has a description")
    failures += len(missing)

    problems = check_library(schema, source_dir)
    for p in problems:
        print("FAIL  %s" % p)
    if not problems:
        print("OK    library names match materials/library.yaml")
    failures += len(problems)

    def rel(p):
        return os.path.relpath(p, source_dir)

    good = sorted(glob.glob(os.path.join(source_dir, "examples", "**", "*.yaml"), recursive=True))
    good += sorted(glob.glob(os.path.join(source_dir, "validation", "cases", "*.yaml")))
    broken = sorted(glob.glob(os.path.join(source_dir, "tests", "schema", "broken", "*.yaml")))
    if not good or not broken:
        print("FAIL  no case files found under %s (%d good, %d broken)"
              % (source_dir, len(good), len(broken)))
        return 1

    def validate(label, load):
        try:
            doc = load()
        except (OSError, yaml.YAMLError) as e:
            print("FAIL  %s: cannot be read: %s" % (label, e))
            return None
        return sorted(validator.iter_errors(doc), key=lambda e: list(e.absolute_path))

    good_items = [(rel(p), lambda p=p: load_yaml(p)) for p in good]
    good_items += [("snippet: " + name, lambda t=text: yaml.load(t, Loader=CaseLoader))
                   for name, text in GOOD_SNIPPETS.items()]
    for label, load in good_items:
        errors = validate(label, load)
        if errors is None:
            failures += 1
        elif errors:
            failures += 1
            best = jsonschema.exceptions.best_match(errors)
            print("FAIL  %s: expected valid, got %d error(s); %s: %s"
                  % (label, len(errors), where(best), best.message))
        else:
            print("OK    %s" % label)

    for path in broken:
        with open(path, encoding="utf-8") as f:
            expect = re.findall(r"^#\s*expect-error:\s*(.+?)\s*$", f.read(), re.M)
        errors = validate(rel(path), lambda p=path: load_yaml(p))
        if errors is None:
            failures += 1
            continue
        if not expect:
            failures += 1
            print("FAIL  %s: no '# expect-error: ...' line" % rel(path))
            continue
        messages = list(all_messages(errors))
        missing = [x for x in expect if not any(x in m for m in messages)]
        if not errors:
            failures += 1
            print("FAIL  %s: expected invalid (%s), but it validates" % (rel(path), expect[0]))
        elif missing:
            failures += 1
            print("FAIL  %s: rejected, but not for %r; got: %s"
                  % (rel(path), missing, "; ".join(messages)))
        else:
            best = jsonschema.exceptions.best_match(errors)
            print("OK    %s: rejected as expected (%d error(s)); %s: %s"
                  % (rel(path), len(errors), where(best), best.message))

    print("%d unexpected result(s)" % failures if failures else "all as expected")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
