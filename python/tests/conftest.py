"""Shared fixtures: the `symbody` command line of this checkout, to compare the package with.

The CLI is `$SYMBODY_BIN` if set, else `cargo run --release --` from the repository root
(cargo builds it when needed; CI has built it already)."""

import os
import pathlib
import shlex
import subprocess

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    """Runs `symbody ARGS…`, failing the test with its output if it fails."""
    if os.environ.get("SYMBODY_BIN"):
        base = shlex.split(os.environ["SYMBODY_BIN"])
    else:
        base = ["cargo", "run", "--quiet", "--release", "--bin", "symbody", "--"]

    def run(*args):
        p = subprocess.run(
            base + [str(a) for a in args], cwd=REPO, capture_output=True, text=True
        )
        assert p.returncode == 0, f"{base + list(args)} failed:\n{p.stdout}\n{p.stderr}"
        return p.stdout

    return run


def read_csv(path):
    """(columns, data) of a CSV the CLI wrote: one header line, then numbers."""
    with open(path) as f:
        columns = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return columns, data
