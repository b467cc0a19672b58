"""Mechanism files from Python: a copied, renamed file runs interpreted with the compiled
mechanism's numbers, whether given as a str or a pathlib.Path, and a file that is missing,
a folder, not UTF-8 or not a mechanism is an exception naming it, never a crash."""

import pathlib
import shutil

import numpy as np
import pytest

import symbody
from conftest import REPO

MECHANISMS = REPO / "mechanisms"


@pytest.fixture
def ups_copy(tmp_path):
    """`mechanisms/ups_stewart.toml` copied under another name, so nothing compiled matches."""
    path = tmp_path / "my_platform.toml"
    shutil.copy(MECHANISMS / "ups_stewart.toml", path)
    return path


def relative(a, b):
    """The largest |a - b| relative to the larger of each |b| and the column's largest |b|."""
    scale = np.maximum(np.abs(b), np.abs(b).max(axis=0, keepdims=True))
    scale[scale == 0] = 1.0
    return float((np.abs(a - b) / scale).max())


def test_a_file_simulates_as_the_compiled_mechanism(ups_copy, capsys):
    compiled = symbody.simulate("ups_stewart", t_end=0.2)
    assert compiled.summary["source"] is None and compiled.summary["note"] is None
    worst = 0.0
    for name in (str(ups_copy), ups_copy):
        run = symbody.simulate(name, t_end=0.2)
        assert run.summary["source"] == str(ups_copy)
        assert "interpreted from" in run.summary["note"]
        assert sorted(run) == sorted(compiled)
        for stem, table in run.items():
            ref = compiled[stem]
            assert table.columns == ref.columns, stem
            assert table.data.shape == ref.data.shape, stem
        bodies = run["bodies"].data
        assert bodies.shape[0] == 21
        worst = max(worst, relative(bodies, compiled["bodies"].data))
    with capsys.disabled():
        print(f"\nups_stewart from a file, 0.2 s: bodies within {worst:.2e} (relative)")
    assert worst <= 1e-10, worst


def test_mechanism_and_session_take_a_path(ups_copy):
    compiled = symbody.Mechanism("ups_stewart")
    assert not compiled.interpreted and compiled.source is None
    for name in (str(ups_copy), ups_copy):
        m = symbody.Mechanism(name)
        assert m.interpreted and m.source == str(ups_copy)
        assert m.name == compiled.name and m.n_coords == compiled.n_coords
        q = compiled.q0 + 0.01 * np.sin(np.arange(m.n_coords))
        qd = 0.1 * np.cos(np.arange(m.n_coords))
        np.testing.assert_allclose(m.phi(q, 0.1), compiled.phi(q, 0.1), rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose(
            m.force(q, qd, 0.1), compiled.force(q, qd, 0.1), rtol=1e-13, atol=1e-13
        )
        np.testing.assert_allclose(
            m.mass(q).toarray(), compiled.mass(q).toarray(), rtol=1e-13, atol=1e-13
        )

        s = symbody.Session(name)
        assert s.interpreted and s.source == str(ups_copy)
        r = symbody.Session("ups_stewart")
        assert not r.interpreted and r.source is None
        s.advance_to(0.05)
        r.advance_to(0.05)
        np.testing.assert_allclose(s.q, r.q, rtol=1e-10, atol=1e-12)
        np.testing.assert_allclose(
            s.driver_efforts(), r.driver_efforts(), rtol=1e-9, atol=1e-9
        )


def test_fk_takes_a_path(ups_copy):
    compiled = symbody.fk("ups_stewart", at=0.1)
    for name in (str(ups_copy), ups_copy):
        f = symbody.fk(name, at=0.1)
        np.testing.assert_allclose(f.position, compiled.position, rtol=1e-10, atol=1e-12)
        np.testing.assert_allclose(f.rotation, compiled.rotation, rtol=1e-10, atol=1e-12)


def test_a_path_object_is_always_a_file(tmp_path, monkeypatch):
    # "slider_crank" as a str is the registered mechanism; as a Path, the file of that name.
    monkeypatch.chdir(tmp_path)
    assert not symbody.Mechanism("slider_crank").interpreted
    with pytest.raises(FileNotFoundError, match="slider_crank"):
        symbody.Mechanism(pathlib.Path("slider_crank"))
    shutil.copy(MECHANISMS / "slider_crank.toml", tmp_path / "slider_crank")
    m = symbody.Mechanism(pathlib.Path("slider_crank"))
    assert m.interpreted and m.source == "slider_crank"


def test_bad_files_are_exceptions_naming_them(tmp_path):
    missing = tmp_path / "missing.toml"
    broken = tmp_path / "broken.toml"
    broken.write_text('name = "broken"\n[bodies.arm\nmass = 1.0\n')
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b'name = "x"\n# caf\xe9\n')
    cases = [
        (missing, FileNotFoundError, "no such file"),
        (tmp_path, IsADirectoryError, "folder"),
        (broken, ValueError, f"{broken}:2:12"),
        (binary, ValueError, "line 2, column 6"),
    ]
    calls = [
        lambda n: symbody.Mechanism(n),
        lambda n: symbody.simulate(n, t_end=0.1),
        lambda n: symbody.Session(n),
        lambda n: symbody.fk(n),
    ]
    for path, kind, says in cases:
        for name in (str(path), path):
            for call in calls:
                with pytest.raises(kind) as e:
                    call(name)
                message = str(e.value)
                assert str(path) in message, message
                assert says in message, message
    with pytest.raises(TypeError, match="os.PathLike"):
        symbody.Mechanism(42)


@pytest.mark.parametrize(
    "stem", ["three_rps", "rsup_slider_crank", "parallelogram_four_bar", "bricard_loop"]
)
def test_the_example_files_run_from_python(stem):
    """The four files a new user wrote from published definitions (examples/mechanisms/) run
    from Python with nothing built: a short simulation holds the constraints, and a session
    and the functions work on the same file."""
    path = REPO / "examples" / "mechanisms" / f"{stem}.toml"
    run = symbody.simulate(path, t_end=0.2)
    assert run.summary["source"] == str(path)
    assert run.summary["max_phi"] < 1e-8
    session = symbody.Session(path)
    session.advance_to(0.05)
    m = symbody.Mechanism(path)
    assert m.interpreted
    assert np.abs(m.phi(session.q, 0.05)).max() < 1e-8
