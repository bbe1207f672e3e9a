# SPDX-License-Identifier: MIT
"""Scenes and simulations: the same numbers as `collide data`, and the physics they teach."""
import math
import sys

import numpy
import pytest

import collide
from conftest import program_error, program_json, run_program


def test_presets_are_the_programs():
    listed = [line.split()[0] for line in run_program("presets").stdout.splitlines() if line]
    assert list(collide.presets()) == listed


@pytest.mark.parametrize("name", [line.split()[0] for line in
                                  run_program("presets").stdout.splitlines() if line])
def test_every_presets_summary_is_collide_datas(name):
    run = collide.simulate(collide.Scene.preset(name))
    assert run.summary == program_json("data", name, "--json", "-")


def test_events_are_collide_datas():
    run = collide.simulate("granular-chain")
    expected = program_json("data", "granular-chain", "--json", "-", "--events")["events"]
    assert run.events == expected
    # Impacts only (no strings, no soft contacts): one event per collision.
    assert len(run.events) == run.summary["collision_count"]


def test_overrides_are_the_programs_set():
    scene = collide.Scene.preset("worked-example").with_(restitution=0.3, **{"body.2.mass": 3})
    expected = program_json("data", "worked-example", "--json", "-", "--set", "restitution=0.3",
                            "--set", "body.2.mass=3")
    assert collide.simulate(scene).summary == expected


def test_override_follows_the_closed_form():
    # 1 kg at +2 m/s meets 1 kg at -1 m/s with e = 0.3: v1' = (p - m2 e u) / M, v2' = (p + m1 e u) / M
    # with closing speed u = 3 m/s, and the loss 1/2 mu (1 - e^2) u^2, mu = 1/2 kg.
    run = collide.simulate(collide.Scene.preset("worked-example").with_(e=0.3))
    bodies = run.summary["bodies"]
    assert bodies[0]["final_velocity"][0] == pytest.approx((1 - 0.3 * 3) / 2, abs=1e-12)
    assert bodies[1]["final_velocity"][0] == pytest.approx((1 + 0.3 * 3) / 2, abs=1e-12)
    assert run.summary["energy_lost"] == pytest.approx(0.5 * 0.5 * (1 - 0.09) * 9, rel=1e-12)


def test_shortcuts_are_the_programs():
    scene = collide.Scene.preset("worked-example").with_(m2=3, e=0, v1=4)
    expected = program_json("data", "worked-example", "--json", "-", "--m2", "3", "--e", "0",
                            "--v1", "4")
    summary = collide.simulate(scene).summary
    assert summary == expected
    # e = 0: one common velocity, the momentum over the total mass.
    assert summary["bodies"][0]["final_velocity"][0] == pytest.approx((4 - 3) / 4, abs=1e-12)


def test_duration_as_the_programs():
    run = collide.simulate("worked-example", duration=1.5)
    assert run.summary == program_json("data", "worked-example", "--json", "-", "--duration", "1.5")


def test_scene_file_text_and_path(scratch):
    text = collide.Scene.preset("elastic").to_toml()
    path = scratch / "mine.toml"
    path.write_text(text)
    from_path = collide.simulate(collide.Scene.from_toml(path))
    assert from_path.summary == program_json("data", str(path), "--json", "-")
    from_text = collide.simulate(collide.Scene.from_toml(text, name="mine"))
    assert from_text.summary == from_path.summary


def test_state_is_exact_and_conserves():
    run = collide.simulate("worked-example")
    before = run.state(0.0)
    assert [body["velocity"][0] for body in before["bodies"]] == [2.0, -1.0]
    total = before["kinetic_energy"]
    after = run.state(run.duration)
    assert [body["velocity"][0] for body in after["bodies"]] == pytest.approx([-0.25, 1.25])
    for t in numpy.linspace(0.0, run.duration, 41):
        state = run.state(t)
        assert state["momentum"][0] == pytest.approx(1.0, abs=1e-12)
        assert state["kinetic_energy"] + state["energy_lost"] == pytest.approx(total, rel=1e-12)


def test_table_is_collide_datas_csv():
    table = collide.simulate("worked-example").table(dt=0.05)
    csv = run_program("data", "worked-example", "--csv", "-", "--dt", "0.05").stdout.splitlines()
    assert list(table.columns) == csv[0].split(",")
    expected = numpy.array([[float(value) for value in row.split(",")] for row in csv[1:]])
    assert numpy.array_equal(table.to_numpy(), expected)


def test_table_without_pandas_is_a_structured_array(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    table = collide.simulate("worked-example").table(dt=0.05)
    assert isinstance(table, numpy.ndarray)
    assert table["t_s"].tolist() == [round(0.05 * k, 9) for k in range(81)]


@pytest.mark.parametrize("make, arguments", [
    (lambda: collide.Scene.preset("worked-example").with_(restitution=2),
     ["worked-example", "--set", "restitution=2"]),
    (lambda: collide.Scene.preset("worked-example").with_(**{"body.2.mass": -1}),
     ["worked-example", "--set", "body.2.mass=-1"]),
    (lambda: collide.Scene.preset("worked-example").with_(e=1.5),
     ["worked-example", "--e", "1.5"]),
    (lambda: collide.Scene.preset("worked-example").with_(restitutoin=0.5),
     ["worked-example", "--set", "restitutoin=0.5"]),
    (lambda: collide.Scene.preset("worked-exampel"), ["worked-exampel"]),
])
def test_bad_input_raises_the_programs_message(make, arguments):
    expected = program_error("data", *arguments, "--json", "-")
    with pytest.raises(collide.SceneError) as raised:
        make()
    assert isinstance(raised.value, ValueError)
    assert str(raised.value) == expected


def test_bad_scene_text_names_its_line(scratch):
    text = 'preset = "worked-example"\nrestitution = "soft"\n'
    path = scratch / "scene.toml"
    path.write_text(text)
    expected = program_error("data", str(path), "--json", "-")
    with pytest.raises(collide.SceneError) as raised:
        collide.Scene.from_toml(path)
    assert str(raised.value) == expected


def test_bad_times_raise():
    run = collide.simulate("worked-example")
    with pytest.raises(collide.SceneError, match=r"^t: 5\.0: allowed: a time from 0 to 4 s"):
        run.state(5.0)
    with pytest.raises(collide.SceneError, match=r"^dt: 1\.0: allowed: 0\.0005 to 0\.05 seconds"):
        run.table(dt=1.0)
    with pytest.raises(collide.SceneError, match=r"^duration: -1\.0: allowed: more than 0"):
        collide.simulate("worked-example", duration=-1.0)
    with pytest.raises(TypeError):
        collide.Scene.preset("worked-example").with_(restitution=object())


@pytest.mark.parametrize("form", ["text", "latex", "markdown", "mathml"])
def test_working_is_collide_solves(form):
    working = collide.solve(collide.Scene.preset("billiards-glancing"), impact=1)
    expected = run_program("solve", "billiards-glancing", "--impact", "1", "--format", form).stdout
    assert getattr(working, form) == expected


def test_working_shows_typeset_in_jupyter():
    working = collide.solve("worked-example", lang="de")
    assert working._repr_markdown_() == run_program("solve", "worked-example", "--lang", "de",
                                                    "--format", "markdown").stdout
    shown = working._repr_latex_()
    assert shown.startswith("$$\\begin{align*}") and shown.endswith("\\end{align*}$$")
    assert "\\noindent" not in shown and "%" not in shown


def test_working_of_a_missing_impact_raises():
    with pytest.raises(collide.SceneError, match=r"^impact: '2': no such impact in "
                                                 r"'worked-example'; allowed: 1$"):
        collide.solve("worked-example", impact=2)
