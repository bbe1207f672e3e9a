# SPDX-License-Identifier: MIT
"""A simulation: the numbers of ``collide data`` (summary, events, table) and the exact state at
any time."""
from __future__ import annotations

import csv
import io
import json
from typing import Any, Dict, List, Optional

import numpy

from . import _collide
from ._scene import Scene, _toml_value, as_scene


class Run:
    """What :func:`collide.simulate` returns. The motion between events is exact, so
    :meth:`state` is exact at any time."""

    def __init__(self, scene: Scene, native: "_collide.Run") -> None:
        self.scene = scene
        self._native = native
        self._summary: Optional[Dict[str, Any]] = None
        self._events: Optional[List[Dict[str, Any]]] = None

    @property
    def summary(self) -> Dict[str, Any]:
        """``collide data SCENE --json``, parsed: bodies, momentum and kinetic energy before and
        after, energy lost, collision count."""
        if self._summary is None:
            self._summary = json.loads(self._native.summary_json(False))
        return self._summary

    @property
    def events(self) -> List[Dict[str, Any]]:
        """Every event (impacts, walls, strings, contacts), as the ``events`` of
        ``collide data --json --events`` (docs/data-format.md)."""
        if self._events is None:
            self._events = json.loads(self._native.summary_json(True))["events"]
        return self._events

    @property
    def duration(self) -> float:
        return self._native.duration

    @property
    def warnings(self) -> List[str]:
        """The physics warnings the program prints (a run stopped at a cap, a ledger mismatch)."""
        return list(self._native.warnings)

    def table(self, dt: float = 0.01) -> Any:
        """``collide data --csv --dt DT``: one row per step (and the last instant), columns named as
        the CSV's header (t_s, then each body's position, velocity, momentum, kinetic and
        potential energy, then the total momentum and the energy books; docs/data-format.md).
        A pandas DataFrame where pandas is installed, else a numpy structured array."""
        text = self._native.csv(float(dt), _toml_value(dt))
        header_line, _, rows = text.partition("\n")
        names = next(csv.reader([header_line]))
        values = numpy.loadtxt(io.StringIO(rows), delimiter=",", ndmin=2, dtype=float)
        table = numpy.empty(len(values), dtype=[(name, "f8") for name in names])
        for column, name in enumerate(names):
            table[name] = values[:, column]
        try:
            import pandas
        except ImportError:
            return table
        return pandas.DataFrame(table)

    def state(self, t: float) -> Dict[str, Any]:
        """The exact state at ``t`` seconds (after a collision at exactly t): each body's
        position, velocity, angle and angular velocity, the total momentum, kinetic and
        potential energy, the energy lost so far and the collisions so far."""
        return self._native.state(float(t), _toml_value(t))

    def __repr__(self) -> str:
        return f"<collide.Run of {self.scene!r}: {self.summary['collision_count']} collisions>"


def simulate(scene: "Scene | str", duration: Optional[float] = None) -> Run:
    """Simulates ``scene`` (a Scene, a preset name or a scene file path) over its duration, or
    ``duration`` seconds, exactly as ``collide data`` does."""
    scene = as_scene(scene)
    return Run(scene, _collide.simulate(scene._recipe(duration)))
