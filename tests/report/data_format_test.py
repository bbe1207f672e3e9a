#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""`collide data`, version 2 (docs/data-format.md, issue 39), for every preset and the ballistic
pendulum whose string goes slack: the --json output validates against docs/data.schema.json (its
first 400 events: all but the ideal gas's); its events' losses add up to energy_lost (releases to energy_released) within 1e-9 relative; every CSV
row's energy columns add up to the energy at the start within 1e-9 relative, at 50 instants or more;
and the soft contact's loss accrues while it lasts. The energy at the start is computed here from
the initial conditions (1/2 m v^2 + m g h), never read from the program's books. Costs a few
seconds: one `collide data` per case (two for the soft contact).

Usage: data_format_test.py SCHEMA COLLIDE"""
import csv
import io
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import jsonschema

RELATIVE = 1e-9
# Events validated against the schema per case: the ideal gas logs some 40,000, which the
# validator would take most of a minute over; the rest of them go through the checks below.
SCHEMA_EVENTS = 400
# A bullet fast enough to swing the block over the top: the string goes slack and snaps taut again.
SLACK_STRING = ("ballistic-pendulum", ["--set", "body.2.velocity=[591.8,0]"])


def fail(message):
    print("data_format_test: " + message, file=sys.stderr)
    sys.exit(1)


def collide_data(collide, name, extra, directory, dt_s):
    json_path = Path(directory) / "summary.json"
    csv_path = Path(directory) / "table.csv"
    command = [collide, "data", name, *extra, "--json", str(json_path), "--events",
               "--csv", str(csv_path), "--dt", repr(dt_s), "-q"]
    done = subprocess.run(command, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        fail(" ".join(command) + " failed: " + done.stderr)
    summary = json.loads(json_path.read_text(encoding="utf-8"))
    rows = list(csv.reader(io.StringIO(csv_path.read_text(encoding="utf-8"))))
    return summary, rows[0], [[float(cell) for cell in row] for row in rows[1:]]


def initial_energy(summary):
    """1/2 m v^2 - m g.x over the bodies as they start (potential energy zero at the origin)."""
    g = summary["gravity"]
    energy = 0.0
    for body in summary["bodies"]:
        m, x, v = body["mass"], body["initial_position"], body["initial_velocity"]
        energy += 0.5 * m * (v[0] ** 2 + v[1] ** 2) - m * (g[0] * x[0] + g[1] * x[1])
        if "initial_spin" in body:  # a rolling ball: I = 2/5 m r^2 about a horizontal axis
            w, r = body["initial_spin"], body["radius"]
            energy += 0.2 * m * r * r * (w[0] ** 2 + w[1] ** 2)
    return energy


def check_events(case, summary):
    events = summary["events"]
    count = len(summary["bodies"])
    lost = released = 0.0
    last_time = 0.0
    for event in events:
        if event["time"] < last_time:
            fail(f"{case}: events out of time order at t = {event['time']}")
        last_time = event["time"]
        for key in ("a", "b"):
            if isinstance(event.get(key), int) and not 1 <= event[key] <= count:
                fail(f"{case}: {key} = {event[key]} is no body number (1 to {count})")
        lost += event["energy_lost"]
        released += event["energy_released"]
    scale = max(summary["energy_lost"], summary["energy_released"],
                summary["kinetic_energy_initial"], sys.float_info.min)
    if abs(lost - summary["energy_lost"]) > RELATIVE * scale:
        fail(f"{case}: the events lose {lost!r} J, the run {summary['energy_lost']!r} J")
    if abs(released - summary["energy_released"]) > RELATIVE * scale:
        fail(f"{case}: the events release {released!r} J, the run {summary['energy_released']!r} J")
    return {event["kind"] for event in events}


def check_rows(case, summary, header, rows):
    """Every _J column but energy_released_J adds up to the start plus energy_released_J."""
    start_J = initial_energy(summary)
    if abs(summary["energy_initial"] - start_J) > RELATIVE * max(abs(start_J), 1e-300):
        fail(f"{case}: energy_initial {summary['energy_initial']!r} J, the bodies give {start_J!r}")
    released = header.index("energy_released_J")
    parts = [k for k, name in enumerate(header) if name.endswith("_J") and k != released]
    if len(rows) < 50:
        fail(f"{case}: {len(rows)} rows, fewer than 50 instants")
    for row in rows:
        books = sum(row[k] for k in parts) - row[released]
        # Relative to the energies in the books: gravity's zero is the origin, so the start can
        # be near 0 where the parts are not.
        scale = max(abs(start_J), sum(abs(row[k]) for k in parts) + row[released])
        if abs(books - start_J) > RELATIVE * scale:
            fail(f"{case}: at t = {row[0]} the energy columns add up to {books!r} J, the start "
                 f"is {start_J!r} J")


def check_soft_contact(collide, directory):
    """The loss accrues from first to last contact: strictly inside each contact it lies strictly
    between its values before and after, and it never goes down."""
    summary, header, rows = collide_data(collide, "soft-contact", [], directory, 0.0005)
    lost = header.index("energy_lost_J")
    starts = [e["time"] for e in summary["events"] if e["kind"] == "contact_start"]
    ends = [e["time"] for e in summary["events"] if e["kind"] == "contact_end"]
    if not starts or len(starts) != len(ends):
        fail(f"soft-contact: contacts start at {starts} and end at {ends}")
    for before, after in zip(rows, rows[1:]):
        if after[lost] < before[lost]:
            fail(f"soft-contact: energy_lost_J goes down at t = {after[0]}")
    for start, end in zip(starts, ends):
        before = [row[lost] for row in rows if row[0] <= start][-1]
        after = [row[lost] for row in rows if row[0] >= end][0]
        inside = [row[lost] for row in rows if start < row[0] < end]
        if not after > before:
            fail(f"soft-contact: the contact from t = {start} loses nothing")
        if len(inside) < 2 or not any(before < value < after for value in inside):
            fail(f"soft-contact: the contact from t = {start} to {end} books its loss at once")


def main():
    schema_path, collide = sys.argv[1:3]
    schema = json.loads(Path(schema_path).read_text(encoding="utf-8"))
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    listed = subprocess.run([collide, "presets"], capture_output=True, text=True, timeout=60)
    names = [line.split()[0] for line in listed.stdout.splitlines() if line.strip()]
    if listed.returncode != 0 or not names:
        fail("no preset names from 'collide presets': " + listed.stderr)
    kinds = set()
    with tempfile.TemporaryDirectory() as directory:
        for name, extra in [(name, []) for name in names] + [SLACK_STRING]:
            case = " ".join([name, *extra])
            summary, header, rows = collide_data(collide, name, extra, directory, 0.05)
            if len(rows) < 50:  # a short scene: 50 instants over its duration
                step = max(summary["duration"] / 49, 0.0005)
                summary, header, rows = collide_data(collide, name, extra, directory, step)
            sample = dict(summary, events=summary["events"][:SCHEMA_EVENTS])
            errors = sorted(validator.iter_errors(sample), key=lambda e: list(e.path))
            if errors:
                fail(f"{case}: not as docs/data.schema.json says: {errors[0].message} at "
                     f"{'/'.join(map(str, errors[0].path))}")
            kinds |= check_events(case, summary)
            check_rows(case, summary, header, rows)
            if extra == SLACK_STRING[1] and not {"string_slack", "string_taut"} <= kinds:
                fail(f"{case}: no string_slack and string_taut events")
        check_soft_contact(collide, directory)
    expected = {"impact", "wall", "rest", "release", "contact_start", "contact_end",
                "string_slack", "string_taut"}
    if not expected <= kinds:
        fail(f"the presets show no event of the kinds {sorted(expected - kinds)}")


main()
