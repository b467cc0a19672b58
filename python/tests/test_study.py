"""`symbody.study` from Python: the rows equal the command line's `symbody study` of the same
scene, the order of `params` is kept, threads change nothing, a set that cannot be built is a
failed row, and wrong names are ValueErrors."""

import csv
import re
import subprocess

import numpy as np
import pytest

import symbody
from conftest import REPO


def test_a_study_equals_the_command_lines(tmp_path):
    scene = tmp_path / "crank.toml"
    scene.write_text(
        'mechanism = "slider_crank"\n[time]\nend = 0.5\n[study]\n'
        "parameters = { r = [0.08, 0.1, 0.12] }\n"
    )
    exe = REPO / "target" / "release" / "symbody"
    if not exe.exists():
        pytest.skip("the command line is not built")
    subprocess.run([str(exe), "study", str(scene), "--out", str(tmp_path)], check=True)
    with open(tmp_path / "study.csv", newline="") as f:
        cli = sorted(csv.DictReader(f), key=lambda row: int(row["run"]))
    py = symbody.study(scene, {"r": [0.08, 0.1, 0.12]})
    assert list(py["r"]) == [0.08, 0.1, 0.12]
    for column in ("max|motor|", "max|F guide|", "energy_balance"):
        assert list(py[column]) == [float(row[column]) for row in cli], column


def test_rows_keep_their_order_and_threads_change_nothing():
    params = {"r": np.linspace(0.08, 0.12, 6), "len": np.full(6, 0.35)}
    one = symbody.study("slider_crank", params, t_end=0.3, jobs=1)
    two = symbody.study("slider_crank", params, t_end=0.3, jobs=2)
    assert list(one["run"]) == list(range(6))
    assert np.array_equal(np.asarray(one["r"]), params["r"])
    for column in one:
        if column != "wall_s":
            assert list(one[column]) == list(two[column]), column
    assert all(s == "ok" for s in one["status"])
    some = symbody.study("slider_crank", params, t_end=0.3, metrics=["max|motor|"])
    assert "max|motor|" in some and "energy_balance" not in some


def test_failed_rows_and_wrong_names():
    rows = symbody.study("four_bar", {"b": [0.1, 0.35]}, t_end=0.1)
    assert list(rows["status"]) == ["failed", "ok"]
    assert "kappa" in rows["error"][0]
    assert np.isnan(rows["energy_balance"][0])
    with pytest.raises(ValueError, match="did you mean `r`"):
        symbody.study("slider_crank", {"rr": [0.1]})
    with pytest.raises(ValueError, match="metrics"):
        symbody.study("slider_crank", {"r": [0.1]}, t_end=0.1, metrics=["nothing"])


def test_metrics_are_chosen_and_ordered_as_in_a_scene():
    rows = symbody.study(
        "stewart_6_6",
        {"r_platform": [0.1, 0.11]},
        t_end=0.3,
        metrics=["max fk_condition", "max platform.z", "max|act1|"],
    )
    metrics = [c for c in rows if c not in ("run", "r_platform", "status", "error", "wall_s")]
    assert metrics == ["max fk_condition", "max platform.z", "max|act1|"]
    assert all(s == "ok" for s in rows["status"])
    # A wider platform is better conditioned (the command line's example study shows it).
    assert 1 < rows["max fk_condition"][1] < rows["max fk_condition"][0]
    with pytest.raises(ValueError, match="no six-leg platform"):
        symbody.study("slider_crank", {"r": [0.1]}, t_end=0.1, metrics=["max fk_condition"])
    with pytest.raises(ValueError, match=re.escape("did you mean `max|motor|`")):
        symbody.study("slider_crank", {"r": [0.1]}, t_end=0.1, metrics=["max|motr|"])
