# SPDX-License-Identifier: MIT
"""Scenes: a preset or a scene file, with overrides applied as ``collide --set`` applies them."""
from __future__ import annotations

import json
import numbers
import os
from typing import Any, Dict, Optional, Tuple

from . import _collide

# The program's two-body shortcuts (--m1, --e, --v1, --theta1, ...): key, kind of override.
# Kinds as scene::Override::Kind: 0 a value, 1 a speed keeping the direction, 2 a direction
# keeping the speed.
_SHORTCUTS = {
    "m1": ("body.1.mass", 0),
    "m2": ("body.2.mass", 0),
    "e": ("restitution", 0),
    "v1": ("body.1", 1),
    "v2": ("body.2", 1),
    "theta1": ("body.1", 2),
    "theta2": ("body.2", 2),
}


def presets() -> Dict[str, str]:
    """Every preset's name and one-line description, in the order ``collide presets`` lists them."""
    return dict(_collide.presets())


def _toml_item(value: Any) -> str:
    """A value inside a TOML array: strings quoted."""
    if isinstance(value, str):
        return json.dumps(value)
    return _toml_value(value)


def _toml_value(value: Any) -> str:
    """A value as typed after ``--set KEY=``: numbers in their shortest exact form, a bare word
    taken as a string (``dark``), a quantity with its unit as written (``"60 km/h"``)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_item(item) for item in value) + "]"
    raise TypeError(f"{value!r}: a scene value is a number, a bool, a string or a list of them")


def _override(key: str, value: Any) -> Tuple[str, str, str, int]:
    text = _toml_value(value)
    if key in _SHORTCUTS:
        target, kind = _SHORTCUTS[key]
        return (target, text, f"--{key} {text}", kind)
    return (key, text, f"--set {key}={text}", 0)


class Scene:
    """A scene to simulate and draw: ``Scene.preset(name)`` or ``Scene.from_toml(text_or_path)``,
    changed with ``scene.with_(...)``. Immutable; checked when made (bad input raises
    :class:`collide.SceneError` with the program's message)."""

    __slots__ = ("_source", "_is_text", "_text_name", "_overrides", "_info")

    def __init__(self) -> None:
        raise TypeError("make a Scene with Scene.preset(name) or Scene.from_toml(text_or_path)")

    @classmethod
    def _make(cls, source: str, is_text: bool, text_name: str, overrides: tuple) -> "Scene":
        scene = object.__new__(cls)
        scene._source = source
        scene._is_text = is_text
        scene._text_name = text_name
        scene._overrides = overrides
        scene._info = _collide.describe(scene._recipe())
        return scene

    @classmethod
    def preset(cls, name: str) -> "Scene":
        """A built-in preset (see :func:`collide.presets`)."""
        return cls._make(str(name), False, "", ())

    @classmethod
    def from_toml(cls, text_or_path: "str | os.PathLike[str]", name: Optional[str] = None) -> "Scene":
        """A scene file (docs/scene-format.md): its path, or its text. Text (anything with a line
        break or an ``=``) is named ``name`` (default ``scene``) in messages and output names."""
        if isinstance(text_or_path, os.PathLike):
            return cls._make(os.fspath(text_or_path), False, "", ())
        text = str(text_or_path)
        if "\n" in text or "=" in text:
            return cls._make(text, True, (name or "scene") + ".toml", ())
        return cls._make(text, False, "", ())

    def with_(self, **changes: Any) -> "Scene":
        """The scene with values changed as ``--set KEY=VALUE`` changes them, in order:
        ``with_(restitution=0.3, **{"body.2.mass": 3, "view.theme": "dark"})``. The program's
        two-body shortcuts are keys too: ``m1``, ``m2``, ``e``, ``v1``, ``v2``, ``theta1``,
        ``theta2``."""
        added = tuple(_override(key, value) for key, value in changes.items())
        return Scene._make(self._source, self._is_text, self._text_name, self._overrides + added)

    def to_toml(self, lang: Optional[str] = None) -> str:
        """The scene as a scene file that reads back to the same scene (words in ``lang``, else
        the scene's own language)."""
        return _collide.to_toml(self._recipe(), lang or "")

    @property
    def name(self) -> str:
        return self._info["name"]

    @property
    def title(self) -> str:
        return self._info["title"]

    @property
    def duration(self) -> float:
        """Simulated seconds."""
        return self._info["duration"]

    @property
    def dimensions(self) -> int:
        return self._info["dimensions"]

    def _recipe(self, duration: Optional[float] = None) -> tuple:
        typed = "" if duration is None else _toml_value(duration)
        number = None if duration is None else float(duration)
        return (self._source, self._is_text, self._text_name, list(self._overrides), number, typed)

    def __repr__(self) -> str:
        if self._is_text:
            made = f"Scene.from_toml(<text {self._text_name!r}>)"
        elif self._source in presets():
            made = f"Scene.preset({self._source!r})"
        else:
            made = f"Scene.from_toml({self._source!r})"
        if not self._overrides:
            return made
        changes = ", ".join(
            origin[len("--set "):] if origin.startswith("--set ") else origin[2:].replace(" ", "=", 1)
            for _, _, origin, _ in self._overrides
        )
        return f"{made}.with_({changes})"


def as_scene(scene: "Scene | str") -> Scene:
    """A Scene, or a preset name or scene file path given instead of one."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, os.PathLike)):
        text = os.fspath(scene)
        if text.endswith(".toml") or "/" in text or "\n" in text:
            return Scene.from_toml(scene)
        return Scene.preset(text)
    raise TypeError(f"{scene!r}: expected a collide.Scene, a preset name or a scene file path")
