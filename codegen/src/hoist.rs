//! Hoisting of what depends on the run-time parameters alone (docs/design.md, decision 35):
//! every largest subexpression of the per-step functions whose only variables are
//! parameters (`Var::P`) is replaced by a hoisted value `Var::K(j)`; the generated `setup`
//! computes those values once per parameter set, and the per-step functions read them.
//! With the file's parameters the per-step code does what it did with literals: one load
//! where a folded constant stood.

use crate::equations::{Dynamics, System};
use crate::expr::{Arena, Id, Node, Var};
use crate::symbolic::Entry;

/// What a node depends on.
#[derive(Clone, Copy, PartialEq)]
enum Kind {
    /// Constants only.
    Constant,
    /// Parameters (and constants).
    Parameters,
    /// A coordinate, velocity or time.
    State,
}

/// Rewrites the per-step roots of `sys` (Φ, Φq, Φt, γ, masses, forces and their Jacobians,
/// potential, power) over hoisted values; returns the nodes `k[j]` stands for, in order.
pub fn system(sys: &mut System) -> Vec<Id> {
    let mut hoisted = Vec::new();
    rewrite(sys, |a, roots| {
        let (new, h) = hoist(a, roots);
        hoisted = h;
        new
    });
    hoisted
}

/// [`system`], then every hoisted value replaced by the constant it has at the parameters
/// `p`: the equations the generated code evaluates, with `setup`'s results folded in (the
/// interpreter's; the same operations, so the same numbers to the last bit).
pub fn bound(sys: &mut System, p: &[f64]) {
    let hoisted = system(sys);
    let env = |v: Var| match v {
        Var::P(i) => p[i as usize],
        _ => f64::NAN,
    };
    let k = sys.arena.eval_many(&hoisted, &env);
    rewrite(sys, |a, roots| {
        let values: Vec<Id> = k.iter().map(|&v| a.constant(v)).collect();
        a.substitute(roots, &|v| match v {
            Var::K(j) => Some(values[j as usize]),
            _ => None,
        })
    });
}

/// The per-step roots of `sys` replaced by `f(arena, roots)`, in order.
fn rewrite(sys: &mut System, f: impl FnOnce(&mut Arena, &[Id]) -> Vec<Id>) {
    let mut roots: Vec<Id> = vec![sys.potential, sys.power_nc];
    roots.extend(sys.phi.iter().chain(&sys.phi_t).chain(&sys.gamma));
    roots.extend(sys.phi_q.iter().map(|e| e.2));
    if let Some(t) = &sys.tangent {
        roots.extend(t.phi.iter().chain(&t.phi_q).chain(&t.phi_t).chain(&t.gamma));
    }
    for d in &sys.dynamics {
        roots.extend(d.mass.iter().map(|e| e.2));
        roots.extend(&d.force);
        roots.extend(d.force_q.iter().map(|e| e.2));
        roots.extend(d.force_qd.iter().map(|e| e.2));
        roots.extend(d.tangent.mass.iter().chain(&d.tangent.force));
    }
    let new = f(&mut sys.arena, &roots);
    let mut it = new.into_iter();
    let mut next = || it.next().expect("one new root per root");
    sys.potential = next();
    sys.power_nc = next();
    for r in sys
        .phi
        .iter_mut()
        .chain(&mut sys.phi_t)
        .chain(&mut sys.gamma)
    {
        *r = next();
    }
    let entries = |v: &mut Vec<Entry>, next: &mut dyn FnMut() -> Id| {
        for e in v.iter_mut() {
            e.2 = next();
        }
    };
    entries(&mut sys.phi_q, &mut next);
    let ids = |v: &mut Vec<Id>, next: &mut dyn FnMut() -> Id| {
        for x in v.iter_mut() {
            *x = next();
        }
    };
    if let Some(t) = &mut sys.tangent {
        for v in [&mut t.phi, &mut t.phi_q, &mut t.phi_t, &mut t.gamma] {
            ids(v, &mut next);
        }
    }
    for d in &mut sys.dynamics {
        let Dynamics {
            mass,
            force,
            force_q,
            force_qd,
            tangent,
            ..
        } = d;
        entries(mass, &mut next);
        ids(force, &mut next);
        entries(force_q, &mut next);
        entries(force_qd, &mut next);
        ids(&mut tangent.mass, &mut next);
        ids(&mut tangent.force, &mut next);
    }
}

/// `roots` with their parameter-only subexpressions replaced by `Var::K(j)`, and the
/// replaced nodes (`k[j]`).
pub fn hoist(a: &mut Arena, roots: &[Id]) -> (Vec<Id>, Vec<Id>) {
    let len = a.len();
    let mut kind = Vec::with_capacity(len);
    // Children come before parents in the arena, so one pass in order classifies all.
    for i in 0..len {
        let node = a.node(Id(i as u32));
        kind.push(match node {
            Node::Const(_) => Kind::Constant,
            Node::Var(Var::P(_)) => Kind::Parameters,
            Node::Var(_) => Kind::State,
            _ => node
                .children()
                .map(|c| kind[c.index()])
                .fold(Kind::Constant, |acc, k| match (acc, k) {
                    (Kind::State, _) | (_, Kind::State) => Kind::State,
                    (Kind::Parameters, _) | (_, Kind::Parameters) => Kind::Parameters,
                    _ => Kind::Constant,
                }),
        });
    }
    let mut mark = a.reachable(roots);
    mark.resize(len, false);
    // The outermost parameter-only nodes: roots, and operands of nodes that depend on the
    // state.
    let mut frontier = vec![false; len];
    for &r in roots {
        frontier[r.index()] |= kind[r.index()] == Kind::Parameters;
    }
    for i in (0..len).filter(|&i| mark[i] && kind[i] == Kind::State) {
        for c in a.node(Id(i as u32)).children() {
            frontier[c.index()] |= kind[c.index()] == Kind::Parameters;
        }
    }
    let mut hoisted = Vec::new();
    let mut new: Vec<Id> = (0..len).map(|i| Id(i as u32)).collect();
    for i in 0..len {
        let id = Id(i as u32);
        if frontier[i] {
            new[i] = a.var(Var::K(hoisted.len() as u32));
            hoisted.push(id);
            continue;
        }
        if !mark[i] || kind[i] != Kind::State {
            continue;
        }
        let r = |x: Id| new[x.index()];
        new[i] = match a.node(id) {
            Node::Add(x, y) => a.add(r(x), r(y)),
            Node::Mul(x, y) => a.mul(r(x), r(y)),
            Node::Neg(x) => a.neg(r(x)),
            Node::Recip(x) => a.recip(r(x)),
            Node::Powi(x, n) => a.powi(r(x), n),
            Node::Atan2(y, x) => a.atan2(r(y), r(x)),
            Node::Call(f, x) => a.call(f, r(x)),
            Node::Const(_) | Node::Var(_) => id,
        };
    }
    (roots.iter().map(|r| new[r.index()]).collect(), hoisted)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `m·g·y + (m·g)·v²`: `m·g` is hoisted once, the state-dependent products stay.
    #[test]
    fn parameter_only_subexpressions_become_hoisted_values() {
        let mut a = Arena::new();
        let (m, y, v) = (a.var(Var::P(0)), a.var(Var::Q(0)), a.var(Var::Qd(0)));
        let g = a.constant(9.81);
        let mg = a.mul(m, g);
        let e1 = a.mul(mg, y);
        let v2 = a.powi(v, 2);
        let e2 = a.mul(mg, v2);
        let root = a.add(e1, e2);
        let (new, hoisted) = hoist(&mut a, &[root, mg, g]);
        assert_eq!(hoisted, vec![mg]);
        let env = |x: Var| match x {
            Var::P(_) => 2.0,
            Var::Q(_) => 3.0,
            Var::Qd(_) => 0.5,
            Var::K(_) => 2.0 * 9.81,
            Var::T | Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => 0.0,
        };
        assert_eq!(a.eval(new[0], &env), a.eval(root, &env));
        assert_eq!(a.node(new[1]), Node::Var(Var::K(0)));
        assert_eq!(new[2], g);
        assert!(!a.variables(new[0]).contains(&Var::P(0)));
    }
}
