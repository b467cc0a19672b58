//! `--html`: one self-contained HTML file that animates a run. Each body is drawn from the
//! mechanism's own geometry (its joint points): a plate through three or more points, a rod
//! between two (or from one to the centre of mass), a box sized by the principal inertias when
//! it has none; the legs of a six-leg platform as lines; play/pause, a time slider, the
//! current time and one selected force with its history. The renderer (`viewer.html`) is
//! plain canvas 2D written here: nothing is fetched, so the file works offline.

use std::fmt::Write as _;
use std::path::Path;
use symbody_runtime::{JointKind, MechanismInfo};

/// A body's pose: centre of mass and unit quaternion `[w, x, y, z]`.
pub type BodyPose = ([f64; 3], [f64; 4]);

/// One recorded force series for the selector.
pub struct Force<'a> {
    pub name: &'a str,
    pub unit: &'a str,
    pub values: Vec<f64>,
}

/// Writes `path`: the run of `info` at times `t` with `poses[k][body]`.
pub fn write(
    path: &Path,
    title: &str,
    info: &MechanismInfo,
    t: &[f64],
    poses: &[Vec<BodyPose>],
    forces: &[Force<'_>],
) -> Result<(), String> {
    let html =
        include_str!("viewer.html").replace("/*DATA*/null", &data(title, info, t, poses, forces));
    std::fs::write(path, html).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// The run as a JavaScript object literal (JSON).
fn data(
    title: &str,
    info: &MechanismInfo,
    t: &[f64],
    poses: &[Vec<BodyPose>],
    forces: &[Force<'_>],
) -> String {
    let mut points: Vec<Vec<[f64; 3]>> = vec![Vec::new(); info.bodies.len()];
    let mut ground: Vec<[f64; 3]> = Vec::new();
    for j in info.joints {
        // Drivers and normalization rows repeat joints or carry no geometry.
        if matches!(j.kind, JointKind::Driver | JointKind::Normalization) {
            continue;
        }
        for (body, p) in [(j.body1, j.point1), (j.body2, j.point2)] {
            let list = match body {
                Some(b) => &mut points[b],
                None => &mut ground,
            };
            if !list.iter().any(|q| dist(q, &p) < 1e-12) {
                list.push(p);
            }
        }
    }
    let legs = info.platform.map(|p| p.legs).unwrap_or(&[]);
    // A platform's legs may be bare point-distance drivers: their points still outline it.
    if let Some(p) = info.platform {
        for leg in p.legs {
            ground.push(leg.base);
            if !points[p.body]
                .iter()
                .any(|q| dist(q, &leg.platform) < 1e-12)
            {
                points[p.body].push(leg.platform);
            }
        }
    }
    let mut s = String::from("{");
    let _ = write!(s, "\"title\":{},", string(title));
    let up = info.gravity.map(|g| -g);
    let up = if up.iter().any(|&g| g != 0.0) {
        up
    } else {
        [0.0, 1.0, 0.0]
    };
    let _ = write!(s, "\"up\":{},", numbers(&up));
    let _ = write!(s, "\"t\":{},", numbers(t));
    s.push_str("\"bodies\":[");
    for (b, body) in info.bodies.iter().enumerate() {
        let mut pts = points[b].clone();
        let shape = match pts.len() {
            0 => "box",
            1 | 2 => "rod",
            _ => {
                order_around_centroid(&mut pts);
                "plate"
            }
        };
        let list: Vec<String> = pts.iter().map(|p| numbers(p)).collect();
        let _ = write!(
            s,
            "{}{{\"name\":{},\"shape\":\"{shape}\",\"points\":[{}],\"half\":{}}}",
            if b > 0 { "," } else { "" },
            string(body.name),
            list.join(","),
            numbers(&box_half_extents(body.mass, body.inertia))
        );
    }
    s.push_str("],\"poses\":[");
    for (k, row) in poses.iter().enumerate() {
        let flat: Vec<f64> = row
            .iter()
            .flat_map(|(r, q)| r.iter().chain(q.iter()).copied())
            .collect();
        let _ = write!(s, "{}{}", if k > 0 { "," } else { "" }, numbers(&flat));
    }
    let grounds: Vec<String> = ground.iter().map(|p| numbers(p)).collect();
    let _ = write!(s, "],\"ground\":[{}],\"legs\":[", grounds.join(","));
    for (i, leg) in legs.iter().enumerate() {
        let _ = write!(
            s,
            "{}{{\"base\":{},\"body\":{},\"point\":{}}}",
            if i > 0 { "," } else { "" },
            numbers(&leg.base),
            info.platform.map_or(0, |p| p.body),
            numbers(&leg.platform)
        );
    }
    let names: Vec<String> = forces.iter().map(|f| string(f.name)).collect();
    let units: Vec<String> = forces.iter().map(|f| string(f.unit)).collect();
    let values: Vec<String> = forces.iter().map(|f| numbers(&f.values)).collect();
    let _ = write!(
        s,
        "],\"forces\":{{\"names\":[{}],\"units\":[{}],\"values\":[{}]}}}}",
        names.join(","),
        units.join(","),
        values.join(",")
    );
    s
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

/// Sorts points by angle about their centroid in their best plane, so the polygon through
/// them does not cross itself.
fn order_around_centroid(pts: &mut [[f64; 3]]) {
    use nalgebra::{Matrix3, Vector3};
    let v: Vec<Vector3<f64>> = pts.iter().map(|p| Vector3::from(*p)).collect();
    let c = v.iter().sum::<Vector3<f64>>() / v.len() as f64;
    let cov: Matrix3<f64> = v.iter().map(|p| (p - c) * (p - c).transpose()).sum();
    let eig = cov.symmetric_eigen();
    let mut order: Vec<usize> = (0..3).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
    let (e1, e2) = (
        eig.eigenvectors.column(order[0]).into_owned(),
        eig.eigenvectors.column(order[1]).into_owned(),
    );
    pts.sort_by(|a, b| {
        let angle = |p: &[f64; 3]| {
            let d = Vector3::from(*p) - c;
            d.dot(&e2).atan2(d.dot(&e1))
        };
        angle(a).total_cmp(&angle(b))
    });
}

/// Half extents of the uniform box with this mass and these principal inertias
/// (`I_x = m(b² + c²)/12`, …); a small cube when they do not describe one.
fn box_half_extents(mass: f64, i: [f64; 3]) -> [f64; 3] {
    let side = |a: f64, b: f64, c: f64| (6.0 * (b + c - a) / mass).max(0.0).sqrt();
    let h = [
        side(i[0], i[1], i[2]) / 2.0,
        side(i[1], i[2], i[0]) / 2.0,
        side(i[2], i[0], i[1]) / 2.0,
    ];
    if h.iter().all(|x| x.is_finite() && *x > 0.0) {
        h
    } else {
        [0.05; 3]
    }
}

fn numbers(v: &[f64]) -> String {
    let items: Vec<String> = v
        .iter()
        .map(|x| {
            if x.is_finite() {
                format!("{x}")
            } else {
                "null".into()
            }
        })
        .collect();
    format!("[{}]", items.join(","))
}

fn string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '<' => out.push_str("\\u003c"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_uniform_box_is_recovered_from_its_inertias() {
        // 2 × 1 × 0.5 m, 3 kg: I_x = m(b² + c²)/12 and so on.
        let (m, a, b, c) = (3.0, 2.0, 1.0, 0.5);
        let i = [
            m * (b * b + c * c) / 12.0,
            m * (a * a + c * c) / 12.0,
            m * (a * a + b * b) / 12.0,
        ];
        let h = box_half_extents(m, i);
        for (got, want) in h.iter().zip([a / 2.0, b / 2.0, c / 2.0]) {
            assert!((got - want).abs() < 1e-12, "{h:?}");
        }
    }

    #[test]
    fn strings_cannot_close_the_script() {
        assert_eq!(string("a\"</script>"), "\"a\\\"\\u003c/script>\"");
    }

    /// Whatever the text (a title, a force's name or unit), the page keeps the template's
    /// scripts: nothing closes one early or opens another.
    #[test]
    fn text_cannot_break_out_of_the_page() {
        let info = symbody_mechanisms::REGISTRY
            .find("four_bar")
            .unwrap()
            .default_mechanism()
            .info();
        let evil = "x</script><script>alert(1)</script><!--\u{2028}\"\\\n-->";
        let poses = vec![vec![([0.0; 3], [1.0, 0.0, 0.0, 0.0]); info.bodies.len()]];
        let force = Force {
            name: evil,
            unit: evil,
            values: vec![1.0],
        };
        let path = std::env::temp_dir().join(format!("symbody-viewer-{}.html", std::process::id()));
        write(&path, evil, info, &[0.0], &poses, &[force]).unwrap();
        let page = std::fs::read_to_string(&path).unwrap();
        let _ = std::fs::remove_file(&path);
        let template = include_str!("viewer.html");
        for tag in ["</script", "<script", "<!--", "</"] {
            assert_eq!(
                page.matches(tag).count(),
                template.matches(tag).count(),
                "{tag}"
            );
        }
    }
}
