//! The tables of a generic run (`bodies`, `joints`, `drivers`, `energy`): their columns, one
//! row per output, whole for Python and tests, and as CSV files written while the run goes,
//! so that a run that stops keeps every output it reached.

use crate::generic::Recording;
use crate::number::{self, Shortest};
use std::fs::File;
use std::io::{self, BufWriter, Write as _};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// One output table of a run: what `symbody simulate <name>` writes to `<stem>.csv` and what
/// the Python package returns as `simulate(name)[stem]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// File stem: `bodies`, `joints`, `drivers` or `energy` (the paper scenario's:
    /// `platform`, `joint_forces`, `actuators`, [`crate::output::tables`]).
    pub stem: &'static str,
    /// Column names, `t` first.
    pub columns: Vec<String>,
    /// One row per output time, `columns.len()` values each.
    pub rows: Vec<Vec<f64>>,
}

const STEMS: [&str; 4] = ["bodies", "joints", "drivers", "energy"];

/// A body's columns in `bodies.csv`: the pose, then (with [`Recording::velocities`]) the
/// velocity of the centre of mass and the angular velocity, then (with
/// [`Recording::accelerations`]) their rates.
const POSE: [&str; 7] = ["x", "y", "z", "qw", "qx", "qy", "qz"];
const VELOCITY: [&str; 6] = ["vx", "vy", "vz", "wx", "wy", "wz"];
const ACCELERATION: [&str; 6] = ["ax", "ay", "az", "alphax", "alphay", "alphaz"];

/// The parts of each body's column group in `rec`'s `bodies.csv`.
fn body_parts(rec: &Recording) -> Vec<&'static str> {
    let mut parts = POSE.to_vec();
    if rec.velocities {
        parts.extend(VELOCITY);
    }
    if rec.accelerations {
        parts.extend(ACCELERATION);
    }
    parts
}

/// The unit of column `column` (`t`, or `<item>.<part>`) of table `stem`: SI, `1` for the
/// dimensionless quaternion components; a driver's effort is a force or a torque by the
/// coordinate it drives.
pub fn unit(rec: &Recording, stem: &str, column: &str) -> &'static str {
    if column == "t" {
        return "s";
    }
    let part = column.rsplit_once('.').map_or("", |(_, p)| p);
    match stem {
        "bodies" => match part {
            "x" | "y" | "z" => "m",
            "vx" | "vy" | "vz" => "m/s",
            "wx" | "wy" | "wz" => "rad/s",
            "ax" | "ay" | "az" => "m/s²",
            "alphax" | "alphay" | "alphaz" => "rad/s²",
            _ => "1",
        },
        "joints" if part.starts_with('f') => "N",
        "joints" => "N·m",
        "drivers" => rec
            .drivers
            .iter()
            .map(|&j| &rec.info.joints[j])
            .find(|j| j.name == column)
            .map_or("", |j| j.effort_unit),
        _ => "J",
    }
}

/// The stems and columns (`t` first) of the tables `rec` records: one column group per
/// recorded body, joint and driver; a table with nothing recorded is left out.
pub fn columns(rec: &Recording) -> Vec<(&'static str, Vec<String>)> {
    let info = rec.info;
    let named = |names: &[usize], label: &dyn Fn(usize) -> &'static str, parts: &[&str]| {
        names
            .iter()
            .flat_map(|&i| {
                let name = label(i);
                parts.iter().map(move |c| format!("{name}.{c}"))
            })
            .collect::<Vec<_>>()
    };
    STEMS
        .into_iter()
        .filter_map(|stem| {
            let values = match stem {
                "bodies" => named(&rec.bodies, &|b| info.bodies[b].name, &body_parts(rec)),
                "joints" => named(
                    &rec.joints,
                    &|j| info.joints[j].name,
                    &["fx", "fy", "fz", "mx", "my", "mz"],
                ),
                "drivers" => rec
                    .drivers
                    .iter()
                    .map(|&j| info.joints[j].name.to_string())
                    .collect(),
                _ if rec.energy_table => ["kinetic", "potential", "work"].map(String::from).into(),
                _ => Vec::new(),
            };
            (!values.is_empty()).then(|| {
                (
                    stem,
                    std::iter::once("t".to_string()).chain(values).collect(),
                )
            })
        })
        .collect()
}

/// Row `k` (output `rec.t[k]`) of the table `stem`, `t` first.
pub fn row(rec: &Recording, stem: &str, k: usize) -> Vec<f64> {
    let mut row = vec![rec.t[k]];
    match stem {
        "bodies" => {
            for &b in &rec.bodies {
                let (r, e) = &rec.poses[k][b];
                row.extend(r.iter().chain(e));
                if rec.velocities {
                    row.extend(velocities(rec, b, k));
                }
                if rec.accelerations {
                    row.extend(accelerations(rec, b, k));
                }
            }
        }
        "joints" => row.extend(
            rec.wrenches[k]
                .iter()
                .flat_map(|w| w.force.iter().chain(&w.moment).copied()),
        ),
        "drivers" => row.extend(&rec.efforts[k]),
        _ => {
            let e = &rec.energy[k];
            row.extend([e.kinetic, e.potential, e.work]);
        }
    }
    row
}

/// Body `b`'s centre-of-mass velocity and global angular velocity at output `k`, from the
/// recorded coordinates and their rates (the first three coordinates of a body are its
/// centre of mass).
fn velocities(rec: &Recording, b: usize, k: usize) -> [f64; 6] {
    let body = &rec.info.bodies[b];
    let (q, qd) = (&rec.q[k], &rec.qd[k]);
    let v = &qd[body.coord_offset..body.coord_offset + 3];
    // The coordinates were recorded from a valid state, so their slices exist.
    let w = symbody_runtime::pose::angular_velocity(body, q, qd)
        .map_or([f64::NAN; 3], |w| [w.x, w.y, w.z]);
    [v[0], v[1], v[2], w[0], w[1], w[2]]
}

/// Body `b`'s centre-of-mass acceleration and global angular acceleration at output `k`.
fn accelerations(rec: &Recording, b: usize, k: usize) -> [f64; 6] {
    let body = &rec.info.bodies[b];
    let (q, qd, qdd) = (&rec.q[k], &rec.qd[k], &rec.qdd[k]);
    let a = &qdd[body.coord_offset..body.coord_offset + 3];
    let w = symbody_runtime::pose::angular_acceleration(body, q, qd, qdd)
        .map_or([f64::NAN; 3], |w| [w.x, w.y, w.z]);
    [a[0], a[1], a[2], w[0], w[1], w[2]]
}

/// The tables of a run, whole ([`columns`], every output's [`row`]).
pub fn tables(rec: &Recording) -> Vec<Table> {
    columns(rec)
        .into_iter()
        .map(|(stem, columns)| Table {
            stem,
            columns,
            rows: (0..rec.t.len()).map(|k| row(rec, stem, k)).collect(),
        })
        .collect()
}

/// Writes `bodies.csv`, `joints.csv`, `drivers.csv` and `energy.csv` ([`tables`]) into `dir`.
pub fn write_csvs(rec: &Recording, dir: &Path) -> io::Result<Vec<PathBuf>> {
    let mut files = CsvTables::create(rec, dir)?;
    for k in 0..rec.t.len() {
        files.append(rec, k)?;
    }
    files.finish()
}

/// How long rows may wait in memory before they are flushed to disk: a run that is killed
/// loses at most this much of its output, and a run with many small outputs does not pay a
/// system call for each.
const FLUSH_EVERY: Duration = Duration::from_millis(200);

/// The tables' CSV files, open while a run goes: [`CsvTables::create`] writes the headers
/// before the first step (so an unwritable folder is reported before any work), and
/// [`CsvTables::append`] each output as it is recorded.
pub struct CsvTables {
    files: Vec<(&'static str, PathBuf, BufWriter<File>)>,
    flushed: Instant,
    number: Shortest,
}

impl CsvTables {
    /// Creates `dir` and one file per table of `rec` (its selection of bodies, joints,
    /// drivers; no rows yet), with its header. Names from the mechanism file are quoted
    /// where CSV needs it.
    pub fn create(rec: &Recording, dir: &Path) -> io::Result<Self> {
        std::fs::create_dir_all(dir)?;
        let mut files = Vec::new();
        for (stem, columns) in columns(rec) {
            let path = dir.join(format!("{stem}.csv"));
            let mut w = BufWriter::new(File::create(&path)?);
            number::write_header(&mut w, &columns)?;
            files.push((stem, path, w));
        }
        let mut tables = CsvTables {
            files,
            flushed: Instant::now(),
            number: Shortest::default(),
        };
        tables.flush()?;
        Ok(tables)
    }

    /// Appends output `k` of `rec` to every file (flushing now and then, see
    /// [`FLUSH_EVERY`]).
    pub fn append(&mut self, rec: &Recording, k: usize) -> io::Result<()> {
        for (stem, _, w) in &mut self.files {
            // Shortest text that reads back to the same f64 (as the paper's CSVs).
            number::write_record(w, row(rec, stem, k), &mut self.number)?;
        }
        if self.flushed.elapsed() >= FLUSH_EVERY {
            self.flush()?;
        }
        Ok(())
    }

    fn flush(&mut self) -> io::Result<()> {
        for (_, _, w) in &mut self.files {
            w.flush()?;
        }
        self.flushed = Instant::now();
        Ok(())
    }

    /// Flushes every file and returns their paths.
    pub fn finish(mut self) -> io::Result<Vec<PathBuf>> {
        self.flush()?;
        Ok(self.files.into_iter().map(|(_, path, _)| path).collect())
    }
}
