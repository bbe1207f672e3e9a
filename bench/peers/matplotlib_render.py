#!/usr/bin/python3
"""The teacher's alternative to `collide render worked-example`: a matplotlib FuncAnimation.

The same picture as collide's worked example: two 1 kg blocks 0.5 m wide on a track (1 kg at -2 m
moving at +2 m/s, 1 kg at +2 m moving at -1 m/s, e = 0.5), a velocity arrow with its value above each
block, an energy bar (blue and orange for the kinetic energy of blocks 1 and 2, gray for the energy
lost so far, the whole bar the initial kinetic energy) with labels under it, a title, a time readout
and a caption. The physics is the exact analytic solution, computed here.

Written the way a teacher would: plain FuncAnimation (no blitting), FFMpegWriter with libx264,
preset veryfast, crf 20, yuv420p; every frame is drawn by Agg and piped to ffmpeg as raw RGBA.

    matplotlib_render.py OUT.mp4 [--size 1280x720] [--fps 60] [--duration 10]
    matplotlib_render.py OUT.png --still 2.5 [--size 1280x720]

Run it with Debian's /usr/bin/python3 (python3-matplotlib).
"""
import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import animation, patches  # noqa: E402

# --- The worked example, solved exactly -------------------------------------------------------
M1, M2 = 1.0, 1.0  # kg
X1, X2 = -2.0, 2.0  # m, centres at t = 0
V1, V2 = 2.0, -1.0  # m/s
E = 0.5  # coefficient of restitution
WIDTH = 0.5  # m, both blocks

# Contact when the gap between facing sides closes: (X2 - X1 - WIDTH) / (V1 - V2).
T_HIT = (X2 - X1 - WIDTH) / (V1 - V2)
# Momentum conservation and the definition of e.
V1_AFTER = ((M1 - E * M2) * V1 + (1 + E) * M2 * V2) / (M1 + M2)
V2_AFTER = ((1 + E) * M1 * V1 + (M2 - E * M1) * V2) / (M1 + M2)
KE0 = 0.5 * M1 * V1 ** 2 + 0.5 * M2 * V2 ** 2
LOST = 0.5 * (M1 * M2 / (M1 + M2)) * (1 - E ** 2) * (V1 - V2) ** 2

BLUE = (0 / 255, 114 / 255, 178 / 255)
ORANGE = (230 / 255, 159 / 255, 0 / 255)
GRAY = (153 / 255, 153 / 255, 153 / 255)
INK = (0.13, 0.13, 0.13)


def state(t):
    """Centres (m), velocities (m/s) and energy lost (J) at time t."""
    if t < T_HIT:
        return X1 + V1 * t, X2 + V2 * t, V1, V2, 0.0
    x1 = X1 + V1 * T_HIT + V1_AFTER * (t - T_HIT)
    x2 = X2 + V2 * T_HIT + V2_AFTER * (t - T_HIT)
    return x1, x2, V1_AFTER, V2_AFTER, LOST


def darker(color, k=0.6):
    return tuple(c * k for c in color)


class Picture:
    """Builds the figure once; update(t) moves everything to time t."""

    def __init__(self, width_px, height_px, duration_s):
        dpi = 100
        self.fig = plt.figure(figsize=(width_px / dpi, height_px / dpi), dpi=dpi, facecolor="white")
        self.dpi = dpi
        h = height_px

        # The view covers the whole motion (as collide frames it), with room for the arrows.
        xs = []
        for i in range(401):
            x1, x2, *_ = state(duration_s * i / 400)
            xs += [x1 - WIDTH / 2, x1 + WIDTH / 2, x2 - WIDTH / 2, x2 + WIDTH / 2]
        lo, hi = min(xs), max(xs)
        margin = 0.08 * (hi - lo)
        self.view = (lo - margin, hi + margin)
        self.arrow_scale = 0.15 * (self.view[1] - self.view[0]) / max(abs(V1), abs(V2))

        title_pt = 0.05 * h * 72 / dpi
        text_pt = 0.041 * h * 72 / dpi
        small_pt = 0.034 * h * 72 / dpi

        self.fig.text(0.03, 0.95, "Inelastic collision, e = 0.5", fontsize=title_pt, color=INK,
                      ha="left", va="top")
        self.clock = self.fig.text(0.97, 0.95, "", fontsize=title_pt, color=INK, ha="right", va="top")

        # The scene: world coordinates, metres square.
        self.ax = self.fig.add_axes([0.03, 0.30, 0.94, 0.58])
        self.ax.set_xlim(*self.view)
        self.ax.set_ylim(-0.6 * WIDTH, 2.4 * WIDTH)
        self.ax.set_aspect("equal", adjustable="datalim")
        self.ax.axis("off")
        self.ax.axhline(0.0, color=INK, linewidth=0.006 * h * 72 / dpi)
        self.blocks, self.arrows, self.speeds = [], [], []
        for color in (BLUE, ORANGE):
            block = patches.Rectangle((0, 0), WIDTH, WIDTH, facecolor=color, edgecolor=darker(color),
                                      linewidth=0.005 * h * 72 / dpi)
            self.ax.add_patch(block)
            self.blocks.append(block)
            arrow = patches.FancyArrow(0, 0, 1, 0, width=0.02, head_width=0.1, head_length=0.1,
                                       length_includes_head=True, color=INK)
            self.ax.add_patch(arrow)
            self.arrows.append(arrow)
            self.speeds.append(self.ax.text(0, 0, "", fontsize=small_pt, color=INK, ha="center",
                                            va="bottom"))

        # The energy bar: the whole width is the initial kinetic energy.
        self.bar = self.fig.add_axes([0.03, 0.14, 0.94, 0.06])
        self.bar.set_xlim(0, KE0)
        self.bar.set_ylim(0, 1)
        self.bar.set_xticks([])
        self.bar.set_yticks([])
        for spine in self.bar.spines.values():
            spine.set_linewidth(0.006 * h * 72 / dpi)
            spine.set_color(INK)
        self.segments = [self.bar.add_patch(patches.Rectangle((0, 0), 0, 1, facecolor=c,
                                                              edgecolor="none"))
                         for c in (BLUE, ORANGE, GRAY)]
        self.labels = [self.fig.text(x, 0.125, "", fontsize=small_pt, color=INK, ha=ha, va="top")
                       for x, ha in ((0.03, "left"), (0.5, "center"), (0.97, "right"))]
        self.fig.text(0.03, 0.025, "Momentum is conserved; with e = 0.5 part of the kinetic energy "
                      "is lost in the collision.", fontsize=small_pt, color=INK, ha="left",
                      va="bottom")

    def update(self, t):
        x1, x2, v1, v2, lost = state(t)
        self.clock.set_text(f"t = {t:.2f} s")
        shaft = 0.008 * 2.4 * WIDTH * 3.0
        for block, arrow, speed, x, v in zip(self.blocks, self.arrows, self.speeds, (x1, x2),
                                             (v1, v2)):
            block.set_xy((x - WIDTH / 2, 0.0))
            y = WIDTH + 0.15
            length = v * self.arrow_scale
            arrow.set_data(x=x, y=y, dx=length if abs(length) > 1e-9 else 1e-9, dy=0.0,
                           width=shaft, head_width=0.12, head_length=min(0.1, abs(length) + 1e-9))
            speed.set_position((x, y + 0.1))
            speed.set_text(f"{v:+.2f} m/s")
        ke1, ke2 = 0.5 * M1 * v1 ** 2, 0.5 * M2 * v2 ** 2
        left = 0.0
        for segment, value in zip(self.segments, (ke1, ke2, lost)):
            segment.set_x(left)
            segment.set_width(value)
            left += value
        for label, name, value in zip(self.labels, ("KE1", "KE2", "lost"), (ke1, ke2, lost)):
            label.set_text(f"{name} {value:.2f} J")
        return []


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--fps", type=int, default=60)
    parser.add_argument("--duration", type=float, default=10.0)
    parser.add_argument("--still", type=float, default=None, help="save one PNG at this time")
    args = parser.parse_args()
    width_px, height_px = (int(v) for v in args.size.split("x"))

    if args.still is not None:
        picture = Picture(width_px, height_px, 4.0)  # the scene's own duration frames the still
        picture.update(args.still)
        picture.fig.savefig(args.output, dpi=picture.dpi)
        return

    picture = Picture(width_px, height_px, args.duration)
    frames = round(args.fps * args.duration)
    anim = animation.FuncAnimation(picture.fig, lambda k: picture.update(k / args.fps),
                                   frames=frames, interval=1000 / args.fps, blit=False,
                                   repeat=False)
    writer = animation.FFMpegWriter(fps=args.fps, codec="libx264",
                                    extra_args=["-preset", "veryfast", "-crf", "20",
                                                "-pix_fmt", "yuv420p"])
    anim.save(args.output, writer=writer, dpi=picture.dpi)


if __name__ == "__main__":
    main()
