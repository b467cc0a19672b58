//! Parameters set at run time (`--set`, scenes' `[parameters]`, `files::with_parameters`)
//! against the reference of the issue: the mechanism file edited to that value. The edited
//! file is written to a temporary folder and loaded as any file; the set parameter goes
//! through `model::load_with`. Both must give the same run, and differ from the file's values.

use symbody::files::{self, Overrides};
use symbody::generic::{self, Options, Recording};
use symbody_mechanisms::REGISTRY;
use symbody_runtime::{Entry, Origin};

fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("symbody-params-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The file of registered `name` with the line `parameter = …` given `value` instead.
fn edited(name: &str, parameter: &str, value: f64) -> String {
    let Origin::Compiled { file, .. } = REGISTRY.find(name).unwrap().origin else {
        panic!("compiled")
    };
    let text = std::fs::read_to_string(file).unwrap();
    let mut hits = 0;
    let lines: Vec<String> = text
        .lines()
        .map(|l| match l.split_once('=') {
            Some((k, _)) if k.trim() == parameter && !l.trim_start().starts_with('#') => {
                hits += 1;
                format!("{parameter} = {value:?}")
            }
            _ => l.to_string(),
        })
        .collect();
    assert_eq!(hits, 1, "{name}: one line sets `{parameter}`");
    lines.join("\n") + "\n"
}

fn run(entry: &Entry) -> Recording {
    let opts = Options {
        t_end: Some(0.3),
        ..Options::default()
    };
    generic::run(entry, &opts).unwrap_or_else(|e| panic!("{}: {e}", entry.name))
}

/// Largest |a − b| over every recorded quantity, relative to the largest |b| of its kind.
fn max_rel(a: &Recording, b: &Recording) -> f64 {
    assert_eq!(a.t, b.t);
    let rel = |x: &[Vec<f64>], y: &[Vec<f64>]| {
        let scale = y
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| m.max(v.abs()))
            .max(1e-300);
        x.iter()
            .flatten()
            .zip(y.iter().flatten())
            .fold(0.0f64, |m, (p, q)| m.max((p - q).abs() / scale))
    };
    let flat = |r: &Recording| -> Vec<Vec<f64>> {
        r.wrenches
            .iter()
            .map(|w| {
                w.iter()
                    .flat_map(|w| w.force.into_iter().chain(w.moment))
                    .collect()
            })
            .collect()
    };
    rel(&a.q, &b.q)
        .max(rel(&a.qd, &b.qd))
        .max(rel(&a.efforts, &b.efforts))
        .max(rel(&flat(a), &flat(b)))
}

fn set(name: &str, value: f64) -> Vec<(String, f64)> {
    vec![(name.to_string(), value)]
}

#[test]
fn a_set_parameter_runs_as_the_file_edited_to_that_value() {
    let dir = temp_dir("edited");
    let cases = [
        ("slider_crank", "r", 0.12),
        ("stewart_6_6", "r_platform", 0.11),
        ("stewart_6_6", "m_cyl", 0.36),
        ("oscillators", "k", 65.0),
        ("four_bar", "b", 0.37),
    ];
    for (name, parameter, value) in cases {
        let with = files::with_parameters(&REGISTRY, name, &set(parameter, value))
            .unwrap_or_else(|e| panic!("{name} {parameter}: {e}"));
        // Every case runs the compiled code (decisions 35 and 36); the reference the file.
        assert!(
            matches!(with.origin, Origin::Compiled { .. }),
            "{name} {parameter}: {:?}",
            files::note(with)
        );
        let path = dir.join(format!("{name}_{parameter}.toml"));
        std::fs::write(&path, edited(name, parameter, value)).unwrap();
        let reference = files::load(&path).unwrap().entry;
        let (got, want) = (run(with), run(reference));
        let d = max_rel(&got, &want);
        assert!(d <= 1e-12, "{name} {parameter} = {value}: {d:e}");
        // The value took effect: the run differs from the file's own values.
        let base = run(REGISTRY.find(name).unwrap());
        let moved = max_rel(&got, &base);
        assert!(moved > 1e-6, "{name} {parameter}: unchanged ({moved:e})");
    }
}

#[test]
fn the_file_values_set_explicitly_reproduce_the_compiled_run() {
    // The crank radius reaches the model's numbers, which the compiled code takes from the
    // file loaded at that value (decision 36); the stiffness is a run-time parameter of the
    // compiled code by name (decision 35).
    for (name, parameter, value, compiled) in [
        ("slider_crank", "r", 0.1, true),
        ("oscillators", "k", 50.0, true),
    ] {
        let with = files::with_parameters(&REGISTRY, name, &set(parameter, value)).unwrap();
        assert_eq!(
            matches!(with.origin, Origin::Compiled { .. }),
            compiled,
            "{name}"
        );
        let d = max_rel(&run(with), &run(REGISTRY.find(name).unwrap()));
        assert!(d <= 1e-13, "{name}: {d:e}");
    }
    // No parameters: the compiled entry itself.
    let none: &Overrides = &[];
    let e = files::with_parameters(&REGISTRY, "slider_crank", none).unwrap();
    assert!(std::ptr::eq(e, REGISTRY.find("slider_crank").unwrap()));
}

#[test]
fn bad_values_are_errors_naming_the_parameter() {
    let err = |name: &str, p: &str, v: f64| {
        files::with_parameters(&REGISTRY, name, &set(p, v))
            .expect_err("refused")
            .to_string()
    };
    let e = err("slider_crank", "rr", 0.12);
    assert!(
        e.contains("no parameter `rr`") && e.contains("did you mean `r`?"),
        "{e}"
    );
    for v in [f64::NAN, f64::INFINITY] {
        let e = err("slider_crank", "r", v);
        assert!(
            e.contains("parameter `r` set to") && e.contains("finite"),
            "{e}"
        );
    }
    let e = err("stewart_6_6", "m_cyl", -1.0);
    assert!(
        e.contains("with m_cyl = -1 set") && e.contains("mass"),
        "{e}"
    );
    // A coupler too short to close the loop: the derived angle has no value.
    let e = err("four_bar", "b", 0.1);
    assert!(e.contains("with b = 0.1 set") && e.contains("kappa"), "{e}");
}

#[test]
fn a_scene_sets_parameters_on_its_mechanism() {
    let text = "mechanism = \"slider_crank\"\n[time]\nend = 0.3\n[parameters]\nr = 0.12\n";
    let scene = symbody::scene::load(&REGISTRY, "crank.toml", text).unwrap();
    assert_eq!(scene.parameters, set("r", 0.12));
    let Origin::Compiled { parameters, .. } = scene.entry.origin else {
        panic!("compiled, with the scene's parameters")
    };
    assert_eq!(parameters, &[("r", 0.12)]);
    let direct = files::with_parameters(&REGISTRY, "slider_crank", &set("r", 0.12)).unwrap();
    assert_eq!(max_rel(&run(scene.entry), &run(direct)), 0.0);
    // An unknown name is located in the scene.
    let bad = "mechanism = \"slider_crank\"\n[parameters]\nradius = 0.12\n";
    let e = symbody::scene::load(&REGISTRY, "crank.toml", bad)
        .expect_err("unknown parameter")
        .to_string();
    assert!(
        e.contains("crank.toml:2:") && e.contains("no parameter `radius`"),
        "{e}"
    );
}

/// Random and degenerate parameter values on every shipped mechanism (seeded): each set is
/// either refused with a typed error or gives a mechanism whose short run ends in an error or
/// in finite values; nothing panics.
#[test]
fn random_and_degenerate_parameter_values_never_panic() {
    use symbody_testkit::common::Rng;
    let mut rng = Rng(0xBAD_5EED);
    let (mut built, mut refused, mut ran) = (0, 0, 0);
    for entry in REGISTRY.iter() {
        let listed = files::parameters(&REGISTRY, entry.name).unwrap().parameters;
        let names: Vec<String> = listed.iter().map(|p| p.name.clone()).collect();
        let defaults: Vec<f64> = listed.iter().map(|p| p.value).collect();
        if names.is_empty() {
            continue;
        }
        for _ in 0..12 {
            let k = 1 + (rng.next_u64() % 3) as usize;
            let set: Vec<(String, f64)> = (0..k)
                .map(|_| {
                    let i = (rng.next_u64() % names.len() as u64) as usize;
                    let v = match rng.next_u64() % 8 {
                        0 => 0.0,
                        1 => -defaults[i],
                        2 => 1e300,
                        3 => 1e-300,
                        4 => f64::INFINITY,
                        _ => defaults[i] * rng.uniform(0.5, 1.5),
                    };
                    (names[i].clone(), v)
                })
                .collect();
            let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                let e = files::with_parameters(&REGISTRY, entry.name, &set).ok()?;
                let opts = Options {
                    t_end: Some(0.02),
                    ..Options::default()
                };
                Some(generic::run(e, &opts).ok().map(|rec| {
                    let finite = rec.q.iter().flatten().all(|x| x.is_finite());
                    assert!(finite, "{}: {set:?} ran to non-finite values", entry.name);
                }))
            }));
            match outcome {
                Err(_) => panic!("{}: {set:?} panicked", entry.name),
                Ok(None) => refused += 1,
                Ok(Some(run)) => {
                    built += 1;
                    ran += usize::from(run.is_some());
                }
            }
        }
    }
    eprintln!("parameter sets: {built} built ({ran} ran 0.02 s), {refused} refused");
    assert!(built > 0 && refused > 0, "both outcomes are exercised");
}

/// A set that changes the structure the generator found is reported with what changed:
/// the 3-RPS platform with its second base joint put on the first one's (φ2 = φ1 = 90°) has
/// two legs on one line, so their rows depend on each other and the platform gains freedom.
#[test]
fn a_set_that_changes_the_structure_says_what_changed() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/mechanisms/three_rps.toml"
    );
    let base = files::load(std::path::Path::new(file)).unwrap().entry;
    assert_eq!(
        files::note(base).map(|n| n.contains("with these values")),
        Some(false)
    );
    let moved = files::reparametrized(base, &set("phi2", std::f64::consts::FRAC_PI_2)).unwrap();
    let note = files::note(moved).unwrap();
    assert!(
        note.contains("the dependent rows change from none to"),
        "{note}"
    );
    assert!(note.contains("leg2"), "{note}");
    assert!(note.contains("the DOF change from 0 to"), "{note}");
    // Set to the file's own value, nothing changes and nothing is said about structure.
    let same = files::reparametrized(base, &set("phi2", 210f64.to_radians())).unwrap();
    assert!(!files::note(same).unwrap().contains("with these values"));
}

/// A derived parameter set from outside the file stands for its expression, also where the
/// expression reaches masses and inertias (it used to be expanded there regardless): the run
/// equals the file with that line replaced by the value, on whichever route takes it.
#[test]
fn a_derived_parameter_set_replaces_its_expression() {
    let dir = temp_dir("derived");
    for (name, parameter, value) in [
        ("n_four_bar_2", "i_cross", 0.5),
        ("stewart_6_6", "i_cyl_xz", 0.003),
        ("four_bar", "theta0", 1.2),
    ] {
        let with = files::with_parameters(&REGISTRY, name, &set(parameter, value)).unwrap();
        let path = dir.join(format!("{name}_{parameter}.toml"));
        std::fs::write(&path, edited(name, parameter, value)).unwrap();
        let reference = files::load(&path).unwrap().entry;
        let got = run(with);
        let d = max_rel(&got, &run(reference));
        assert!(d <= 1e-12, "{name} {parameter} = {value}: {d:e}");
        let moved = max_rel(&got, &run(REGISTRY.find(name).unwrap()));
        assert!(moved > 1e-6, "{name} {parameter}: unchanged ({moved:e})");
    }
}
