"""The Python package against the command line (same tables, same paper force), the
constraint Jacobian against finite differences, Dietmaier's 40 assembly modes against the
published geometry, and errors as Python exceptions."""

import numpy as np
import pytest

import symbody
from conftest import read_csv


def test_mechanisms_lists_the_registry():
    names = symbody.mechanisms()
    assert "slider_crank" in names and "stewart_6_6" in names and "dietmaier_6_6" in names
    assert len(set(names)) == len(names)


def test_simulate_tables_equal_the_cli_csvs(cli, tmp_path):
    # Default step, alpha and output step on both sides: also checks the defaults agree.
    cli("simulate", "slider_crank", "--t-end", "0.5", "--out", tmp_path, "--no-plots")
    run = symbody.simulate("slider_crank", t_end=0.5)
    assert sorted(run) == ["bodies", "drivers", "energy", "joints"]
    for stem, table in run.items():
        columns, data = read_csv(tmp_path / f"{stem}.csv")
        assert table.name == stem
        assert table.columns == columns, stem
        assert table.data.shape == data.shape == (51, len(columns)), stem
        np.testing.assert_allclose(table.data, data, rtol=1e-12, atol=1e-12, err_msg=stem)
    drivers = run["drivers"]
    np.testing.assert_array_equal(drivers["t"], drivers.data[:, 0])
    assert len(drivers) == 51
    assert set(drivers.to_dict()) == set(drivers.columns)


def test_simulate_options_reach_the_run():
    run = symbody.simulate("four_bar", t_end=0.1, output_step=0.05, formulation="exact")
    np.testing.assert_allclose(run["energy"]["t"], [0.0, 0.05, 0.1], atol=1e-15)


def test_simulate_on_the_planar_model_gives_the_spatial_runs_tables():
    # four_bar's planar model (9 coordinates) integrates; the tables are the spatial ones.
    planar = symbody.simulate("four_bar", t_end=0.2, reduced=True)
    spatial = symbody.simulate("four_bar", t_end=0.2)
    for table in ("bodies", "joints", "drivers"):
        assert planar[table].columns == spatial[table].columns
        for c in planar[table].columns:
            np.testing.assert_array_equal(planar[table][c], spatial[table][c])
    with pytest.raises(ValueError, match="`bricard` has no reduced model"):
        symbody.simulate("bricard", t_end=0.1, reduced=True)


def test_session_leg1_force_at_1s_equals_the_paper_scenario(cli, tmp_path, capsys):
    cli("simulate", "--t-end", "1", "--output-step", "0.5", "--no-plots", "--out", tmp_path)
    columns, data = read_csv(tmp_path / "actuators.csv")
    row = data[np.flatnonzero(data[:, 0] == 1.0)[0]]
    expected = row[columns.index("act1")]

    # The paper's integrator settings (Session's defaults are simulate's).
    s = symbody.Session("stewart_6_6", alpha=-0.05, project_velocities=False)
    s.advance_to(1.0)
    assert s.t == 1.0
    force = s.driver_effort("act1")
    with capsys.disabled():
        print(f"\nPython: leg 1 force at t = 1 s: {force:.15e} N")
    assert abs(force - expected) <= 1e-9 * abs(expected), (force, expected)
    # The very number Rust's session computes, bit for bit.
    assert force == symbody.paper_leg1_force_at_1s()


def test_session_surface():
    s = symbody.Session("stewart_6_6", alpha=-0.05, step=1e-3)
    m = symbody.Mechanism("stewart_6_6")
    assert s.q.shape == s.qd.shape == (m.n_coords,)
    assert len(s.coord_names) == m.n_coords
    s.step()
    assert s.t == pytest.approx(1e-3, abs=1e-15)
    s.advance_to(0.25)
    assert s.t == 0.25
    lam = s.multipliers()
    assert lam.shape == (m.n_constraints,) and np.all(np.isfinite(lam))
    efforts = s.driver_efforts()
    assert efforts.shape == (len(s.driver_names),) == (6,)
    for name, value in zip(s.driver_names, efforts):
        assert s.driver_effort(name) == value
    joint = next(j for j in s.joint_names if j not in s.driver_names)
    force, moment = s.joint_wrench(joint)
    assert force.shape == moment.shape == (3,)
    assert np.linalg.norm(force) > 0.0
    # The constraints hold along the run.
    assert np.max(np.abs(m.phi(s.q, s.t))) < 1e-8


@pytest.mark.parametrize("name", symbody.mechanisms())
def test_phi_q_equals_central_differences_of_phi(name):
    m = symbody.Mechanism(name)
    rng = np.random.default_rng(7)
    # Away from the file's pose, so no term hides behind a zero.
    q = m.q0 + 0.05 * rng.standard_normal(m.n_coords)
    t = 0.3
    jac = m.phi_q(q, t)
    data, (rows, cols) = jac
    assert jac.shape == (m.n_constraints, m.n_coords)
    assert len(data) == len(rows) == len(cols)
    assert len(set(zip(rows.tolist(), cols.tolist()))) == len(data), "no duplicates"
    h = 1e-6
    fd = np.empty((m.n_constraints, m.n_coords))
    for j in range(m.n_coords):
        e = np.zeros(m.n_coords)
        e[j] = h
        fd[:, j] = (m.phi(q + e, t) - m.phi(q - e, t)) / (2 * h)
    np.testing.assert_allclose(jac.toarray(), fd, rtol=0, atol=1e-6)


@pytest.mark.parametrize("name", ["stewart_6_6", "spherical_pendulum", "slider_crank"])
def test_mass_gamma_and_force_evaluate_at_any_state(name):
    m = symbody.Mechanism(name)
    q, qd = m.q0, np.linspace(-0.1, 0.1, m.n_coords)
    assert np.max(np.abs(m.phi(q))) < 1e-10, "q0 is assembled"
    mass = m.mass(q)
    assert mass.shape == (m.n_coords, m.n_coords)
    dense = mass.toarray()
    np.testing.assert_array_equal(dense, dense.T)
    assert np.all(np.linalg.eigvalsh(dense) > 0)
    assert m.gamma(q, qd, 0.1).shape == (m.n_constraints,)
    assert m.force(q, qd, 0.1).shape == (m.n_coords,)
    # Without drivers Φ does not depend on t, and γ = −(Φq q̇)_q q̇ is minus the second
    # derivative of Φ(q + s q̇) at s = 0.
    if name == "spherical_pendulum":
        assert not np.any(m.phi_t(q, 0.1))
        h = 1e-4
        second = (m.phi(q + h * qd) - 2 * m.phi(q) + m.phi(q - h * qd)) / h**2
        np.testing.assert_allclose(m.gamma(q, qd), -second, atol=1e-6)


# Dietmaier's platform as published (base points global, platform points in the platform
# frame, leg lengths).
BASE = np.array([
    [0, 0, 0], [1.107915, 0, 0], [0.549094, 0.756063, 0],
    [0.735077, -0.223935, 0.525991], [0.514188, -0.526063, -0.368418],
    [0.590473, 0.094733, -0.205018],
])
TOP = np.array([
    [0, 0, 0], [0.542805, 0, 0], [0.956919, -0.528915, 0],
    [0.665885, -0.353482, 1.402538], [0.478359, 1.158742, 0.107672],
    [-0.137087, -0.235121, 0.353913],
])
LENGTHS = np.array([1, 0.645275, 1.086284, 1.503439, 1.281933, 0.771071])


def test_fk_all_finds_dietmaiers_forty_real_modes():
    r = symbody.fk("dietmaier_6_6", all=True)
    assert r.mode_columns == [
        "x", "y", "z", "r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33",
        "cond", "current",
    ]
    assert r.modes.shape == (40, 14)
    assert r.complex == 40
    np.testing.assert_allclose(r.lengths, LENGTHS, rtol=0, atol=1e-15)
    for row in r.modes:
        p, rot = row[:3], row[3:12].reshape(3, 3)
        np.testing.assert_allclose(rot @ rot.T, np.eye(3), atol=1e-12)
        legs = np.linalg.norm(p + TOP @ rot.T - BASE, axis=1)
        assert np.max(np.abs(legs - LENGTHS)) <= 1e-10
    # The tracked pose (the file's) is one of them, marked once.
    assert r.modes[:, 13].sum() == 1.0 and r.modes[r.current, 13] == 1.0
    np.testing.assert_allclose(r.modes[r.current, :3], r.position, atol=1e-8)
    assert r.residual <= 1e-10 and r.condition > 1.0 and r.iterations >= 0


def test_fk_continues_from_a_given_pose():
    base = symbody.fk("stewart_6_6")
    assert base.modes is None and base.position.shape == (3,) and base.rotation.shape == (3, 3)
    at = symbody.fk("stewart_6_6", at=1.0)
    again = symbody.fk("stewart_6_6", lengths=at.lengths, start=base.pose)
    np.testing.assert_allclose(again.position, at.position, atol=1e-10)
    np.testing.assert_allclose(again.rotation, at.rotation, atol=1e-10)


def test_unknown_names_are_value_errors_listing_the_known_ones():
    for call in (
        lambda: symbody.simulate("stewart"),
        lambda: symbody.Session("stewart"),
        lambda: symbody.Mechanism("stewart"),
        lambda: symbody.fk("stewart"),
    ):
        with pytest.raises(ValueError) as e:
            call()
        for name in symbody.mechanisms():
            assert name in str(e.value), str(e.value)
    with pytest.raises(ValueError, match="did you mean `slider_crank`"):
        symbody.simulate("slidercrank")


def test_bad_options_and_arguments_are_value_errors():
    with pytest.raises(ValueError, match="formulation"):
        symbody.Session("four_bar", formulation="lagrange")
    with pytest.raises(ValueError, match="a0, a1, b1, b0, motor"):
        symbody.Session("four_bar").driver_effort("act9")
    with pytest.raises(ValueError, match="output_step"):
        symbody.simulate("four_bar", output_step=0.0)
    with pytest.raises(ValueError, match="forward kinematics does not apply"):
        symbody.fk("four_bar")
    with pytest.raises(ValueError, match="lengths"):
        symbody.fk("stewart_6_6", lengths=[1.0, 2.0])
    m = symbody.Mechanism("four_bar")
    with pytest.raises(ValueError, match=f"{m.n_coords} entries"):
        m.phi([0.0])


def test_solver_failures_are_runtime_errors():
    # Real poses have these lengths, but the continuation from the file's pose meets a
    # parallel singularity on the way. (Lengths no real pose has are a ValueError.)
    lengths = symbody.fk("dietmaier_6_6").lengths * [0.71, 0.93, 0.81, 1.24, 1.02, 0.88]
    with pytest.raises(RuntimeError, match="parallel singularity"):
        symbody.fk("dietmaier_6_6", lengths=lengths)
    with pytest.raises(ValueError, match="no real pose"):
        symbody.fk("stewart_6_6", lengths=[5.0, 0.1, 5.0, 0.1, 5.0, 0.1])


def test_simulate_crosses_singular_positions_when_asked():
    # The N-four-bar lies flat at t = 0.714 s (IFToMM A02); the option reaches the run.
    for step in (1e-3, 5e-4, 1e-4):
        run = symbody.simulate("n_four_bar_2", t_end=1.5, step=step, cross_singular_positions=True)
        np.testing.assert_allclose(run["energy"]["t"][-1], 1.5, atol=1e-15)


def test_session_crosses_singular_positions_when_asked():
    # Flat at t = 0.70 and 1.22 s; the multipliers at every output need the dropped rows too
    # (the Rust session's sweep over ten steps is in tests/singular_positions.rs).
    for step in (5e-4, 1e-4):
        s = symbody.Session("n_four_bar_2", alpha=0.0, step=step, project_velocities=True,
                            cross_singular_positions=True)
        for k in range(1, 151):
            s.advance_to(k * 0.01)
            assert np.all(np.isfinite(s.multipliers()))
        assert s.t == 1.5


def test_force_jacobian_matches_central_differences_at_rest():
    # At rest the inertial terms vanish with their derivatives, so central differences of
    # force() see the springs and dampers alone (as tests/mechanisms_derivatives.rs does).
    m = symbody.Mechanism("oscillators")
    q, rest = np.asarray(m.q0), np.zeros(m.n_coords)
    dq, dqd = m.force_jacobian(q, rest, 0.0)
    assert dq.shape == dqd.shape == (m.n_coords, m.n_coords)
    dq, dqd = dq.toarray(), dqd.toarray()
    h = 1e-5
    for j in range(m.n_coords):
        e = np.zeros(m.n_coords)
        e[j] = h
        fd_q = (np.asarray(m.force(q + e, rest)) - np.asarray(m.force(q - e, rest))) / (2 * h)
        fd_qd = (np.asarray(m.force(q, rest + e)) - np.asarray(m.force(q, rest - e))) / (2 * h)
        scale = 1.0 + max(abs(dq).max(), abs(dqd).max())
        assert abs(fd_q - dq[:, j]).max() <= 1e-6 * scale, j
        assert abs(fd_qd - dqd[:, j]).max() <= 1e-6 * scale, j
    empty_q, empty_qd = symbody.Mechanism("four_bar").force_jacobian(
        symbody.Mechanism("four_bar").q0, np.zeros(len(symbody.Mechanism("four_bar").q0))
    )
    assert len(empty_q[0]) == len(empty_qd[0]) == 0
