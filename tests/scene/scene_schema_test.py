#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""docs/scene.schema.json: the committed file is the one the field table makes; every preset as
`collide presets show` writes it validates, with the `#:schema` line first; and every bad scene
file of the bad-input matrix that a schema can see is rejected (MalformedToml by the TOML parser,
which an editor runs first). Costs about a second: one `collide presets show` per preset.

Usage: scene_schema_test.py SCHEMA GENERATOR COLLIDE BAD_FILES_WRITER"""
import json
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

import jsonschema

# Bad-input cases whose scene file a schema (or the TOML parser) can tell is wrong. The others
# need geometry (overlaps, a pivot inside a body, a string across a wall), the frame rate of a
# command (a strobe rate), a sweep, or a nan (JSON has none, so a schema cannot name it).
SCHEMA_VISIBLE = {
    "MalformedToml": "not TOML",
    "UnknownKey": "restitutoin is no key",
    "WrongType": "velocity \"fast\" is no quantity",
    "ZeroMass": "mass must be more than 0",
    "NegativeMass": "mass must be more than 0",
    "InfInFile": "gravity beyond 1e4",
    "NegativeDurationInFile": "duration must be more than 0",
    "AbsurdBodyCount": "at most 1000 bodies",
    "HugeUnknownKeyInAFile": "an unknown key",
    "ZeroStringLength": "length must be more than 0",
    "NegativeStringLength": "length must be more than 0",
    "LengthWithoutPivot": "length needs pivot",
    "PivotInA1DScene": "a string hangs only in a 2D scene",
    "StringWithoutGravity": "a string needs gravity pulling down",
}


def fail(message):
    print("scene_schema_test: " + message, file=sys.stderr)
    sys.exit(1)


def main():
    schema_path, generator, collide, writer = sys.argv[1:5]
    committed = Path(schema_path).read_text(encoding="utf-8")
    generated = subprocess.run([generator], check=True, capture_output=True, text=True, timeout=60).stdout
    if committed != generated:
        fail(schema_path + " differs from the field table's schema; regenerate it: "
             "build/tests/scene/collide_scene_schema > docs/scene.schema.json")
    schema = json.loads(committed)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)

    listed = subprocess.run([collide, "presets"], capture_output=True, text=True, timeout=60)
    names = [line.split()[0] for line in listed.stdout.splitlines() if line.strip()]
    if listed.returncode != 0 or not names:
        fail("no preset names from 'collide presets': " + listed.stderr)
    for name in names:
        text = subprocess.run([collide, "presets", "show", name], check=True,
                              capture_output=True, text=True, timeout=60).stdout
        if not text.startswith("#:schema "):
            fail(name + ": 'presets show' does not start with a #:schema line")
        errors = [e.message for e in validator.iter_errors(tomllib.loads(text))]
        if errors:
            fail(name + ": the schema rejects 'presets show': " + errors[0])

    with tempfile.TemporaryDirectory(prefix="collide-schema-") as directory:
        subprocess.run([writer, directory], check=True, timeout=60)
        written = {p.stem: p for p in Path(directory).glob("*.toml")}
        for name, why in SCHEMA_VISIBLE.items():
            if name not in written:
                fail(name + ": no such bad-input case with a scene file")
            try:
                data = tomllib.loads(written[name].read_text(encoding="utf-8"))
            except tomllib.TOMLDecodeError:
                continue  # the editor's TOML parser rejects it
            if validator.is_valid(data):
                fail(name + ": the schema accepts it, but " + why)
    print("scene_schema_test: %d presets valid, %d bad files rejected"
          % (len(names), len(SCHEMA_VISIBLE)))


main()
