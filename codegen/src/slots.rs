//! The numbers of a model that its parameters reach (joint points and axes, lengths, drivers'
//! and loads' constants, masses computed from geometry), so the generated code can take them
//! at run time as `Var::P` (docs/design.md, decision 36).
//!
//! The loader computes these numbers (initial poses, placements, joint frames made local to
//! their bodies), so which of them a parameter reaches is found by loading the file again at
//! slightly moved values: a number that moves is a slot. The equation stages then read the
//! model with each slot [`marked`], and [`Arena::constant`](crate::expr::Arena::constant)
//! writes it as a variable. At run time the file is loaded at the new values and the slots'
//! numbers are read off the new model ([`values_at`]); the other numbers must be the same, or
//! the compiled code does not hold that model.

use crate::diag::Errors;
use crate::expr::{marked, Arena, Id, Node};
use crate::model::{self, DriverTarget, ForceKind, Frame, JointKind, Model};

/// Relative move of each parameter when looking for the numbers it reaches: far above
/// roundoff, far below any value where a mechanism changes its structure.
const NUDGE: f64 = 1e-7;

/// Two values of a number the compiled code holds as a constant are the same when they differ
/// by less than this times the model's largest number: roundoff of the loader's arithmetic (a
/// local axis component that is 0 at one value and 7e-18 at another), not another structure.
const SAME: f64 = 1e-14;

/// Where a model's numbers that its parameters reach are: positions in [`numbers`].
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Slots(pub Vec<u32>);

impl Slots {
    pub fn len(&self) -> usize {
        self.0.len()
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

/// What a number of the model belongs to, as diagnostics name it.
#[derive(Debug, Clone, Copy)]
pub enum Item<'a> {
    Gravity,
    Parameter(&'a str),
    Body(&'a str),
    Joint(&'a str),
    Driver(&'a str),
    Force(&'a str),
}

impl std::fmt::Display for Item<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Item::Gravity => write!(f, "the gravity"),
            Item::Parameter(n) => write!(f, "parameter `{n}`"),
            Item::Body(n) => write!(f, "body `{n}`"),
            Item::Joint(n) => write!(f, "joint `{n}`"),
            Item::Driver(n) => write!(f, "driver `{n}`"),
            Item::Force(n) => write!(f, "force `{n}`"),
        }
    }
}

type Visitor<'f> = dyn FnMut(Item<'_>, &mut f64) + 'f;

/// Every number of `m` that the equation stages read as a field, in a fixed order, with what
/// it belongs to (the constants of its expressions in `t` follow, from [`expressions`]).
fn visit(m: &mut Model, f: &mut Visitor<'_>) {
    fn frame(fr: &mut Frame, item: Item<'_>, f: &mut Visitor<'_>) {
        for v in fr.point.iter_mut().chain(&mut fr.x).chain(&mut fr.z) {
            f(item, v);
        }
    }
    for v in &mut m.gravity {
        f(Item::Gravity, v);
    }
    // Parameters' values: the expressions of masses and inertias read them.
    for p in m.parameters.iter_mut().filter(|p| p.expression.is_none()) {
        f(Item::Parameter(&p.name), &mut p.value);
    }
    for b in &mut m.bodies {
        let item = Item::Body(&b.name);
        for v in std::iter::once(&mut b.mass).chain(&mut b.inertia) {
            f(item, v);
        }
    }
    for j in &mut m.joints {
        let item = Item::Joint(&j.name);
        frame(&mut j.f1, item, f);
        frame(&mut j.f2, item, f);
        match &mut j.kind {
            JointKind::Distance { length } => f(item, length),
            JointKind::EulerPrismatic { axis, perp } => {
                for v in axis.iter_mut().chain(perp.iter_mut().flatten()) {
                    f(item, v);
                }
            }
            _ => {}
        }
    }
    for d in &mut m.drivers {
        if let DriverTarget::PointDistance { f1, f2 } = &mut d.target {
            frame(f1, Item::Driver(&d.name), f);
            frame(f2, Item::Driver(&d.name), f);
        }
    }
    for force in &mut m.forces {
        let item = Item::Force(&force.name);
        match &mut force.kind {
            ForceKind::Spring {
                f1,
                f2,
                stiffness,
                damping,
                free_length,
                ..
            } => {
                frame(f1, item, f);
                frame(f2, item, f);
                for v in [stiffness, damping, free_length] {
                    f(item, v);
                }
            }
            ForceKind::Torsion {
                stiffness,
                damping,
                free_angle,
                ..
            } => {
                for v in [stiffness, damping, free_angle] {
                    f(item, v);
                }
            }
            ForceKind::Force { at, .. } => frame(at, item, f),
            ForceKind::Torque { .. } => {}
        }
    }
}

/// The roots of `m`'s expressions in `t` (drivers' values, actuators' forces and torques,
/// applied loads), with what each belongs to.
fn expressions(m: &mut Model) -> Vec<(Item<'_>, &mut Id)> {
    let mut roots: Vec<(Item<'_>, &mut Id)> = m
        .drivers
        .iter_mut()
        .map(|d| (Item::Driver(&d.name), &mut d.value))
        .collect();
    for force in &mut m.forces {
        let item = Item::Force(&force.name);
        match &mut force.kind {
            ForceKind::Spring { actuator, .. } => roots.push((item, actuator)),
            ForceKind::Torsion { torque, .. } => roots.push((item, torque)),
            ForceKind::Force { value, .. } | ForceKind::Torque { value, .. } => {
                roots.extend(value.iter_mut().map(|v| (item, v)))
            }
        }
    }
    roots
}

/// What number `i` of [`numbers`] belongs to, as diagnostics name it.
pub fn owner(m: &Model, i: usize) -> String {
    let mut copy = m.clone();
    let (mut k, mut found) = (0, None);
    visit(&mut copy, &mut |item, _| {
        if k == i {
            found = Some(item.to_string());
        }
        k += 1;
    });
    let arena = copy.arena.clone();
    for (item, root) in expressions(&mut copy) {
        let mut values = Vec::new();
        walk(&arena, *root, &mut Vec::new(), &mut values);
        if found.is_none() && (k..k + values.len()).contains(&i) {
            found = Some(item.to_string());
        }
        k += values.len();
    }
    found.unwrap_or_else(|| format!("number {i}"))
}

/// The node `n` with its constant's value and children left out: its kind.
fn kind(n: Node) -> Node {
    let z = Id(0);
    match n {
        Node::Const(_) => Node::Const(0),
        Node::Var(v) => Node::Var(v),
        Node::Add(..) => Node::Add(z, z),
        Node::Mul(..) => Node::Mul(z, z),
        Node::Neg(_) => Node::Neg(z),
        Node::Recip(_) => Node::Recip(z),
        Node::Powi(_, k) => Node::Powi(z, k),
        Node::Atan2(..) => Node::Atan2(z, z),
        Node::Call(f, _) => Node::Call(f, z),
    }
}

/// The children of `n` in an order that does not depend on node ids: a sum's or product's
/// constant first (the arena orders their operands by id, and which constant is older
/// depends on values that other expressions share).
fn children(a: &Arena, n: Node) -> Vec<Id> {
    match n {
        Node::Add(x, y) | Node::Mul(x, y) if a.as_const(y).is_some() => vec![y, x],
        _ => n.children().collect(),
    }
}

/// The expression `id` read as a tree (a shared node once per use), depth first: each
/// node's kind into `shape`, each constant into `values`.
fn walk(a: &Arena, id: Id, shape: &mut Vec<Node>, values: &mut Vec<f64>) {
    let n = a.node(id);
    shape.push(kind(n));
    match n {
        Node::Const(bits) => values.push(f64::from_bits(bits)),
        _ => children(a, n)
            .into_iter()
            .for_each(|c| walk(a, c, shape, values)),
    }
}

/// The expression `id` built again, in the same order as [`walk`], with each constant
/// replaced by what `next` makes of it.
fn rebuild(a: &mut Arena, id: Id, next: &mut dyn FnMut(f64) -> f64) -> Id {
    match a.node(id) {
        Node::Const(bits) => {
            let v = next(f64::from_bits(bits));
            a.constant(v)
        }
        Node::Var(v) => a.var(v),
        n @ (Node::Add(..) | Node::Mul(..)) => {
            let c = children(a, n);
            let (x, y) = (rebuild(a, c[0], next), rebuild(a, c[1], next));
            match n {
                Node::Add(..) => a.add(x, y),
                _ => a.mul(x, y),
            }
        }
        Node::Atan2(x, y) => {
            let (x, y) = (rebuild(a, x, next), rebuild(a, y, next));
            a.atan2(x, y)
        }
        Node::Neg(x) => {
            let x = rebuild(a, x, next);
            a.neg(x)
        }
        Node::Recip(x) => {
            let x = rebuild(a, x, next);
            a.recip(x)
        }
        Node::Powi(x, k) => {
            let x = rebuild(a, x, next);
            a.powi(x, k)
        }
        Node::Call(f, x) => {
            let x = rebuild(a, x, next);
            a.call(f, x)
        }
    }
}

/// The numbers the equation stages read from `m` (fields, then the constants of its
/// expressions in `t`), and the shape of those expressions.
pub fn numbers(m: &Model) -> (Vec<f64>, Vec<Node>) {
    let mut copy = m.clone();
    let mut values = Vec::new();
    visit(&mut copy, &mut |_, v| values.push(*v));
    let mut shape = Vec::new();
    let arena = copy.arena.clone();
    for (_, root) in expressions(&mut copy) {
        walk(&arena, *root, &mut shape, &mut values);
    }
    (values, shape)
}

/// The slots of `model` (loaded from `text`, named `source` in messages): the numbers that
/// move when every parameter moves a little. None where the file does not load there, or its
/// expressions change shape. (The numbers that the run-time parameters by name reach, masses
/// and springs' constants, are slots too, which the equations do not read: they read the
/// parameters.)
pub fn find(source: &str, text: &str, model: &Model) -> Slots {
    let set: Vec<(String, f64)> = model
        .parameters
        .iter()
        // A derived parameter set from outside is a number of this model like the others.
        .filter(|p| p.expression.is_none() || p.overridden)
        .enumerate()
        .map(|(i, p)| {
            // Each parameter by its own amount, so that no two moves cancel.
            let factor = NUDGE * (1.0 + (i as f64 * 0.618_033_988_749_895).fract());
            let v = match p.value {
                0.0 => factor,
                v => v * (1.0 + factor),
            };
            (p.name.clone(), v)
        })
        .collect();
    if set.is_empty() {
        return Slots::default();
    }
    let Ok(other) = model::load_with(source, text, &set) else {
        return Slots::default();
    };
    let ((a, shape_a), (b, shape_b)) = (numbers(model), numbers(&other));
    if a.len() != b.len() || shape_a != shape_b {
        return Slots::default();
    }
    Slots(
        (0..a.len() as u32)
            .filter(|&i| a[i as usize].to_bits() != b[i as usize].to_bits())
            .collect(),
    )
}

/// Finds `model`'s slots, sets [`Model::data`] to their values and returns the model the
/// equation stages read: each slot [`marked`] as `p[n + i]` (`n` run-time parameters).
pub fn mark(source: &str, text: &str, model: &mut Model) -> Model {
    let slots = find(source, text, model);
    model.data = data(model, &slots);
    model.data_slots = slots.0.clone();
    let n = model.run_time_parameters().len() as u32;
    let mut marked_model = model.clone();
    let mut position = 0u32;
    let mut next = slots.0.iter().peekable();
    let mut k = n;
    let mut mark_next = |v: f64| -> f64 {
        let out = match next.peek() == Some(&&position) {
            true => {
                next.next();
                k += 1;
                marked(k - 1)
            }
            false => v,
        };
        position += 1;
        out
    };
    visit(&mut marked_model, &mut |_, v| *v = mark_next(*v));
    let mut arena = std::mem::take(&mut marked_model.arena);
    for (_, root) in expressions(&mut marked_model) {
        *root = rebuild(&mut arena, *root, &mut mark_next);
    }
    marked_model.arena = arena;
    marked_model
}

/// The values of `slots` in `m`.
fn data(m: &Model, slots: &Slots) -> Vec<f64> {
    let all = numbers(m).0;
    slots.0.iter().map(|&i| all[i as usize]).collect()
}

/// Why the code generated from a file cannot take a set of parameter values.
#[derive(Debug)]
pub enum Refused {
    /// The file does not load with these values (its diagnostics).
    Load(Errors),
    /// The generated code's slots do not hold the numbers this generator finds at their
    /// positions: the code is from another version of the generator.
    OtherSlots,
    /// A number the generated code holds as a constant differs with these values, or an
    /// expression in `t` changes its terms: what it belongs to.
    Structure(String),
}

/// `p` for the code generated from `text` (its slots `expected`, positions in [`numbers`], and `p`
/// at the file's values `p0`) with `overrides` set: the run-time parameters' values, then the
/// slots' numbers of the file loaded at these values; and that model.
pub fn values_at(
    source: &str,
    text: &str,
    overrides: &[(String, f64)],
    expected: &[u32],
    p0: &[f64],
) -> Result<(Vec<f64>, Model), Refused> {
    let file = model::load(source, text).map_err(Refused::Load)?;
    let ((a, _), named) = (numbers(&file), file.run_time_parameters().len());
    // The code's slots hold the file's numbers at the positions this generator numbers them.
    let same_slots = p0.len() == named + expected.len()
        && expected.iter().zip(&p0[named..]).all(|(&i, v)| {
            a.get(i as usize)
                .is_some_and(|x| x.to_bits() == v.to_bits())
        });
    if !same_slots {
        return Err(Refused::OtherSlots);
    }
    let mut at = model::load_with(source, text, overrides).map_err(Refused::Load)?;
    let p = in_layout(&file, &at, expected)?;
    at.data = p[p.len() - expected.len()..].to_vec();
    at.data_slots = expected.to_vec();
    Ok((p, at))
}

/// `at`'s run-time values in the layout of `like` (the same file loaded at other values):
/// `like`'s named parameters, then the numbers at `slots`. Every expression in t must keep
/// its terms, and every other number stay within 1e-14 of the model's largest; the named
/// parameters are `like`'s (at these values one may no longer qualify, a zero inertia: the
/// masses' check after this one sees what that changes).
fn in_layout(like: &Model, at: &Model, slots: &[u32]) -> Result<Vec<f64>, Refused> {
    let ((a, shape_a), (b, shape_b)) = (numbers(like), numbers(at));
    if a.len() != b.len() || shape_a != shape_b {
        return Err(Refused::Structure(
            "a driver's or load's expression in t, whose terms change".to_string(),
        ));
    }
    let scale = a.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    let held = |i: usize| slots.binary_search(&(i as u32)).is_err();
    if let Some(i) = (0..a.len()).find(|&i| held(i) && !((a[i] - b[i]).abs() <= SAME * scale)) {
        return Err(Refused::Structure(owner(like, i)));
    }
    let value = |name: &str| {
        at.parameters
            .iter()
            .find(|q| q.name == name)
            .map(|q| q.value)
    };
    let named: Option<Vec<f64>> = like
        .run_time_parameters()
        .iter()
        .map(|q| value(&q.name))
        .collect();
    let named = named.ok_or_else(|| Refused::Structure("the named parameters".to_string()))?;
    Ok(named
        .into_iter()
        .chain(data(at, &Slots(slots.to_vec())))
        .collect())
}

/// The run-time values of `base` (the file `text` loaded with some values set and its slots
/// marked, [`mark`]) as the file loaded with `overrides` gives them, in `base`'s layout: its
/// named parameters, then the numbers at its slots. Slots are found by a nudge of 1e-7, so
/// two loads at nearby values may list different numbers whose bits only roundoff moved;
/// every number `base` holds constant must stay within 1e-14 of the largest here, or the
/// layout misses a real dependence (`Refused::Structure`).
pub fn values_like(
    base: &Model,
    source: &str,
    text: &str,
    overrides: &[(String, f64)],
) -> Result<Vec<f64>, Refused> {
    let at = model::load_with(source, text, overrides).map_err(Refused::Load)?;
    in_layout(base, &at, &base.data_slots)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::{marked_index, Var};

    const SLIDER_CRANK: &str = include_str!("../../mechanisms/slider_crank.toml");

    #[test]
    fn the_crank_radius_reaches_points_and_a_mark_becomes_a_variable() {
        let mut m = model::load("slider_crank.toml", SLIDER_CRANK).unwrap();
        let slots = find("slider_crank.toml", SLIDER_CRANK, &m);
        assert!(!slots.is_empty());
        let marked_model = mark("slider_crank.toml", SLIDER_CRANK, &mut m);
        assert_eq!(m.data.len(), slots.len());
        // The crank pin is at (r cos θ0, r sin θ0, 0) on the ground side: a slot, and its z
        // (a literal 0) is not.
        let pin = &marked_model.joints[1];
        assert!(marked_index(pin.f1.point[0]).is_some() || marked_index(pin.f2.point[0]).is_some());
        let mut a = crate::expr::Arena::new();
        let x = a.constant(marked(3));
        assert_eq!(a.node(x), Node::Var(Var::P(3)));
        // Arithmetic on a mark is a NaN, not a mark.
        assert_eq!(marked_index(marked(3) * 2.0), None);
        assert_eq!(marked_index(-marked(3)), None);
    }

    #[test]
    fn other_values_give_the_slots_of_the_new_model_and_the_same_constants() {
        let src = "slider_crank.toml";
        let mut m = model::load(src, SLIDER_CRANK).unwrap();
        mark(src, SLIDER_CRANK, &mut m);
        let (expected, p0) = (m.data_slots.clone(), m.run_time_values());
        let (p, at) = values_at(src, SLIDER_CRANK, &[("r".into(), 0.12)], &expected, &p0).unwrap();
        // The file's slots read off the file loaded at r = 0.12 (whose own slots may differ
        // by numbers that are roundoff at one value and not at the other).
        let again = model::load_with(src, SLIDER_CRANK, &[("r".into(), 0.12)]).unwrap();
        let all = numbers(&again).0;
        let n = again.run_time_parameters().len();
        let read: Vec<f64> = expected.iter().map(|&i| all[i as usize]).collect();
        assert_eq!(p[n..], read[..]);
        assert_eq!(at.parameters, again.parameters);
        assert!(read.contains(&0.12));
        // Slots of another generator: other positions, or other numbers at them.
        assert!(matches!(
            values_at(src, SLIDER_CRANK, &[], &[1, 2, 3], &p0),
            Err(Refused::OtherSlots)
        ));
        let mut other = p0.clone();
        other[n] += 1.0;
        assert!(matches!(
            values_at(src, SLIDER_CRANK, &[], &expected, &other),
            Err(Refused::OtherSlots)
        ));
    }
}
