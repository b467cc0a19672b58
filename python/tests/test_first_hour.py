"""What a first hour with the package needs: one set of integrator defaults, scenes and files
from Python, a run summary, results for pandas, a tidy namespace with docstrings and types,
and errors in Python's words."""

import importlib.metadata
import importlib.resources
import inspect
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import symbody
from conftest import REPO, read_csv


def test_session_defaults_are_simulates():
    # One set of integrator defaults: a session stepped to 1 s with its defaults reports the
    # motor torque `simulate` records there with its own.
    s = symbody.Session("slider_crank")
    s.advance_to(1.0)
    run = symbody.simulate("slider_crank", t_end=1.0)
    torque = run["drivers"]["motor"][-1]
    assert run["drivers"]["t"][-1] == 1.0
    assert abs(s.driver_effort("motor") - torque) <= 1e-12 * abs(torque), (
        s.driver_effort("motor"),
        torque,
    )
    params = inspect.signature(symbody.Session).parameters
    assert params["alpha"].default == inspect.signature(symbody.simulate).parameters["alpha"].default
    assert params["project_velocities"].default is True


def test_simulate_writes_the_clis_csvs_and_a_summary(cli, tmp_path):
    cli("simulate", "four_bar", "--t-end", "0.2", "--out", tmp_path / "cli", "--no-plots")
    run = symbody.simulate("four_bar", t_end=0.2, out=tmp_path / "py")
    assert run["joints"].columns == read_csv(tmp_path / "cli" / "joints.csv")[0]
    for stem in ("bodies", "joints", "drivers", "energy"):
        cli_cols, cli_data = read_csv(tmp_path / "cli" / f"{stem}.csv")
        py_cols, py_data = read_csv(tmp_path / "py" / f"{stem}.csv")
        assert py_cols == cli_cols, stem
        np.testing.assert_allclose(py_data, cli_data, rtol=1e-12, atol=1e-12, err_msg=stem)
        np.testing.assert_array_equal(py_data, run[stem].data)
    assert sorted(pathlib.Path(f).name for f in run.files) == [
        "bodies.csv", "drivers.csv", "energy.csv", "joints.csv",
    ]
    s = run.summary
    assert s["path"] == "integrated"
    assert s["steps"] >= 200 and s["rejected_steps"] >= 0 and s["newton_iterations"] >= s["steps"]
    assert 0.0 < s["wall_time"] < 60.0
    assert 0.0 <= s["max_phi"] < 1e-8
    assert s["energy_scale"] > 0.0 and s["energy_drift"] <= 1e-6 * s["energy_scale"]
    assert s["ill_conditioned"] == [] and s["warnings"] == []
    # Without `out`, nothing is written.
    assert symbody.simulate("four_bar", t_end=0.01).files == []
    # A folder that cannot be made fails before the run, naming the argument.
    (tmp_path / "a_file").write_text("")
    with pytest.raises(OSError, match="out: cannot write"):
        symbody.simulate("four_bar", t_end=0.01, out=tmp_path / "a_file" / "sub")


def test_summary_names_the_ill_conditioned_windows():
    # The N-four-bar lies flat near t = 1.228 s (IFToMM A02); `symbody simulate n_four_bar_2
    # --cross-singular-positions --output-step 1e-3` flags the output there.
    run = symbody.simulate(
        "n_four_bar_2", t_end=1.5, output_step=1e-3, cross_singular_positions=True
    )
    windows = run.summary["ill_conditioned"]
    assert any(abs(w["at"] - 1.228) < 2e-3 for w in windows), windows
    for w in windows:
        assert w["outputs"] >= 1 and w["smallest"] < 1e-5 and w["from"] <= w["at"] <= w["to"]
    assert symbody.simulate("n_four_bar_2", t_end=0.5).summary["ill_conditioned"] == []


def test_a_run_whose_steps_are_too_long_for_its_motion_warns():
    # A03 (Andrews' squeezer) moves on a time scale of ~1e-5 s: at the default 1 ms step its
    # energy balance is off by 7 % of the energy scale (the reference: the energy theorem,
    # which the balance checks), so the summary carries a warning, issued as a
    # RuntimeWarning; with step-size control the balance holds and nothing is said.
    path = REPO / "mechanisms" / "benchmarks" / "andrews_squeezer.toml"
    with pytest.warns(RuntimeWarning, match="energy balance is off by"):
        run = symbody.simulate(path)
    assert len(run.summary["warnings"]) == 1 and "rtol=" in run.summary["warnings"][0]
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        run = symbody.simulate(path, rtol=1e-5)
    assert run.summary["warnings"] == []


def test_run_equals_the_clis_scene_run(cli, tmp_path):
    scene = REPO / "scenes" / "slider_crank.toml"
    cli("run", scene, "--out", tmp_path / "cli", "--no-plots")
    run = symbody.run(scene, out=tmp_path / "py")
    assert sorted(run) == ["bodies", "drivers", "joints"]  # energy = false
    for stem, table in run.items():
        columns, data = read_csv(tmp_path / "cli" / f"{stem}.csv")
        assert table.columns == columns, stem
        np.testing.assert_allclose(table.data, data, rtol=1e-12, atol=1e-12, err_msg=stem)
        assert read_csv(tmp_path / "py" / f"{stem}.csv")[0] == columns
    assert run["bodies"].columns == ["t"] + [f"slider.{c}" for c in "x y z qw qx qy qz".split()]
    assert run.summary["path"] == "kinematic"
    assert "no free degree of freedom" in run.summary["path_reason"]
    assert run.summary["steps"] == 0
    # A str path works as well as a pathlib.Path.
    assert symbody.run(str(scene))["drivers"].columns == ["t", "motor"]


def test_run_of_a_paper_scene_returns_the_paper_tables(cli, tmp_path):
    text = (REPO / "scenes" / "paper.toml").read_text()
    text = text.replace("end = 6.283185307179586", "end = 0.5")
    scene = tmp_path / "paper_short.toml"
    scene.write_text(text)
    cli("run", scene, "--out", tmp_path / "cli", "--no-plots")
    run = symbody.run(scene, out=tmp_path / "py")
    assert sorted(run) == ["actuators", "joint_forces", "platform"]
    for stem, table in run.items():
        columns, data = read_csv(tmp_path / "cli" / f"{stem}.csv")
        assert table.columns == columns, stem
        assert len(table) == 51
        np.testing.assert_allclose(table.data, data, rtol=1e-12, atol=1e-9, err_msg=stem)
        np.testing.assert_array_equal(read_csv(tmp_path / "py" / f"{stem}.csv")[1], data)
    assert run.summary["path"] == "kinematic"


def test_run_errors_name_the_scene():
    with pytest.raises(FileNotFoundError, match="no_such_scene.toml"):
        symbody.run("no_such_scene.toml")
    with pytest.raises(ValueError, match="four_bar.toml"):
        symbody.run(REPO / "mechanisms" / "four_bar.toml")


def test_to_pandas():
    pd = pytest.importorskip("pandas")
    table = symbody.simulate("slider_crank", t_end=0.1)["drivers"]
    df = table.to_pandas()
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == table.columns
    np.testing.assert_array_equal(df.to_numpy(), table.data)


def test_to_pandas_without_pandas_says_how_to_install_it(monkeypatch):
    import builtins

    real_import = builtins.__import__

    def no_pandas(name, *args, **kwargs):
        if name == "pandas" or name.startswith("pandas."):
            raise ImportError("No module named 'pandas'")
        return real_import(name, *args, **kwargs)

    table = symbody.simulate("slider_crank", t_end=0.01)["drivers"]
    monkeypatch.setattr(builtins, "__import__", no_pandas)
    with pytest.raises(ImportError, match="pip install pandas"):
        table.to_pandas()


def test_version_is_the_packages():
    assert symbody.__version__ == importlib.metadata.version("symbody")
    assert re.fullmatch(r"\d+\.\d+\.\d+.*", symbody.__version__)


def _readme_api():
    text = (REPO / "python" / "README.md").read_text()
    return text.split("## API", 1)[1]


def test_namespace_is_the_documented_api():
    # A submodule of the package (symbody.dask, once something imported it) is an attribute
    # of it, documented as a module rather than a name of __all__.
    def submodule(n):
        return getattr(getattr(symbody, n), "__name__", None) == f"symbody.{n}"

    public = sorted(n for n in dir(symbody) if not n.startswith("_") and not submodule(n))
    assert public == sorted(symbody.__all__)
    api = _readme_api()
    for name in symbody.__all__:
        assert re.search(rf"`{name}\b", api), f"{name} missing from python/README.md's API"
    for name in [n for n in dir(symbody) if not n.startswith("_") and submodule(n)]:
        assert re.search(rf"`symbody\.{name}\b", api), f"symbody.{name} not in the API"


def _public_members(obj):
    for name, value in inspect.getmembers(obj):
        if name.startswith("_"):
            continue
        if callable(value) or isinstance(value, property) or inspect.isdatadescriptor(value):
            yield name, value


def test_every_public_name_and_method_has_a_docstring_and_is_in_the_readme():
    api = _readme_api()
    missing, undocumented = [], []
    for name in symbody.__all__:
        obj = getattr(symbody, name)
        if not (obj.__doc__ or "").strip():
            missing.append(name)
        if inspect.isclass(obj):
            for member, value in _public_members(obj):
                if not (getattr(value, "__doc__", None) or "").strip():
                    missing.append(f"{name}.{member}")
                # tuple's and dict's own methods (Coo is a tuple, Results a dict) need no
                # mention
                if not any(hasattr(t, member) for t in (tuple, dict)) and not re.search(rf"`\.{member}\b", api):
                    undocumented.append(f"{name}.{member}")
    assert not missing, f"no docstring: {missing}"
    assert not undocumented, f"not in python/README.md's API: {undocumented}"


def test_package_is_typed():
    package = importlib.resources.files("symbody")
    assert package.joinpath("py.typed").is_file()
    # The compiled module's types, which Session and Mechanism inherit.
    assert package.joinpath("_native.pyi").is_file()
    for name in ("simulate", "run", "fk", "mechanisms"):
        hints = inspect.signature(getattr(symbody, name))
        assert hints.return_annotation is not inspect.Signature.empty, name
    params = inspect.signature(symbody.Session).parameters
    assert params["alpha"].annotation is not inspect.Parameter.empty


def test_errors_name_the_python_arguments():
    with pytest.raises(ValueError) as e:
        symbody.simulate("four_bar", output_step=0.0)
    assert "output_step" in str(e.value) and "--" not in str(e.value), str(e.value)
    with pytest.raises(ValueError) as e:
        symbody.simulate("four_bar", t_end=-1.0)
    assert "t_end" in str(e.value) and "--" not in str(e.value), str(e.value)
    s = symbody.Session("four_bar")
    s.advance_to(0.1)
    with pytest.raises(ValueError) as e:
        s.advance_to(0.05)
    assert "advance_to" in str(e.value) and "t_out" not in str(e.value), str(e.value)


def _compare(out, env=None):
    script = REPO / "python" / "examples" / "compare.py"
    return subprocess.run([sys.executable, str(script), str(out)], capture_output=True,
                          text=True, timeout=300, env=env)


def test_compare_example_plots_and_compares(tmp_path):
    pytest.importorskip("matplotlib")
    p = _compare(tmp_path / "out")
    assert p.returncode == 0, p.stderr
    png = tmp_path / "out" / "motor_efforts.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert re.search(r"four_bar .* slider_crank .*x", p.stdout.splitlines()[-1]), p.stdout


def test_compare_example_without_matplotlib_says_so(tmp_path):
    # A `matplotlib` that cannot be imported shadows the installed one.
    (tmp_path / "matplotlib.py").write_text("raise ImportError('no matplotlib here')\n")
    p = _compare(tmp_path / "out", env=dict(os.environ, PYTHONPATH=str(tmp_path)))
    assert p.returncode == 0, p.stderr
    assert "pip install matplotlib" in p.stdout
    assert (tmp_path / "out" / "motor_efforts.csv").is_file()
    assert "peak |motor torque|" in p.stdout.splitlines()[-1]
