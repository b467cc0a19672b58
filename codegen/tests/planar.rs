//! Planar models (`planar = true`): the generator pins each body's z, θ and β and keeps
//! (x, y, γ), drops the rows the plane makes identically zero, and checks its own rank; a file
//! that cannot be planar is refused naming the place, never modelled silently.

use symbody_codegen::{generate, Errors};

fn shipped(name: &str) -> String {
    let path = format!("{}/../mechanisms/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// `text` without the line `line` (which must be there).
fn without(text: &str, line: &str) -> String {
    assert!(text.contains(line), "{line}");
    text.replacen(line, "", 1)
}

fn error(text: &str) -> String {
    match generate("test.toml", text) {
        Ok(_) => panic!("accepted"),
        Err(Errors(d)) => d
            .iter()
            .map(|d| d.to_string())
            .collect::<Vec<_>>()
            .join("\n"),
    }
}

#[test]
fn the_four_bar_in_its_plane_has_three_coordinates_per_body_and_two_rows_per_hinge() {
    let four_bar = shipped("four_bar");
    let spatial = generate(
        "four_bar.toml",
        &four_bar.replacen("planar = true", "planar = false", 1),
    )
    .unwrap();
    assert!(spatial.report.planar.is_none());
    assert!(!spatial.code.contains("pub mod reduced"));
    let g = generate("four_bar.toml", &four_bar).unwrap();
    // Spatial in Euler angles: 3 bodies × 6, four hinges × 5 rows and the driver's row.
    assert_eq!((g.report.n_coords, g.report.n_rows), (18, 21));
    // Planar: 3 bodies × (x, y, γ), four hinges × 2 rows and the driver's: no DOF, as in space.
    assert_eq!(g.report.planar, Some((9, 9, vec![])));
    assert_eq!(g.report.dof, 0);
    assert!(
        g.report.to_string().contains("planar model: 9 coordinates"),
        "{}",
        g.report
    );
    assert!(g.code.contains("pub mod reduced"));
}

#[test]
fn a_pendulum_on_a_distance_joint_keeps_its_out_of_plane_freedom_only_in_space() {
    // The shipped A01 file is planar: one row in the plane, the spatial model's free
    // swing out of the plane and spins about X and Y are held, with a warning saying so.
    let g = generate("simple_pendulum.toml", &shipped("simple_pendulum")).unwrap();
    assert_eq!(g.report.planar, Some((3, 1, vec![])));
    assert!(
        g.report
            .warnings
            .iter()
            .any(|w| w.contains("holds 3 out-of-plane degree(s) of freedom")),
        "{:?}",
        g.report.warnings
    );
}

#[test]
fn a_planar_file_needs_euler_angles_bodies_in_their_plane_and_gravity_in_it() {
    let four_bar = shipped("four_bar");
    let e = error(&without(&four_bar, "rotation = \"euler\"\n"));
    assert!(
        e.contains("body `crank`") && e.contains("needs Euler angles"),
        "{e}"
    );
    assert!(e.contains("rotation = \"euler\""), "{e}");

    let tilted = four_bar.replacen(
        "angles = [0.0, 0.0, \"theta0\"]",
        "angles = [0.2, 0.0, \"theta0\"]",
        1,
    );
    let e = error(&tilted);
    assert!(
        e.contains("body `crank`") && e.contains("tilted out of the plane"),
        "{e}"
    );

    let falling = four_bar.replacen(
        "gravity = [0.0, -9.81, 0.0]",
        "gravity = [0.0, -9.81, -1.0]",
        1,
    );
    let e = error(&falling);
    assert!(
        e.contains("`gravity`") && e.contains("out of the plane"),
        "{e}"
    );

    let leaving = four_bar.replacen(
        "angles = [0.0, 0.0, \"theta0\"]",
        "angles = [0.0, 0.0, \"theta0\"]\nvelocity = [0.0, 0.0, 0.5]",
        1,
    );
    let e = error(&leaving);
    assert!(
        e.contains("body `crank`") && e.contains("out of the plane"),
        "{e}"
    );
}

#[test]
fn a_planar_file_that_does_not_say_so_is_recognised() {
    // The four-bar in Euler angles without `planar`: its bodies start in their planes and the
    // planar model keeps its mobility, so the generator emits it and says why.
    let g = generate(
        "four_bar.toml",
        &without(&shipped("four_bar"), "planar = true\n"),
    )
    .unwrap();
    assert_eq!(g.report.planar, Some((9, 9, vec![])));
    assert!(
        g.report
            .to_string()
            .contains("(recognised: every body moves in its plane"),
        "{}",
        g.report
    );
    assert!(g.code.contains("pub mod reduced"));
    // The pendulum's planar model would hold out-of-plane freedoms: not recognised unasked.
    let pendulum = without(&shipped("simple_pendulum"), "planar = true\n");
    assert!(generate("p.toml", &pendulum)
        .unwrap()
        .report
        .planar
        .is_none());
    // Nor the Stewart platform, whose bodies are tilted.
    assert!(generate("s.toml", &shipped("stewart_6_6"))
        .unwrap()
        .report
        .planar
        .is_none());
}
