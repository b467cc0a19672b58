"""Two mechanisms side by side: simulate a four-bar linkage and a slider-crank, plot the
effort of each one's motor, and print one line comparing them.

    python python/examples/compare.py [out-folder]     # default: ./compare-out

Writes ``motor_efforts.png`` into the folder (matplotlib, no display needed). Without
matplotlib it says so and writes the efforts as ``motor_efforts.csv`` instead, so the
example still shows the comparison.
"""

import pathlib
import sys

import numpy as np

import symbody

MECHANISMS = ("four_bar", "slider_crank")


def main(out: pathlib.Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    efforts = {}
    for name in MECHANISMS:
        drivers = symbody.simulate(name)["drivers"]
        # The first driver's column: each of these mechanisms has one motor.
        efforts[name] = (drivers["t"], drivers.columns[1], drivers[drivers.columns[1]])

    try:
        import matplotlib

        matplotlib.use("Agg")  # files only: CI machines have no display
        import matplotlib.pyplot as plt
    except ImportError:
        path = out / "motor_efforts.csv"
        t = efforts[MECHANISMS[0]][0]
        columns = [efforts[n][2] for n in MECHANISMS]
        if all(len(c) == len(t) for c in columns):
            np.savetxt(path, np.column_stack([t, *columns]), delimiter=",",
                       header="t," + ",".join(MECHANISMS), comments="")
            print(f"matplotlib is not installed (pip install matplotlib): wrote {path} instead of a plot")
        else:
            print("matplotlib is not installed (pip install matplotlib): no plot written")
    else:
        fig, ax = plt.subplots(figsize=(7, 4))
        for name, (t, driver, effort) in efforts.items():
            ax.plot(t, effort, label=f"{name} ({driver})")
        ax.set_xlabel("t (s)")
        ax.set_ylabel("motor torque (N·m)")
        ax.set_title("Motor effort over time")
        ax.grid(True, alpha=0.3)
        ax.legend()
        fig.tight_layout()
        path = out / "motor_efforts.png"
        fig.savefig(path, dpi=100)
        plt.close(fig)
        print(f"wrote {path}")

    peaks = {name: float(np.max(np.abs(e))) for name, (_, _, e) in efforts.items()}
    a, b = MECHANISMS
    print(
        f"peak |motor torque|: {a} {peaks[a]:.4g} N·m, {b} {peaks[b]:.4g} N·m "
        f"({a} needs {peaks[a] / peaks[b]:.3g}x {b}'s)"
    )


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "compare-out"))
