//! What a mechanism's `MechanismInfo` says about its joints and platform, computed once from
//! the model for both back ends: the Rust emitter writes it as statics ([`crate::rust`]), the
//! interpreter builds it as values ([`crate::interpret`]).

use crate::assembly::Assembly;
use crate::equations::System;
use crate::model::{DriverTarget, JointKind as ModelKind, Model};
use symbody_runtime::JointKind;

/// One `JointInfo`: a joint, a driver or a normalization row.
#[derive(Debug, Clone)]
pub struct Joint {
    pub name: String,
    pub kind: JointKind,
    pub body1: Option<usize>,
    pub body2: Option<usize>,
    pub row_start: usize,
    pub rows: usize,
    pub point1: [f64; 3],
    pub point2: [f64; 3],
    pub effort_sign: f64,
    pub effort_unit: &'static str,
}

/// One `LegInfo` of a detected platform.
#[derive(Debug, Clone)]
pub struct Leg {
    pub driver: String,
    pub base: [f64; 3],
    pub platform: [f64; 3],
    pub row: usize,
}

/// The joints in row order, then the drivers, then the normalization rows.
pub fn joints(model: &Model, sys: &System) -> Vec<Joint> {
    let mut out: Vec<Joint> = model
        .joints
        .iter()
        .enumerate()
        .map(|(k, j)| {
            let (body1, body2) = j.bodies();
            Joint {
                name: j.name.clone(),
                kind: match j.kind {
                    ModelKind::Spherical => JointKind::Spherical,
                    ModelKind::Revolute => JointKind::Revolute,
                    ModelKind::Universal => JointKind::Universal,
                    ModelKind::Cylindrical => JointKind::Cylindrical,
                    ModelKind::Prismatic => JointKind::Prismatic,
                    ModelKind::Fixed => JointKind::Fixed,
                    ModelKind::Distance { .. } => JointKind::Distance,
                    ModelKind::EulerPrismatic { .. } => JointKind::EulerPrismatic,
                },
                body1,
                body2,
                row_start: sys.joint_rows[k],
                rows: j.rows(),
                point1: j.f1.point,
                point2: j.f2.point,
                effort_sign: 0.0,
                effort_unit: "",
            }
        })
        .collect();
    for (k, d) in model.drivers.iter().enumerate() {
        let ((body1, body2), (point1, point2)) = match &d.target {
            DriverTarget::JointAngle(j) | DriverTarget::JointSlide(j) => {
                let j = &model.joints[*j];
                (j.bodies(), (j.f1.point, j.f2.point))
            }
            DriverTarget::BodyCoordinate { body, .. } => {
                let b = &model.bodies[*body];
                ((None, Some(*body)), ([b.q0[0], b.q0[1], b.q0[2]], [0.0; 3]))
            }
            DriverTarget::PointDistance { f1, f2 } => ((f1.body, f2.body), (f1.point, f2.point)),
        };
        out.push(Joint {
            name: d.name.clone(),
            kind: JointKind::Driver,
            body1,
            body2,
            row_start: sys.joint_rows[model.joints.len() + k],
            rows: 1,
            point1,
            point2,
            effort_sign: sys.driver_signs[k],
            effort_unit: if d.is_angular() { "N·m" } else { "N" },
        });
    }
    for (k, &b) in sys.normalized_bodies.iter().enumerate() {
        out.push(Joint {
            name: format!("{}.norm", model.bodies[b].name),
            kind: JointKind::Normalization,
            body1: Some(b),
            body2: None,
            row_start: sys.joint_rows[model.joints.len() + model.drivers.len() + k],
            rows: 1,
            point1: [0.0; 3],
            point2: [0.0; 3],
            effort_sign: 0.0,
            effort_unit: "",
        });
    }
    out
}

/// The platform body and its legs, when the assembly found a six-leg platform.
pub fn platform(model: &Model, sys: &System, asm: &Assembly) -> Option<(usize, Vec<Leg>)> {
    let p = asm.platform.as_ref()?;
    let legs = p
        .legs
        .iter()
        .map(|l| {
            let driver = model.drivers[l.driver].name.clone();
            assert_eq!(
                sys.row_names[l.row], driver,
                "legs::detect numbers rows as Φ does"
            );
            Leg {
                driver,
                base: l.base,
                platform: l.platform,
                row: l.row,
            }
        })
        .collect();
    Some((p.body, legs))
}
