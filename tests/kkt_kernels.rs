//! The generated straight-line KKT kernels (`MechanismInfo::kkt`) on every shipped model:
//! they run wherever the runtime builds the model's pattern, and they compute what
//! `SchurKkt`'s loops compute (the same operations in the same order, less the terms with a
//! structural zero: equal to the last bit) and what the dense LU computes (an independent
//! factorization), including the failures (rank loss, dropped rows, NaN, a mass matrix that
//! is not positive definite).

use nalgebra::DVector;
use symbody_runtime::kkt::{DenseKkt, KktError, KktPattern, KktSolver, SchurKkt};
use symbody_runtime::{Mechanism, MechanismInfo};
use symbody_testkit::common::{dense_phi_q, random_state_for, Rng};

/// Every compiled model: each mechanism's formulations and its reduced (or planar) ones.
fn models() -> Vec<(String, &'static (dyn Mechanism + Sync))> {
    let mut out = Vec::new();
    for registry in [
        &symbody_mechanisms::REGISTRY,
        &symbody_benchmark_mechanisms::REGISTRY,
    ] {
        for entry in registry.iter() {
            for &(f, m) in entry.formulations {
                out.push((format!("{} {}", entry.name, f.name()), m));
                if let Some((r, _)) = entry.reduced(f) {
                    out.push((format!("{} {} reduced", entry.name, f.name()), r));
                }
            }
        }
    }
    out
}

fn without_kernels(p: &KktPattern) -> KktPattern {
    KktPattern {
        kernels: &[],
        ..p.clone()
    }
}

/// Both solvers' results for one right-hand side, or both errors.
type Solved = Result<(Vec<f64>, Vec<f64>), KktError>;

fn solve<K: KktSolver>(k: &mut K, f: &[f64], g: &[f64]) -> Solved {
    let (mut x, mut y) = (vec![0.0; f.len()], vec![0.0; g.len()]);
    k.solve(f, g, &mut x, &mut y)?;
    Ok((x, y))
}

/// Exactly equal, reading `-0.0 == 0.0` (a skipped zero term may flip a zero's sign).
fn assert_same(what: &str, a: &Solved, b: &Solved) {
    match (a, b) {
        (Ok((xa, ya)), Ok((xb, yb))) => {
            for (u, v) in xa.iter().zip(xb).chain(ya.iter().zip(yb)) {
                assert!(u == v, "{what}: {u:e} against {v:e}");
            }
        }
        _ => assert_eq!(a, b, "{what}"),
    }
}

/// The generated `Φqᵀ y` against the dense `Φq` transposed (nalgebra), and offered only for
/// the model's own pattern statics.
fn transpose_matches_dense(name: &str, info: &MechanismInfo, phi_q: &[f64], rng: &mut Rng) {
    let kernels = &info.kkt[0];
    let t = kernels
        .transpose_for(info.phi_q_rows, info.phi_q_cols)
        .unwrap_or_else(|| panic!("{name}: no Φqᵀ y for its own pattern"));
    // The generator's pattern is row-major (reactions rely on it without checking).
    assert!(
        info.phi_q_rows.is_sorted(),
        "{name}: Φq pattern not row-major"
    );
    let copy = info.phi_q_rows.to_vec();
    assert!(kernels.transpose_for(&copy, info.phi_q_cols).is_none());
    let y: Vec<f64> = (0..info.n_constraints)
        .map(|_| rng.uniform(-1.0, 1.0))
        .collect();
    let mut out = vec![f64::NAN; info.n_coords];
    t(phi_q, &y, &mut out).unwrap();
    let dense = dense_phi_q(info, phi_q).transpose() * DVector::from_column_slice(&y);
    let scale = phi_q.iter().fold(1e-300f64, |a, b| a.max(b.abs())) * y.len() as f64;
    for (u, v) in out.iter().zip(dense.iter()) {
        assert!(
            (u - v).abs() <= 1e-14 * scale,
            "{name}: Φqᵀy {u:e} vs dense {v:e}"
        );
    }
    assert!(t(&phi_q[1..], &y, &mut out).is_err());
}

/// The generated `out += Φq x` against the dense `Φq` (nalgebra) to roundoff, and bit for
/// bit against the loop over the nonzeros it replaces (each row's products added to `out`
/// in their order); offered only for the model's own pattern statics.
fn times_add_matches(name: &str, info: &MechanismInfo, phi_q: &[f64], rng: &mut Rng) {
    let kernels = &info.kkt[0];
    assert!(
        kernels.emitted_for(info.phi_q_rows, info.phi_q_cols),
        "{name}: no Φq x for its own pattern"
    );
    let copy = info.phi_q_cols.to_vec();
    assert!(!kernels.emitted_for(info.phi_q_rows, &copy));
    let t = kernels.times_add;
    let x: Vec<f64> = (0..info.n_coords).map(|_| rng.uniform(-1.0, 1.0)).collect();
    let start: Vec<f64> = (0..info.n_constraints)
        .map(|_| rng.uniform(-1.0, 1.0))
        .collect();
    let mut out = start.clone();
    t(phi_q, &x, &mut out).unwrap();
    let mut looped = start.clone();
    for ((&r, &c), &v) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(phi_q) {
        looped[r as usize] += v * x[c as usize];
    }
    assert_eq!(out, looped, "{name}: Φq x against the loop");
    let dense = DVector::from_column_slice(&start)
        + dense_phi_q(info, phi_q) * DVector::from_column_slice(&x);
    let scale = phi_q.iter().fold(1.0f64, |a, b| a.max(b.abs())) * x.len() as f64;
    for (u, v) in out.iter().zip(dense.iter()) {
        assert!(
            (u - v).abs() <= 1e-14 * scale,
            "{name}: Φq x {u:e} vs dense {v:e}"
        );
    }
    assert!(t(phi_q, &x[1..], &mut out).is_err());
}

/// The generated `M v` and `½ q̇ᵀ M q̇` against the dense `M` (nalgebra) to roundoff, and
/// bit for bit against the loops over the nonzeros they replace; offered only for the
/// model's own mass pattern statics. `v` is given a signed zero, where a sum that does not
/// start from zero would differ.
fn mass_kernels_match(name: &str, info: &MechanismInfo, mass: &[f64], rng: &mut Rng) {
    let kernels = &info.kkt[0];
    assert!(
        kernels.mass_emitted_for(info.mass_rows, info.mass_cols),
        "{name}: no M v for its own pattern"
    );
    let copy = info.mass_cols.to_vec();
    assert!(!kernels.mass_emitted_for(info.mass_rows, &copy));
    let n = info.n_coords;
    let mut v: Vec<f64> = (0..n).map(|_| rng.uniform(-1.0, 1.0)).collect();
    v[0] = -0.0;
    let mut out = vec![f64::NAN; n];
    (kernels.mass_times)(mass, &v, &mut out).unwrap();
    let (mut looped, mut energy) = (vec![0.0; n], 0.0);
    for ((&r, &c), &m) in info.mass_rows.iter().zip(info.mass_cols).zip(mass) {
        looped[r as usize] += m * v[c as usize];
        energy += v[r as usize] * m * v[c as usize];
    }
    let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&out), bits(&looped), "{name}: M v against the loop");
    let kinetic = (kernels.kinetic_energy)(mass, &v).unwrap();
    assert_eq!(
        kinetic.to_bits(),
        (0.5 * energy).to_bits(),
        "{name}: energy"
    );
    let mut dense = nalgebra::DMatrix::<f64>::zeros(n, n);
    for ((&r, &c), &m) in info.mass_rows.iter().zip(info.mass_cols).zip(mass) {
        dense[(r as usize, c as usize)] += m;
    }
    let v = DVector::from_column_slice(&v);
    let mv = &dense * &v;
    let scale = mass.iter().fold(1.0f64, |a, b| a.max(b.abs())) * n as f64;
    for (u, w) in out.iter().zip(mv.iter()) {
        assert!(
            (u - w).abs() <= 1e-14 * scale,
            "{name}: M v {u:e} vs dense {w:e}"
        );
    }
    let half = 0.5 * v.dot(&mv);
    assert!(
        (kinetic - half).abs() <= 1e-14 * scale,
        "{name}: energy {kinetic:e} vs {half:e}"
    );
    assert!((kernels.mass_times)(mass, &v.as_slice()[1..], &mut out).is_err());
    assert!((kernels.kinetic_energy)(&mass[1..], v.as_slice()).is_err());
}

/// Factor with the kernels, the loops and the dense LU at `mass` (in `pattern`'s mass
/// order), `phi_q`; solve for random `f, g` and for `f = 0`; compare.
fn compare(what: &str, pattern: &KktPattern, mass: &[f64], phi_q: &[f64], rng: &mut Rng) {
    let mut kern = SchurKkt::new(pattern).unwrap();
    assert!(kern.runs_kernels(), "{what}");
    let mut loops = SchurKkt::new(&without_kernels(pattern)).unwrap();
    assert!(!loops.runs_kernels());
    let mut dense = DenseKkt::new(pattern).unwrap();
    let c = rng.uniform(0.5, 2.0);
    let a = kern.factor(mass, c, phi_q);
    assert_eq!(a, loops.factor(mass, c, phi_q), "{what}");
    if a.is_err() {
        return;
    }
    assert_eq!(kern.pivots(), loops.pivots(), "{what}");
    dense.factor(mass, c, phi_q).unwrap();
    let (n, m) = (pattern.n, pattern.m);
    let f: Vec<f64> = (0..n).map(|_| rng.uniform(-1.0, 1.0)).collect();
    let g: Vec<f64> = (0..m).map(|_| rng.uniform(-1.0, 1.0)).collect();
    for f in [f, vec![0.0; n]] {
        let what = format!("{what} |f| {}", f[0].abs());
        let ours = solve(&mut kern, &f, &g);
        assert_same(&what, &ours, &solve(&mut loops, &f, &g));
        let (x, y) = ours.unwrap();
        let (xd, yd) = solve(&mut dense, &f, &g).unwrap();
        let scale = xd.iter().chain(&yd).fold(1e-300f64, |a, b| a.max(b.abs()));
        for (u, v) in x.iter().zip(&xd).chain(y.iter().zip(&yd)) {
            assert!(
                (u - v).abs() <= 1e-8 * scale,
                "{what}: {u:e} vs dense {v:e}"
            );
        }
    }
}

/// The generated assembly of `c·M − kq·sym(∂Q/∂q) − kqd·sym(∂Q/∂q̇)` on the pattern with
/// the loads' stiffness (`loads`): bit for bit against a loop over the entries as
/// `LoadStiffness::assemble` runs it (from zero, `c·m` at the mass slots, each entry's half
/// subtracted at `(r, c)` and `(c, r)`), and against the dense sum to roundoff. `dq`, `dqd`
/// are random: the assembly is linear in them.
fn loads_kernel_matches(
    name: &str,
    info: &MechanismInfo,
    loads: &KktPattern,
    mass: &[f64],
    rng: &mut Rng,
) {
    let kernel = info
        .kkt
        .iter()
        .find_map(|k| k.loads_for(info))
        .unwrap_or_else(|| panic!("{name}: no loads assembly for its own patterns"));
    let dq: Vec<f64> = info
        .force_q_rows
        .iter()
        .map(|_| rng.uniform(-1.0, 1.0))
        .collect();
    let dqd: Vec<f64> = info
        .force_qd_rows
        .iter()
        .map(|_| rng.uniform(-1.0, 1.0))
        .collect();
    let (c, kq, kqd) = (
        rng.uniform(0.5, 2.0),
        rng.uniform(0.0, 1e-3),
        rng.uniform(0.0, 1e-2),
    );
    let nu = loads.mass_rows.len();
    let mut out = vec![f64::NAN; nu];
    (kernel.assemble)(mass, c, &dq, kq, &dqd, kqd, &mut out).unwrap();
    let slot = |r: u32, c: u32| {
        (0..nu)
            .find(|&s| loads.mass_rows[s] == r && loads.mass_cols[s] == c)
            .expect("in the union")
    };
    let mut looped = vec![0.0; nu];
    for ((&r, &cc), &m) in info.mass_rows.iter().zip(info.mass_cols).zip(mass) {
        looped[slot(r, cc)] = c * m;
    }
    let mut dense = nalgebra::DMatrix::<f64>::zeros(info.n_coords, info.n_coords);
    for ((&r, &cc), &m) in info.mass_rows.iter().zip(info.mass_cols).zip(mass) {
        dense[(r as usize, cc as usize)] += c * m;
    }
    for (rows, cols, vals, k) in [
        (info.force_q_rows, info.force_q_cols, &dq, kq),
        (info.force_qd_rows, info.force_qd_cols, &dqd, kqd),
    ] {
        for ((&r, &cc), &v) in rows.iter().zip(cols).zip(vals.iter()) {
            let half = 0.5 * k * v;
            looped[slot(r, cc)] -= half;
            looped[slot(cc, r)] -= half;
            dense[(r as usize, cc as usize)] -= half;
            dense[(cc as usize, r as usize)] -= half;
        }
    }
    let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(
        bits(&out),
        bits(&looped),
        "{name}: loads assembly against the loop"
    );
    let scale = mass.iter().fold(1.0f64, |a, b| a.max(b.abs())) * c;
    for (s, &v) in out.iter().enumerate() {
        let d = dense[(loads.mass_rows[s] as usize, loads.mass_cols[s] as usize)];
        assert!(
            (v - d).abs() <= 1e-14 * scale,
            "{name}: slot {s}: {v:e} vs dense {d:e}"
        );
    }
    assert!((kernel.assemble)(mass, c, &dq, kq, &dqd, kqd, &mut out[1..]).is_err());
}

/// `mass` spread onto the pattern with the loads' stiffness: the mass entries where they
/// are, and a small symmetric value (a stiffness of 1e-3 of the largest mass entry, of
/// either sign) at each entry only the loads add.
fn with_loads(info: &MechanismInfo, loads: &KktPattern, mass: &[f64]) -> Vec<f64> {
    let big = mass.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    loads
        .mass_rows
        .iter()
        .zip(&loads.mass_cols)
        .map(|(&r, &c)| {
            let at = (0..mass.len()).find(|&k| info.mass_rows[k] == r && info.mass_cols[k] == c);
            at.map_or_else(
                || 1e-3 * big * (f64::from(r.min(c) * 7 + r.max(c) * 3) * 0.37).sin(),
                |k| mass[k],
            )
        })
        .collect()
}

#[test]
fn every_model_small_enough_runs_its_kernels_and_they_equal_the_loops_and_the_dense_lu() {
    let mut rng = Rng(0x5eed_c0de);
    let (mut with, mut with_loads_kernels) = (Vec::new(), Vec::new());
    for (name, m) in models() {
        let info = m.info();
        let pattern = KktPattern::from_info(info);
        // The kernels are emitted for the pattern the runtime builds from the model's INFO,
        // for every model but the spatial 40-bar chain (too long for straight-line code:
        // 605 rows; its planar model has them).
        let runs = SchurKkt::new(&pattern).unwrap().runs_kernels();
        assert_eq!(runs, !info.kkt.is_empty(), "{name}");
        assert_eq!(runs, name != "n_four_bar_40 exact", "{name}");
        if !runs {
            continue;
        }
        with.push(name.clone());
        // And for the pattern HHT factors with the loads' stiffness, where there are loads.
        let loads = pattern.with_loads(
            (info.force_q_rows, info.force_q_cols),
            (info.force_qd_rows, info.force_qd_cols),
        );
        let loads = loads.filter(|p| SchurKkt::new(p).unwrap().runs_kernels());
        if loads.is_some() {
            with_loads_kernels.push(name.clone());
        }
        let (mut mass, mut phi_q) = (vec![0.0; info.mass_nnz()], vec![0.0; info.phi_q_nnz()]);
        for trial in 0..3 {
            let (q, t) = match trial {
                0 => (info.q0.to_vec(), 0.0),
                _ => {
                    let (q, _, t) = random_state_for(&mut rng, info);
                    (q, t)
                }
            };
            m.mass(&q, &mut mass);
            m.phi_q(&q, t, &mut phi_q);
            transpose_matches_dense(&name, info, &phi_q, &mut rng);
            times_add_matches(&name, info, &phi_q, &mut rng);
            mass_kernels_match(&name, info, &mass, &mut rng);
            let what = format!("{name} trial {trial}");
            compare(&what, &pattern, &mass, &phi_q, &mut rng);
            if let Some(loads) = &loads {
                loads_kernel_matches(&name, info, loads, &mass, &mut rng);
                let spread = with_loads(info, loads, &mass);
                compare(
                    &format!("{what} with loads"),
                    loads,
                    &spread,
                    &phi_q,
                    &mut rng,
                );
            }
        }
    }
    with.sort();
    with.dedup();
    assert_eq!(with.len(), 23, "models with kernels: {with:?}");
    with_loads_kernels.sort();
    with_loads_kernels.dedup();
    assert_eq!(
        with_loads_kernels,
        [
            "andrews_squeezer exact",
            "flyball_governor exact",
            "oscillators exact"
        ],
        "models with kernels for their loads' stiffness"
    );
}

#[test]
fn kernels_fail_as_the_loops_do() {
    let m = symbody_mechanisms::REGISTRY
        .find("stewart_6_6")
        .unwrap()
        .default_mechanism();
    let info = m.info();
    let pattern = KktPattern::from_info(info);
    let (mut mass, mut phi_q) = (vec![0.0; info.mass_nnz()], vec![0.0; info.phi_q_nnz()]);
    m.mass(info.q0, &mut mass);
    m.phi_q(info.q0, 0.0, &mut phi_q);
    let row = |r: u32| info.phi_q_rows.iter().map(move |&i| i == r);
    // Row 7 emptied: rank loss, named; then dropped when asked to.
    let mut lost = phi_q.clone();
    for (v, hit) in lost.iter_mut().zip(row(7)) {
        if hit {
            *v = 0.0;
        }
    }
    let mut nan = phi_q.clone();
    nan[11] = f64::NAN;
    let mut negative = mass.clone();
    let diagonal = (0..mass.len())
        .find(|&k| info.mass_rows[k] == 40 && info.mass_cols[k] == 40)
        .unwrap();
    negative[diagonal] = -1.0;
    let cases = [
        ("rank loss", mass.clone(), lost.clone()),
        ("NaN in Φq", mass.clone(), nan),
        ("negative mass", negative, phi_q.clone()),
    ];
    for (what, mass, phi_q) in &cases {
        let mut kern = SchurKkt::new(&pattern).unwrap();
        let mut loops = SchurKkt::new(&without_kernels(&pattern)).unwrap();
        assert!(kern.runs_kernels());
        let a = kern.factor(mass, 1.0, phi_q);
        assert!(a.is_err(), "{what}");
        assert_eq!(a, loops.factor(mass, 1.0, phi_q), "{what}");
    }
    assert!(matches!(
        SchurKkt::new(&pattern).unwrap().factor(&mass, 1.0, &lost),
        Err(KktError::RankDeficient {
            rows: [7, ..],
            count: 1,
            ..
        })
    ));
    let mut kern = SchurKkt::new(&pattern).unwrap();
    let mut loops = SchurKkt::new(&without_kernels(&pattern)).unwrap();
    assert!(kern.drop_dependent_rows(1e-10) && loops.drop_dependent_rows(1e-10));
    kern.factor(&mass, 1.0, &lost).unwrap();
    loops.factor(&mass, 1.0, &lost).unwrap();
    assert_eq!(kern.pivots().unwrap().dropped, 1);
    assert_eq!(kern.pivots(), loops.pivots());
    let f: Vec<f64> = (0..info.n_coords).map(|i| (i as f64).sin()).collect();
    let g: Vec<f64> = (0..info.n_constraints).map(|i| (i as f64).cos()).collect();
    let ours = solve(&mut kern, &f, &g);
    assert_same("dropped row", &ours, &solve(&mut loops, &f, &g));
    assert_eq!(ours.unwrap().1[7], 0.0, "a dropped row carries nothing");
    // Inputs of the wrong length are errors, not panics.
    assert!(matches!(
        kern.factor(&mass[1..], 1.0, &phi_q),
        Err(KktError::Dimension { .. })
    ));
}
