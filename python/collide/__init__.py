# SPDX-License-Identifier: MIT
"""collide in Python: exact event-driven collision physics, its numbers as pandas tables, and its
pictures and videos inline in Jupyter, from the same engine as the ``collide`` program.

    import collide
    scene = collide.Scene.preset("worked-example").with_(restitution=0.3)
    run = collide.simulate(scene)
    run.summary["energy_lost"]
    collide.still(scene, at=2.5)
"""
from ._collide import CollideError, SceneError
from ._figures import Figure, Video, chart, still, strobe, video
from ._run import Run, simulate
from ._scene import Scene, presets
from ._working import Working, solve

SceneError.__module__ = CollideError.__module__ = __name__

__all__ = [
    "CollideError",
    "Figure",
    "Run",
    "Scene",
    "SceneError",
    "Video",
    "Working",
    "chart",
    "presets",
    "simulate",
    "solve",
    "still",
    "strobe",
    "video",
]
