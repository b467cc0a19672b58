"""What a study costs on Dask over the local one: the same runs with ``symbody.study(...,
jobs=N)`` and with ``symbody.dask.study`` on a ``LocalCluster`` of N one-thread worker
processes, the walls and the difference per run (BENCHMARKS.md, "Studies on Dask").

    python python/examples/dask_overhead.py [--runs 200] [--workers 2] [--repeat 3]
        [--target scenes/paper.toml --param m_cyl:0.2:0.4] [--t-end T]

The cluster is started and warmed up (its workers import symbody) before the clock starts:
what is measured is what a study pays on a running cluster. Runs go in turn, local then
cluster, ``--repeat`` times; the medians and the fastest of each are printed, and whether the
rows agree.
"""

import argparse
import statistics
import time

import numpy as np

import symbody
import symbody.dask
from dask.distributed import Client, LocalCluster


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--target", default="scenes/paper.toml")
    ap.add_argument("--param", default="m_cyl:0.2:0.4", help="name:from:to, evenly spaced")
    ap.add_argument("--runs", type=int, default=200)
    ap.add_argument("--t-end", type=float, default=None)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    name, lo, hi = a.param.split(":")
    params = {name: np.linspace(float(lo), float(hi), a.runs)}
    with LocalCluster(
        n_workers=a.workers, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, Client(cluster) as client:
        # Warm-up: each worker imports symbody and loads the target once.
        symbody.dask.study(client, a.target, {name: [float(lo)] * a.workers}, a.t_end)
        local_walls, dask_walls = [], []
        for _ in range(a.repeat):
            t = time.perf_counter()
            local = symbody.study(a.target, params, a.t_end, jobs=a.workers)
            local_walls.append(time.perf_counter() - t)
            t = time.perf_counter()
            remote = symbody.dask.study(client, a.target, params, a.t_end)
            dask_walls.append(time.perf_counter() - t)
        same = local.drop(columns="wall_s").equals(remote.drop(columns="wall_s"))
    lw, dw = statistics.median(local_walls), statistics.median(dask_walls)
    print(f"{a.target}, {a.runs} runs, {a.workers} workers/jobs, median of {a.repeat}")
    print(f"local jobs={a.workers}: {lw:.2f} s ({1e3 * lw / a.runs:.1f} ms/run)")
    print(f"dask {a.workers} workers: {dw:.2f} s ({1e3 * dw / a.runs:.1f} ms/run)")
    print(f"overhead: {1e3 * (dw - lw) / a.runs:+.2f} ms/run ({dw / lw:.3f}x); rows equal: {same}")
    # The fastest of each: on a shared machine, the least disturbed by other work.
    lm, dm = min(local_walls), min(dask_walls)
    print(f"fastest: local {lm:.2f} s, dask {dm:.2f} s: {1e3 * (dm - lm) / a.runs:+.2f} ms/run")
    print(f"walls local {[round(w, 2) for w in local_walls]} dask {[round(w, 2) for w in dask_walls]}")


if __name__ == "__main__":
    main()
