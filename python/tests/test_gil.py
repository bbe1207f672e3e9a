# SPDX-License-Identifier: MIT
"""Drawing releases the GIL: two videos drawn from two Python threads are under way at once. Each
reports its frames as it draws them (the progress callback a notebook's bar is given), and the
order of those reports says whether the drawings overlapped. With the GIL held while drawing, the
second thread could not even start its video until the first had drawn its last frame. No clock
is read: the test asserts an order of events, not a time."""
import threading

import collide

# The long video has many times the frames of the short one, so that the short one, started after
# the long one's first frame, begins drawing long before the long one ends (its simulation and its
# label plan are a small part of the long one's drawing).
LONG_FRAMES = 240
SHORT_FRAMES = 10
# What a thread that never reports is given before the test fails instead of hanging.
WAIT_S = 120


def draw(path, frames, name, reports, first_report):
    recipe = collide.Scene.preset("worked-example")._recipe(2.0)

    def progress(done, total):
        reports.append((name, done, total))
        first_report.set()

    collide._collide.video(recipe, str(path), frames // 2, False, {"size": "320x180"}, progress)


def test_two_videos_draw_at_once(tmp_path):
    reports = []
    long_started, short_started = threading.Event(), threading.Event()
    long_video = threading.Thread(
        target=draw, args=(tmp_path / "long.mp4", LONG_FRAMES, "long", reports, long_started))
    short_video = threading.Thread(
        target=draw, args=(tmp_path / "short.mp4", SHORT_FRAMES, "short", reports, short_started))
    long_video.start()
    assert long_started.wait(WAIT_S), "the long video reported no frame"
    short_video.start()
    long_video.join(WAIT_S)
    short_video.join(WAIT_S)
    assert not long_video.is_alive() and not short_video.is_alive()

    order = [name for name, _, _ in reports]
    assert "short" in order, "the short video reported no frame"
    # Both finished all their frames.
    assert max(done for name, done, _ in reports if name == "long") == LONG_FRAMES
    assert max(done for name, done, _ in reports if name == "short") == SHORT_FRAMES
    # The short video reported a frame while the long one still had frames to draw, and the long
    # one went on drawing after that: the two drawings overlapped.
    first_short = order.index("short")
    long_after = [done for name, done, _ in reports[first_short:] if name == "long"]
    assert long_after and min(long_after) < LONG_FRAMES, reports
