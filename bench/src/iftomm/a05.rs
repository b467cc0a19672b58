//! Benchmark A05, the stiff flyball governor: the generated `flyball_governor` mechanism
//! against a hand-derived minimal-coordinate model integrated with classical RK4.
//!
//! The reference shares nothing with symbody's generator: four coordinates (the shaft's
//! speed ω — its angle never enters —, the slider height s and the two rod angles θᵢ from the
//! downward vertical), Lagrange's equations written out below, and a fixed-step RK4 far
//! below its stability limit. In the frame turning with the shaft every point of interest
//! stays in one plane, which is what keeps the equations short:
//!
//! - kinetic energy ½(I₀ + A(θ₁) + A(θ₂))ω² + ½ m_s ṡ² + ½ J (θ̇₁² + θ̇₂²), with
//!   A(θ) = I_ax cos²θ + I_tr sin²θ + m_b (a + L/2 sinθ)² + m_p (a + L sinθ)² the rod's (and
//!   its ball's) moment of inertia about the shaft, J = I_tr + m_b L²/4 + m_p L² about the
//!   hinge, I₀ the shaft's and the slider's axial inertias;
//! - gravity m_s g s − g (m_b L/2 + m_p L) cosθᵢ;
//! - spring i from the slider point (±a, s) to the rod midpoint
//!   (±(a + L/2 sinθᵢ), L − L/2 cosθᵢ): both ends turn with the shaft, so the spring's rate
//!   ḋ has no ω part and its force enters only the θᵢ and s equations.
//!
//! The shaft is free, so ω changes as the balls move (angular momentum is conserved).

use super::Error;
use super::{integrate, point, Outcome, Problem, Published, Settings, Spec};

const MECHANISM: &str = "flyball_governor";

/// Outputs per second of simulated time: the error is measured at these instants.
const OUTPUTS_PER_SECOND: f64 = 100.0;

/// HHT step and α of the timed run. The damped mode (|λ| ≈ 7e3 1/s) is resolved by the
/// springs' stiffness and damping in the Newton matrix (`HhtBuilder::load_stiffness`, on by
/// default), so the step follows the motion: the error falls as h² with α = 0 (2.0e-6 at
/// h = 2.5e-4, 4.9e-6 at 4e-4, 7.7e-6 at 5e-4; BENCHMARKS.md), and 4e-4 leaves half the
/// tolerance. Without the loads in the matrix, Newton needed h ≤ 1.25e-4 s and α = −0.2,
/// and α = 0 stopped between t = 3.4 and 4.6 s at every step tried.
const SETTINGS: Settings = Settings {
    step: 4.0e-4,
    alpha: 0.0,
    tolerances: None,
    reuse_factorization: false,
    planar: false,
};

/// RK4 step of the reference. The slider's damped mode has |λ| ≈ 2C(∂d/∂s)²/m_s ≈ 7e3 1/s,
/// so RK4 (stable for h|λ| < 2.78) needs h < 4e-4 s; 1e-5 s is far inside and halving it
/// changes s by less than 1e-12 m.
const REFERENCE_STEP: f64 = 1.0e-5;

pub static PROBLEM: Problem = Problem {
    spec: Spec {
        id: "A05",
        title: "Stiff flyball governor",
        mechanism: MECHANISM,
        t_end: 10.0,
        short_t_end: 1.0,
        measure: "max |s − s_ref| over outputs every 0.01 s (m), s the slider's height above \
                  the shaft's foot",
        tolerance: 1.0e-5,
        caveat: "the UDC page's length, tolerance and output steps were not found: 10 s is the ports' length, the tolerance and output spacing are ours",
        reference: "a hand-derived Lagrange model in the 4 minimal coordinates (shaft speed, \
                    slider height, two rod angles), integrated with classical RK4 at 1e-5 s \
                    (converged to 1e-12 m by halving); it shares no code or equations with \
                    the generated mechanism",
        source: "M. González et al., University of A Coruña, IFToMM multibody benchmark A05, \
                 http://lim.ii.udc.es/mbsbenchmark/dist/A05/A05_specification.xml (2005); \
                 geometry as in the OpenSim port, github.com/RehabEngGroup/\
                 MBSbenchmarksInOpenSim (src/A05-FlyballGovernor). The stored copy of the \
                 XML ends before its analysis section, so t_end, output rate and tolerance \
                 are ours",
        published: &[Published {
            code: "OpenSim 3.2, CPodes BDF (10 s run)",
            cpu_seconds: 0.233,
            machine: "Intel Core i5-4570 @ 3.2 GHz, Windows 8.1 64-bit",
            source: "rehabenggroup.github.io/MBSbenchmarksInOpenSim, A05_FlyballGovernor.html",
        }],
    },
    settings: SETTINGS,
    run,
};

fn run(t_end: f64, settings: Settings) -> Result<Outcome, Error> {
    let outputs = (t_end * OUTPUTS_PER_SECOND).round().max(1.0) as usize;
    let mut s = Vec::with_capacity(outputs + 1);
    let (cpu, stats) = integrate(MECHANISM, settings, t_end, outputs, |_, q, _| {
        s.push(point(MECHANISM, "slider", [0.0; 3], q)?[2]);
        Ok(())
    })?;
    let s_ref = reference_s(t_end, outputs, REFERENCE_STEP);
    let error = s
        .iter()
        .zip(&s_ref)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    Ok(Outcome {
        t_end,
        error,
        cpu,
        stats,
        step: settings.step,
        alpha: settings.alpha,
    })
}

/// The benchmark's data (SI), written out again rather than read from the mechanism file so
/// that a mistake in one shows up as a difference.
mod data {
    pub const G: f64 = 9.81;
    pub const L: f64 = 1.0;
    const W: f64 = 0.01;
    const RHO: f64 = 3000.0;
    const CUBE: f64 = 0.1;
    pub const A: f64 = 0.05;
    pub const MB: f64 = RHO * L * W * W;
    pub const MS: f64 = RHO * CUBE * CUBE * CUBE;
    pub const MP: f64 = 5.0;
    pub const K: f64 = 8.0e5;
    pub const C: f64 = 4.0e4;
    pub const L0: f64 = 0.5;
    pub const S0: f64 = 0.5;
    /// Rod (or shaft) about its own axis, and about a transverse axis through its centre.
    pub const I_AX: f64 = MB * (W * W + W * W) / 12.0;
    pub const I_TR: f64 = MB * (L * L + W * W) / 12.0;
    /// Shaft and slider about the shaft's axis.
    pub const I0: f64 = I_AX + MS * (CUBE * CUBE + CUBE * CUBE) / 12.0;
    /// Rod and ball about the hinge.
    pub const J: f64 = I_TR + MB * L * L / 4.0 + MP * L * L;
}

/// State of the reference: [s, θ₁, θ₂, ω, ṡ, θ̇₁, θ̇₂].
type State = [f64; 7];

/// A(θ) and dA/dθ: a rod with its ball about the shaft's axis.
fn axial_inertia(th: f64) -> (f64, f64) {
    use data::*;
    let (sn, cs) = th.sin_cos();
    let rc = A + 0.5 * L * sn;
    let rb = A + L * sn;
    let a = I_AX * cs * cs + I_TR * sn * sn + MB * rc * rc + MP * rb * rb;
    let da = 2.0 * (I_TR - I_AX) * sn * cs + MB * rc * L * cs + 2.0 * MP * rb * L * cs;
    (a, da)
}

/// Generalized forces of one spring–damper on its rod angle and on s.
fn spring(th: f64, thd: f64, s: f64, sd: f64) -> (f64, f64) {
    use data::*;
    let (sn, cs) = th.sin_cos();
    let dx = 0.5 * L * sn;
    let dz = L - 0.5 * L * cs - s;
    let d = dx.hypot(dz);
    let dd_th = 0.5 * L * (dx * cs + dz * sn) / d;
    let dd_s = -dz / d;
    let tension = K * (d - L0) + C * (dd_th * thd + dd_s * sd);
    (-tension * dd_th, -tension * dd_s)
}

fn rate(y: &State) -> State {
    use data::*;
    let [s, th1, th2, w, sd, thd1, thd2] = *y;
    let (a1, da1) = axial_inertia(th1);
    let (a2, da2) = axial_inertia(th2);
    let (q1, qs1) = spring(th1, thd1, s, sd);
    let (q2, qs2) = spring(th2, thd2, s, sd);
    let moment = G * (0.5 * MB * L + MP * L);
    let wd = -(da1 * thd1 + da2 * thd2) * w / (I0 + a1 + a2);
    let thdd1 = (0.5 * da1 * w * w - moment * th1.sin() + q1) / J;
    let thdd2 = (0.5 * da2 * w * w - moment * th2.sin() + q2) / J;
    let sdd = (qs1 + qs2) / MS - G;
    [sd, thd1, thd2, wd, sdd, thdd1, thdd2]
}

fn rk4_step(y: &mut State, h: f64) {
    let shifted = |k: &State, f: f64| {
        let mut z = *y;
        z.iter_mut().zip(k).for_each(|(z, k)| *z += f * k);
        z
    };
    let k1 = rate(y);
    let k2 = rate(&shifted(&k1, 0.5 * h));
    let k3 = rate(&shifted(&k2, 0.5 * h));
    let k4 = rate(&shifted(&k3, h));
    for (i, y) in y.iter_mut().enumerate() {
        *y += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}

/// s at `outputs + 1` equally spaced times from 0 to `t_end`, RK4 at about `h`.
fn reference_s(t_end: f64, outputs: usize, h: f64) -> Vec<f64> {
    let dt = t_end / outputs as f64;
    let substeps = (dt / h).ceil().max(1.0) as usize;
    let h = dt / substeps as f64;
    let th0 = std::f64::consts::FRAC_PI_2 - 30f64.to_radians();
    let mut y: State = [
        data::S0,
        th0,
        th0,
        2.0 * std::f64::consts::PI,
        0.0,
        0.0,
        0.0,
    ];
    let mut s = Vec::with_capacity(outputs + 1);
    s.push(y[0]);
    for _ in 0..outputs {
        for _ in 0..substeps {
            rk4_step(&mut y, h);
        }
        s.push(y[0]);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Halving the reference step changes s by round-off only.
    #[test]
    fn reference_converges() {
        let coarse = reference_s(1.0, 100, 2.0 * REFERENCE_STEP);
        let fine = reference_s(1.0, 100, REFERENCE_STEP);
        let diff = coarse
            .iter()
            .zip(&fine)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            diff < 1e-11,
            "reference moved by {diff:e} m on halving its step"
        );
    }
}
