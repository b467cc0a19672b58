//! Crossing singular positions. The N-four-bar (IFToMM A02 with N = 2) lies flat, its rows
//! dependent for an instant, four times in its first 3.5 s: every route that integrates it
//! (`simulate`/scene runs through `generic::run`, and the session that Python and C wrap)
//! must pass all four at every step of a sweep between 1e-3 and 1e-4 s, and a run that
//! starts exactly on a flat position must cross it and report its reactions there.
//!
//! References: the count of flat positions is read off each run's own crank angle, and the
//! runs must agree with each other (they converge to one motion), with the energy, which
//! A02 conserves, and with the equations of motion at the flat state itself.

use symbody::generic::{self, Options, Recording};
use symbody::session::{Session, Settings};
use symbody_benchmark_mechanisms::REGISTRY;
use symbody_runtime::kkt::DEFAULT_PIVOT_TOLERANCE;
use symbody_runtime::{
    EnergyMeter, Entry, HhtBuilder, KinematicSettings, Mechanism, MechanismInfo, Rotation,
};

const NAME: &str = "n_four_bar_2";
const T_END: f64 = 3.5;
/// Flat positions before `T_END` (the cranks horizontal at t ≈ 0.70, 1.22, 2.65, 3.17 s).
const FLATS: usize = 4;
/// Ten steps between 1e-3 and 1e-4 s, among them every one at which `simulate` stopped
/// before the multipliers' solves dropped dependent rows too (5e-4, 4e-4, 2.5e-4, 2e-4, 1e-4).
const STEPS: [f64; 10] = [
    1e-3, 8e-4, 6e-4, 5e-4, 4e-4, 3e-4, 2.5e-4, 2e-4, 1.5e-4, 1e-4,
];

fn mechanism() -> &'static (dyn Mechanism + Sync) {
    REGISTRY.find(NAME).expect("registered").default_mechanism()
}

/// `sin θ` of the first crank (turning about Z): it changes sign exactly when the crank
/// passes the horizontal.
fn crank_sine(info: &MechanismInfo, q: &[f64]) -> f64 {
    let b = &info.bodies[0];
    assert_eq!(b.name, "crank0");
    let r = &q[b.coord_offset + 3..];
    match b.rotation {
        Rotation::Quaternion => 2.0 * r[0] * r[3],
        // [θ, β, γ] with A = Rz(γ)·Ry(β)·Rx(θ): the turn about Z is γ.
        Rotation::Euler => r[2].sin(),
    }
}

fn sign_changes(values: impl IntoIterator<Item = f64>) -> usize {
    let v: Vec<f64> = values.into_iter().collect();
    v.windows(2).filter(|w| w[0] * w[1] < 0.0).count()
}

fn total_energy(mech: &dyn Mechanism, q: &[f64], qd: &[f64]) -> f64 {
    let info = mech.info();
    let mut mass = vec![0.0; info.mass_nnz()];
    mech.mass(q, &mut mass);
    symbody_runtime::kinematics::kinetic_energy(info, &mass, qd) + mech.potential(q)
}

/// `generic::run` of `entry` to `T_END` at step `h`, crossing singular positions, outputs
/// every millisecond: it must get there across every flat position, holding Φ and the energy,
/// and flag the reactions near each flat position as ill-conditioned.
fn crossing_run(entry: &Entry, h: f64) -> Recording {
    let opts = Options {
        t_end: Some(T_END),
        step: h,
        output_step: 1e-3,
        cross_singular: true,
        ..Options::default()
    };
    let rec = generic::run(entry, &opts).unwrap_or_else(|e| panic!("h = {h}: {e}"));
    assert_eq!(*rec.t.last().unwrap(), T_END, "h = {h}");
    let flats = sign_changes(rec.q.iter().map(|q| crank_sine(rec.info, q)));
    assert_eq!(flats, FLATS, "h = {h}");
    assert!(rec.max_phi < 1e-8, "h = {h}: |Φ| {}", rec.max_phi);
    let (drift, scale) = rec.energy_balance().expect("the work is integrated");
    assert!(
        drift < 1e-4 * scale,
        "h = {h}: energy drift {drift} of {scale}"
    );
    // Each flat position flags the output nearest to it (measured: relative pivots 4e-7 …
    // 4e-6 there, within 0.5 ms of the flat position), and only those outputs are flagged
    // (ill-conditioned reactions).
    let windows = rec.ill_conditioned();
    assert_eq!(windows.len(), FLATS, "h = {h}: {windows:?}");
    for w in windows {
        let k = rec.t.iter().position(|&t| t == w.at).unwrap();
        let s = crank_sine(rec.info, &rec.q[k]);
        assert!(
            s.abs() < 0.05,
            "h = {h}: flagged at t = {} where sin θ = {s}",
            w.at
        );
    }
    rec
}

/// Runs `generic::run` at the steps `STEPS[k]` for the `k` given; returns the end states'
/// `sin θ`. (Before the Newton noise probe tried several sign patterns, the Euler-angle model
/// stopped at t = 0.714 s at h = 4e-4 and 2.5e-4: the one pseudo-random pattern was nearly
/// orthogonal to the direction Φq loses there, so the noise floor was underestimated 70–300×
/// and the step was cut until it failed.)
fn simulate_sweep(ks: impl Iterator<Item = usize>) -> Vec<(f64, f64)> {
    let entry = REGISTRY.find(NAME).unwrap();
    let mut finals = Vec::new();
    for h in ks.map(|k| STEPS[k]) {
        let rec = crossing_run(entry, h);
        finals.push((h, crank_sine(rec.info, rec.q.last().unwrap())));
    }
    finals
}

/// The shipped file in quaternions (`rotation = "quaternion"`), interpreted.
fn quaternion_entry() -> &'static Entry {
    let shipped = concat!(env!("CARGO_MANIFEST_DIR"), "/mechanisms/n_four_bar_2.toml");
    let text = std::fs::read_to_string(shipped).unwrap();
    let euler = "\nrotation = \"euler\"\nplanar = true\n";
    assert!(
        text.contains(euler),
        "the shipped file is planar, in Euler angles"
    );
    let quaternion = text.replace(euler, "\nrotation = \"quaternion\"\n");
    let dir = std::env::temp_dir().join(format!("symbody-quaternion-a02-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!(
        "n_four_bar_2_quaternion_{:?}.toml",
        std::thread::current().id()
    ));
    std::fs::write(&path, quaternion).unwrap();
    let entry = symbody::files::load(&path).unwrap().entry;
    let _ = std::fs::remove_file(&path);
    entry
}

/// The same mechanism in quaternions crosses the same flat positions at steps across the
/// sweep.
#[test]
fn the_quaternion_model_crosses_every_flat_position_too() {
    let entry = quaternion_entry();
    for h in [1e-3, 5e-4, 4e-4, 2.5e-4, 1e-4] {
        let rec = crossing_run(entry, h);
        assert_eq!(rec.info.bodies[0].rotation, Rotation::Quaternion);
    }
}

/// The ill-conditioned-reactions flag reads the smallest relative pivot of the multipliers'
/// solve. It must measure the mechanism, not its coordinates: at every output of a run
/// through four flat positions, the quaternion model and the Euler-angle model at the same
/// physical state give the same smallest pivot and drop the same number of rows.
/// (Reference: the other model. Before the quaternions' unit rows were eliminated first, the
/// quaternion model's pivots near the flat positions were 10–34× smaller.)
#[test]
fn the_ill_conditioning_measure_does_not_depend_on_the_rotation_coordinates() {
    let quat = quaternion_entry();
    let rec = crossing_run(quat, 1e-3);
    let euler = mechanism();
    let (qi, ei) = (rec.info, euler.info());
    let solves = KinematicSettings {
        drop_dependent_rows: Some(DEFAULT_PIVOT_TOLERANCE),
        ..KinematicSettings::default()
    };
    let mut on_quat: EnergyMeter = EnergyMeter::with_settings(qi, solves).unwrap();
    let mut on_euler: EnergyMeter = EnergyMeter::with_settings(ei, solves).unwrap();
    let mut smallest = f64::INFINITY;
    for (k, &t) in rec.t.iter().enumerate() {
        let (q, qd) = (&rec.q[k], &rec.qd[k]);
        // Every body turns about Z: e = (cos γ/2, 0, 0, sin γ/2), ω_z = 2 (e0 ė3 − e3 ė0).
        let (mut qe, mut qde) = (vec![0.0; ei.n_coords], vec![0.0; ei.n_coords]);
        for (bq, be) in qi.bodies.iter().zip(ei.bodies) {
            let (o, p) = (bq.coord_offset, be.coord_offset);
            qe[p..p + 3].copy_from_slice(&q[o..o + 3]);
            qde[p..p + 3].copy_from_slice(&qd[o..o + 3]);
            let (e, ed) = (&q[o + 3..o + 7], &qd[o + 3..o + 7]);
            assert!(e[1].abs() < 1e-12 && e[2].abs() < 1e-12, "t = {t}: {e:?}");
            qe[p + 5] = 2.0 * e[3].atan2(e[0]);
            qde[p + 5] = 2.0 * (e[0] * ed[3] - e[3] * ed[0]);
        }
        on_quat.record(&quat.default_mechanism(), t, q, qd).unwrap();
        on_euler.record(&euler, t, &qe, &qde).unwrap();
        let (a, b) = (on_quat.pivots().unwrap(), on_euler.pivots().unwrap());
        assert_eq!(a.dropped, b.dropped, "t = {t}");
        assert!(
            (a.smallest - b.smallest).abs() <= 1e-6 * b.smallest,
            "t = {t}: quaternions {} against Euler angles {}",
            a.smallest,
            b.smallest
        );
        smallest = smallest.min(b.smallest);
    }
    // The run passed close to the flat positions, where the measure is small.
    assert!(smallest < 1e-4, "{smallest}");
}

// The sweep in two halves, so the two run side by side.
#[test]
fn simulate_crosses_every_flat_position_at_the_coarser_steps() {
    simulate_sweep((0..STEPS.len()).step_by(2));
}

#[test]
fn simulate_crosses_every_flat_position_at_the_finer_steps() {
    let finals = simulate_sweep((1..STEPS.len()).step_by(2));
    // One motion, converging: the end states agree to the integrator's error.
    let finest = finals.last().unwrap().1;
    for (h, s) in finals {
        assert!((s - finest).abs() < 2e-3, "h = {h}: sin θ {s} vs {finest}");
    }
}

#[test]
fn the_scene_run_is_the_same_run() {
    // `symbody run scenes/n_four_bar_2.toml` integrates through the same loop as `simulate`
    // (so the sweep above covers it): the same options give bit-identical outputs.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/n_four_bar_2.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let mut scene = symbody::scene::load(&REGISTRY, path, &text).unwrap();
    assert!(scene.cross_singular);
    let entry = REGISTRY.find(NAME).unwrap();
    for h in [5e-4, 1e-4] {
        (scene.t_end, scene.step) = (1.5, h);
        let (_, outcome) = symbody::scene::run(&scene, entry).unwrap_or_else(|e| panic!("{e}"));
        let symbody::scene::Outcome::Tables(from_scene) = outcome else {
            panic!("the scene writes tables")
        };
        let opts = Options {
            t_end: Some(1.5),
            step: h,
            alpha: scene.alpha,
            output_step: scene.output_step,
            cross_singular: true,
            ..Options::default()
        };
        let direct = generic::run(entry, &opts).unwrap();
        assert_eq!(from_scene.q, direct.q, "h = {h}");
        assert_eq!(from_scene.wrenches, direct.wrenches, "h = {h}");
    }
}

#[test]
fn the_session_crosses_every_flat_position_at_every_step() {
    for h in STEPS {
        let settings = Settings {
            step: h,
            alpha: 0.0,
            project_velocities: true,
            cross_singular_positions: true,
            ..Settings::default()
        };
        let mut s = Session::new(&REGISTRY, NAME, settings).unwrap();
        let info = s.info();
        let mut sines = vec![crank_sine(info, s.q())];
        // Outputs every 10 ms, each with the multipliers (the C and Python calls).
        for k in 1..=(T_END / 0.01).round() as usize {
            s.advance_to(k as f64 * 0.01)
                .unwrap_or_else(|e| panic!("h = {h}: {e}"));
            s.driver_efforts(&mut [])
                .unwrap_or_else(|e| panic!("h = {h}, t = {}: {e}", s.t()));
            s.joint_wrench("a0")
                .unwrap_or_else(|e| panic!("h = {h}, t = {}: {e}", s.t()));
            sines.push(crank_sine(info, s.q()));
        }
        assert_eq!(sign_changes(sines), FLATS, "h = {h}");
    }
}

/// The flat pose exactly: every link along +X (zero angles), the cranks turning
/// at `w` about Z, the couplers translating with their tips.
fn flat_state(info: &MechanismInfo, w: f64) -> (Vec<f64>, Vec<f64>) {
    let (mut q, mut qd) = (vec![0.0; info.n_coords], vec![0.0; info.n_coords]);
    for b in info.bodies {
        assert_eq!(b.rotation, Rotation::Euler, "{}", b.name);
        let o = b.coord_offset;
        let (x, vy, spin) = match b.name {
            "crank0" => (0.5, 0.5 * w, w),
            "crank1" => (1.5, 0.5 * w, w),
            "crank2" => (2.5, 0.5 * w, w),
            "coupler1" => (1.5, w, 0.0),
            "coupler2" => (2.5, w, 0.0),
            other => panic!("unexpected body {other}"),
        };
        // [θ, β, γ] = 0, turning at γ̇ = ω about Z.
        q[o] = x;
        qd[o + 1] = vy;
        qd[o + 5] = spin;
    }
    (q, qd)
}

/// From the flat pose, thrown up at 1 rad/s: the energy error after 0.5 s at step `h`,
/// checking on the way that the start and its output at the flat instant hold.
fn from_the_flat_position(h: f64) -> f64 {
    let mech = mechanism();
    let info = mech.info();
    let (q0, qd0) = flat_state(info, 1.0);
    let mut phi = vec![0.0; info.n_constraints];
    mech.phi(&q0, 0.0, &mut phi);
    assert!(
        phi.iter().all(|p| p.abs() < 1e-15),
        "not assembled: {phi:?}"
    );
    let solves = KinematicSettings {
        drop_dependent_rows: Some(DEFAULT_PIVOT_TOLERANCE),
        ..KinematicSettings::default()
    };
    let mut it = HhtBuilder::new()
        .alpha(0.0)
        .step(h)
        .project_velocities(true)
        .q0(&q0)
        .qd0(&qd0)
        .kinematic_settings(solves)
        .build(mech)
        .unwrap();
    // The consistent start kept the flat pose and the given (consistent) velocity.
    for (a, b) in it.q().iter().zip(&q0).chain(it.qd().iter().zip(&qd0)) {
        assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    }
    let mut meter: EnergyMeter = EnergyMeter::with_settings(info, solves).unwrap();
    meter.record(&mech, 0.0, it.q(), it.qd()).unwrap();
    let pivots = meter.pivots().unwrap();
    assert!(pivots.dropped > 0, "{pivots:?}");
    // The reactions there are one valid distribution: they satisfy the equations of motion
    // M q̈ + Φqᵀλ = Q at the flat state.
    let n = info.n_coords;
    let (mut mass, mut force) = (vec![0.0; info.mass_nnz()], vec![0.0; n]);
    mech.mass(&q0, &mut mass);
    mech.force(&q0, &qd0, 0.0, &mut force);
    let mut residual = force.iter().map(|f| -f).collect::<Vec<_>>();
    for ((&r, &c), &m) in info.mass_rows.iter().zip(info.mass_cols).zip(&mass) {
        residual[r as usize] += m * meter.qdd()[c as usize];
    }
    for ((&r, &c), &v) in info
        .phi_q_rows
        .iter()
        .zip(info.phi_q_cols)
        .zip(meter.phi_q())
    {
        residual[c as usize] += v * meter.lambda()[r as usize];
    }
    let scale = force.iter().fold(1.0f64, |s, f| s.max(f.abs()));
    assert!(
        residual.iter().all(|r| r.abs() < 1e-10 * scale),
        "{residual:?}"
    );
    // The links rise a little, fall back through the flat position and are well below it
    // 0.5 s later.
    let e0 = total_energy(mech, &q0, &qd0);
    it.advance_to(0.5).unwrap();
    assert!(
        crank_sine(info, it.q()) < -0.3,
        "{}",
        crank_sine(info, it.q())
    );
    (total_energy(mech, it.q(), it.qd()) - e0).abs() / e0
}

#[test]
fn a_run_that_starts_exactly_on_a_flat_position_crosses_it_at_second_order() {
    // A02 conserves energy; crossing the flat position twice must not cost the integrator
    // its order (measured: 1.3e-4 and 3.3e-5 relative).
    let (coarse, fine) = (from_the_flat_position(1e-3), from_the_flat_position(5e-4));
    assert!(coarse < 3e-4, "{coarse}");
    let order = (coarse / fine).log2();
    assert!(
        (1.7..2.3).contains(&order),
        "{coarse} -> {fine}: order {order}"
    );
}
