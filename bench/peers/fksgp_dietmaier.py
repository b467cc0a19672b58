"""Peer timing: Martyushev's fkSGP elimination-template solver (github.com/martyushev/fkSGP, MIT; Mech. Mach. Theory 215:106170, 2025) on Dietmaier's 40-real-mode 6-6 Stewart-Gough platform -- wall time per call (all 40 complex assembly modes), real-mode count, leg-length residuals, and how often repeated calls (random internal rotations) miss real modes. Side-by-side reference for our Rust forward-kinematics solver; a manual benchmark, NOT run in CI.

Usage: python3 bench/peers/fksgp_dietmaier.py [--fksgp /tmp/fkSGP] [-n 200] [--warmup 20] [--repeats 50] [--threads 1] [--seed 0]

Needs numpy and scipy. --fksgp is a checkout of the fkSGP repository (the directory holding its python/ folder).
Only this harness is ours; the solver is imported from that checkout, unmodified. Its package
__init__.py is bypassed (it imports test.py, which only parses on Python >= 3.12), so the
solver module (python/solver66.py, or python/solver_fkSGP.py in checkouts before 2026-01-30)
is loaded directly as a submodule of a stand-in package.
"""

import argparse
import os
import sys


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--fksgp", default="/tmp/fkSGP", help="fkSGP checkout (default /tmp/fkSGP)")
    p.add_argument("-n", type=int, default=200, help="timed calls (default 200)")
    p.add_argument("--warmup", type=int, default=20, help="untimed warm-up calls (default 20)")
    p.add_argument("--repeats", type=int, default=50, help="calls checked for the real-mode count (default 50)")
    p.add_argument("--threads", default="1",
                   help="BLAS/LAPACK threads, set before numpy is imported; 'default' leaves the environment alone (default 1)")
    p.add_argument("--seed", type=int, default=0, help="seed of numpy's global RNG, which the solver draws its rotations from")
    p.add_argument("--commit", default=None, help="fkSGP commit to report when the checkout has no .git")
    return p.parse_args()


ARGS = parse_args()
if ARGS.threads != "default":
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "BLIS_NUM_THREADS"):
        os.environ[var] = ARGS.threads

import gc  # noqa: E402
import importlib  # noqa: E402
import importlib.machinery  # noqa: E402
import importlib.util  # noqa: E402
import inspect  # noqa: E402
import platform  # noqa: E402
import subprocess  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
import scipy  # noqa: E402

# Dietmaier's platform (1998): base points X_i, platform points x_i, leg lengths l_i.
X_BASE = np.array([
    [0.0, 0.0, 0.0],
    [1.107915, 0.0, 0.0],
    [0.549094, 0.756063, 0.0],
    [0.735077, -0.223935, 0.525991],
    [0.514188, -0.526063, -0.368418],
    [0.590473, 0.094733, -0.205018],
])
X_PLAT = np.array([
    [0.0, 0.0, 0.0],
    [0.542805, 0.0, 0.0],
    [0.956919, -0.528915, 0.0],
    [0.665885, -0.353482, 1.402538],
    [0.478359, 1.158742, 0.107672],
    [-0.137087, -0.235121, 0.353913],
])
LEGS = np.array([1.0, 0.645275, 1.086284, 1.503439, 1.281933, 0.771071])
L_SQ = LEGS**2  # the solver takes squared leg lengths

IMAG_TOL = 1e-8  # a mode is real when every entry of its [R | t] has |imag| below this
DISTINCT_TOL = 1e-6  # two real modes are the same when their [R | t] differ by less (max abs)


def load_solver(root):
    """Return (callable, module file, takes_real_only) from an fkSGP checkout, without running its __init__."""
    pkgdir = os.path.join(root, "python")
    if not os.path.isdir(pkgdir):
        sys.exit(f"no python/ folder under {root}; pass --fksgp")
    name = "_fksgp_peer"
    spec = importlib.machinery.ModuleSpec(name, None, is_package=True)
    pkg = importlib.util.module_from_spec(spec)
    pkg.__path__ = [pkgdir]
    sys.modules[name] = pkg
    for mod_name in ("solver66", "solver_fkSGP"):
        path = os.path.join(pkgdir, mod_name + ".py")
        if os.path.isfile(path):
            mod = importlib.import_module(f"{name}.{mod_name}")
            fn = getattr(mod, mod_name)
            params = list(inspect.signature(fn).parameters)
            return fn, path, params, len(params) >= 4
    sys.exit(f"neither solver66.py nor solver_fkSGP.py under {pkgdir}")


def fksgp_commit(root):
    if ARGS.commit:
        return ARGS.commit
    try:
        return subprocess.run(["git", "-C", root, "rev-parse", "HEAD"], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown (no .git in checkout; pass --commit)"


def analyse(Rt):
    """Classify one call's output: (total, real mask, real R, real t)."""
    Rt = np.asarray(Rt)
    imag = np.abs(np.imag(Rt)).reshape(Rt.shape[0], -1).max(axis=1) if Rt.size else np.zeros(0)
    real = imag < IMAG_TOL
    R = np.real(Rt[real, :, :3])
    t = np.real(Rt[real, :, 3])
    return Rt.shape[0], real, R, t


def leg_residuals(R, t, src, dst):
    """max_i | |R src_i + t - dst_i| - l_i | for each mode."""
    p = np.einsum("kab,ib->kia", R, src) + t[:, None, :] - dst[None, :, :]
    return np.abs(np.linalg.norm(p, axis=2) - LEGS[None, :]).max(axis=1)


def count_distinct(R, t):
    flat = np.concatenate([R.reshape(len(R), -1), t], axis=1)
    keep = []
    for v in flat:
        if all(np.abs(v - w).max() > DISTINCT_TOL for w in keep):
            keep.append(v)
    return len(keep)


def quartiles_ms(samples):
    q1, med, q3 = np.percentile(np.asarray(samples) * 1e3, [25, 50, 75])
    return q1, med, q3


def time_calls(call, n):
    samples = np.empty(n)
    gc_was = gc.isenabled()
    gc.disable()
    try:
        for k in range(n):
            t0 = time.perf_counter()
            call()
            samples[k] = time.perf_counter() - t0
    finally:
        if gc_was:
            gc.enable()
    return samples


def main():
    root = os.path.abspath(ARGS.fksgp)
    solver, path, params, takes_real_only = load_solver(root)
    np.random.seed(ARGS.seed)

    if takes_real_only:
        def call_all():
            return solver(X_BASE, X_PLAT, L_SQ, 0)  # realOnly=0: all complex modes

        def call_real():
            return solver(X_BASE, X_PLAT, L_SQ, 1)  # realOnly=1: their own real filter
    else:
        def call_all():
            return solver(X_BASE, X_PLAT, L_SQ)
        call_real = None

    print("== environment")
    print(f"python {platform.python_version()} ({platform.python_implementation()}), numpy {np.__version__}, scipy {scipy.__version__}")
    print(f"BLAS threads: {ARGS.threads}  (OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')}), cpus {os.cpu_count()}, loadavg {os.getloadavg()[0]:.2f}")
    print(f"fkSGP checkout {root}, commit {fksgp_commit(root)}")
    print(f"solver {os.path.relpath(path, root)}: {solver.__name__}({', '.join(params)})")

    # One call, examined closely.
    Rt, err = call_all()
    total, real, R, t = analyse(Rt)
    fwd = leg_residuals(R, t, X_PLAT, X_BASE)  # |R x_i + t - X_i| - l_i
    inv = leg_residuals(R, t, X_BASE, X_PLAT)  # |R X_i + t - x_i| - l_i
    orth = np.abs(np.einsum("kba,kbc->kac", R, R) - np.eye(3)).max() if len(R) else float("nan")
    dets = np.linalg.det(R) if len(R) else np.zeros(0)
    print("\n== one call (realOnly=0)")
    print(f"solutions returned: {total}; real (|imag| < {IMAG_TOL:g} in every entry of [R | t]): {real.sum()}; distinct real: {count_distinct(R, t)}")
    print(f"Rt shape {np.shape(Rt)}, dtype {np.asarray(Rt).dtype}; their err (algebraic): max {np.max(err):.3g}")
    if len(R):
        print(f"worst leg residual, convention R x_i + t = X_i (platform -> base): {fwd.max():.3e}  (median {np.median(fwd):.3e})")
        print(f"worst leg residual, convention R X_i + t = x_i (base -> platform): {inv.max():.3e}")
        conv = "R x + t (maps platform points into the base frame)" if fwd.max() < inv.max() else "R X + t (maps base points into the platform frame)"
        print(f"=> convention: {conv}")
        print(f"rotations: max |R^T R - I| {orth:.2e}, det in [{dets.min():.12f}, {dets.max():.12f}]")

    # Timing.
    for _ in range(ARGS.warmup):
        call_all()
    s_all = time_calls(call_all, ARGS.n)
    print(f"\n== timing, {ARGS.n} calls after {ARGS.warmup} warm-up calls (perf_counter, gc off)")
    q1, med, q3 = quartiles_ms(s_all)
    print(f"all modes (realOnly=0): median {med:.3f} ms, quartiles [{q1:.3f}, {q3:.3f}] ms, min {s_all.min()*1e3:.3f} ms, mean {s_all.mean()*1e3:.3f} ms")
    if call_real is not None:
        for _ in range(ARGS.warmup):
            call_real()
        s_real = time_calls(call_real, ARGS.n)
        q1, med, q3 = quartiles_ms(s_real)
        print(f"real only (realOnly=1): median {med:.3f} ms, quartiles [{q1:.3f}, {q3:.3f}] ms, min {s_real.min()*1e3:.3f} ms")

    # Robustness over repeated calls (fresh random rotations each time).
    counts, distinct, worst, totals = [], [], [], []
    for _ in range(ARGS.repeats):
        Rt, _err = call_all()
        total, real, R, t = analyse(Rt)
        totals.append(total)
        counts.append(int(real.sum()))
        distinct.append(count_distinct(R, t))
        worst.append(leg_residuals(R, t, X_PLAT, X_BASE).max() if len(R) else float("nan"))
    counts, distinct, worst = np.array(counts), np.array(distinct), np.array(worst)
    print(f"\n== {ARGS.repeats} repeated calls (realOnly=0)")
    print(f"solutions returned per call: {sorted(set(totals))}")
    hist = {int(c): int((counts == c).sum()) for c in np.unique(counts)}
    hist_d = {int(c): int((distinct == c).sum()) for c in np.unique(distinct)}
    print(f"real modes per call: {hist}  (count: calls)")
    print(f"distinct real modes per call: {hist_d}")
    print(f"calls with 40 distinct real modes: {(distinct == 40).sum()}/{ARGS.repeats}")
    print(f"worst leg residual per call: median {np.nanmedian(worst):.3e}, max {np.nanmax(worst):.3e}")
    tail = ", ".join(f"> {th:g}: {(worst > th).sum()}" for th in (1e-8, 1e-6, 1e-5, 1e-4, 1e-3))
    print(f"calls whose worst real mode has leg residual {tail} (of {ARGS.repeats}; raw solver output, no Newton polish)")


if __name__ == "__main__":
    main()
