#!/usr/bin/env python3
"""Validates every scene file under scenes/ against scenes/scene.schema.json (JSON Schema).

Run by ctest (test `scene_schema`). Also checks that the schema rejects a scene known to be
wrong, so that a schema that accepts everything cannot pass.
"""
import json
import pathlib
import sys

import jsonschema


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    schema = json.loads((root / "scenes" / "scene.schema.json").read_text())
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    failures = 0
    scenes = sorted(p for p in (root / "scenes").rglob("*.json") if p.name != "scene.schema.json")
    for path in scenes:
        errors = list(validator.iter_errors(json.loads(path.read_text())))
        for e in errors:
            print(f"{path}: {'/'.join(map(str, e.absolute_path))}: {e.message}")
        failures += bool(errors)
    # Negative controls: each of these must be rejected.
    wrong = [
        {"version": 1, "objects": [], "objcts": []},
        {"version": 2, "objects": []},
        {"version": 1, "objects": [{"type": "sphere", "material": "m", "center": [0, 0], "radius": 1}]},
        {"version": 1, "objects": [{"type": "spd", "generator": "ballz"}]},
        {"version": 1, "camera": {"from": [0, 0, 5], "at": [0, 0, 0], "path": {"keys": []}}, "objects": []},
        {"version": 1, "camera": {"from": [0, 0, 5], "at": [0, 0, 0], "path": {"keys": [{"from": [1, 0, 5]}]}},
         "objects": []},
    ]
    for scene in wrong:
        if validator.is_valid(scene):
            print(f"schema accepts a wrong scene: {json.dumps(scene)}")
            failures += 1
    print(f"{len(scenes)} scenes checked, {failures} failures")
    return 1 if failures or not scenes else 0


if __name__ == "__main__":
    sys.exit(main())
