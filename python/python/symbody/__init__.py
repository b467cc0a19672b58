"""symbody from Python: the generated mechanisms simulated, stepped and solved by the same Rust
code as the ``symbody`` command line and the C library.

>>> import symbody
>>> symbody.mechanisms()                      # registered mechanisms
>>> run = symbody.simulate("slider_crank", t_end=1.0)
>>> run["drivers"].columns, run["drivers"].data.shape, run.summary["steps"]
>>> scene = symbody.run("scenes/slider_crank.toml", out="out")   # a scene, CSVs written
>>> s = symbody.Session("stewart_6_6"); s.advance_to(1.0); s.driver_effort("act1")
>>> m = symbody.Mechanism("robots/arm.toml")  # any mechanism file, interpreted at once
>>> m.interpreted, m.source                     # (True, "robots/arm.toml")
>>> symbody.simulate("slider_crank", params={"r": 0.12})         # a file parameter, no build
>>> symbody.study("slider_crank", {"r": [0.08, 0.1, 0.12]})      # one row per run, all cores

Errors from Rust arrive as ``ValueError`` (an unknown name, a bad option or argument) or
``RuntimeError`` (a solver failure), with the Rust message; a mechanism file that is not
there as ``FileNotFoundError`` (``IsADirectoryError`` for a folder).
"""

from ._core import (
    Coo,
    FkResult,
    Mechanism,
    Results,
    Session,
    Table,
    fk,
    mechanisms,
    paper_leg1_force_at_1s,
    run,
    simulate,
    study,
)
from ._native import __version__

__all__ = [
    "Coo",
    "FkResult",
    "Mechanism",
    "Results",
    "Session",
    "Table",
    "fk",
    "study",
    "mechanisms",
    "paper_leg1_force_at_1s",
    "run",
    "simulate",
]
