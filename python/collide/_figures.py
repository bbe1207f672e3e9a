# SPDX-License-Identifier: MIT
"""Pictures and videos drawn by the program's own pipelines, shown inline by Jupyter and saved in
any of the program's formats."""
from __future__ import annotations

import base64
import html
import os
import sys
import tempfile
from typing import Any, Callable, Dict, Optional, Tuple

from . import _collide
from ._scene import Scene, _toml_value, as_scene

Size = Tuple[int, int]


def _size_text(size: Size) -> str:
    width, height = size
    return f"{int(width)}x{int(height)}"


def _look(size: Size, lang: Optional[str], theme: Optional[str], chart: Optional[str],
          panels: Optional[str]) -> Dict[str, Any]:
    return {"size": _size_text(size), "lang": lang, "theme": theme, "chart": chart,
            "panels": panels}


def _drawn_bytes(draw: Callable[[str], Dict[str, Any]], suffix: str) -> Tuple[bytes, Dict[str, Any]]:
    """What `draw` writes to a file named *suffix, read back; the file is gone after."""
    with tempfile.TemporaryDirectory(prefix="collide-") as folder:
        path = os.path.join(folder, "figure" + suffix)
        info = draw(path)
        with open(path, "rb") as drawn:
            return drawn.read(), info


class Figure:
    """A still, a stroboscopic picture or a chart. Jupyter shows it inline (PNG and SVG);
    :meth:`save` writes it as the program would, in the format the path's extension names
    (``.png``, ``.svg``, ``.pdf``). Drawn when first shown or saved."""

    def __init__(self, kind: str, scene: Scene, draw: Callable[[str], Dict[str, Any]]) -> None:
        self.kind = kind
        self.scene = scene
        self._draw = draw
        self._png: Optional[bytes] = None
        self._svg: Optional[str] = None
        self.info: Dict[str, Any] = {}

    def png(self) -> bytes:
        """The picture as PNG bytes."""
        if self._png is None:
            self._png, self.info = _drawn_bytes(self._draw, ".png")
        return self._png

    def svg(self) -> str:
        """The picture as an SVG document."""
        if self._svg is None:
            data, self.info = _drawn_bytes(self._draw, ".svg")
            self._svg = data.decode("utf-8")
        return self._svg

    def save(self, path: "str | os.PathLike[str]") -> str:
        """Writes the picture to ``path`` (PNG, SVG or PDF by its extension), under a temporary
        name renamed into place: a failure or Ctrl-C leaves nothing there. Returns the path."""
        target = os.fspath(path)
        self.info = self._draw(target)
        return target

    def _repr_png_(self) -> bytes:
        return self.png()

    def _repr_svg_(self) -> str:
        return self.svg()

    def __repr__(self) -> str:
        return f"<collide.Figure {self.kind} of {self.scene!r}>"


def still(scene: "Scene | str", at: Optional[float] = None, size: Size = (1280, 720),
          lang: Optional[str] = None, theme: Optional[str] = None, chart: Optional[str] = None,
          panels: Optional[str] = None, transparent: bool = False) -> Figure:
    """One instant, ``at`` seconds (default: the middle of the scene), as ``collide still``."""
    scene = as_scene(scene)
    at_typed = "" if at is None else _toml_value(at)
    at_s = None if at is None else float(at)
    look = _look(size, lang, theme, chart, panels)

    def draw(path: str) -> Dict[str, Any]:
        return _collide.still(scene._recipe(), path, at_s, at_typed, transparent, look)

    return Figure("still", scene, draw)


def strobe(scene: "Scene | str", rate: Optional[float] = None, size: Size = (1280, 720),
           lang: Optional[str] = None, theme: Optional[str] = None, chart: Optional[str] = None,
           panels: Optional[str] = None) -> Figure:
    """The bodies at t = k / rate over the whole scene in one picture, as ``collide strobe``
    (default rate: the scene's, else chosen so that a body's images do not overlap)."""
    scene = as_scene(scene)
    rate_typed = "" if rate is None else _toml_value(rate)
    rate_hz = None if rate is None else float(rate)
    look = _look(size, lang, theme, chart, panels)

    def draw(path: str) -> Dict[str, Any]:
        return _collide.strobe(scene._recipe(), path, rate_hz, rate_typed, look)

    return Figure("strobe", scene, draw)


def chart(scene: "Scene | str", quantity: Optional[str] = None, size: Size = (1280, 720),
          lang: Optional[str] = None, theme: Optional[str] = None) -> Figure:
    """The scene's chart alone (``quantity``: energy, momentum, force or speed; default the
    scene's, else energy), as ``collide chart``."""
    scene = as_scene(scene)
    look = _look(size, lang, theme, quantity, None)

    def draw(path: str) -> Dict[str, Any]:
        return _collide.chart(scene._recipe(), path, look)

    return Figure("chart", scene, draw)


def _in_notebook() -> bool:
    """Whether this runs in a Jupyter kernel (not a script, not a terminal IPython)."""
    shell = sys.modules.get("IPython")
    if shell is None:
        return False
    running = shell.get_ipython()
    return running is not None and type(running).__name__ == "ZMQInteractiveShell"


def _progress_bar(progress: Optional[bool]) -> Optional[Callable[[int, int], None]]:
    """A tqdm bar's update for the frames drawn: asked for (True), or by default (None) in a
    notebook; nothing in scripts unless asked, nor where tqdm is not installed."""
    if progress is False or (progress is None and not _in_notebook()):
        return None
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    bar = None

    def update(done: int, total: int) -> None:
        nonlocal bar
        if bar is None:
            bar = tqdm(total=total, unit="frame", desc="drawing", leave=False)
        bar.update(done - bar.n)
        if done >= total:
            bar.close()

    return update


class Video:
    """A video as ``collide render`` makes it. Jupyter shows it inline as an HTML5 video with its
    narration as captions; :meth:`save` writes it (``.mp4``, ``.webm``, ``.gif``, or a folder for
    PNG frames, by the path). Drawn when first shown or saved."""

    def __init__(self, scene: Scene, fps: int, look: Dict[str, Any],
                 progress: Optional[bool] = None) -> None:
        self.scene = scene
        self.fps = fps
        self._look = look
        self._progress = progress
        self._mp4: Optional[bytes] = None
        self._vtt: Optional[str] = None
        self.info: Dict[str, Any] = {}

    def _render(self, path: str, captions: bool) -> Dict[str, Any]:
        self.info = _collide.video(self.scene._recipe(), path, self.fps, captions, self._look,
                                   _progress_bar(self._progress))
        return self.info

    def mp4(self) -> bytes:
        """The video as MP4 (H.264) bytes."""
        if self._mp4 is None:
            with tempfile.TemporaryDirectory(prefix="collide-") as folder:
                path = os.path.join(folder, "video.mp4")
                self._render(path, captions=True)
                with open(path, "rb") as video:
                    self._mp4 = video.read()
                with open(os.path.join(folder, "video.vtt"), encoding="utf-8") as captions:
                    self._vtt = captions.read()
        return self._mp4

    def captions(self) -> str:
        """The narration as WebVTT captions."""
        self.mp4()
        assert self._vtt is not None
        return self._vtt

    def save(self, path: "str | os.PathLike[str]", captions: bool = False) -> str:
        """Writes the video to ``path`` in the format its extension names, under a temporary name
        renamed into place (a failure or Ctrl-C leaves nothing there); ``captions``: WebVTT
        beside it (NAME.vtt). Returns the path."""
        target = os.fspath(path)
        self._render(target, captions)
        return target

    def _repr_html_(self) -> str:
        video = base64.b64encode(self.mp4()).decode("ascii")
        vtt = base64.b64encode(self.captions().encode("utf-8")).decode("ascii")
        width = self.info.get("size", (640, 360))[0]
        lang = html.escape(self._look.get("lang") or "en")
        return (f'<video controls width="{min(width, 960)}">'
                f'<source type="video/mp4" src="data:video/mp4;base64,{video}">'
                f'<track kind="captions" label="Narration" srclang="{lang}" default '
                f'src="data:text/vtt;base64,{vtt}"></video>')

    def __repr__(self) -> str:
        return f"<collide.Video of {self.scene!r} at {self.fps} fps>"


def video(scene: "Scene | str", fps: int = 60, size: Size = (1280, 720),
          lang: Optional[str] = None, theme: Optional[str] = None, chart: Optional[str] = None,
          panels: Optional[str] = None, progress: Optional[bool] = None) -> Video:
    """The scene as a video, as ``collide render``: ``fps`` frames per second of ``size``.
    ``progress``: a progress bar (tqdm) while it is drawn; by default in a notebook only."""
    return Video(as_scene(scene), int(fps), _look(size, lang, theme, chart, panels), progress)
