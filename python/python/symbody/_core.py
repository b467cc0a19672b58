"""The Python half of ``symbody``: tables, answers and wrappers around ``symbody._native``.
Everything public is re-exported by ``symbody/__init__.py``; the names here that it does not
export (NumPy, typing) stay out of the package's namespace."""

from __future__ import annotations

from dataclasses import dataclass, field
import os
import warnings
from typing import TYPE_CHECKING, Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _native

if TYPE_CHECKING:
    import pandas

#: A file or folder: a ``str`` or any ``os.PathLike`` such as ``pathlib.Path``.
PathLike = Union[str, "os.PathLike[str]"]

#: A mechanism: a registered name (``"slider_crank"``) or a mechanism file's path. A ``str``
#: is a path when it ends in ``.toml`` or has a folder (``"robots/arm.toml"``), as on the
#: command line; a ``pathlib.Path`` (any other ``os.PathLike``) is always a path. A file's
#: equations run interpreted, nothing generated or compiled: a missing file is
#: ``FileNotFoundError``, a folder ``IsADirectoryError``, a file that is no mechanism (TOML
#: or modelling mistakes, not UTF-8) a ``ValueError`` naming the file, line and column.
MechanismLike = Union[str, "os.PathLike[str]"]

# `symbody simulate <name>`'s defaults, stated once in Rust (`generic::Options::default`):
# `simulate` and `Session` both take them from there.
_DEFAULTS = _native.defaults()


@dataclass(frozen=True)
class Table:
    """One output table of a run, with the columns of ``symbody simulate <name>``'s
    ``<name>.csv``: ``t`` first, then one group per body, joint or driver.

    ``data`` has one row per output time. ``table["column"]`` is that column (a view),
    ``len(table)`` the number of rows, ``table.to_dict()`` a ``{column: array}`` dict and
    ``table.to_pandas()`` a ``pandas.DataFrame``.
    """

    name: str
    columns: List[str]
    data: np.ndarray = field(repr=False)

    def __getitem__(self, column: str) -> np.ndarray:
        try:
            return self.data[:, self.columns.index(column)]
        except ValueError:
            raise KeyError(
                f"{self.name} has no column {column!r}; it has: {', '.join(self.columns)}"
            ) from None

    def __len__(self) -> int:
        return self.data.shape[0]

    def to_dict(self) -> Dict[str, np.ndarray]:
        """``{column: array}``, the columns in order (views of ``data``)."""
        return {c: self.data[:, k] for k, c in enumerate(self.columns)}

    def to_pandas(self) -> "pandas.DataFrame":
        """A ``pandas.DataFrame`` of ``data`` with the table's columns (``t`` a column, as
        in the CSV file). pandas is optional: without it this raises ``ImportError``."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError(
                "Table.to_pandas() needs pandas, which is not installed: "
                "pip install pandas (or use table.to_dict() / table.data)"
            ) from e
        return pandas.DataFrame(self.data, columns=list(self.columns))


class Results(Dict[str, Table]):
    """What :func:`simulate` and :func:`run` return: a dict of :class:`Table` by name (the
    CSV file's stem), with the run's ``summary`` and the ``files`` it wrote.

    ``summary`` is a dict: ``path`` (``"integrated"`` or ``"kinematic"``; for a scene also
    ``path_reason``, why), ``steps`` and ``rejected_steps`` of the integrator (0 on the
    kinematic path), ``newton_iterations``, ``chord_iterations`` (the kinematic path's
    simplified-Newton corrections), ``factorizations``, ``wall_time`` (s), ``max_phi`` (the
    largest |Φ| at the outputs), ``max_velocity_residual``, the energy balance
    ``energy_drift`` (the largest |ΔT + ΔV − W| since the start, J) on a scale of
    ``energy_scale`` (the largest |T| + |V|, J; both ``None`` for a kinematic scene with
    ``energy = false``, which integrates no work), and ``ill_conditioned``: the windows of
    outputs near a singular position whose reactions amplify the motion's error, each a dict
    ``from``, ``to`` (s), ``outputs``, ``smallest`` (relative pivot), ``at`` (s),
    ``dropped`` (outputs at which dependent rows were dropped). The paper scenario's tables
    (a scene with ``files = "paper"``) record neither: those three are ``None``.
    ``warnings``: what the run says not to trust, in words (today: an energy balance off by
    more than 1 % of the energy scale, the steps too long for the motion); each is also
    issued as a :class:`RuntimeWarning`.

    For :func:`simulate` also ``source`` (the mechanism file the equations were interpreted
    from, ``None`` for compiled code) and ``note``.

    ``files`` lists the CSV files written (empty without ``out``).
    """

    def __init__(self, tables: Dict[str, Table], summary: Dict[str, Any], files: List[str]):
        super().__init__(tables)
        self.summary: Dict[str, Any] = summary
        self.files: List[str] = files

    def __repr__(self) -> str:
        return f"Results({sorted(self)}, files={len(self.files)})"


def _results(answer: Tuple[Any, Any, Any]) -> Results:
    tables, summary, files = answer
    for message in summary.get("warnings", []):
        # stacklevel 3: the caller of simulate() or run(), not this module.
        warnings.warn(message, RuntimeWarning, stacklevel=3)
    return Results(
        {stem: Table(stem, list(columns), data) for stem, columns, data in tables},
        dict(summary),
        [os.fspath(f) for f in files],
    )


def mechanisms() -> List[str]:
    """Names of every registered mechanism (``symbody list``)."""
    return list(_native.mechanisms())


def _params(params: Optional[Mapping[str, float]]) -> Optional[Dict[str, float]]:
    return None if params is None else {str(k): float(v) for k, v in params.items()}


def simulate(
    name: MechanismLike,
    t_end: Optional[float] = None,
    step: float = _DEFAULTS["step"],
    alpha: float = _DEFAULTS["alpha"],
    output_step: float = _DEFAULTS["output_step"],
    formulation: Optional[str] = None,
    cross_singular_positions: bool = False,
    out: Optional[PathLike] = None,
    params: Optional[Mapping[str, float]] = None,
    sensitivities: Optional[Sequence[str]] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    reduced: bool = False,
) -> Results:
    """Simulates the mechanism ``name`` as ``symbody simulate <name>`` does: a registered
    name, or a mechanism file's path (a ``str`` ending in ``.toml`` or with a folder, or a
    ``pathlib.Path``), whose equations then run interpreted (see :data:`MechanismLike`).

    ``t_end`` defaults to the mechanism file's; ``step`` is the HHT step (s), ``alpha`` HHT's
    α in [-1/3, 0] (velocities are projected onto the constraints after each step; the
    defaults are :class:`Session`'s too), ``output_step`` the spacing of the rows (s),
    ``formulation`` ``"paper"`` or ``"exact"`` (default: the mechanism's first).
    ``cross_singular_positions`` lets the integrator pass positions where constraint rows
    are dependent for an instant (a linkage lying flat, as the IFToMM A02 N-four-bar); by
    default it stops there and names the rows. ``out``: a folder to write
    ``bodies.csv``, ``joints.csv``, ``drivers.csv`` and ``energy.csv`` into (created if
    needed), as ``--out`` does. ``params``: parameters of the mechanism file (its
    ``[parameters]``, e.g. ``{"r": 0.12}``) set to other values, as ``--set`` does: the file's
    equations are re-derived for them and interpreted (nothing to build).

    Returns :class:`Results`: ``{"bodies", "joints", "drivers", "energy"}`` → :class:`Table`,
    each with the columns and values of the CSV of that name, and the run's ``summary``,
    whose ``source`` is the file the equations were interpreted from (``None`` when they
    are compiled code) and ``note`` what the command line prints about that (or ``None``).
    ``sensitivities``: names of the file's parameters; the results then also have the table
    ``sensitivities`` (as ``--sensitivities`` writes it): ``t``, then ``<output>/<parameter>``,
    the derivative of each body pose, joint wrench and driver effort with respect to each.
    ``rtol``, ``atol``: step-size control on positions and velocities instead of the fixed
    ``step`` (which becomes the first step tried), as ``--rtol``/``--atol``; either alone sets
    both. The summary's ``steps`` counts the steps taken. ``reduced``: integrate the
    mechanism's generated reduced model (its planar model where the file is planar) and read
    every step back on the full model, as ``--reduced``: the same tables.
    """
    return _results(
        _native.simulate(
            name,
            t_end,
            step,
            alpha,
            output_step,
            formulation,
            cross_singular_positions,
            None if out is None else os.fspath(out),
            _params(params),
            _names(sensitivities),
            rtol,
            atol,
            reduced,
        )
    )


def _names(names: Optional[Sequence[str]]) -> List[str]:
    if isinstance(names, str):
        raise TypeError("sensitivities: give a list of parameter names, e.g. ['r']")
    return [] if names is None else [str(n) for n in names]


def run(
    scene: PathLike,
    out: Optional[PathLike] = None,
    sensitivities: Optional[Sequence[str]] = None,
    params: Optional[Mapping[str, float]] = None,
) -> Results:
    """Runs the scene file ``scene`` (``scenes/*.toml``: mechanism, time, outputs, solver) as
    ``symbody run <scene>`` does: kinematic analysis when that is exact for the outputs it
    asks for, HHT-α integration otherwise (``summary["path"]``, and why in
    ``summary["path_reason"]``).

    Returns :class:`Results` with the tables the scene asks for (``bodies``, ``joints``,
    ``drivers``, ``energy``; with ``files = "paper"`` the paper scenario's ``platform``,
    ``joint_forces`` and ``actuators``), each with its CSV file's columns. ``out``: a
    folder to write those CSV files into. A missing file is ``FileNotFoundError``; a scene
    with mistakes a ``ValueError`` naming the file, line and field. ``sensitivities``: as for
    :func:`simulate`, on the path the scene took. ``params``: parameters of the mechanism file
    set on top of the scene's ``[parameters]``, as ``symbody run --set`` does.
    """
    return _results(
        _native.run(
            os.fspath(scene),
            None if out is None else os.fspath(out),
            _names(sensitivities),
            _params(params),
        )
    )


def _study_columns(params: Any) -> Tuple[List[str], List[np.ndarray]]:
    """The parameter names and one float column each of ``params`` (a dict of equally long
    arrays or a pandas DataFrame), as :func:`study` and ``symbody.dask.study`` take them."""
    if hasattr(params, "columns") and hasattr(params, "__getitem__"):
        names = [str(c) for c in params.columns]
        columns = [np.asarray(params[c], dtype=float).ravel() for c in params.columns]
    else:
        names = [str(k) for k in params]
        columns = [np.atleast_1d(np.asarray(params[k], dtype=float)).ravel() for k in params]
    if len({len(c) for c in columns}) > 1:
        raise ValueError("params: every parameter needs as many values")
    return names, columns


def study(
    target: MechanismLike,
    params: Any,
    t_end: Optional[float] = None,
    metrics: Optional[Sequence[str]] = None,
    jobs: Optional[int] = None,
) -> Any:
    """Runs ``target`` once per row of ``params``, as ``symbody study`` does, on ``jobs``
    threads (default: every core) with the GIL released, and returns one row per run.

    ``target`` is a scene file (a ``.toml`` with a top-level ``mechanism``: its time, outputs
    and solver are used) or a mechanism (a registered name or a mechanism file, run over
    ``t_end``, default its file's, with a scene's defaults). ``params`` gives the mechanism
    file's parameters for each run: a dict of equally long arrays, or a pandas DataFrame
    (one column per parameter). ``metrics`` names the metric columns, in their order, as a
    scene's ``[study] metrics`` does: ``max|<driver>|``, ``max|F <joint>|``,
    ``max|M <joint>|``, ``energy_balance``, ``max|Phi|``, ``min <body>.<coordinate>`` /
    ``max <body>.<coordinate>`` (e.g. ``max platform.z``) and, for a six-leg platform,
    ``min fk_condition`` / ``max fk_condition`` (the condition number of its forward-kinematics
    Jacobian). Default: the scene's ``metrics``, else every driver's and joint's, the energy
    balance and ``max|Phi|``. An unknown name is a ValueError naming the closest.

    Returns a pandas DataFrame (a dict of NumPy arrays without pandas) with the columns
    ``run``, the parameters, the metrics, ``status`` (``"ok"`` or ``"failed"``), ``error``
    and ``wall_s``, in the order of ``params``' rows. A parameter set that cannot be built or
    run is a failed row (metrics NaN) with its error, not an exception.
    """
    names, columns = _study_columns(params)
    answer = _native.study(
        target,
        names,
        [c.tolist() for c in columns],
        t_end,
        None if metrics is None else [str(m) for m in metrics],
        None if jobs is None else int(jobs),
    )
    table: Dict[str, np.ndarray] = {k: np.asarray(v) for k, v in answer.items()}
    try:
        import pandas
    except ImportError:
        return table
    return pandas.DataFrame(table)


@dataclass(frozen=True)
class FkResult:
    """Answer of :func:`fk`.

    The pose reached by continuation from the start pose (``None`` fields when ``all=True``
    and the continuation failed; ``error`` then says why): ``position`` (3,) of the platform
    frame's origin and ``rotation`` (3, 3) platform → global, ``euler`` (θ, β, γ) of
    R = Rz(γ)·Ry(β)·Rx(θ), the largest leg-length ``residual`` (m), Newton ``iterations`` of
    the last continuation step, continuation ``steps``, the Jacobian's ``condition`` number
    and its determinant sign ``det_sign``. ``lengths`` are the leg lengths solved for,
    ``legs`` the drivers' names.

    With ``all=True``: ``modes`` (n, 14), one row per real assembly mode with
    ``mode_columns`` = x, y, z, r11 … r33, cond, current (the columns of
    ``assembly_modes.csv``), ``current`` the row of the tracked pose (or ``None``),
    ``complex`` the number of complex solutions (real ones included), ``modes_residual``
    the worst leg-length residual over the real modes.
    """

    legs: List[str]
    lengths: np.ndarray
    position: Optional[np.ndarray] = None
    rotation: Optional[np.ndarray] = None
    euler: Optional[np.ndarray] = None
    residual: Optional[float] = None
    iterations: Optional[int] = None
    steps: Optional[int] = None
    condition: Optional[float] = None
    det_sign: Optional[float] = None
    error: Optional[str] = None
    modes: Optional[np.ndarray] = field(default=None, repr=False)
    mode_columns: Optional[List[str]] = None
    current: Optional[int] = None
    complex: Optional[int] = None
    modes_residual: Optional[float] = None

    @property
    def pose(self) -> Tuple[Optional[np.ndarray], Optional[np.ndarray]]:
        """``(position, rotation)``: also accepted as ``start`` by :func:`fk`."""
        return self.position, self.rotation


def fk(
    name: MechanismLike,
    lengths: Optional[Sequence[float]] = None,
    start: Union[Sequence[float], Tuple[Any, Any], None] = None,
    at: float = 0.0,
    all: bool = False,  # noqa: A002 - the command line's --all
    params: Optional[Mapping[str, float]] = None,
) -> FkResult:
    """Forward kinematics of a six-leg platform, as ``symbody fk <name>``; ``name`` is a
    registered name or a mechanism file's path (see :data:`MechanismLike`).

    Continues the pose from ``start`` along the straight path in leg-length space to
    ``lengths`` (six leg lengths, m; default: what the drivers prescribe at time ``at``), so
    the answer stays on the start's assembly mode. ``start`` is six numbers
    ``x, y, z, θ, β, γ`` (as ``--from``) or a pair ``(position, rotation)`` such as
    ``FkResult.pose``; default: the mechanism file's initial pose. ``all=True`` also finds
    every assembly mode (``--all``). ``params`` as in :func:`simulate`. A mechanism that is not such a platform is a
    ``ValueError``; a parallel singularity on the way a ``RuntimeError``.
    """
    legs = None if lengths is None else np.asarray(lengths, dtype=float).ravel()
    pose: Any = None
    if start is not None:
        if isinstance(start, (tuple, list)) and len(start) == 2:
            position, rotation = start
            pose = (
                np.ascontiguousarray(position, dtype=float).ravel(),
                np.ascontiguousarray(rotation, dtype=float),
            )
        else:
            pose = np.asarray(start, dtype=float).ravel()
    return FkResult(**_native.fk(name, legs, pose, float(at), bool(all), _params(params)))


class Coo(tuple):
    """A sparse matrix as SciPy's COO triplet ``(data, (rows, cols))``, with its ``shape``:
    ``scipy.sparse.coo_array(m, shape=m.shape)`` builds it, ``m.toarray()`` makes it dense
    without SciPy. ``data`` are float64, ``rows`` and ``cols`` int64; the entries are the
    generated structural nonzeros (no duplicates)."""

    shape: Tuple[int, ...]

    def __new__(cls, triplet: Tuple[np.ndarray, Tuple[np.ndarray, np.ndarray]], shape: Sequence[int]) -> "Coo":
        data, (rows, cols) = triplet
        self = super().__new__(cls, (data, (rows, cols)))
        self.shape = tuple(shape)
        return self

    @property
    def data(self) -> np.ndarray:
        """The nonzero values (float64)."""
        return self[0]

    @property
    def rows(self) -> np.ndarray:
        """Row of each value (int64)."""
        return self[1][0]

    @property
    def cols(self) -> np.ndarray:
        """Column of each value (int64)."""
        return self[1][1]

    def toarray(self) -> np.ndarray:
        """The dense ``shape`` array."""
        dense = np.zeros(self.shape)
        np.add.at(dense, (self.rows, self.cols), self.data)
        return dense

    def __repr__(self) -> str:
        return f"Coo(shape={self.shape}, nnz={len(self.data)})"


class Mechanism(_native.Mechanism):
    """The generated functions of the mechanism ``name`` (``formulation`` ``"paper"`` or
    ``"exact"``; default: its first), evaluated at any state. ``name`` is a registered name
    or a mechanism file's path (``Mechanism("robot.toml")``, ``Mechanism(pathlib.Path(...))``;
    see :data:`MechanismLike`), whose equations are then interpreted, nothing compiled:
    ``interpreted`` says which, ``source`` is the file (``None`` for compiled code).
    ``params`` (e.g. ``{"r": 0.12}``) sets parameters of the mechanism file, as in
    :func:`simulate`.

    Sizes and names: ``n_coords``, ``n_constraints``, ``q0`` (the file's assembled initial
    coordinates), ``qd0``, ``coord_names``, ``row_names``, ``redundant_rows``. Evaluations
    (``q``, ``qd``: any sequence of ``n_coords`` numbers; ``t`` in s, default 0):
    ``phi(q, t)``, ``phi_t(q, t)``, ``phi_q(q, t)`` (a :class:`Coo` of shape
    ``(n_constraints, n_coords)``), ``gamma(q, qd, t)`` (Φq q̈ = γ), ``mass(q)`` (a
    :class:`Coo` of shape ``(n_coords, n_coords)``, both triangles), ``force(q, qd, t)``
    (generalized forces), ``force_jacobian(q, qd, t)`` (the applied loads' ∂Q/∂q and ∂Q/∂q̇,
    two :class:`Coo` of shape ``(n_coords, n_coords)``, empty without springs, dampers or
    actuators) and ``potential(q)``.
    """

    def phi_q(self, q: Sequence[float], t: float = 0.0) -> Coo:
        """Φq(q, t), the constraint Jacobian, shape ``(n_constraints, n_coords)``."""
        return Coo(super().phi_q(q, t), (self.n_constraints, self.n_coords))

    def mass(self, q: Sequence[float]) -> Coo:
        """M(q), the mass matrix (both triangles), shape ``(n_coords, n_coords)``."""
        return Coo(super().mass(q), (self.n_coords, self.n_coords))

    def force_jacobian(
        self, q: Sequence[float], qd: Sequence[float], t: float = 0.0
    ) -> Tuple[Coo, Coo]:
        """The applied loads' ∂Q/∂q and ∂Q/∂q̇ (springs, dampers, actuators), each shape
        ``(n_coords, n_coords)``; empty without such loads."""
        shape = (self.n_coords, self.n_coords)
        dq, dqd = super().force_jacobian(q, qd, t)
        return Coo(dq, shape), Coo(dqd, shape)


class Session(_native.Session):
    """One simulation of the mechanism ``name`` to drive step by step: HHT-α from the
    mechanism's consistent start. ``name`` is a registered name or a mechanism file's path
    (see :data:`MechanismLike`); ``interpreted`` and ``source`` say where the equations come
    from, as for :class:`Mechanism`.

    The defaults are :func:`simulate`'s (``alpha``, ``step``, and velocities projected onto
    the constraints after each step), so a session and a run of the same mechanism report
    the same numbers. The paper's runs use ``alpha=-0.05, project_velocities=False``.
    ``formulation`` is ``"paper"`` or ``"exact"`` (default: the mechanism's first);
    ``cross_singular_positions``, ``params``, ``rtol`` and ``atol`` (step-size control; every
    time given to ``advance_to`` is landed on exactly) as in :func:`simulate`.

    State: ``t``, ``q``, ``qd``, ``coord_names``. Stepping: ``step()``, ``advance_to(t)``.
    Forces of the current state: ``driver_effort(name)``, ``driver_efforts()``
    (``driver_names`` order), ``joint_wrench(name)`` → ``(force, moment)`` on the joint's
    first body (global frame, moment about the joint point), ``multipliers()``.
    """

    def __new__(
        cls,
        name: MechanismLike,
        formulation: Optional[str] = None,
        alpha: float = _DEFAULTS["alpha"],
        step: float = _DEFAULTS["step"],
        project_velocities: bool = _DEFAULTS["project_velocities"],
        cross_singular_positions: bool = False,
        params: Optional[Mapping[str, float]] = None,
        rtol: Optional[float] = None,
        atol: Optional[float] = None,
    ) -> "Session":
        return super().__new__(
            cls,
            name,
            formulation,
            alpha,
            step,
            project_velocities,
            cross_singular_positions,
            _params(params),
            rtol,
            atol,
        )


def paper_leg1_force_at_1s() -> float:
    """The paper platform's actuator 1 force (N) at t = 1 s with the paper scenario's
    integrator settings (``Session("stewart_6_6", alpha=-0.05, project_velocities=False)``):
    the number the Rust example, the C example and this package all print."""
    return _native.paper_leg1_force_at_1s()
