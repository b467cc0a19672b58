"""Sensitivities from Python (`sensitivities=` on `simulate` and `run`, as `--sensitivities`):
the table's columns, its values against differences of whole runs at p ± δ, p ± 2δ
(Richardson-extrapolated central differences, δ = 1e-3·p, every solve done again), and bad
names refused; and step-size control (`rtol`, `atol` on `simulate`)."""

import numpy as np
import pytest

import symbody
from conftest import REPO


def extrapolated(column, parameter, value, **kwargs):
    """d(column)/d(parameter) of `simulate` runs, from whole runs around `value`."""
    d = 1e-3 * value
    runs = [
        symbody.simulate(params={parameter: value + k * d}, **kwargs)["bodies"][column]
        for k in (-2, -1, 1, 2)
    ]
    c1 = (runs[2] - runs[1]) / (2 * d)
    c2 = (runs[3] - runs[0]) / (4 * d)
    return (4 * c1 - c2) / 3


def test_simulate_returns_the_derivatives_of_an_integrated_run():
    kwargs = dict(name="spherical_pendulum", t_end=1.0)
    run = symbody.simulate(sensitivities=["l", "m"], **kwargs)
    s = run["sensitivities"]
    assert s.columns[:3] == ["t", "bob.x/l", "bob.x/m"]
    assert np.array_equal(s["t"], run["bodies"]["t"])
    for column in ("bob.x", "bob.z"):
        reference = extrapolated(column, "l", 1.0, **kwargs)
        ours = s[f"{column}/l"]
        scale = np.abs(reference).max()
        assert scale > 0.1
        assert np.abs(ours - reference).max() <= 1e-6 * scale


def test_run_differentiates_the_paper_scene_on_its_kinematic_path(tmp_path):
    run = symbody.run(REPO / "scenes" / "paper.toml", out=tmp_path, sensitivities=["m_platform"])
    assert run.summary["path"] == "kinematic"
    s = run["sensitivities"]
    efforts = [c for c in s.columns if c.startswith("act")]
    assert efforts == [f"act{i}/m_platform" for i in range(1, 7)]
    # A heavier payload needs more force from the legs that hold it up.
    assert all(np.abs(s[c]).max() > 1.0 for c in efforts)
    assert (tmp_path / "sensitivities.csv").exists()


def test_unknown_names_are_refused_with_the_closest():
    with pytest.raises(ValueError, match=r"no parameter `ll` \(did you mean `l`\?\)"):
        symbody.simulate("spherical_pendulum", t_end=0.1, sensitivities=["ll"])
    with pytest.raises(TypeError, match="list of parameter names"):
        symbody.simulate("spherical_pendulum", t_end=0.1, sensitivities="l")


def test_step_size_control_from_python():
    """`rtol`/`atol` as `--rtol`/`--atol`: the error against a tight run shrinks with the
    tolerance, and the summary reports the range of the steps taken."""
    reference = symbody.simulate("spherical_pendulum", t_end=1.0, step=1e-5)["bodies"]["bob.x"]
    errors = []
    for rtol in (1e-4, 1e-6):
        run = symbody.simulate("spherical_pendulum", t_end=1.0, rtol=rtol)
        assert 0 < run.summary["smallest_step"] <= run.summary["largest_step"]
        errors.append(np.abs(run["bodies"]["bob.x"] - reference).max())
    assert errors[1] < errors[0] / 10, errors
    assert symbody.simulate("spherical_pendulum", t_end=0.1).summary["smallest_step"] is None
    with pytest.raises(ValueError, match="rtol 0: a tolerance must be positive"):
        symbody.simulate("spherical_pendulum", t_end=0.1, rtol=0.0)


def test_a_session_with_step_size_control_lands_on_the_times_asked():
    s = symbody.Session("spherical_pendulum", rtol=1e-6, atol=1e-8)
    s.advance_to(0.37)
    assert s.t == 0.37
    run = symbody.simulate("spherical_pendulum", t_end=0.37, output_step=0.37, rtol=1e-6, atol=1e-8)
    assert np.allclose(s.q[:3], [run["bodies"][c][-1] for c in ("bob.x", "bob.y", "bob.z")], atol=1e-6)
    with pytest.raises(ValueError, match="atol -1: a tolerance must be positive"):
        symbody.Session("spherical_pendulum", rtol=1e-6, atol=-1.0)
