//! The IFToMM multibody benchmark problems A01–A05 (the University of A Coruña library, the
//! IFToMM Technical Committee's benchmark set): each problem's published definition, its
//! published error measure against an independent reference, and a timed run.
//!
//! Each problem is one file (`a01.rs` … `a05.rs`) holding a [`Problem`]: the published
//! specification ([`Spec`], with its source), and a `run` that integrates the generated
//! mechanism to a given end time and measures the published error. `cargo run --release
//! --bin mbs_benchmarks` runs every problem to its published end time; `tests/iftomm.rs`
//! runs each one shortened.

use std::time::{Duration, Instant};

use nalgebra::Vector3;
use symbody_runtime::kinematics::kinetic_energy;
use symbody_runtime::{pose, BodyInfo, HhtBuilder, Mechanism, Stats};

pub use symbody::scenario::ScenarioError as Error;

pub mod a01;
pub mod a02;
pub mod a03;
pub mod a04;
pub mod a05;

/// A CPU time another code published for the same problem.
#[derive(Debug, Clone, Copy)]
pub struct Published {
    /// The code and its method, as published.
    pub code: &'static str,
    /// CPU time for the whole published run (s).
    pub cpu_seconds: f64,
    /// The machine it was measured on, as published.
    pub machine: &'static str,
    /// Where it was published.
    pub source: &'static str,
}

/// A problem's published definition.
#[derive(Debug, Clone, Copy)]
pub struct Spec {
    /// `"A01"` … `"A05"`.
    pub id: &'static str,
    pub title: &'static str,
    /// The generated mechanism's registry name (`mechanisms/<name>.toml`).
    pub mechanism: &'static str,
    /// Published simulation length (s).
    pub t_end: f64,
    /// Shortened length the CI test runs (s).
    pub short_t_end: f64,
    /// The published error measure, in words.
    pub measure: &'static str,
    /// The tolerance on that measure: the published "high precision" one where it was found.
    pub tolerance: f64,
    /// What of the definition is not the published one (empty when all of it is), and why.
    pub caveat: &'static str,
    /// What the error is measured against, and why that reference is independent of symbody.
    pub reference: &'static str,
    /// Where the definition was published.
    pub source: &'static str,
    /// CPU times other codes published for the full run.
    pub published: &'static [Published],
}

/// One measured run.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// End time reached (s).
    pub t_end: f64,
    /// The published error measure.
    pub error: f64,
    /// Wall time of the integration alone (reference and measuring excluded).
    pub cpu: Duration,
    /// Integrator statistics.
    pub stats: Stats,
    /// Integration step (s) and HHT α used.
    pub step: f64,
    pub alpha: f64,
}

impl Outcome {
    /// Whether the error meets the tolerance.
    pub fn passed(&self, spec: &Spec) -> bool {
        self.error <= spec.tolerance
    }
}

/// A benchmark problem: its definition and how to run it.
pub struct Problem {
    pub spec: Spec,
    /// The integration settings the problem is benchmarked with (why: in its file).
    pub settings: Settings,
    /// Runs the problem from its published initial state to `t_end` (s) with `settings`
    /// (the problem's own, or others for a work-precision sweep).
    pub run: fn(t_end: f64, settings: Settings) -> Result<Outcome, Error>,
}

/// Every problem, in order.
pub fn problems() -> [&'static Problem; 6] {
    [
        &a01::PROBLEM,
        &a02::PROBLEM_2,
        &a02::PROBLEM_40,
        &a03::PROBLEM,
        &a04::PROBLEM,
        &a05::PROBLEM,
    ]
}

/// Integration settings of one run.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    /// The step; with `tolerances`, the first step tried.
    pub step: f64,
    pub alpha: f64,
    /// Step-size control `(rtol, atol)` (`HhtBuilder::tolerances`); `None`: fixed step.
    pub tolerances: Option<(f64, f64)>,
    /// Keep Newton's factorization across steps (`HhtBuilder::reuse_factorization`).
    pub reuse_factorization: bool,
    /// Integrate the mechanism's planar model (x, y, γ per body; its file says
    /// `planar = true`) instead of the spatial one; outputs are read on the spatial model.
    pub planar: bool,
}

impl Settings {
    /// The integrator settings every problem shares: these, with velocities projected
    /// onto the constraints after every step (as `symbody simulate <name>` does), which
    /// keeps α = 0 stable.
    pub fn builder(&self) -> HhtBuilder {
        let builder = HhtBuilder::new()
            .step(self.step)
            .alpha(self.alpha)
            .project_velocities(true)
            .reuse_factorization(self.reuse_factorization);
        match self.tolerances {
            Some((rtol, atol)) => builder.tolerances(rtol, atol),
            None => builder,
        }
    }
}

/// Integrates the registered mechanism `name` with HHT from its file's initial state to
/// `t_end`, calling `sample(t, q, qd)` at `outputs + 1` equally spaced times (including 0
/// and `t_end`); the first error `sample` returns ends the run. Velocities are projected
/// onto the constraints after every step (as `symbody simulate <name>` does), which keeps
/// α = 0 stable. Returns the wall time of the integration (sampling excluded) and the
/// statistics.
pub fn integrate(
    name: &str,
    settings: Settings,
    t_end: f64,
    outputs: usize,
    sample: impl FnMut(f64, &[f64], &[f64]) -> Result<(), Error>,
) -> Result<(Duration, Stats), Error> {
    integrate_with(
        name,
        settings.builder(),
        settings.planar,
        t_end,
        outputs,
        sample,
    )
}

/// As [`integrate`], with every integrator setting given.
pub fn integrate_with(
    name: &str,
    builder: HhtBuilder,
    planar: bool,
    t_end: f64,
    outputs: usize,
    mut sample: impl FnMut(f64, &[f64], &[f64]) -> Result<(), Error>,
) -> Result<(Duration, Stats), Error> {
    let entry = symbody::generic::find(&crate::REGISTRY, name)?;
    let spatial = entry.default_mechanism();
    let (mech, reduction) = match planar {
        false => (spatial, None),
        true => {
            let (m, r) = entry.reduced(entry.formulations[0].0).ok_or_else(|| {
                Error::Options(format!("`{name}` has no planar model (`planar = true`)"))
            })?;
            (m, Some(r))
        }
    };
    let n = spatial.info().n_coords;
    let (mut q, mut qd) = (vec![0.0; n], vec![0.0; n]);
    let mut sample = |t: f64, qr: &[f64], qdr: &[f64]| match reduction {
        None => sample(t, qr, qdr),
        Some(r) => {
            r.expand(qr, t, 0, &mut q)?;
            r.expand(qdr, t, 1, &mut qd)?;
            sample(t, &q, &qd)
        }
    };
    let start = Instant::now();
    let mut it = builder.build(mech)?;
    let mut cpu = start.elapsed();
    sample(it.t(), it.q(), it.qd())?;
    for k in 1..=outputs {
        let t_out = t_end * k as f64 / outputs as f64;
        let start = Instant::now();
        it.advance_to(t_out)?;
        cpu += start.elapsed();
        sample(it.t(), it.q(), it.qd())?;
    }
    Ok((cpu, it.stats()))
}

/// The default formulation of mechanism `name` and the description of its body `body`.
fn body(
    name: &str,
    body: &str,
) -> Result<(&'static (dyn Mechanism + Sync), &'static BodyInfo), Error> {
    let mech = symbody::generic::find(&crate::REGISTRY, name)?.default_mechanism();
    let info = mech.info();
    let b = info
        .body_index(body)
        .ok_or_else(|| Error::Options(format!("`{name}` has no body `{body}`")))?;
    Ok((mech, &info.bodies[b]))
}

/// World position of `local` (body coordinates) on body `body` of mechanism `name` at `q`.
pub fn point(name: &str, body: &str, local: [f64; 3], q: &[f64]) -> Result<[f64; 3], Error> {
    let (_, body) = self::body(name, body)?;
    let p = pose::point_world(Some(body), q, &local)?;
    Ok([p.x, p.y, p.z])
}

/// World velocity of `local` on body `body` of mechanism `name` at `(q, qd)`: ṙ + ω × A·s.
pub fn point_velocity(
    name: &str,
    body: &str,
    local: [f64; 3],
    q: &[f64],
    qd: &[f64],
) -> Result<[f64; 3], Error> {
    let (_, body) = self::body(name, body)?;
    let omega = pose::angular_velocity(body, q, qd)?;
    let a = pose::rotation_matrix(body, q)?;
    let o = body.coord_offset;
    let v = Vector3::new(qd[o], qd[o + 1], qd[o + 2]) + omega.cross(&(a * Vector3::from(local)));
    Ok([v.x, v.y, v.z])
}

/// Kinetic plus potential energy of mechanism `name` at `(q, qd)` (J).
pub fn energy(name: &str, q: &[f64], qd: &[f64]) -> Result<f64, Error> {
    let mech = symbody::generic::find(&crate::REGISTRY, name)?.default_mechanism();
    let info = mech.info();
    let mut mass = vec![0.0; info.mass_nnz()];
    mech.mass(q, &mut mass);
    Ok(kinetic_energy(info, &mass, qd) + mech.potential(q))
}

/// One classical RK4 step of θ̈ = f(θ), the one-coordinate references' integrator.
pub fn rk4_step(theta: &mut f64, omega: &mut f64, h: f64, f: impl Fn(f64) -> f64) {
    let (th, w) = (*theta, *omega);
    let (k1t, k1w) = (w, f(th));
    let (k2t, k2w) = (w + 0.5 * h * k1w, f(th + 0.5 * h * k1t));
    let (k3t, k3w) = (w + 0.5 * h * k2w, f(th + 0.5 * h * k2t));
    let (k4t, k4w) = (w + h * k3w, f(th + h * k3t));
    *theta += h / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t);
    *omega += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
}
