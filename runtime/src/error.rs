//! The runtime's one error type: every failure carries the time, residual and names needed
//! to act on it, so no solver ever has to return a result it does not trust.

use std::fmt;

use crate::mechanism::{JointKind, MechanismInfo};

/// Newton's last increment in a step that did not converge: how far from its tolerance it
/// stayed, and in which unknown.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewtonIncrement {
    /// The largest weighted increment (1 = the tolerances `rel_tol`, `abs_tol_*`).
    pub size: f64,
    /// The coordinate where it is largest ([`MechanismInfo::coord_names`]).
    pub coord: &'static str,
    /// Whether in the constraint force Φqᵀλ on that coordinate; otherwise in its
    /// acceleration.
    pub constraint_force: bool,
}

/// A constraint row named for a report.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ConstraintRow {
    /// Row index in Φ.
    pub row: usize,
    /// The row's name from [`MechanismInfo::row_names`] (`"?"` if the mechanism has none).
    pub name: &'static str,
    /// The joint owning the row (`"?"` if none does).
    pub joint: &'static str,
    /// What owns the row, in the words of the mechanism file: reports say "joint `j`",
    /// "driver `d`" or "the unit-quaternion condition of body `b`" from it, never an
    /// internal row name the user did not write (`b.norm`).
    pub owner: RowOwner,
}

/// What a constraint row belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RowOwner {
    /// A `[[joint]]` of the file; the row is `<joint>.<primitive>`.
    Joint,
    /// A `[[driver]]`: one row, named as the driver.
    Driver,
    /// A quaternion body's `eᵀe = 1`: generated, not written in the file.
    UnitQuaternion { body: &'static str },
    /// Outside every joint (a hand-written mechanism without joint tables).
    Unknown,
}

impl ConstraintRow {
    /// Looks the row's names up in `info`; never panics on an out-of-range row.
    pub fn new(info: &MechanismInfo, row: usize) -> Self {
        let owner = info.joint_of_row(row);
        ConstraintRow {
            row,
            name: info.row_names.get(row).copied().unwrap_or("?"),
            joint: owner.map(|j| j.name).unwrap_or("?"),
            owner: match owner.map(|j| (j.kind, j.body1)) {
                Some((JointKind::Normalization, b)) => RowOwner::UnitQuaternion {
                    body: b.and_then(|b| info.bodies.get(b)).map_or("?", |b| b.name),
                },
                Some((JointKind::Driver, _)) => RowOwner::Driver,
                Some(_) => RowOwner::Joint,
                None => RowOwner::Unknown,
            },
        }
    }
}

impl fmt::Display for ConstraintRow {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.owner {
            RowOwner::UnitQuaternion { body } => write!(
                f,
                "the unit-quaternion condition of body `{body}` (e0² + e1² + e2² + e3² = 1, \
                 row {})",
                self.row
            ),
            RowOwner::Driver => write!(f, "driver `{}` (row {})", self.joint, self.row),
            RowOwner::Joint => write!(
                f,
                "joint `{}` (row {} `{}`)",
                self.joint, self.row, self.name
            ),
            RowOwner::Unknown => write!(f, "row {} `{}`", self.row, self.name),
        }
    }
}

/// Everything that can go wrong in the runtime.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A Newton iteration did not converge within its iteration limit (or diverged).
    NewtonFailed {
        /// What was being solved, e.g. `"position analysis"` or `"HHT step"`.
        analysis: &'static str,
        time: f64,
        /// Unscaled constraint residual |Φ|∞ at the iterate closest to Φ = 0 (the last one
        /// when the analysis does not keep the best).
        residual: f64,
        iterations: usize,
        /// The row where that residual is largest (what could not be satisfied), when the
        /// analysis has constraint rows.
        row: Option<ConstraintRow>,
    },
    /// HHT had to cut the step below the minimum without converging.
    StepSizeTooSmall {
        time: f64,
        step: f64,
        /// Unscaled constraint residual |Φ|∞ of the last failed attempt.
        residual: f64,
        /// The row where that residual is largest (what could not be satisfied), when the
        /// attempt got far enough to evaluate Φ.
        row: Option<ConstraintRow>,
        /// Newton's last increment, when the attempt got as far as one: with Φ satisfied it
        /// says what did not settle (an acceleration or a constraint force). Boxed: it is
        /// rare, and every `Result` carrying an `Error` would otherwise grow by its size.
        increment: Option<Box<NewtonIncrement>>,
    },
    /// Step-size control cut the step below the minimum without meeting the tolerances:
    /// the local error estimate (weighted RMS, 1 = the tolerance) stayed above 1.
    ToleranceNotMet {
        time: f64,
        step: f64,
        /// The weighted local error estimate of the last attempt (> 1).
        error: f64,
        /// The coordinate whose weighted error was largest, and whether in its velocity.
        coord: &'static str,
        velocity: bool,
        /// Unscaled constraint residual |Φ|∞ of the last attempt (it converged).
        residual: f64,
    },
    /// The constraint Jacobian lost rank: these rows are (numerically) dependent on others.
    SingularJacobian { time: f64, rows: Vec<ConstraintRow> },
    /// The independent constraint rows are satisfied but these redundant rows
    /// ([`MechanismInfo::redundant_rows`]) are not: they contradict the others, so the
    /// mechanism's geometry (joint points, axes, lengths) is inconsistent.
    InconsistentConstraints {
        time: f64,
        rows: Vec<ConstraintRow>,
        /// Largest |Φ| over the redundant rows.
        residual: f64,
    },
    /// The mass matrix is not positive definite in the block holding this coordinate.
    MassNotPositiveDefinite {
        time: f64,
        coord: usize,
        name: &'static str,
    },
    /// A body's Euler angles came too close to the β = ±90° singularity.
    EulerSingularity {
        time: f64,
        body: &'static str,
        /// β in radians.
        beta: f64,
    },
    /// A platform held by six legs of driven length reached a parallel (type-II)
    /// singularity while its pose was tracked along the legs' lengths: there the lengths stop
    /// determining the pose, and beyond it the pose can continue on another assembly mode.
    PlatformSingularity {
        /// Time (or path parameter) of the singular pose.
        time: f64,
        /// Condition number of the platform's homogeneous Jacobian there.
        condition: f64,
        /// The legs (one-based) whose lines became linearly dependent.
        legs: Vec<usize>,
        /// `true` when the tracked pose had already passed to another assembly mode (the
        /// Jacobian's determinant changed sign), `false` when it was stopped before.
        switched: bool,
    },
    /// A NaN or infinity appeared in the named quantity.
    NotFinite { time: f64, what: &'static str },
    /// A setting is out of its valid range.
    InvalidSetting {
        name: &'static str,
        value: f64,
        reason: &'static str,
    },
    /// A slice or vector had the wrong length.
    DimensionMismatch {
        what: &'static str,
        expected: usize,
        got: usize,
    },
    /// A joint, body or row index that does not exist, or a joint of the wrong kind.
    InvalidIndex {
        what: &'static str,
        index: usize,
        reason: &'static str,
    },
    /// The sparsity patterns in the mechanism info are inconsistent.
    InvalidPattern { reason: String },
    /// A sensitivity analysis needs the directional derivatives of the equations
    /// ([`crate::Mechanism::tangents`]), which this mechanism does not provide.
    NoTangents { mechanism: &'static str },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NewtonFailed {
                analysis,
                time,
                residual,
                iterations,
                row,
            } => {
                write!(
                    f,
                    "{analysis}: Newton iteration failed at t = {time:.6} s after {iterations} \
                     iterations, constraint residual |Φ|∞ = {residual:e}"
                )?;
                match row {
                    Some(r) => write!(f, ", largest in {r}"),
                    None => Ok(()),
                }
            }
            Error::StepSizeTooSmall {
                time,
                step,
                residual,
                row,
                increment,
            } => {
                write!(
                    f,
                    "HHT step size {step:.3e} s at t = {time:.6} s is below the minimum \
                     without convergence"
                )?;
                if let Some(inc) = increment {
                    let NewtonIncrement {
                        size,
                        coord,
                        constraint_force,
                    } = **inc;
                    let what = match constraint_force {
                        true => "constraint force on",
                        false => "acceleration of",
                    };
                    write!(
                        f,
                        ": Newton's last increment is {size:.3e} times its tolerance, largest \
                         in the {what} `{coord}`"
                    )?;
                }
                write!(f, "; constraint residual |Φ|∞ = {residual:.3e}")?;
                match row {
                    Some(r) => write!(f, ", largest in {r}"),
                    None => Ok(()),
                }
            }
            Error::ToleranceNotMet {
                time,
                step,
                error,
                coord,
                velocity,
                residual,
            } => write!(
                f,
                "HHT step size {step:e} s at t = {time:.6} s is below the minimum and the local \
                 error estimate is still {error:.3e} times the tolerance (largest in the {} of \
                 `{coord}`; constraint residual |Φ|∞ = {residual:e}): loosen rtol/atol or lower \
                 min_step",
                if *velocity { "velocity" } else { "position" }
            ),
            Error::SingularJacobian { time, rows } => {
                write!(
                    f,
                    "constraint Jacobian lost rank at t = {time:.6} s (residual not \
                     available: the system has no unique solution); dependent rows:"
                )?;
                for (i, r) in rows.iter().enumerate() {
                    write!(f, "{} {r}", if i == 0 { "" } else { "," })?;
                }
                write!(
                    f,
                    ". If the mechanism passes this position by design (a linkage lying flat), \
                     let the solver drop the dependent rows there: `--cross-singular-positions` \
                     (scenes: `[solver] cross_singular_positions = true`)"
                )
            }
            Error::InconsistentConstraints {
                time,
                rows,
                residual,
            } => {
                write!(
                    f,
                    "redundant constraint rows contradict the others at t = {time:.6} s: with \
                     the independent rows satisfied they keep a residual |Φ|∞ = {residual:e}; \
                     fix the geometry (joint points, axes or lengths) so they agree; rows:"
                )?;
                for (i, r) in rows.iter().enumerate() {
                    write!(f, "{} {r}", if i == 0 { "" } else { "," })?;
                }
                Ok(())
            }
            Error::MassNotPositiveDefinite { time, coord, name } => write!(
                f,
                "mass matrix is not positive definite at t = {time:.6} s in the block of \
                 coordinate {coord} `{name}`"
            ),
            Error::EulerSingularity { time, body, beta } => write!(
                f,
                "body `{body}` reached β = {:.3}° at t = {time:.6} s, too close to the Euler \
                 singularity at ±90° (cos β = {:.3e})",
                beta.to_degrees(),
                beta.cos()
            ),
            Error::PlatformSingularity {
                time,
                condition,
                legs,
                switched,
            } => {
                let legs: Vec<String> = legs.iter().map(|l| l.to_string()).collect();
                write!(
                    f,
                    "the platform reaches a parallel singularity at t = {time:.6} (condition \
                     number {condition:.3e} of its Jacobian; the lines of legs {} are nearly \
                     dependent): ",
                    legs.join(", ")
                )?;
                if *switched {
                    write!(
                        f,
                        "the tracked pose passed to another assembly mode there (the \
                         Jacobian's determinant changed sign)"
                    )
                } else {
                    write!(
                        f,
                        "the leg lengths stop determining the pose, and beyond it the pose \
                         would have to jump to another assembly mode; change the leg-length \
                         path to keep away from it"
                    )
                }
            }
            Error::NotFinite { time, what } => {
                write!(f, "non-finite value in {what} at t = {time:.6} s")
            }
            Error::InvalidSetting {
                name,
                value,
                reason,
            } => write!(f, "invalid setting {name} = {value}: {reason}"),
            Error::DimensionMismatch {
                what,
                expected,
                got,
            } => write!(f, "{what} has length {got}, expected {expected}"),
            Error::InvalidIndex {
                what,
                index,
                reason,
            } => write!(f, "invalid {what} index {index}: {reason}"),
            Error::InvalidPattern { reason } => write!(f, "invalid sparsity pattern: {reason}"),
            Error::NoTangents { mechanism } => write!(
                f,
                "`{mechanism}` has no directional derivatives of its equations, which \
                 sensitivities need: regenerate its code (`cargo xtask generate`) or load \
                 its file"
            ),
        }
    }
}

impl std::error::Error for Error {}

/// Checks a slice length, for public entry points that must not panic on bad input.
pub(crate) fn check_len(what: &'static str, expected: usize, got: usize) -> Result<(), Error> {
    if expected == got {
        Ok(())
    } else {
        Err(Error::DimensionMismatch {
            what,
            expected,
            got,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanism::Mechanism;
    use crate::testmodels::{CircleDriver, QuaternionPendulum};

    #[test]
    fn rows_are_named_by_what_the_file_wrote() {
        // The quaternion pendulum's rows: pivot.x, pivot.y, pivot.z, then bob.norm, which
        // the generator adds and no file names.
        let info = QuaternionPendulum.info();
        let norm = ConstraintRow::new(info, 3).to_string();
        assert!(
            norm.contains("unit-quaternion condition of body `bob`") && !norm.contains(".norm"),
            "{norm}"
        );
        let joint = ConstraintRow::new(info, 1).to_string();
        assert!(
            joint.starts_with("joint `pivot`") && joint.contains("pivot.y"),
            "{joint}"
        );
        let driver = ConstraintRow::new(CircleDriver.info(), 5).to_string();
        assert!(driver.starts_with("driver `lift`"), "{driver}");
        let error = Error::SingularJacobian {
            time: 0.5,
            rows: vec![ConstraintRow::new(info, 3)],
        }
        .to_string();
        assert!(!error.contains("bob.norm"), "{error}");
        let outside = ConstraintRow::new(info, 99).to_string();
        assert!(outside.contains("row 99"), "{outside}");
    }
}
