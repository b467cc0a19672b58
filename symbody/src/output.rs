//! CSV outputs of a run: platform pose, joint reactions, actuator forces.

use crate::number::Shortest;
use crate::scenario::{Run, LEGS};
use crate::tables::Table;
use std::io;
use std::path::Path;

/// Writes a CSV: the header line, then one line per row (shortest round-trip numbers).
pub fn write(path: &Path, header: &str, rows: impl Iterator<Item = Vec<f64>>) -> io::Result<()> {
    let mut s = Vec::with_capacity(1 << 16);
    let mut num = Shortest::default();
    s.extend_from_slice(header.as_bytes());
    s.push(b'\n');
    for row in rows {
        crate::number::write_record(&mut s, row, &mut num)?;
    }
    std::fs::write(path, s)
}

/// `t`, then `names`.
fn with_t(names: impl IntoIterator<Item = String>) -> Vec<String> {
    std::iter::once("t".to_string()).chain(names).collect()
}

/// `{prefix}{leg}_{x,y,z}` for every leg.
fn force_columns(prefix: &str) -> impl Iterator<Item = String> + '_ {
    (1..=LEGS).flat_map(move |i| ["x", "y", "z"].map(|c| format!("{prefix}{i}_{c}")))
}

/// The paper scenario's tables (`platform`, `joint_forces`, `actuators`): the columns and
/// rows of its CSV files, whole, for the Python package and [`write_csvs`].
pub fn tables(run: &Run) -> Vec<Table> {
    let rows = |row: &dyn Fn(usize) -> Vec<f64>| (0..run.t.len()).map(row).collect();
    let at = |k: usize, values: &[f64]| {
        let mut row = vec![run.t[k]];
        row.extend_from_slice(values);
        row
    };
    vec![
        Table {
            stem: "platform",
            columns: with_t(["x", "y", "z", "theta", "beta", "gamma"].map(String::from)),
            rows: rows(&|k| at(k, &run.platform[k])),
        },
        Table {
            stem: "joint_forces",
            columns: with_t(force_columns("upper").chain(force_columns("lower"))),
            rows: rows(&|k| at(k, &[run.upper[k].concat(), run.lower[k].concat()].concat())),
        },
        Table {
            stem: "actuators",
            columns: with_t((1..=LEGS).map(|i| format!("act{i}"))),
            rows: rows(&|k| at(k, &run.actuators[k])),
        },
    ]
}

/// The files [`write_csvs`] writes, each with its columns and their units (the headers
/// carry names only): the platform's pose in m and rad, the forces in N.
pub fn columns() -> Vec<(String, Vec<(String, &'static str)>)> {
    tables(&Run::default())
        .into_iter()
        .map(|table| {
            let units = table
                .columns
                .into_iter()
                .map(|c| {
                    let unit = match c.as_str() {
                        "t" => "s",
                        "x" | "y" | "z" => "m",
                        "theta" | "beta" | "gamma" => "rad",
                        _ => "N",
                    };
                    (c, unit)
                })
                .collect();
            (format!("{}.csv", table.stem), units)
        })
        .collect()
}

/// Writes `platform.csv`, `joint_forces.csv` and `actuators.csv` ([`tables`]) into `dir`.
pub fn write_csvs(run: &Run, dir: &Path) -> io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for table in tables(run) {
        write(
            &dir.join(format!("{}.csv", table.stem)),
            &table.columns.join(","),
            table.rows.into_iter(),
        )?;
    }
    Ok(())
}
