//! The interpreter back end (decision 31): a mechanism file turned, while the program runs,
//! into a registry [`Entry`] whose mechanisms evaluate instruction tapes
//! ([`symbody_runtime::Interpreted`]) lowered from the same DAG roots the Rust emitter uses.
//! Nothing is compiled; the front end (parse, equations, assembly) is the generator's own.

use crate::assembly::Assembly;
use crate::equations::{self, Dynamics, System};
use crate::expr::{Id, Var};
use crate::model::{self, Model};
use crate::symbolic::Entry as Nonzero;
use crate::tape::lower;
use crate::{info, Errors, Report};
use std::any::Any;
use std::cell::RefCell;
use std::sync::Arc;
use symbody_runtime::interpreted::{DynamicTapes, KinematicTapes};
use symbody_runtime::registry::Formulations;
use symbody_runtime::{
    BodyInfo, Entry, Formulation, Interpreted, JointInfo, LegInfo, Mechanism, MechanismInfo,
    Origin, PlatformInfo, Rotation,
};

/// A mechanism file ready to run.
pub struct Loaded {
    /// Lives as long as the program: solvers and sessions take `&'static` mechanisms, as
    /// they do for compiled ones. Load a file once and keep the entry.
    pub entry: &'static Entry,
    /// What the generator found out (sizes, rank, mobility, redundant rows, warnings).
    pub report: Report,
    /// The file's parameters with the values used.
    pub parameters: Vec<model::Parameter>,
}

thread_local! {
    /// While [`load_scoped`] builds an entry: where its allocations are kept instead of
    /// leaked, to be freed when the caller is done with the entry.
    static KEPT: RefCell<Option<Vec<Box<dyn Any>>>> = const { RefCell::new(None) };
}

/// `b` for the rest of the program, or, while [`load_scoped`] builds, until it returns.
fn keep<T: ?Sized + 'static>(b: Box<T>) -> &'static T {
    KEPT.with(|kept| match kept.borrow_mut().as_mut() {
        None => Box::leak(b),
        Some(kept) => {
            let p: *const T = &*b;
            kept.push(Box::new(b));
            // SAFETY: moving the box does not move its allocation, which `load_scoped` frees
            // only after its caller's closure, whose contract is not to keep the reference.
            unsafe { &*p }
        }
    })
}

fn leak<T: 'static>(v: Vec<T>) -> &'static [T] {
    keep(v.into_boxed_slice())
}

fn leak_str(s: &str) -> &'static str {
    keep(s.to_owned().into_boxed_str())
}

fn leak_strs(v: &[String]) -> &'static [&'static str] {
    leak(v.iter().map(|s| leak_str(s)).collect())
}

fn pattern(entries: &[Nonzero]) -> (&'static [u32], &'static [u32]) {
    let (rows, cols): (Vec<u32>, Vec<u32>) = entries.iter().map(|e| (e.0, e.1)).unzip();
    (leak(rows), leak(cols))
}

fn values(entries: &[Nonzero]) -> Vec<Id> {
    entries.iter().map(|e| e.2).collect()
}

/// Parses, checks and assembles the mechanism file `text` (`source` names it in messages and
/// is kept as the entry's [`Origin`]; `stale`: it replaces a compiled entry whose code is
/// older than the file), and builds its interpreted mechanisms.
pub fn load(source: &str, text: &str, stale: bool) -> Result<Loaded, Errors> {
    load_with(source, text, &[], stale)
}

/// [`load`] with some of the file's parameters set to other values ([`model::load_with`]):
/// the whole front end runs again, so the assembly, rank, redundant rows and platform
/// detection are those of the new values.
pub fn load_with(
    source: &str,
    text: &str,
    parameters: &[(String, f64)],
    stale: bool,
) -> Result<Loaded, Errors> {
    load_as(source, text, parameters, (stale, false))
}

/// [`load_with`], the mechanisms also evaluating the equations' directional derivatives
/// (`Mechanism::tangents`, for sensitivities): their tapes take about as long to build as
/// all the others, so only a load that needs them builds them.
pub fn load_with_tangents(
    source: &str,
    text: &str,
    parameters: &[(String, f64)],
    stale: bool,
) -> Result<Loaded, Errors> {
    load_as(source, text, parameters, (stale, true))
}

fn load_as(
    source: &str,
    text: &str,
    parameters: &[(String, f64)],
    (stale, tangents): (bool, bool),
) -> Result<Loaded, Errors> {
    let model = model::load_with(source, text, parameters)?;
    let (model, system, assembly) = front_end(source, text, model, parameters, tangents)?;
    let entry = entry(&model, system, &assembly, (source, stale, parameters));
    Ok(Loaded {
        entry,
        report: assembly.report,
        parameters: model.parameters,
    })
}

/// The equations of `model` (loaded from `text` with `parameters` set) and its assembly: the
/// compiled code's equations (run-time values as variables, hoisted), with this model's
/// values bound, so interpreted and compiled runs agree bit for bit; with their directional
/// derivatives where `tangents` (what the tapes need, not a description).
fn front_end(
    source: &str,
    text: &str,
    mut model: Model,
    parameters: &[(String, f64)],
    tangents: bool,
) -> Result<(Model, System, Assembly), Errors> {
    let marked = crate::slots::mark(source, text, &mut model);
    let mut system = equations::build_parametric(&marked);
    if tangents {
        crate::tangent::add(&mut system);
    }
    crate::hoist::bound(&mut system, &model.run_time_values());
    let assembly = crate::assembly::assemble(&model, &system, source).map_err(|mut e| {
        // A pose that no longer assembles: say which of the values set it follows from.
        let set: Vec<_> = parameters
            .iter()
            .filter_map(|(k, v)| {
                let p = model.parameters.iter().find(|p| p.name == *k)?;
                let hit = e.0.iter().map(|d| p.affects.contains(&d.item)).collect();
                Some((k.clone(), *v, hit))
            })
            .collect();
        model::blame(&mut e, &set);
        e
    })?;
    Ok((model, system, assembly))
}

/// What the generator decides from the numbers of `model` (the file `text` loaded with
/// `parameters` set), without its mass matrix and forces and without tapes: the assembled pose
/// and velocities, the dependent rows, the bodies, joints and platform, each formulation's
/// [`MechanismInfo`] with no mass pattern (leaked, or kept as [`scoped`] keeps).
pub fn describe(
    source: &str,
    text: &str,
    model: Model,
    parameters: &[(String, f64)],
) -> Result<Vec<(Formulation, &'static MechanismInfo)>, Errors> {
    let formulations = model.formulations.clone();
    let kinematic = Model {
        formulations: Vec::new(),
        ..model
    };
    let (model, system, assembly) = front_end(source, text, kinematic, parameters, false)?;
    let shared = Shared::new(&model, &system, &assembly);
    Ok(formulations
        .iter()
        .map(|&f| (formulation(f), shared.info(&model, &system, f, None)))
        .collect())
}
/// As [`load`], but the entry lives only while `f` runs and is freed when it returns (or
/// panics): for callers that load many files, such as the fuzzer, where [`load`]'s entries
/// (tens of kB each) would add up.
///
/// # Safety
///
/// Nothing reached through the entry (its mechanisms, their [`MechanismInfo`], names,
/// patterns) may be used after `f` returns: every solver built on it must be dropped inside
/// `f`, and no `&'static` reference taken from it may be stored elsewhere.
pub unsafe fn load_scoped<R>(
    source: &str,
    text: &str,
    stale: bool,
    f: impl FnOnce(&Loaded) -> R,
) -> Result<R, Errors> {
    // SAFETY: the same contract.
    unsafe { load_scoped_with(source, text, &[], stale, f) }
}

/// [`load_scoped`] with some of the file's parameters set ([`load_with`]): for studies, which
/// build one mechanism per parameter set.
///
/// # Safety
///
/// As [`load_scoped`].
pub unsafe fn load_scoped_with<R>(
    source: &str,
    text: &str,
    parameters: &[(String, f64)],
    stale: bool,
    f: impl FnOnce(&Loaded) -> R,
) -> Result<R, Errors> {
    let build = || load_with(source, text, parameters, stale);
    // SAFETY: the same contract.
    unsafe { scoped(build, |loaded| loaded.map(|l| f(&l))) }
}

/// `run` on what `build` builds ([`load_with`], [`describe`]), which is kept until `run`
/// returns (or panics) instead of leaked. What `run` itself loads is leaked as usual.
///
/// # Safety
///
/// Nothing `build` built may be used after `run` returns (as [`load_scoped`] says).
pub unsafe fn scoped<T, R>(build: impl FnOnce() -> T, run: impl FnOnce(T) -> R) -> R {
    /// Frees what was kept, also when `build` or `run` panics.
    struct Freed(Option<Vec<Box<dyn Any>>>);
    impl Drop for Freed {
        fn drop(&mut self) {
            KEPT.with(|kept| kept.borrow_mut().take());
            drop(self.0.take());
        }
    }
    let previous = KEPT.with(|kept| kept.borrow_mut().replace(Vec::new()));
    assert!(previous.is_none(), "scoped loads do not nest");
    let mut freed = Freed(None);
    let built = build();
    freed.0 = KEPT.with(|kept| kept.borrow_mut().take());
    run(built)
}

fn kinematic_tapes(sys: &System) -> KinematicTapes {
    let n = sys.n_coords;
    let pq = values(&sys.phi_q);
    let a = &sys.arena;
    KinematicTapes {
        phi: lower(a, n, &[&sys.phi]),
        phi_q: lower(a, n, &[&pq]),
        phi_t: lower(a, n, &[&sys.phi_t]),
        gamma: lower(a, n, &[&sys.gamma]),
        eval_kinematics: lower(a, n, &[&sys.phi, &pq, &sys.phi_t, &sys.gamma]),
        potential: lower(a, n, &[&[sys.potential]]),
        power_nc: lower(a, n, &[&[sys.power_nc]]),
    }
}

/// `d`'s tapes; `tangents` (where the system has them): their roots over the coordinates
/// of [`tangent_inputs`], and their count.
fn dynamic_tapes(sys: &System, d: &Dynamics, tangents: Option<(&[Id], usize)>) -> DynamicTapes {
    let n = sys.n_coords;
    let a = &sys.arena;
    let (pq, mass) = (values(&sys.phi_q), values(&d.mass));
    let tangents = tangents.map(|(t, n_joined)| {
        let m = sys.n_constraints;
        let (tk, td) = t.split_at(3 * m + sys.phi_q.len());
        let (phi, rest) = tk.split_at(m);
        let (phi_q, rest) = rest.split_at(sys.phi_q.len());
        let (phi_t, gamma) = rest.split_at(m);
        let (d_mass, d_force) = td.split_at(d.mass.len());
        lower(a, n_joined, &[phi, phi_q, phi_t, gamma, d_mass, d_force])
    });
    DynamicTapes {
        force_jacobian: lower(a, n, &[&values(&d.force_q), &values(&d.force_qd)]),
        mass: lower(a, n, &[&mass]),
        force: lower(a, n, &[&d.force]),
        eval_newton: lower(a, n, &[&sys.phi, &pq, &mass, &d.force]),
        tangents,
    }
}

/// The tangents of `sys` (where [`crate::tangent::add`] made them) with the direction
/// renamed to coordinates after the point's, as a tape reads them (`q` = `[q, dq, dp]`,
/// `qd` = `[qd, dqd]`): per formulation, Φ', Φq', Φt', γ', then its M' and Q'; and the
/// count of those coordinates.
fn tangent_inputs(sys: &mut System) -> Option<(Vec<Vec<Id>>, usize)> {
    let t = sys.tangent.as_ref()?;
    let kinematic = [t.phi.as_slice(), &t.phi_q, &t.phi_t, &t.gamma].concat();
    let per_formulation: Vec<Vec<Id>> = sys
        .dynamics
        .iter()
        .map(|d| [kinematic.as_slice(), &d.tangent.mass, &d.tangent.force].concat())
        .collect();
    let n = sys.n_coords as u32;
    let n_p = sys.value_lengths().0;
    let a = &mut sys.arena;
    let dq: Vec<Id> = (0..n).map(|i| a.var(Var::Q(n + i))).collect();
    let dqd: Vec<Id> = (0..n).map(|i| a.var(Var::Qd(n + i))).collect();
    let dp: Vec<Id> = (0..n_p as u32).map(|i| a.var(Var::Q(2 * n + i))).collect();
    let map = |v: Var| match v {
        Var::Dq(i) => Some(dq[i as usize]),
        Var::Dqd(i) => Some(dqd[i as usize]),
        Var::Dp(i) => Some(dp[i as usize]),
        _ => None,
    };
    let renamed = per_formulation
        .iter()
        .map(|roots| sys.arena.substitute(roots, &map))
        .collect();
    Some((renamed, 2 * n as usize + n_p))
}

/// What every formulation's [`MechanismInfo`] shares.
struct Shared {
    name: &'static str,
    bodies: &'static [BodyInfo],
    joints: &'static [JointInfo],
    platform: Option<PlatformInfo>,
    phi_q: (&'static [u32], &'static [u32]),
    coord_names: &'static [&'static str],
    row_names: &'static [&'static str],
    q0: &'static [f64],
    qd0: &'static [f64],
    redundant_rows: &'static [u32],
}

impl Shared {
    fn new(model: &Model, sys: &System, asm: &Assembly) -> Self {
        let bodies = leak(
            model
                .bodies
                .iter()
                .map(|b| BodyInfo {
                    name: leak_str(&b.name),
                    coord_offset: b.offset,
                    rotation: match b.rotation {
                        model::Rotation::Euler => Rotation::Euler,
                        model::Rotation::Quaternion => Rotation::Quaternion,
                    },
                    mass: b.mass,
                    inertia: b.inertia,
                })
                .collect(),
        );
        let joints = leak(
            info::joints(model, sys)
                .into_iter()
                .map(|j| JointInfo {
                    name: leak_str(&j.name),
                    kind: j.kind,
                    body1: j.body1,
                    body2: j.body2,
                    row_start: j.row_start,
                    rows: j.rows,
                    point1: j.point1,
                    point2: j.point2,
                    effort_sign: j.effort_sign,
                    effort_unit: j.effort_unit,
                })
                .collect(),
        );
        let platform = info::platform(model, sys, asm).map(|(body, legs)| PlatformInfo {
            body,
            legs: leak(
                legs.into_iter()
                    .map(|l| LegInfo {
                        driver: leak_str(&l.driver),
                        base: l.base,
                        platform: l.platform,
                        row: l.row,
                    })
                    .collect(),
            ),
        });
        Shared {
            name: leak_str(&model.name),
            bodies,
            joints,
            platform,
            phi_q: pattern(&sys.phi_q),
            coord_names: leak_strs(&sys.coord_names),
            row_names: leak_strs(&sys.row_names),
            q0: leak(asm.q0.clone()),
            qd0: leak(model.qd0()),
            redundant_rows: leak(asm.redundant_rows.clone()),
        }
    }

    /// The info of formulation `f` with the patterns of its dynamics `d` (none: empty).
    fn info(
        &self,
        model: &Model,
        sys: &System,
        f: model::Formulation,
        d: Option<&Dynamics>,
    ) -> &'static MechanismInfo {
        let none: &[Nonzero] = &[];
        let (mass, force_q, force_qd) = match d {
            Some(d) => (&d.mass[..], &d.force_q[..], &d.force_qd[..]),
            None => (none, none, none),
        };
        let (mass_rows, mass_cols) = pattern(mass);
        let (force_q_rows, force_q_cols) = pattern(force_q);
        let (force_qd_rows, force_qd_cols) = pattern(force_qd);
        keep(Box::new(MechanismInfo {
            name: self.name,
            n_coords: sys.n_coords,
            n_constraints: sys.n_constraints,
            formulation: formulation(f),
            gravity: model.gravity,
            phi_q_rows: self.phi_q.0,
            phi_q_cols: self.phi_q.1,
            mass_rows,
            mass_cols,
            mass_is_constant: d.is_some_and(|d| d.mass_is_constant),
            force_q_rows,
            force_q_cols,
            force_qd_rows,
            force_qd_cols,
            bodies: self.bodies,
            joints: self.joints,
            coord_names: self.coord_names,
            row_names: self.row_names,
            q0: self.q0,
            qd0: self.qd0,
            redundant_rows: self.redundant_rows,
            platform: self.platform,
            kkt: &[],
        }))
    }
}

fn formulation(f: model::Formulation) -> Formulation {
    match f {
        model::Formulation::Paper => Formulation::Paper,
        model::Formulation::Exact => Formulation::Exact,
    }
}

fn entry(
    model: &Model,
    mut sys: System,
    asm: &Assembly,
    (source, stale, parameters): (&str, bool, &[(String, f64)]),
) -> &'static Entry {
    let tangents = tangent_inputs(&mut sys);
    let sys = &sys;
    let values: Arc<[f64]> = model.run_time_values().into();
    let shared = Shared::new(model, sys, asm);
    let kinematic = Arc::new(kinematic_tapes(sys));
    let formulations: Vec<(Formulation, &'static (dyn Mechanism + Sync))> = model
        .formulations
        .iter()
        .map(|&f| {
            let k = sys
                .dynamics
                .iter()
                .position(|d| d.formulation == f)
                .expect("the equations hold every formulation the model lists");
            let d = &sys.dynamics[k];
            let info = shared.info(model, sys, f, Some(d));
            let t = tangents.as_ref().map(|(t, n)| (t[k].as_slice(), *n));
            let tapes = dynamic_tapes(sys, d, t);
            let m = Interpreted::new(info, kinematic.clone(), Arc::new(tapes), values.clone());
            let m: &'static (dyn Mechanism + Sync) = keep(Box::new(m));
            (formulation(f), m)
        })
        .collect();
    let formulations: Formulations = leak(formulations);
    keep(Box::new(Entry {
        name: shared.name,
        t_end: model.t_end,
        formulations,
        reduced: None,
        origin: Origin::Interpreted {
            file: leak_str(source),
            stale,
            parameters: leak(parameters.iter().map(|(k, v)| (leak_str(k), *v)).collect()),
        },
        run_time: None,
    }))
}
