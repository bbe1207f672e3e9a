# SPDX-License-Identifier: MIT
"""What the package's tests share: the program they compare against and its outputs."""
import json
import os
import subprocess
from pathlib import Path

import numpy
import pytest

REPOSITORY = Path(__file__).resolve().parents[2]
# The golden tolerance of tests/support/golden.hpp: llvmpipe varies a channel by 1-2 levels.
CHANNEL_TOLERANCE = 3
MAX_PIXELS_BEYOND = 24
GROSS_TOLERANCE = 48


def program() -> str:
    return os.environ.get("COLLIDE_PROGRAM", str(REPOSITORY / "build" / "collide"))


def run_program(*arguments: str, check: bool = True) -> subprocess.CompletedProcess:
    """The program with `arguments`, its output as text; in English whatever the caller's LANG."""
    environment = dict(os.environ, LANG="C.UTF-8", LC_ALL="C.UTF-8")
    done = subprocess.run([program(), *arguments], capture_output=True, text=True,
                          env=environment, timeout=120)
    if check and done.returncode != 0:
        raise AssertionError(f"collide {' '.join(arguments)}: exit {done.returncode}: {done.stderr}")
    return done


def program_json(*arguments: str):
    return json.loads(run_program(*arguments).stdout)


def program_error(*arguments: str) -> str:
    """The one line the program prints for bad input, without its "collide: " prefix."""
    done = run_program(*arguments, check=False)
    assert done.returncode == 2, done
    line = done.stderr.strip()
    assert line.startswith("collide: ") and "\n" not in line, line
    return line[len("collide: "):]


def assert_same_picture(actual: numpy.ndarray, expected: numpy.ndarray) -> None:
    """Equal within the golden tolerance (tests/support/golden.hpp)."""
    assert actual.shape == expected.shape
    difference = numpy.abs(actual.astype(int) - expected.astype(int)).max(axis=-1)
    assert difference.max() <= GROSS_TOLERANCE, difference.max()
    assert (difference > CHANNEL_TOLERANCE).sum() <= MAX_PIXELS_BEYOND


@pytest.fixture
def scratch(tmp_path):
    return tmp_path


# llvmpipe draws on one thread: the suite runs beside others on two cores, and the GIL test needs
# the two drawings' threads to be all there is. Set before the GL module is first loaded.
os.environ.setdefault("LP_NUM_THREADS", "1")
