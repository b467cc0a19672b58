//! CSV outputs of a run: platform pose, joint reactions, actuator forces.

use crate::scenario::{Run, LEGS};
use std::fmt::Write as _;
use std::io;
use std::path::Path;

/// Writes a CSV: the header line, then one line per row (shortest round-trip numbers).
pub fn write(path: &Path, header: &str, rows: impl Iterator<Item = Vec<f64>>) -> io::Result<()> {
    let mut s = String::with_capacity(1 << 16);
    s.push_str(header);
    s.push('\n');
    for row in rows {
        for (i, v) in row.iter().enumerate() {
            if i > 0 {
                s.push(',');
            }
            // Shortest representation that reads back to the same f64.
            let _ = write!(s, "{v:?}");
        }
        s.push('\n');
    }
    std::fs::write(path, s)
}

fn force_header(prefix: &str) -> String {
    let mut h = String::from("t");
    for i in 1..=LEGS {
        for c in ["x", "y", "z"] {
            let _ = write!(h, ",{prefix}{i}_{c}");
        }
    }
    h
}

fn force_rows<'a>(run: &'a Run, f: &'a [[[f64; 3]; LEGS]]) -> impl Iterator<Item = Vec<f64>> + 'a {
    run.t.iter().zip(f).map(|(t, legs)| {
        std::iter::once(*t)
            .chain(legs.iter().flat_map(|v| v.iter().copied()))
            .collect()
    })
}

const PLATFORM_HEADER: &str = "t,x,y,z,theta,beta,gamma";

fn joint_forces_header() -> String {
    format!("{},{}", force_header("upper"), &force_header("lower")[2..])
}

fn actuators_header() -> String {
    let mut h = String::from("t");
    for i in 1..=LEGS {
        let _ = write!(h, ",act{i}");
    }
    h
}

/// The files [`write_csvs`] writes, each with its columns and their units (the headers
/// carry names only): the platform's pose in m and rad, the forces in N.
pub fn columns() -> Vec<(&'static str, Vec<(String, &'static str)>)> {
    let units = |header: &str, unit: fn(&str) -> &'static str| {
        header
            .split(',')
            .map(|c| (c.to_string(), if c == "t" { "s" } else { unit(c) }))
            .collect()
    };
    vec![
        (
            "platform.csv",
            units(PLATFORM_HEADER, |c| {
                if ["x", "y", "z"].contains(&c) {
                    "m"
                } else {
                    "rad"
                }
            }),
        ),
        ("joint_forces.csv", units(&joint_forces_header(), |_| "N")),
        ("actuators.csv", units(&actuators_header(), |_| "N")),
    ]
}

/// Writes `platform.csv`, `joint_forces.csv` and `actuators.csv` into `dir`.
pub fn write_csvs(run: &Run, dir: &Path) -> io::Result<()> {
    std::fs::create_dir_all(dir)?;
    write(
        &dir.join("platform.csv"),
        PLATFORM_HEADER,
        run.t
            .iter()
            .zip(&run.platform)
            .map(|(t, p)| std::iter::once(*t).chain(p.iter().copied()).collect()),
    )?;
    let header = joint_forces_header();
    write(
        &dir.join("joint_forces.csv"),
        &header,
        force_rows(run, &run.upper)
            .zip(force_rows(run, &run.lower))
            .map(|(mut u, l)| {
                u.extend_from_slice(&l[1..]);
                u
            }),
    )?;
    write(
        &dir.join("actuators.csv"),
        &actuators_header(),
        run.t
            .iter()
            .zip(&run.actuators)
            .map(|(t, a)| std::iter::once(*t).chain(a.iter().copied()).collect()),
    )
}
