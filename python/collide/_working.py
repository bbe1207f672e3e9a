# SPDX-License-Identifier: MIT
"""The working of an impact (``collide solve``): the laws, the scene's numbers substituted and the
result, shown typeset in Jupyter."""
from __future__ import annotations

import re
from typing import Optional

from . import _collide
from ._scene import Scene, as_scene

_HEADING = re.compile(r"^\\noindent\\(?:textbf|emph)\{(.*)\}$")


def _for_mathjax(latex: str) -> str:
    """The LaTeX working as one display that MathJax typesets: its headings as text rows of one
    align* (MathJax has no \\noindent, and takes math only)."""
    rows = []
    for line in latex.splitlines():
        line = line.strip()
        heading = _HEADING.match(line)
        if heading:
            rows.append(r"&\text{" + heading.group(1) + "}")
        elif line and not line.startswith(("%", r"\begin{align*}", r"\end{align*}")):
            rows.append(line.removesuffix(r"\\").rstrip())
    return "$$\\begin{align*}\n" + " \\\\\n".join(rows) + "\n\\end{align*}$$"


class Working:
    """What :func:`collide.solve` returns: ``text`` (Unicode), ``latex`` (amsmath align*, for a
    document), ``markdown`` ($…$ math) and ``mathml``, as ``collide solve --format`` writes them.
    Jupyter shows it typeset."""

    def __init__(self, scene: Scene, written: dict) -> None:
        self.scene = scene
        self.title: str = written["title"]
        self.text: str = written["text"]
        self.latex: str = written["latex"]
        self.markdown: str = written["markdown"]
        self.mathml: str = written["mathml"]

    def _repr_markdown_(self) -> str:
        return self.markdown

    def _repr_latex_(self) -> str:
        return _for_mathjax(self.latex)

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"<collide.Working {self.title!r}>"


def solve(scene: "Scene | str", impact: int = 1, lang: Optional[str] = None) -> Working:
    """The working of impact ``impact`` (1 for the first) of ``scene``, its words in ``lang``
    (else the scene's language, else English), as ``collide solve``."""
    scene = as_scene(scene)
    return Working(scene, _collide.solve(scene._recipe(), int(impact), lang or ""))
