"""symbody from Python: the generated mechanisms simulated, stepped and solved by the same Rust
code as the ``symbody`` command line and the C library.

>>> import symbody
>>> symbody.mechanisms()                      # registered mechanisms
>>> run = symbody.simulate("slider_crank", t_end=1.0)
>>> run["drivers"].columns, run["drivers"].data.shape
>>> s = symbody.Session("stewart_6_6"); s.advance_to(1.0); s.driver_effort("act1")

Errors from Rust arrive as ``ValueError`` (an unknown name, a bad option or argument) or
``RuntimeError`` (a solver failure), with the Rust message.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _native
from ._native import Session

__all__ = [
    "Coo",
    "FkResult",
    "Mechanism",
    "Session",
    "Table",
    "fk",
    "mechanisms",
    "simulate",
]


@dataclass(frozen=True)
class Table:
    """One output table of a run, with the columns of ``symbody simulate <name>``'s
    ``<name>.csv``: ``t`` first, then one group per body, joint or driver.

    ``data`` has one row per output time. ``table["column"]`` is that column (a view),
    ``len(table)`` the number of rows, and ``table.to_dict()`` a ``{column: array}`` dict
    (``pandas.DataFrame(table.data, columns=table.columns)`` makes a data frame).
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
        return {c: self.data[:, k] for k, c in enumerate(self.columns)}


def mechanisms() -> List[str]:
    """Names of every registered mechanism (``symbody list``)."""
    return list(_native.mechanisms())


def simulate(
    name: str,
    t_end: Optional[float] = None,
    step: float = 1e-3,
    alpha: float = 0.0,
    output_step: float = 0.01,
    formulation: Optional[str] = None,
    cross_singular_positions: bool = False,
) -> Dict[str, Table]:
    """Simulates the registered mechanism ``name`` as ``symbody simulate <name>`` does.

    ``t_end`` defaults to the mechanism file's; ``step`` is the HHT step (s), ``alpha`` HHT's
    α in [-1/3, 0] (velocities are projected onto the constraints after each step),
    ``output_step`` the spacing of the rows (s), ``formulation`` ``"paper"`` or ``"exact"``
    (default: the mechanism's first). ``cross_singular_positions`` lets the integrator pass
    positions where constraint rows are dependent for an instant (a linkage lying flat, as
    the IFToMM A02 N-four-bar); by default it stops there and names the rows.

    Returns ``{"bodies", "joints", "drivers", "energy"}`` → :class:`Table`, each with the
    columns and values of the CSV of that name.
    """
    tables = _native.simulate(
        name, t_end, step, alpha, output_step, formulation, cross_singular_positions
    )
    return {stem: Table(stem, list(columns), data) for stem, columns, data in tables}


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
    def pose(self):
        """``(position, rotation)``: also accepted as ``start`` by :func:`fk`."""
        return self.position, self.rotation


def fk(
    name: str,
    lengths: Optional[Sequence[float]] = None,
    start=None,
    at: float = 0.0,
    all: bool = False,  # noqa: A002 - the command line's --all
) -> FkResult:
    """Forward kinematics of a six-leg platform, as ``symbody fk <name>``.

    Continues the pose from ``start`` along the straight path in leg-length space to
    ``lengths`` (six leg lengths, m; default: what the drivers prescribe at time ``at``), so
    the answer stays on the start's assembly mode. ``start`` is six numbers
    ``x, y, z, θ, β, γ`` (as ``--from``) or a pair ``(position, rotation)`` such as
    ``FkResult.pose``; default: the mechanism file's initial pose. ``all=True`` also finds
    every assembly mode (``--all``). A mechanism that is not such a platform is a
    ``ValueError``; a parallel singularity on the way a ``RuntimeError``.
    """
    if lengths is not None:
        lengths = np.asarray(lengths, dtype=float).ravel()
    if start is not None:
        if isinstance(start, (tuple, list)) and len(start) == 2:
            position, rotation = start
            start = (
                np.ascontiguousarray(position, dtype=float).ravel(),
                np.ascontiguousarray(rotation, dtype=float),
            )
        else:
            start = np.asarray(start, dtype=float).ravel()
    return FkResult(**_native.fk(name, lengths, start, float(at), bool(all)))


class Coo(tuple):
    """A sparse matrix as SciPy's COO triplet ``(data, (rows, cols))``, with its ``shape``:
    ``scipy.sparse.coo_array(m, shape=m.shape)`` builds it, ``m.toarray()`` makes it dense
    without SciPy. ``data`` are float64, ``rows`` and ``cols`` int64; the entries are the
    generated structural nonzeros (no duplicates)."""

    def __new__(cls, triplet, shape):
        data, (rows, cols) = triplet
        self = super().__new__(cls, (data, (rows, cols)))
        self.shape = tuple(shape)
        return self

    @property
    def data(self) -> np.ndarray:
        return self[0]

    @property
    def rows(self) -> np.ndarray:
        return self[1][0]

    @property
    def cols(self) -> np.ndarray:
        return self[1][1]

    def toarray(self) -> np.ndarray:
        dense = np.zeros(self.shape)
        np.add.at(dense, (self.rows, self.cols), self.data)
        return dense

    def __repr__(self) -> str:
        return f"Coo(shape={self.shape}, nnz={len(self.data)})"


class Mechanism(_native.Mechanism):
    """The generated functions of the registered mechanism ``name`` (``formulation``
    ``"paper"`` or ``"exact"``; default: its first), evaluated at any state.

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

    def phi_q(self, q, t: float = 0.0) -> Coo:
        return Coo(super().phi_q(q, t), (self.n_constraints, self.n_coords))

    def mass(self, q) -> Coo:
        return Coo(super().mass(q), (self.n_coords, self.n_coords))

    def force_jacobian(self, q, qd, t: float = 0.0) -> Tuple[Coo, Coo]:
        shape = (self.n_coords, self.n_coords)
        dq, dqd = super().force_jacobian(q, qd, t)
        return Coo(dq, shape), Coo(dqd, shape)


def paper_leg1_force_at_1s() -> float:
    """The paper platform's actuator 1 force (N) at t = 1 s with :class:`Session`'s default
    settings: the number the Rust example, the C example and this package all print."""
    return _native.paper_leg1_force_at_1s()
