# SPDX-License-Identifier: MIT
"""Pictures and videos: the program's own, inline in Jupyter and saved; the GIL released while they
are drawn; Ctrl-C stops a drawing cleanly."""
import io
import json
import os
import signal
import subprocess
import sys
import threading
import time

import numpy
import pytest
from PIL import Image

import collide
from conftest import REPOSITORY, assert_same_picture, program_error, run_program

SIZE = (640, 360)
SIZE_TEXT = "640x360"


def decoded(png: bytes) -> numpy.ndarray:
    return numpy.asarray(Image.open(io.BytesIO(png)).convert("RGBA"))


def rasterized(svg_path) -> numpy.ndarray:
    """An SVG file drawn by librsvg at its own size."""
    png = subprocess.run(["rsvg-convert", str(svg_path)], capture_output=True, check=True,
                         timeout=60).stdout
    return decoded(png)


FIGURES = [
    ("still", lambda: collide.still("worked-example", at=2.5, size=SIZE), ["--at", "2.5"]),
    ("strobe", lambda: collide.strobe("bouncing-ball", size=SIZE), []),
    ("chart", lambda: collide.chart("worked-example", size=SIZE), []),
]


@pytest.mark.parametrize("command, make, arguments", FIGURES, ids=[f[0] for f in FIGURES])
def test_png_and_svg_are_the_programs(command, make, arguments, scratch):
    scene = "bouncing-ball" if command == "strobe" else "worked-example"
    figure = make()
    for extension in ("png", "svg"):
        path = scratch / f"program.{extension}"
        run_program(command, scene, *arguments, "--size", SIZE_TEXT, "-o", str(path),
                    "--no-alt-text" if command == "still" else "--quiet")
        if extension == "png":
            assert_same_picture(decoded(figure._repr_png_()), decoded(path.read_bytes()))
        else:
            ours = scratch / "ours.svg"
            ours.write_text(figure._repr_svg_())
            assert_same_picture(rasterized(ours), rasterized(path))


def test_save_writes_the_format_the_path_names(scratch):
    figure = collide.still("worked-example", at=1.0, size=SIZE)
    assert figure.save(scratch / "a.pdf") == str(scratch / "a.pdf")
    assert (scratch / "a.pdf").read_bytes().startswith(b"%PDF-")
    figure.save(scratch / "a.png")
    assert Image.open(scratch / "a.png").size == SIZE
    assert sorted(os.listdir(scratch)) == ["a.pdf", "a.png"]  # nothing else left beside them
    with pytest.raises(collide.SceneError) as raised:
        figure.save(scratch / "a.bmp")
    assert str(raised.value) == program_error("still", "worked-example", "-o",
                                              str(scratch / "a.bmp"))


def test_bad_picture_options_raise_the_programs_message():
    with pytest.raises(collide.SceneError) as raised:
        collide.still("worked-example", theme="purple").png()
    assert str(raised.value) == program_error("still", "worked-example", "--theme", "purple",
                                              "-o", "x.png")
    with pytest.raises(collide.SceneError, match=r"^at: 9: allowed: a time from 0 to 4 s"):
        collide.still("worked-example", at=9).png()
    with pytest.raises(collide.SceneError, match=r"^--size: '8x8': "):
        collide.still("worked-example", size=(8, 8)).png()


def test_a_one_second_video_decodes(scratch):
    clip = collide.video(collide.Scene.preset("worked-example").with_(duration=1), fps=30,
                         size=(320, 180))
    page = clip._repr_html_()
    assert page.startswith('<video controls') and '<track kind="captions"' in page
    assert clip.captions().startswith("WEBVTT")
    path = scratch / "clip.mp4"
    path.write_bytes(clip.mp4())
    probe = json.loads(subprocess.run(
        ["ffprobe", "-v", "error", "-count_frames", "-show_streams", "-show_format", "-of", "json",
         str(path)], capture_output=True, check=True, text=True, timeout=60).stdout)
    video = [s for s in probe["streams"] if s["codec_type"] == "video"][0]
    assert (video["codec_name"], video["width"], video["height"]) == ("h264", 320, 180)
    assert int(video["nb_read_frames"]) == 30
    assert float(probe["format"]["duration"]) == pytest.approx(1.0, abs=0.05)
    clip.save(scratch / "saved.webm", captions=True)
    assert sorted(os.listdir(scratch)) == ["clip.mp4", "saved.vtt", "saved.webm"]


def test_python_runs_while_a_video_is_drawn():
    # With the GIL held while drawing, this thread's loop would stand still until the video ends.
    clip = collide.video(collide.Scene.preset("worked-example").with_(duration=2), fps=30,
                         size=(320, 180))
    drawer = threading.Thread(target=clip.mp4)
    drawer.start()
    turns = 0
    while drawer.is_alive():
        turns += 1
        time.sleep(0.001)
    drawer.join()
    assert turns >= 20, turns  # about one turn per millisecond of drawing, which takes > 100 ms


def test_progress_counts_the_frames(scratch):
    # What a notebook's progress bar is given: frames drawn of frames in all, up to all of them.
    seen = []
    collide._collide.video(collide.Scene.preset("worked-example")._recipe(1.0),
                           str(scratch / "counted.mp4"), 20, False, {"size": "160x90"},
                           lambda done, total: seen.append((done, total)))
    assert seen[-1] == (20, 20)
    assert all(total == 20 for _, total in seen)
    assert [done for done, _ in seen] == sorted(done for done, _ in seen)


INTERRUPTED = """
import collide, sys
scene = collide.Scene.preset("ideal-gas").with_(duration=600)
print("drawing", flush=True)
try:
    collide.video(scene, fps=60, size=(640, 360)).save(sys.argv[1])
except KeyboardInterrupt:
    print("interrupted", flush=True)
"""


def test_ctrl_c_stops_a_video_cleanly(scratch):
    target = scratch / "long.mp4"
    child = subprocess.Popen([sys.executable, "-c", INTERRUPTED, str(target)],
                             stdout=subprocess.PIPE, text=True, env=os.environ.copy())
    assert child.stdout.readline() == "drawing\n"
    time.sleep(1.5)
    child.send_signal(signal.SIGINT)
    output, _ = child.communicate(timeout=20)
    assert output == "interrupted\n"
    assert child.returncode == 0
    assert os.listdir(scratch) == []  # no video, no temporary file
