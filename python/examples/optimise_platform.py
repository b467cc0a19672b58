"""Sizing with exact gradients: the radius of the base's joint circle of the paper's
Stewart platform (`scenes/stewart_6_6.toml`: the paper's motion, generic tables) that minimises the peak actuator force over one period,
found by `scipy.optimize.minimize` (L-BFGS-B, bounded) twice: with the gradients of symbody's
sensitivities (`sensitivities=["r_platform"]`), and with scipy's own finite differences. Prints
the optimum, iterations, runs and wall time of each.

    python3 python/examples/optimise_platform.py
"""

import sys
import time
from pathlib import Path

import numpy as np
from scipy.optimize import minimize

import symbody

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "stewart_6_6.toml"
PARAMETER = "r_base"
# Below 0.25 m the legs cannot reach the paper's motion (the position analysis fails).
BOUNDS = [(0.25, 0.42)]
START = 0.27


class Objective:
    """The peak |effort| of the six actuators over the period, counting the runs it takes."""

    def __init__(self):
        self.runs = 0

    def efforts(self, r, sensitivities=()):
        self.runs += 1
        run = symbody.run(SCENE, params={PARAMETER: float(r)}, sensitivities=list(sensitivities))
        table = run["drivers"]
        columns = [c for c in table.columns if c != "t"]
        return run, np.column_stack([table[c] for c in columns])

    def value(self, x):
        _, f = self.efforts(x[0])
        return np.abs(f).max()

    def value_and_gradient(self, x):
        run, f = self.efforts(x[0], [PARAMETER])
        k, i = np.unravel_index(np.abs(f).argmax(), f.shape)
        # The peak's derivative is that of the effort where it is reached (the maximum of
        # smooth functions is differentiable wherever one of them alone reaches it).
        derivative = run["sensitivities"][f"act{i + 1}/{PARAMETER}"][k]
        return np.abs(f[k, i]), np.array([np.sign(f[k, i]) * derivative])


def optimise(with_gradients):
    objective = Objective()
    start = time.perf_counter()
    if with_gradients:
        result = minimize(
            objective.value_and_gradient, [START], jac=True, method="L-BFGS-B", bounds=BOUNDS
        )
    else:
        result = minimize(objective.value, [START], method="L-BFGS-B", bounds=BOUNDS)
    return result, objective.runs, time.perf_counter() - start


def main():
    for label, exact in (("exact gradients", True), ("finite differences", False)):
        result, runs, wall = optimise(exact)
        print(
            f"{label:18}: {PARAMETER} = {result.x[0]:.6f} m, peak {result.fun:.4f} N, "
            f"{result.nit} iterations, {runs} runs, {wall:.1f} s ({result.message})"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
