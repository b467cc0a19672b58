"""Studies on a Dask cluster: ``symbody.study`` split into chunks of rows, each chunk run by
``symbody.study`` on a worker, the answers put back in row order.

>>> from dask.distributed import Client
>>> import numpy as np, symbody.dask
>>> client = Client("tcp://scheduler:8786")          # or LocalCluster(), SLURMCluster(), ...
>>> rows = symbody.dask.study(client, "slider_crank", {"r": np.linspace(0.08, 0.12, 1000)})

The result equals ``symbody.study(target, params, ...)`` (same columns and values; ``wall_s``
is each run's own time, so it differs). Only plain data travels: the target's name or
absolute path and each chunk's parameter values as lists of floats. Workers import
``symbody`` (installed in their environment) and, for a file target, read the file at the
same absolute path (a shared file system). A chunk whose worker dies is run again by Dask; a
chunk that raises is retried ``retries`` times.

The steps are public for other executors or finer control: :func:`split` (plain data),
:func:`run_chunk` (on a worker) and :func:`combine` (the chunks' answers, in any order).

``import symbody`` does not need Dask; this module does (``pip install "dask[distributed]"``).
"""

from __future__ import annotations

import math
import os
import pathlib
from typing import Any, Dict, List, Optional, Sequence

try:
    # Not used by name here (the client's methods do the work), but a worker and `Client`
    # need it: failing at import says what to install instead of failing later on a worker.
    import distributed  # noqa: F401
except ImportError as e:  # pragma: no cover - exercised by a test that hides the module
    raise ImportError(
        'symbody.dask needs Dask\'s distributed scheduler: pip install "dask[distributed]"'
    ) from e

import numpy as np

from . import _core

#: Chunks per worker thread when ``chunk_size`` is not given: a few, so that a slow chunk or a
#: lost worker leaves the others something to do, and each chunk still holds many runs.
CHUNKS_PER_THREAD = 4


def study(
    client: Any,
    target: _core.MechanismLike,
    params: Any,
    t_end: Optional[float] = None,
    metrics: Optional[Sequence[str]] = None,
    chunk_size: Optional[int] = None,
    retries: int = 3,
) -> Any:
    """:func:`symbody.study` on the workers of the ``dask.distributed`` ``client``.

    ``target``, ``params``, ``t_end`` and ``metrics`` are those of :func:`symbody.study`. The
    rows go in chunks of ``chunk_size`` (default: about ``CHUNKS_PER_THREAD`` chunks per
    worker thread, from ``client.nthreads()``), one task each, run with ``jobs=1`` (a
    worker with several threads runs several chunks). A chunk that raises is retried
    ``retries`` times; one whose worker died is rerun by Dask.

    Returns the DataFrame (a dict of arrays without pandas) that ``symbody.study(target,
    params, t_end, metrics)`` returns: ``run`` numbered 0, 1, ... in the order of
    ``params``' rows. Wrong parameter or metric names and a target that cannot be loaded
    raise here, on the client, before anything is sent.
    """
    names, columns = _core._study_columns(params)
    # Validates names, metrics and target here (a ValueError now, not a retried task) and
    # gives the columns of an empty study.
    empty = _core.study(target, {n: [] for n in names}, t_end, metrics, jobs=1)
    n_rows = len(columns[0]) if columns else 0
    if n_rows == 0:
        return empty
    if chunk_size is None:
        threads = sum(client.nthreads().values()) or 1
        chunk_size = math.ceil(n_rows / (CHUNKS_PER_THREAD * threads))
    chunks = split(target, params, t_end, metrics, chunk_size)
    futures = client.map(run_chunk, chunks, retries=retries, pure=False)
    try:
        parts = client.gather(futures)
    except BaseException:
        # A chunk failed for good (or the caller interrupted): the others would go on
        # running for nobody.
        client.cancel(futures)
        raise
    return combine(parts)


def split(
    target: _core.MechanismLike,
    params: Any,
    t_end: Optional[float] = None,
    metrics: Optional[Sequence[str]] = None,
    chunk_size: int = 1,
) -> List[Dict[str, Any]]:
    """``params``' rows in chunks of ``chunk_size`` (the last may be shorter), each a plain
    dict for :func:`run_chunk`: ``start`` (its first row's index), ``target`` (a name, or a
    file's absolute path, so that a worker in another folder finds it), ``params`` (``{name:
    [float, ...]}``), ``t_end`` and ``metrics``."""
    if chunk_size < 1:
        raise ValueError(f"chunk_size must be at least 1, not {chunk_size}")
    names, columns = _core._study_columns(params)
    n_rows = len(columns[0]) if columns else 0
    portable = _portable(target)
    kept = None if metrics is None else [str(m) for m in metrics]
    return [
        {
            "start": start,
            "target": portable,
            "params": {n: c[start : start + chunk_size].tolist() for n, c in zip(names, columns)},
            "t_end": None if t_end is None else float(t_end),
            "metrics": kept,
        }
        for start in range(0, n_rows, chunk_size)
    ]


def run_chunk(chunk: Dict[str, Any]) -> Dict[str, Any]:
    """Runs one chunk of :func:`split` with ``symbody.study(..., jobs=1)``: ``{"start":
    ..., "table": {column: list}}``, plain Python values (exact floats) for the trip back."""
    table = _core.study(
        chunk["target"], chunk["params"], chunk["t_end"], chunk["metrics"], jobs=1
    )
    return {
        "start": chunk["start"],
        "table": {str(k): np.asarray(table[k]).tolist() for k in table},
    }


def combine(parts: Sequence[Dict[str, Any]]) -> Any:
    """The answers of :func:`run_chunk` (at least one, in any order) as one study: rows in
    the order of ``start``, ``run`` renumbered 0, 1, ..., as :func:`symbody.study` builds
    it (a pandas DataFrame, a dict of arrays without pandas)."""
    if not parts:
        raise ValueError("combine needs at least one chunk's answer")
    ordered = sorted(parts, key=lambda p: p["start"])
    columns = list(ordered[0]["table"])
    merged: Dict[str, List[Any]] = {k: [] for k in columns}
    for part in ordered:
        if list(part["table"]) != columns:
            raise ValueError("the chunks' answers have different columns")
        for k in columns:
            merged[k].extend(part["table"][k])
    # Each chunk numbers its runs from 0; the study's numbers are the rows' indices.
    merged["run"] = list(range(len(merged["run"])))
    # As symbody.study: NumPy arrays of the plain values, then a DataFrame when pandas is here.
    table = {k: np.asarray(v) for k, v in merged.items()}
    try:
        import pandas
    except ImportError:
        return table
    return pandas.DataFrame(table)


def _portable(target: _core.MechanismLike) -> str:
    """``target`` as the workers should get it: a registered name as it is, a file (a ``str``
    ending in ``.toml`` or with a folder, as the Rust side reads it, or any ``os.PathLike``)
    as its absolute path, which names a file in any working folder."""
    if isinstance(target, str):
        if target.endswith(".toml") or len(pathlib.PurePath(target).parts) > 1:
            return os.path.abspath(target)
        return target
    return os.path.abspath(os.fsdecode(target))
