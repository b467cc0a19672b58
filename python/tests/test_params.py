"""Parameters of a mechanism file set from Python (`params=`, as `--set`): a run equals the
run of the file edited to that value, the value takes effect, and a wrong name or value is a
ValueError naming the parameter."""

import re

import numpy as np
import pytest

import symbody
from conftest import REPO


def edited(tmp_path, name, parameter, value):
    """`mechanisms/<name>.toml` with the line `parameter = …` set to `value`."""
    text = (REPO / "mechanisms" / f"{name}.toml").read_text()
    new, hits = re.subn(rf"(?m)^{parameter}\s*=.*$", f"{parameter} = {value!r}", text)
    assert hits == 1
    path = tmp_path / f"{name}_edited.toml"
    path.write_text(new)
    return path


def test_a_set_parameter_runs_as_the_edited_file(tmp_path):
    run = symbody.simulate("slider_crank", t_end=0.3, params={"r": 0.12})
    assert "r = 0.12" in run.summary["note"]
    reference = symbody.simulate(edited(tmp_path, "slider_crank", "r", 0.12), t_end=0.3)
    base = symbody.simulate("slider_crank", t_end=0.3)
    # The compiled code on the file's numbers at r = 0.12 against the edited file interpreted:
    # the same equations, evaluated in another order (roundoff).
    for table in ("bodies", "joints", "drivers"):
        for column in run[table].columns:
            a, b = np.asarray(run[table][column]), np.asarray(reference[table][column])
            scale = max(1.0, float(np.max(np.abs(b))))
            assert np.max(np.abs(a - b)) <= 1e-12 * scale, column
    assert not np.allclose(run["drivers"]["motor"], base["drivers"]["motor"])


def test_mechanism_session_and_fk_take_params():
    m = symbody.Mechanism("slider_crank", params={"r": 0.12})
    # The compiled code takes the numbers the file gives at r = 0.12 (nothing interpreted).
    assert not m.interpreted
    assert not np.allclose(m.q0, symbody.Mechanism("slider_crank").q0)
    s = symbody.Session("slider_crank", params={"r": 0.12})
    s.advance_to(0.1)
    assert np.isfinite(s.driver_effort("motor"))
    wide = symbody.fk("stewart_6_6", params={"r_platform": 0.11})
    narrow = symbody.fk("stewart_6_6")
    # The initial pose is the file's; the legs reaching the wider platform are longer.
    assert wide.residual < 1e-10
    assert not np.allclose(wide.lengths, narrow.lengths)


def test_wrong_names_and_values_name_the_parameter():
    with pytest.raises(ValueError, match="did you mean `r`"):
        symbody.simulate("slider_crank", t_end=0.1, params={"rr": 0.12})
    with pytest.raises(ValueError, match="parameter `r` set to NaN"):
        symbody.Mechanism("slider_crank", params={"r": float("nan")})
