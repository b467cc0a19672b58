//! Forward-kinematics tests against independent references: inverse kinematics (a pose's
//! lengths are computed directly), finite differences, and Dietmaier's published geometry
//! with 40 real assembly modes.

use nalgebra::Vector3;

use super::track::{dependent_legs, TrackSettings};
use super::*;

/// Dietmaier (1998), "The Stewart-Gough platform of general geometry can have 40 real
/// postures", as tabulated in the MIT-licensed fkSGP tests (base points, platform points,
/// leg lengths).
pub(crate) fn dietmaier() -> (Legs, [f64; 6]) {
    let v = Vector3::new;
    let legs = Legs {
        base: [
            v(0.0, 0.0, 0.0),
            v(1.107915, 0.0, 0.0),
            v(0.549094, 0.756063, 0.0),
            v(0.735077, -0.223935, 0.525991),
            v(0.514188, -0.526063, -0.368418),
            v(0.590473, 0.094733, -0.205018),
        ],
        top: [
            v(0.0, 0.0, 0.0),
            v(0.542805, 0.0, 0.0),
            v(0.956919, -0.528915, 0.0),
            v(0.665885, -0.353482, 1.402538),
            v(0.478359, 1.158742, 0.107672),
            v(-0.137087, -0.235121, 0.353913),
        ],
    };
    (
        legs,
        [1.0, 0.645275, 1.086284, 1.503439, 1.281933, 0.771071],
    )
}

/// The paper's platform (paper-scenario.md): base circle 0.27 m, platform circle 0.105 m.
fn paper() -> (Legs, Pose) {
    let deg = |d: f64| d.to_radians();
    let on_circle = |r: f64, a: f64| Vector3::new(r * deg(a).cos(), 0.0, -r * deg(a).sin());
    let phi = [10.5, 109.5, 130.5, 229.5, 250.5, 349.5];
    let alpha = [49.5, 70.5, 169.5, 190.5, 289.5, 310.5];
    let legs = Legs {
        base: phi.map(|a| on_circle(0.27, a)),
        top: alpha.map(|a| on_circle(0.105, a)),
    };
    (
        legs,
        Pose::from_euler([0.0, 0.3466575, 0.0], [0.0, 0.0, 0.0]),
    )
}

fn general_pose() -> Pose {
    Pose::from_euler([0.05, 0.32, -0.02], [0.1, -0.2, 0.3])
}

#[test]
fn study_equations_vanish_at_a_pose() {
    let (legs, _) = paper();
    let pose = general_pose();
    let lengths = legs.lengths(&pose);
    assert!(super::modes::study_residual(&legs, &lengths, &pose) < 1e-15);
    let wrong = lengths.map(|l| l + 1e-3);
    assert!(super::modes::study_residual(&legs, &wrong, &pose) > 1e-4);
}

#[test]
fn jacobian_matches_finite_differences_of_the_lengths() {
    let (legs, _) = paper();
    let pose = general_pose();
    let j = legs.jacobian(&pose);
    let h = 1e-6;
    for k in 0..6 {
        let mut d = nalgebra::Vector6::zeros();
        d[k] = h;
        let plus = legs.lengths(&pose.moved(&d));
        d[k] = -h;
        let minus = legs.lengths(&pose.moved(&d));
        for i in 0..6 {
            let fd = (plus[i] - minus[i]) / (2.0 * h);
            assert!(
                (fd - j[(i, k)]).abs() < 1e-8,
                "J[{i},{k}]: {fd} vs {}",
                j[(i, k)]
            );
        }
    }
}

#[test]
fn newton_returns_the_pose_whose_lengths_it_was_given() {
    let (legs, home) = paper();
    let pose = general_pose();
    let s = legs
        .solve(&legs.lengths(&pose), &home, Settings::default())
        .unwrap();
    assert!(s.residual <= 1e-13, "residual {}", s.residual);
    assert!(s.pose.distance(&pose, 1.0) < 1e-12);
    assert!(s.iterations < 10);
    assert!(s.condition.is_finite() && s.condition > 1.0);
}

#[test]
fn euler_angles_round_trip() {
    let p = Pose::from_euler([1.0, 2.0, 3.0], [0.3, -0.4, 2.5]);
    let [t, b, g] = p.euler_angles();
    assert!((t - 0.3).abs() < 1e-14 && (b + 0.4).abs() < 1e-14 && (g - 2.5).abs() < 1e-14);
}

#[test]
fn bad_input_is_a_typed_error() {
    let (legs, home) = paper();
    let mut l = legs.lengths(&home);
    l[2] = f64::NAN;
    assert!(matches!(
        legs.solve(&l, &home, Settings::default()),
        Err(Error::NotFinite { .. })
    ));
    // Leg 1 shorter than the base and platform circles allow: no pose exists.
    let mut l = legs.lengths(&home);
    l[0] = 0.01;
    assert!(matches!(
        legs.solve(&l, &home, Settings::default()),
        Err(Error::NewtonFailed { .. })
    ));
    assert!(matches!(
        assembly_modes(&legs, &[0.4, 0.4, 0.4, -0.4, 0.4, 0.4]),
        Err(Error::InvalidSetting { .. })
    ));
}

#[test]
fn dietmaier_geometry_has_forty_real_assembly_modes() {
    let (legs, lengths) = dietmaier();
    let modes = assembly_modes(&legs, &lengths).unwrap();
    assert_eq!(modes.complex, 40, "complex solutions found");
    assert_eq!(modes.real.len(), 40, "real solutions found");
    let lc = legs.characteristic_length();
    for (k, m) in modes.real.iter().enumerate() {
        // Independent check: the lengths recomputed from the pose.
        let l = legs.lengths(&m.pose);
        let res = (0..6)
            .map(|i| (l[i] - lengths[i]).abs())
            .fold(0.0, f64::max);
        assert!(res <= 1e-10, "mode {k}: residual {res}");
        let rtr = m.pose.rotation.transpose() * m.pose.rotation;
        assert!((rtr - nalgebra::Matrix3::identity()).amax() < 1e-12);
        assert!(m.pose.rotation.determinant() > 0.0);
        for other in &modes.real[..k] {
            assert!(m.pose.distance(&other.pose, lc) > 1e-6, "mode {k} repeated");
        }
        // Newton from a nearby start returns to this mode, not to a neighbour.
        let start = m.pose.moved(&nalgebra::Vector6::from_element(1e-5));
        let s = legs.solve(&lengths, &start, Settings::default()).unwrap();
        assert!(
            s.pose.distance(&m.pose, lc) < 1e-9,
            "mode {k}: Newton went elsewhere"
        );
    }
}

/// A twist of the paper's platform about the vertical: its Jacobian's determinant changes
/// sign at some angle (found here from the pose path alone), so tracking the lengths of
/// that pose path must stop there and say so.
#[test]
fn tracking_through_a_parallel_singularity_is_reported_with_its_time() {
    let (legs, home) = paper();
    let pose_at = |s: f64| Pose::from_euler([0.0, 0.3466575, 0.0], [0.0, 2.0 * s, 0.0]);
    let det = |s: f64| legs.jacobian(&pose_at(s)).determinant();
    let (mut lo, mut hi) = (0.0, 1.0);
    assert!(
        det(lo) * det(hi) < 0.0,
        "the twist path must cross a singularity"
    );
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if det(lo) * det(mid) > 0.0 {
            lo = mid
        } else {
            hi = mid
        }
    }
    let s_star = lo;
    let err = track(
        &legs,
        |s| legs.lengths(&pose_at(s)),
        &home,
        0.0,
        1.0,
        TrackSettings::default(),
    )
    .unwrap_err();
    let Error::PlatformSingularity {
        time, condition, ..
    } = err
    else {
        panic!("expected a platform singularity, got {err}");
    };
    assert!(
        (time - s_star).abs() < 0.02,
        "reported at {time}, singular at {s_star}"
    );
    assert!(condition > 1e3, "condition {condition}");
    // Before it, tracking is uneventful and reaches the pose path.
    let ok = track(
        &legs,
        |s| legs.lengths(&pose_at(s)),
        &home,
        0.0,
        0.8 * s_star,
        TrackSettings::default(),
    )
    .unwrap();
    assert!(ok.solution.pose.distance(&pose_at(0.8 * s_star), 1.0) < 1e-12);
    assert!(!dependent_legs(&legs, &pose_at(s_star)).is_empty());
}

/// A random complex point `z` and platform for the Study-form checks.
fn random_study(rng: &mut super::modes::SplitMix) -> (super::study::Study, super::study::Z) {
    use super::study::{Study, C, Z};
    let mut c = || C::new(2.0 * rng.next() - 1.0, 2.0 * rng.next() - 1.0);
    let a = std::array::from_fn(|_| Vector3::new(c(), c(), c()));
    let b = std::array::from_fn(|_| Vector3::new(c(), c(), c()));
    let l2 = std::array::from_fn(|_| c());
    let z = Z::from_fn(|_, _| c());
    (Study::complex(a, b, l2), z)
}

/// The Study-form Jacobian and the rate along a change of the coefficients against
/// central differences of the equations themselves (complex steps along each unknown; the
/// equations are holomorphic, so one complex direction gives the whole derivative).
#[test]
fn study_jacobian_and_parameter_rate_match_central_differences() {
    use super::study::{C, Z};
    let mut rng = super::modes::SplitMix(7);
    for _ in 0..5 {
        let (study, z) = random_study(&mut rng);
        let (other, patch) = random_study(&mut rng);
        let (_, j) = study.eval(&z, &patch);
        let h = C::new(1e-6, 1e-6);
        for c in 0..8 {
            let mut dz = Z::zeros();
            dz[c] = h;
            let (fp, _) = study.eval(&(z + dz), &patch);
            let (fm, _) = study.eval(&(z - dz), &patch);
            for r in 0..8 {
                let fd = (fp[r] - fm[r]) / (h * 2.0);
                assert!(
                    (fd - j[c][r]).norm() < 1e-8,
                    "J[{r},{c}]: {fd} vs {}",
                    j[c][r]
                );
            }
        }
        let delta = study.towards(&other);
        let rate = study.rate(&z, &study.legs(&z), &delta);
        let (fp, _) = study.moved(&delta, h).eval(&z, &patch);
        let (fm, _) = study.moved(&delta, -h).eval(&z, &patch);
        for r in 0..8 {
            let fd = (fp[r] - fm[r]) / (h * 2.0);
            assert!(
                (fd - rate[r]).norm() < 1e-8,
                "rate[{r}]: {fd} vs {}",
                rate[r]
            );
        }
    }
}

/// The shipped start: 40 distinct regular solutions of the shipped platform (the generic
/// count, so none is missing), and the example that writes the table makes the same set.
#[test]
fn shipped_start_solutions_are_the_start_platforms_forty() {
    use super::study::{size, Lu, Z};
    let generic = super::start::generic();
    assert_eq!(generic.solutions.len(), super::modes::GENERIC_COUNT);
    let mut rng = super::modes::SplitMix(3);
    let patch = Z::from_fn(|_, _| rng.complex());
    for (k, z) in generic.solutions.iter().enumerate() {
        let z = z / patch.dot(z);
        let (f, j) = generic.study.eval(&z, &patch);
        assert!(
            size(&f) < 1e-12 * size(&z).powi(2),
            "solution {k}: residual {}",
            size(&f)
        );
        assert!(Lu::new(&j).is_some(), "solution {k} is singular");
        let e = z.fixed_rows::<4>(0);
        assert!(
            e.dot(&e).norm() > 1e-3 * size(&z).powi(2),
            "solution {k} is degenerate"
        );
        for (m, w) in generic.solutions[..k].iter().enumerate() {
            let w = w / patch.dot(w);
            assert!(size(&(w - z)) > 1e-6, "solutions {m} and {k} are one");
        }
    }
    let made = super::start::start_solutions(START_SEED).unwrap();
    for (k, z) in generic.solutions.iter().enumerate() {
        assert!(
            made.iter().any(|w| super::start::same(w, z)),
            "shipped solution {k} is not the seed's: regenerate with `cargo run -p \
             symbody-runtime --example fk_start_table > runtime/src/fk/start_data.rs`"
        );
    }
}

/// The seed `examples/fk_start_table.rs` writes the shipped table with.
const START_SEED: u64 = 0x0004_0574_7a27;

/// Every call, whatever its random choices, finds all 40 real modes of Dietmaier's platform.
#[test]
fn dietmaier_forty_real_modes_in_each_of_a_thousand_calls_with_random_choices() {
    let (legs, lengths) = dietmaier();
    let mut fallbacks = 0;
    for seed in 0..1000 {
        let modes = assembly_modes_seeded(&legs, &lengths, seed).unwrap();
        assert_eq!(modes.real.len(), 40, "seed {seed}: real modes found");
        fallbacks += usize::from(modes.fallback);
    }
    eprintln!("1000 calls: {fallbacks} fell back to the linear-product homotopy");
}

/// On random general platforms, every real mode the linear-product homotopy alone finds is
/// found from the shipped start, and the complex counts agree.
#[test]
fn parameter_homotopy_finds_every_mode_the_linear_product_homotopy_finds() {
    let mut rng = super::modes::SplitMix(11);
    let mut point = |r: f64| {
        Vector3::new(
            r * (2.0 * rng.next() - 1.0),
            r * (2.0 * rng.next() - 1.0),
            r * (2.0 * rng.next() - 1.0),
        )
    };
    let (mut real, mut fallbacks) = (0, 0);
    for k in 0..100 {
        let legs = Legs {
            base: std::array::from_fn(|_| point(1.0)),
            top: std::array::from_fn(|_| point(0.5)),
        };
        let p = point(0.3) + Vector3::new(0.0, 0.0, 1.0);
        let w = point(0.5);
        let pose = Pose {
            position: p,
            rotation: *nalgebra::Rotation3::new(w).matrix(),
        };
        let lengths = legs.lengths(&pose);
        let reference = super::modes::modes(&legs, &lengths, 1, false).unwrap();
        let modes = assembly_modes_seeded(&legs, &lengths, k).unwrap();
        assert_eq!(
            modes.complex, reference.complex,
            "platform {k}: complex count"
        );
        let lc = legs.characteristic_length();
        for m in &reference.real {
            assert!(
                modes
                    .real
                    .iter()
                    .any(|n| n.pose.distance(&m.pose, lc) < 1e-9),
                "platform {k}: a mode of the linear-product homotopy is missing"
            );
        }
        assert_eq!(modes.real.len(), reference.real.len(), "platform {k}");
        real += modes.real.len();
        fallbacks += usize::from(modes.fallback);
    }
    eprintln!(
        "100 platforms, {real} real modes: {fallbacks} fell back to the linear-product homotopy"
    );
    assert!(
        real > 100,
        "the platforms must have real modes to compare ({real})"
    );
}
