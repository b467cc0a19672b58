"""Peer column: MuJoCo (pip `mujoco`) on the paper's 6-6 Stewart platform scenario -- the leg-1 upper-joint force error against symbody's h = 1e-4 s reference, and wall time, for a sweep of MuJoCo steps and solver settings, with symbody timed side by side in the same run. A manual benchmark, NOT run in CI.

Usage (from the repository root, after `cargo build --release --bin symbody`):

    python3 bench/peers/mujoco_stewart.py [--runs 3] [--quick] [--symbody target/release/symbody]
        [--csv bench/peers/mujoco_stewart.csv] [--md bench/peers/mujoco_stewart.md]

Needs `pip install mujoco numpy`. bench/peers/mujoco_stewart.md explains the model and the choices.

The model (docs/paper-scenario.md, kept in the paper's frames: MuJoCo's gravity is set to
(0, -9.81, 0), so Y is up and nothing is rotated or mapped back):
- the platform is a free body (1.79 kg, inertia diag(0.0326, 0.065, 0.0326) at its CoM, starting
  at (0, 0.3466575, 0), level);
- each leg is a lower cylinder hanging from the world at B_i by a ball joint, frame as symbody's
  `placement` (y from B_i to T_i, x the outward horizontal made perpendicular, z = x × y), CoM at
  (0, 0.125, 0); and an upper piston, child of the cylinder by a slide joint along local y, CoM at
  the piston's frame origin, its top T_i at (0, 0.125, 0);
- the loop is closed by an equality `connect` between site T_i on the platform (site1) and the
  piston top (site2);
- the driver is an equality `joint` on the slide (its coordinate is c_i(t) - c_i0, the distance of
  the two CoMs along the axis minus its initial value; c_i0 is the initial leg length minus 0.25 m,
  0.1500403058 m, as symbody's `initial`).

MuJoCo's equalities are soft: the solver returns f = (A + R)^-1 (a_ref - J a0) with
a_ref = -b J v - k imp r. A joint equality has no time argument, so a_ref lacks the driver's
velocity and acceleration. Setting polycoef[0] each step to
    c~(t) + (c~''(t) + b c~'(t)) / (k imp)        (c~ = c - c0; b, k, imp read from efc_KBIP)
makes a_ref exactly -b (v - c~') - k imp (q - c~) + c~'', the reference of the rheonomic constraint
q - c~(t) = 0 ("ff" driver). For RK4, whose stages run at t + h/2 and t + h inside mj_step, the same
terms are added to efc_aref of the driver rows from a control callback (called inside every stage
after a_ref is formed; "cb" driver). "naive" sets polycoef[0] = c~(t) only (what the MuJoCo docs'
joint equality gives directly).

Forces: the connect's efc_force rows are the force on body1 (the platform) at the anchor, in the
global frame (qfrc_constraint = J^T efc_force with J = d(p1 - p2)/dq); checked here by a static test.
They are read at each output state: for Euler/implicit from the mj_step that starts at that
output (its mj_forward is at exactly that state), for RK4 from an explicit mj_forward.
"""

import argparse
import os
import sys


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--runs", type=int, default=3, help="timed repetitions of every run (median reported; default 3)")
    p.add_argument("--quick", action="store_true", help="a few coarse runs only (smoke test)")
    p.add_argument("--symbody", default="target/release/symbody", help="symbody binary (default target/release/symbody)")
    p.add_argument("--csv", default="bench/peers/mujoco_stewart.csv", help="results CSV ('' to skip)")
    p.add_argument("--md", default="", help="also write the Markdown tables to this file")
    p.add_argument("--threads", default="1", help="BLAS threads for numpy's small solves (default 1)")
    return p.parse_args()


ARGS = parse_args()
if ARGS.threads != "default":
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "BLIS_NUM_THREADS"):
        os.environ[var] = ARGS.threads

import math  # noqa: E402
import platform as pyplatform  # noqa: E402
import re  # noqa: E402
import subprocess  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
import mujoco  # noqa: E402

# ---------------------------------------------------------------- the scenario (docs/paper-scenario.md)
R_BASE, R_PLAT, HALF, Y0 = 0.27, 0.105, 0.125, 0.3466575
PHI = [10.5, 109.5, 130.5, 229.5, 250.5, 349.5]
ALPHA = [49.5, 70.5, 169.5, 190.5, 289.5, 310.5]
AMP = np.array([0.02, -0.06, 0.02, -0.02, 0.08, -0.02])
M_PLAT, I_PLAT = 1.79, (0.0326, 0.065, 0.0326)
L_PART, M_CYL, R_CYL, M_PIS, R_PIS = 0.25, 0.30, 0.015, 0.20, 0.010
I_CYL = (M_CYL * (3 * R_CYL**2 + L_PART**2) / 12, M_CYL * R_CYL**2 / 2)  # (x = z, y)
I_PIS = (M_PIS * (3 * R_PIS**2 + L_PART**2) / 12, M_PIS * R_PIS**2 / 2)
G = 9.81
T_END = 2 * math.pi
OUT_DT = 0.04
N_OUT = int(T_END / OUT_DT + 1e-9)  # outputs at 0.04 k, k = 0..157 (<= 2π)
REF_STEP = 1e-4


def point(r, deg):
    a = math.radians(deg)
    return np.array([r * math.cos(a), 0.0, -r * math.sin(a)])


def f(x):
    return f"{float(x):.17g}"


BASE = [point(R_BASE, p) for p in PHI]
TOP_LOCAL = [point(R_PLAT, a) for a in ALPHA]
TOP0 = [t + np.array([0.0, Y0, 0.0]) for t in TOP_LOCAL]
# symbody's driver `initial`: the distance of the two CoMs at the initial pose.
C0 = [float(np.linalg.norm(t - b)) - 2 * HALF for b, t in zip(BASE, TOP0)]


def model_xml(h, integrator, solref, solimp, iterations=100, tolerance=1e-12):
    legs, eqs = [], []
    for i in range(6):
        b, t = BASE[i], TOP0[i]
        y = (t - b) / np.linalg.norm(t - b)
        mid = 0.5 * (b + t)
        horiz = np.array([mid[0], 0.0, mid[2]])
        x = horiz - y * horiz.dot(y)
        x /= np.linalg.norm(x)
        z = np.cross(x, y)
        q = np.zeros(4)
        mujoco.mju_mat2Quat(q, np.column_stack([x, y, z]).ravel())
        legs.append(f"""
    <body name="lower{i+1}" pos="{f(b[0])} {f(b[1])} {f(b[2])}" quat="{' '.join(f(v) for v in q)}">
      <joint name="ball{i+1}" type="ball"/>
      <inertial pos="0 {f(HALF)} 0" mass="{f(M_CYL)}" diaginertia="{f(I_CYL[0])} {f(I_CYL[1])} {f(I_CYL[0])}"/>
      <body name="upper{i+1}" pos="0 {f(HALF + C0[i])} 0">
        <joint name="slide{i+1}" type="slide" axis="0 1 0"/>
        <inertial pos="0 0 0" mass="{f(M_PIS)}" diaginertia="{f(I_PIS[0])} {f(I_PIS[1])} {f(I_PIS[0])}"/>
        <site name="top{i+1}" pos="0 {f(HALF)} 0"/>
      </body>
    </body>""")
        eqs.append(f'<connect name="upper_sph{i+1}" site1="T{i+1}" site2="top{i+1}" solref="{solref}" solimp="{solimp}"/>')
    for i in range(6):
        eqs.append(f'<joint name="act{i+1}" joint1="slide{i+1}" polycoef="0 0 0 0 0" solref="{solref}" solimp="{solimp}"/>')
    sites = "\n      ".join(f'<site name="T{i+1}" pos="{f(p[0])} 0 {f(p[2])}"/>' for i, p in enumerate(TOP_LOCAL))
    return f"""<mujoco model="stewart_6_6_paper_scenario">
  <option timestep="{f(h)}" gravity="0 {f(-G)} 0" integrator="{integrator}" solver="Newton"
          iterations="{iterations}" ls_iterations="50" tolerance="{f(tolerance)}">
    <flag contact="disable"/>
  </option>
  <worldbody>
    <body name="platform" pos="0 {f(Y0)} 0">
      <freejoint name="platform"/>
      <inertial pos="0 0 0" mass="{f(M_PLAT)}" diaginertia="{' '.join(f(v) for v in I_PLAT)}"/>
      {sites}
    </body>{''.join(legs)}
  </worldbody>
  <equality>
    {chr(10).join('    ' + e for e in eqs).strip()}
  </equality>
</mujoco>"""


# ---------------------------------------------------------------- one MuJoCo run
class Config:
    def __init__(self, integrator, driver, solref, solimp, label):
        self.integrator, self.driver, self.solref, self.solimp, self.label = integrator, driver, solref, solimp, label

    def solref_at(self, h):
        # "2h" / "4h": the time constant as a multiple of the step (2h is MuJoCo's refsafe minimum)
        tc, zeta = self.solref.split()
        if tc.endswith("h"):
            tc = f((float(tc[:-1]) if tc[:-1] else 1.0) * h)
        return f"{tc} {zeta}"


def dense_J(m, d):
    if mujoco.mj_isSparse(m):
        J = np.zeros((d.nefc, m.nv))
        mujoco.mju_sparse2dense(J, d.efc_J, d.efc_J_rownnz, d.efc_J_rowadr, d.efc_J_colind)
        return J
    return d.efc_J.reshape(d.nefc, m.nv).copy()


class Run:
    """A compiled model with its driver bookkeeping."""

    def __init__(self, cfg, h):
        self.cfg, self.h = cfg, h
        t0 = time.perf_counter()
        self.m = mujoco.MjModel.from_xml_string(model_xml(h, cfg.integrator, cfg.solref_at(h), cfg.solimp))
        self.compile_s = time.perf_counter() - t0
        self.d = mujoco.MjData(self.m)
        m, d = self.m, self.d
        mujoco.mj_forward(m, d)
        assert d.nefc == 24 and m.nv == 30, (d.nefc, m.nv)
        self.eq_drv = np.array([m.equality(f"act{i+1}").id for i in range(6)])
        self.rows_drv = np.array([r for r in range(d.nefc) if d.efc_id[r] in set(self.eq_drv)])
        leg1 = m.equality("upper_sph1").id
        self.rows_leg1 = np.array([r for r in range(d.nefc) if d.efc_id[r] == leg1])
        assert len(self.rows_leg1) == 3 and len(self.rows_drv) == 6
        kbip = d.efc_KBIP[self.rows_drv]
        self.b, self.kimp = kbip[:, 1].copy(), (kbip[:, 0] * kbip[:, 2]).copy()
        if np.any(kbip[:, 3] != 0):
            sys.exit("impedance varies with the violation: give a flat solimp (d0 = dwidth)")

    def driver_data(self, t):
        """polycoef[0] of the six driver equalities at time t."""
        s, c = math.sin(t), math.cos(t)
        if self.cfg.driver == "ff":
            return AMP * s + AMP * (self.b * c - s) / self.kimp
        if self.cfg.driver == "cb":
            return np.zeros(6)  # the control callback adds the whole driver reference to efc_aref
        return AMP * s  # naive

    def kinematic_state(self, t):
        """Exact pose at time t (Newton on the 24 constraint residuals), least-kinetic-energy velocity with c~'(t)."""
        m, d = self.m, self.d
        mujoco.mj_resetData(m, d)
        d.time = t
        m.eq_data[self.eq_drv, 0] = AMP * math.sin(t)
        cb = mujoco.get_mjcb_control()
        mujoco.set_mjcb_control(None)
        try:
            for _ in range(50):
                mujoco.mj_forward(m, d)
                r = d.efc_pos.copy()
                if np.abs(r).max() < 1e-15:
                    break
                J = dense_J(m, d)
                dq = -J.T @ np.linalg.solve(J @ J.T, r)
                mujoco.mj_integratePos(m, d.qpos, dq, 1.0)
            else:
                raise RuntimeError(f"kinematics did not converge at t = {t}: {np.abs(r).max():.2e}")
            M = np.zeros((m.nv, m.nv))
            mujoco.mj_fullM(m, d, M)
            J = dense_J(m, d)
            w = np.zeros(d.nefc)
            w[self.rows_drv] = AMP * math.cos(t)
            n = m.nv
            K = np.block([[M, J.T], [J, np.zeros((d.nefc, d.nefc))]])
            d.qvel[:] = np.linalg.solve(K, np.concatenate([np.zeros(n), w]))[:n]
            mujoco.mj_forward(m, d)
        finally:
            mujoco.set_mjcb_control(cb)

    def simulate(self, preroll):
        """Whole scenario; returns (wall seconds, forces (N_OUT+1, 3), steps)."""
        m, d, h = self.m, self.d, self.h
        cfg = self.cfg
        per = int(round(OUT_DT / h))
        assert abs(per * h - OUT_DT) < 1e-12, (h, per)
        eqd = m.eq_data
        drv, rows_drv, rows_leg1 = self.eq_drv, self.rows_drv, self.rows_leg1
        b, kimp = self.b, self.kimp
        F = np.zeros((N_OUT + 1, 3))
        if cfg.driver == "cb":
            def control(m_, d_):
                t = d_.time
                s, c = math.sin(t), math.cos(t)
                d_.efc_aref[rows_drv] += AMP * (b * c - s) + kimp * AMP * s
            mujoco.set_mjcb_control(control)
        try:
            start = time.perf_counter()
            n0 = -preroll
            self.kinematic_state(n0 * h)
            data = self.driver_data
            n = n0
            # pre-roll: from the exact state at t = -preroll·h up to t = 0, so that the soft
            # constraints have settled into their deflection when the first output is taken
            while n < 0:
                d.time = n * h
                eqd[drv, 0] = data(n * h)
                mujoco.mj_step(m, d)
                n += 1
            read_after_step = cfg.integrator != "RK4"
            for k in range(N_OUT + 1):
                t = n * h
                if read_after_step and k < N_OUT:
                    # mj_step's own mj_forward is at exactly this output state
                    for j in range(per):
                        d.time = n * h
                        eqd[drv, 0] = data(n * h)
                        mujoco.mj_step(m, d)
                        n += 1
                        if j == 0:
                            F[k] = d.efc_force[rows_leg1]
                else:
                    d.time = t
                    eqd[drv, 0] = data(t)
                    mujoco.mj_forward(m, d)
                    F[k] = d.efc_force[rows_leg1]
                    if k < N_OUT:
                        for _ in range(per):
                            d.time = n * h
                            eqd[drv, 0] = data(n * h)
                            mujoco.mj_step(m, d)
                            n += 1
            wall = time.perf_counter() - start
        finally:
            mujoco.set_mjcb_control(None)
        return wall, F, n - n0


# ---------------------------------------------------------------- checks
def static_test():
    """Frozen drivers at t = 0, zero velocity: each upper joint carries m g / 6 vertically."""
    cfg = Config("Euler", "ff", "2h 1", "0.9999 0.9999 0.001 0.5 2", "static")
    r = Run(cfg, 1e-4)
    m, d = r.m, r.d
    mujoco.mj_resetData(m, d)
    mujoco.mj_forward(m, d)
    rows = [[rr for rr in range(d.nefc) if d.efc_id[rr] == m.equality(f"upper_sph{i+1}").id] for i in range(6)]
    cold = np.array([d.efc_force[rw] for rw in rows])
    # let the soft constraints settle (frozen drivers, 0.2 s at 1e-4 s): a static equilibrium
    for _ in range(2000):
        mujoco.mj_step(m, d)
    mujoco.mj_forward(m, d)
    settled = np.array([d.efc_force[rw] for rw in rows])
    expect = M_PLAT * G / 6
    return expect, cold, settled, float(np.abs(d.qvel).max())


def run_symbody(binary, h, out_dir):
    cmd = [binary, "simulate", "--step", repr(h), "--output-step", repr(OUT_DT), "--no-plots", "--out", out_dir]
    p = subprocess.run(cmd, check=True, capture_output=True, text=True)
    wall = re.search(r"wall time\s+([0-9.]+) ms", p.stdout)
    if not wall:
        sys.exit(f"no `wall time` line in symbody's output:\n{p.stdout}")
    steps = re.search(r"steps\s+([0-9]+) accepted", p.stdout)
    raw = np.loadtxt(os.path.join(out_dir, "joint_forces.csv"), delimiter=",", skiprows=1)
    return float(wall.group(1)) / 1e3, raw[:, 0], raw[:, 1:4], int(steps.group(1)) if steps else -1


def fmt_e(x):
    return f"{x:.1e}" if np.isfinite(x) else "diverged"


def main():
    runs = max(1, ARGS.runs)
    tmp = tempfile.mkdtemp(prefix="mujoco_stewart_")
    print(f"MuJoCo {mujoco.__version__}, numpy {np.__version__}, Python {pyplatform.python_version()}, "
          f"{pyplatform.machine()} {pyplatform.processor() or ''}".strip(), flush=True)

    # reference: symbody at h = 1e-4 s (its own error vs h/2 and 2h is <= 1.3e-8 N, BENCHMARKS.md)
    ref_dir = os.path.join(tmp, "ref")
    _, t_ref, F_ref, _ = run_symbody(ARGS.symbody, REF_STEP, ref_dir)
    t_ref, F_ref = t_ref[: N_OUT + 1], F_ref[: N_OUT + 1]
    assert np.allclose(t_ref, OUT_DT * np.arange(N_OUT + 1), atol=1e-9), "reference output times"
    print(f"reference: symbody simulate --step {REF_STEP:g} --output-step {OUT_DT}; "
          f"leg-1 force at t=0 {F_ref[0]}", flush=True)

    expect, cold, settled, vmax = static_test()
    print(f"static test (frozen drivers, t=0, v=0): m g/6 = {expect:.6f} N; F_y on the platform, legs 1..6:\n"
          f"  at the exact pose     {np.array2string(cold[:, 1], precision=6)} (sum {cold[:, 1].sum():.6f} of {M_PLAT * G:.6f})\n"
          f"  settled (0.2 s)       {np.array2string(settled[:, 1], precision=9)} max |F_y - m g/6| "
          f"{np.abs(settled[:, 1] - expect).max():.1e} (max |v| {vmax:.1e})\n"
          f"  leg 1 settled F = {settled[0]}", flush=True)

    rows = []  # dicts

    # symbody in the same run: timed before and after the MuJoCo sweep (the machine is shared),
    # the median over both batches reported
    sym_steps = [2e-2, 1e-2] if ARGS.quick else [2e-2, 1e-2, 5e-3, 2e-3, 1e-3]
    sym = {h: dict(walls=[], err=None, steps=-1) for h in sym_steps}

    def time_symbody(batch):
        for h in sym_steps:
            for _ in range(runs):
                w, t, F, n = run_symbody(ARGS.symbody, h, os.path.join(tmp, f"sym_{h:g}"))
                sym[h]["walls"].append(w)
            sym[h]["err"], sym[h]["steps"] = np.abs(F[: N_OUT + 1] - F_ref).max(axis=1), n
            print(f"symbody h={h:g} ({batch}): walls {[round(w * 1e3, 1) for w in sym[h]['walls'][-runs:]]} ms, "
                  f"err {sym[h]['err'].max():.2e} N", flush=True)

    loads = [os.getloadavg()[0]]
    time_symbody("before MuJoCo")

    best = Config("Euler", "ff", "2h 1", "0.9999 0.9999 0.001 0.5 2", "A: Euler, τ=2h, ζ=1, d=0.9999")
    configs = [
        (best, [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5]),
        (Config("Euler", "ff", "2h 0.5", "0.9999 0.9999 0.001 0.5 2", "B: Euler, τ=2h, ζ=0.5, d=0.9999"),
         [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5]),
        (Config("implicitfast", "ff", "2h 1", "0.9999 0.9999 0.001 0.5 2", "C: implicitfast, τ=2h, ζ=1, d=0.9999"),
         [1e-2, 1e-3, 1e-4, 1e-5]),
        (Config("RK4", "cb", "4h 1", "0.9999 0.9999 0.001 0.5 2", "D: RK4, τ=4h, ζ=1, d=0.9999"),
         [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4]),
        (Config("RK4", "cb", "0.002 0.5", "0.9999 0.9999 0.001 0.5 2", "E: RK4, τ=2 ms, ζ=0.5, d=0.9999"),
         [1e-3, 5e-4, 2e-4, 1e-4]),
        (Config("Euler", "ff", "2h 1", "0.999 0.999 0.001 0.5 2", "F: Euler, τ=2h, ζ=1, d=0.999"),
         [1e-3, 1e-4, 1e-5]),
        (Config("Euler", "naive", "0.02 1", "0.9 0.95 0.001 0.5 2", "G: MuJoCo defaults (Euler, solref 0.02 1, solimp 0.9 0.95), naive driver"),
         [2e-3]),
    ]
    if ARGS.quick:
        configs = [(best, [1e-2, 1e-3]), (configs[3][0], [1e-2])]
    for cfg, steps in configs:
        for h in steps:
            r = Run(cfg, h)
            tc = float(cfg.solref_at(h).split()[0])
            preroll = int(math.ceil(20 * tc / h)) if cfg.driver != "naive" else 0
            walls, F, nsteps = [], None, 0
            for _ in range(runs):
                w, F, nsteps = r.simulate(preroll)
                walls.append(w)
            walls.sort()
            with np.errstate(invalid="ignore"):
                err = np.abs(F - F_ref).max(axis=1)
            err = np.where(np.isfinite(err), err, np.inf)
            row = dict(engine=f"MuJoCo {mujoco.__version__}", integrator=cfg.integrator, driver=cfg.driver,
                       solref=cfg.solref_at(h), solimp=cfg.solimp, h=h, steps=nsteps, preroll=preroll,
                       wall=walls[len(walls) // 2], walls=walls, err=err.max(), err_t0=err[0], err_rest=err[1:].max(),
                       label=cfg.label, compile=r.compile_s)
            rows.append(row)
            print(f"{cfg.label} h={h:g}: wall {row['wall']*1e3:.1f} ms ({nsteps} steps, pre-roll {preroll}), "
                  f"err {fmt_e(row['err'])} N (t=0: {fmt_e(row['err_t0'])})", flush=True)

    time_symbody("after MuJoCo")
    loads.append(os.getloadavg()[0])
    for h in sym_steps:
        walls, err = sorted(sym[h]["walls"]), sym[h]["err"]
        rows.insert(sym_steps.index(h), dict(
            engine="symbody", integrator="HHT-α (α=-0.05)", driver="exact (index-3 DAE)", solref="-", solimp="-",
            h=h, steps=sym[h]["steps"], preroll=0, wall=float(np.median(walls)), walls=walls, err=err.max(),
            err_t0=err[0], err_rest=err[1:].max(), label="symbody (HHT-α, α = −0.05, recovered forces)"))
    print(f"1-minute load average at start / end: {loads[0]:.2f} / {loads[1]:.2f}", flush=True)

    # MuJoCo's engine alone, no Python in the loop (frozen drivers, best config, h = 1e-4)
    r = Run(best, 1e-4)
    mujoco.mj_forward(r.m, r.d)
    nstep = 20000
    t0 = time.perf_counter()
    mujoco.mj_step(r.m, r.d, nstep=nstep)
    engine_us = (time.perf_counter() - t0) / nstep * 1e6
    print(f"MuJoCo engine alone (mj_step(m, d, nstep={nstep}), Euler, h=1e-4): {engine_us:.2f} µs/step", flush=True)

    write(rows, engine_us, expect, cold, settled, loads)


def cheapest(rows, target, engine):
    ok = [r for r in rows if r["engine"].startswith(engine) and r["err"] <= target]
    return min(ok, key=lambda r: r["wall"]) if ok else None


def write(rows, engine_us, expect, cold, settled, loads):
    if ARGS.csv:
        with open(ARGS.csv, "w") as fh:
            fh.write("engine,config,integrator,driver,solref,solimp,h,steps,preroll_steps,wall_median_ms,walls_ms,"
                     "err_leg1_N,err_t0_N,err_after_t0_N\n")
            for r in rows:
                fh.write(",".join([r["engine"], '"' + r["label"] + '"', r["integrator"], r["driver"], r["solref"],
                                   r["solimp"], f"{r['h']:g}", str(r["steps"]), str(r["preroll"]),
                                   f"{r['wall']*1e3:.2f}", " ".join(f"{w*1e3:.2f}" for w in r["walls"]),
                                   f"{r['err']:.3e}", f"{r['err_t0']:.3e}", f"{r['err_rest']:.3e}"]) + "\n")
        print(f"wrote {ARGS.csv}")
    lines = ["| engine / settings | h (s) | steps | wall (ms) | leg-1 force err (N) | err at t=0 (N) |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['label']} | {r['h']:g} | {r['steps']} | {r['wall']*1e3:.1f} | {fmt_e(r['err'])} | "
                     f"{fmt_e(r['err_t0'])} |")
    lines += ["", "| target (N) | MuJoCo: cheapest run reaching it | wall (ms) | symbody: cheapest run | wall (ms) | MuJoCo / symbody |",
              "|---|---|---|---|---|---|"]
    mj_rows = [r for r in rows if r["engine"].startswith("MuJoCo")]
    for target in (1e-4, 1e-5, 1e-6):
        mj, sy = cheapest(rows, target, "MuJoCo"), cheapest(rows, target, "symbody")
        if mj:
            mjs = f"{mj['label']}, h = {mj['h']:g} (err {mj['err']:.1e})"
            mjw = f"{mj['wall']*1e3:.1f}"
        else:
            b = min(mj_rows, key=lambda r: r["err"])
            mjs = f"not reached; best {b['err']:.1e} ({b['label']}, h = {b['h']:g})"
            mjw = "-"
        sys_ = f"h = {sy['h']:g} (err {sy['err']:.1e})" if sy else "not in this sweep"
        syw = f"{sy['wall']*1e3:.1f}" if sy else "-"
        ratio = f"{mj['wall'] / sy['wall']:.1f}×" if mj and sy else "-"
        lines.append(f"| {target:.0e} | {mjs} | {mjw} | {sys_} | {syw} | {ratio} |")
    lines += ["", f"MuJoCo {mujoco.__version__}; symbody walls: median of {2 * max(1, ARGS.runs)} runs "
              f"(half before, half after the MuJoCo sweep); 1-minute load average {loads[0]:.2f} at start, "
              f"{loads[1]:.2f} at end (2 cores, shared).",
              f"MuJoCo's engine alone (`mj_step(m, d, nstep=20000)`, config A, h = 1e-4): {engine_us:.2f} µs/step.",
              f"Static test: m g/6 = {expect:.6f} N; MuJoCo F_y at the exact pose {cold[0, 1]:.6f} N "
              f"(soft constraints: sum {cold[:, 1].sum():.4f} of {M_PLAT * G:.4f} N), "
              f"after settling {settled[0, 1]:.9f} N (max |F_y − m g/6| over the legs "
              f"{np.abs(settled[:, 1] - expect).max():.1e} N)."]
    text = "\n".join(lines)
    print(text)
    if ARGS.md:
        with open(ARGS.md, "w") as fh:
            fh.write(text + "\n")
        print(f"wrote {ARGS.md}")


if __name__ == "__main__":
    main()
