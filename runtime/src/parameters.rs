//! Run-time parameters of generated code (docs/design.md, decision 35): the entries of a
//! file's `[parameters]` that reach only masses, inertias and springs' stiffness and damping
//! are inputs of the generated functions rather than literals, so they change without
//! regenerating.
//! Everything that depends on them alone is computed once per parameter set by the
//! generated `setup`; this module checks a new set before it replaces the old one.

use std::fmt;

/// Why a parameter set was refused; the previous set stays in force.
#[derive(Debug, Clone, PartialEq)]
pub enum ParameterError {
    /// No parameter of this name; `closest` is the nearest run-time parameter, if any.
    Unknown {
        name: String,
        closest: Option<&'static str>,
    },
    /// A parameter of the file that the generated code does not take at run time: derived
    /// from others, or reaching geometry, drivers or applied loads, which decide the assembly
    /// or the structure of the equations.
    NotRunTime { name: String },
    /// NaN or infinite.
    NotFinite { name: String, value: f64 },
    /// A whole `p` of the wrong length.
    Values { expected: usize, given: usize },
    /// A body's mass came out zero, negative or not finite.
    Mass {
        body: &'static str,
        value: f64,
        parameters: String,
    },
    /// A body's principal inertias came out non-positive, or no rigid body has them (one
    /// larger than the sum of the other two).
    Inertia {
        body: &'static str,
        values: [f64; 3],
        parameters: String,
    },
    /// A spring's stiffness or damping came out negative or not finite.
    ForceConstant {
        force: &'static str,
        field: &'static str,
        value: f64,
        parameters: String,
    },
}

impl fmt::Display for ParameterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParameterError::Unknown { name, closest } => {
                write!(f, "unknown parameter `{name}`")?;
                match closest {
                    Some(c) => write!(f, " (did you mean `{c}`?)"),
                    None => Ok(()),
                }
            }
            ParameterError::NotRunTime { name } => write!(
                f,
                "parameter `{name}` is not set by name in the generated code (it is derived \
                 from others, or reaches points, axes, lengths or drivers, which the mechanism \
                 file computes from it); set it on the mechanism file (`--set`, \
                 `files::with_parameters`), whose numbers at that value the compiled code takes"
            ),
            ParameterError::NotFinite { name, value } => {
                write!(f, "parameter `{name}` = {value}: give a finite number")
            }
            ParameterError::Values { expected, given } => write!(
                f,
                "{given} run-time values given where the generated code takes {expected}"
            ),
            ParameterError::Mass {
                body,
                value,
                parameters,
            } => write!(
                f,
                "body `{body}`: mass {value} with {parameters}; a mass must be positive"
            ),
            ParameterError::Inertia {
                body,
                values,
                parameters,
            } => write!(
                f,
                "body `{body}`: principal inertias {values:?} with {parameters}; each must be \
                 positive and at most the sum of the other two"
            ),
            ParameterError::ForceConstant {
                force,
                field,
                value,
                parameters,
            } => write!(
                f,
                "force `{force}`: {field} {value} with {parameters}; it must not be negative"
            ),
        }
    }
}

impl std::error::Error for ParameterError {}

/// The run-time parameters of one generated mechanism.
#[derive(Debug)]
pub struct RunTimeParameters {
    /// Their names, in the order of `p`.
    pub names: &'static [&'static str],
    /// The file's other parameters (refused with [`ParameterError::NotRunTime`]).
    pub others: &'static [&'static str],
    /// The bodies' names, in the order of `mass_properties`.
    pub bodies: &'static [&'static str],
    /// `mass_properties(p, out)`: each body's mass and three principal inertias.
    pub mass_properties: fn(&[f64], &mut [f64]),
    /// The forces' names, in the order of `force_constants`.
    pub forces: &'static [&'static str],
    /// `force_constants(p, out)`: each force's stiffness and damping (0 for applied loads).
    pub force_constants: fn(&[f64], &mut [f64]),
}

impl RunTimeParameters {
    /// `p` with the values of `set` (by name), checked: every name known, every value
    /// finite. On error `p` is unchanged.
    pub fn assign(&self, p: &mut [f64], set: &[(&str, f64)]) -> Result<(), ParameterError> {
        for &(name, value) in set {
            if !self.names.contains(&name) {
                if self.others.contains(&name) {
                    return Err(ParameterError::NotRunTime { name: name.into() });
                }
                let closest = self
                    .names
                    .iter()
                    .map(|c| (strsim::levenshtein(name, c), *c))
                    .filter(|(d, c)| *d <= 2.max(c.len() / 3))
                    .min()
                    .map(|(_, c)| c);
                return Err(ParameterError::Unknown {
                    name: name.into(),
                    closest,
                });
            }
            if !value.is_finite() {
                return Err(ParameterError::NotFinite {
                    name: name.into(),
                    value,
                });
            }
        }
        for &(name, value) in set {
            let i = self.names.iter().position(|n| *n == name).expect("checked");
            p[i] = value;
        }
        Ok(())
    }

    /// Checks the bodies' masses and inertias and the forces' stiffness and damping at `p`,
    /// which `set` gave its new values (named in the errors); `props` is scratch of four
    /// entries per body, `constants` of two per force.
    /// Copies a whole `p` (the named parameters, then the model's numbers) into `p`:
    /// `values` must have its length and finite numbers.
    pub fn assign_all(&self, p: &mut [f64], values: &[f64]) -> Result<(), ParameterError> {
        if values.len() != p.len() {
            return Err(ParameterError::Values {
                expected: p.len(),
                given: values.len(),
            });
        }
        if let Some(i) = values.iter().position(|v| !v.is_finite()) {
            let name = match self.names.get(i) {
                Some(n) => n.to_string(),
                None => format!("model number {}", i - self.names.len()),
            };
            let value = values[i];
            return Err(ParameterError::NotFinite { name, value });
        }
        p.copy_from_slice(values);
        Ok(())
    }

    pub fn check(
        &self,
        p: &[f64],
        set: &[(&str, f64)],
        props: &mut [f64],
        constants: &mut [f64],
    ) -> Result<(), ParameterError> {
        (self.mass_properties)(p, props);
        (self.force_constants)(p, constants);
        let shown = || match set.is_empty() {
            true => "these values".to_string(),
            false => {
                let values: Vec<String> = set.iter().map(|(n, v)| format!("{n} = {v}")).collect();
                format!("{} set", values.join(", "))
            }
        };
        for (b, v) in props.chunks_exact(4).enumerate() {
            let body = self.bodies[b];
            if !(v[0] > 0.0 && v[0].is_finite()) {
                return Err(ParameterError::Mass {
                    body,
                    value: v[0],
                    parameters: shown(),
                });
            }
            let i = [v[1], v[2], v[3]];
            let sum = i[0] + i[1] + i[2];
            // The same allowance for roundoff as the file's own check.
            let rigid = (0..3).all(|k| i[k] - (sum - i[k]) <= 1e-9 * sum);
            if !(i.iter().all(|x| *x > 0.0 && x.is_finite()) && rigid) {
                return Err(ParameterError::Inertia {
                    body,
                    values: i,
                    parameters: shown(),
                });
            }
        }
        for (f, v) in constants.chunks_exact(2).enumerate() {
            for (field, &value) in ["stiffness", "damping"].into_iter().zip(v) {
                if !(value >= 0.0 && value.is_finite()) {
                    return Err(ParameterError::ForceConstant {
                        force: self.forces[f],
                        field,
                        value,
                        parameters: shown(),
                    });
                }
            }
        }
        Ok(())
    }
}
