# SPDX-License-Identifier: MIT
"""docs/notebooks/restitution.ipynb runs from top to bottom without an error, and shows its
pictures and video inline."""
import base64
import os
import subprocess
from pathlib import Path

import nbformat
from nbclient import NotebookClient

import collide

from conftest import REPOSITORY

NOTEBOOK = REPOSITORY / "docs" / "notebooks" / "restitution.ipynb"


def outputs_of(notebook, mime):
    return [output["data"][mime] for cell in notebook.cells if cell.cell_type == "code"
            for output in cell.get("outputs", []) if mime in output.get("data", {})]


def first_frame(mp4: bytes, folder) -> bytes:
    video = folder / "inline.mp4"
    video.write_bytes(mp4)
    frame = folder / "first-frame.png"
    subprocess.run(["ffmpeg", "-v", "error", "-i", str(video), "-frames:v", "1", str(frame)],
                   check=True, timeout=60)
    return frame.read_bytes()


def test_the_notebook_runs_and_shows_its_pictures(scratch, monkeypatch):
    # Jupyter's connection files, IPython's profile and matplotlib's font cache in the test's own
    # folder, not the home directory.
    for variable in ("JUPYTER_RUNTIME_DIR", "IPYTHONDIR", "MPLCONFIGDIR"):
        monkeypatch.setenv(variable, str(scratch / variable.lower()))
    # The kernel imports the package under test, whatever the folder it runs in.
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(collide.__file__)))
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(
        [package_parent] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]))
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel's debugger's notes
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    assert all(not cell.get("outputs") for cell in notebook.cells if cell.cell_type == "code")
    # The kernel is this interpreter's: the package on its path, in a folder of the test's own.
    NotebookClient(notebook, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": str(scratch)}}).execute()
    pngs = outputs_of(notebook, "image/png")
    assert len(pngs) == 3  # the loss chart, the still, the strobe
    workings = outputs_of(notebook, "text/markdown")
    assert len(workings) == 1 and workings[0].startswith("**Impact 1 of 1: cart 1 and cart 2")
    videos = [page for page in outputs_of(notebook, "text/html") if page.startswith("<video")]
    assert len(videos) == 1 and '<track kind="captions"' in videos[0]
    mp4 = base64.b64decode(videos[0].split("data:video/mp4;base64,")[1].split('"')[0])
    frame = first_frame(mp4, scratch)
    # Where asked (the report on the package's pull request), the inline still and the video's
    # first frame are kept to be looked at.
    keep = os.environ.get("COLLIDE_NOTEBOOK_PICTURES")
    if keep:
        folder = Path(keep)
        folder.mkdir(parents=True, exist_ok=True)
        (folder / "still.png").write_bytes(base64.b64decode(pngs[1]))
        (folder / "video-first-frame.png").write_bytes(frame)
