//! The second back end (decision 31): the same DAG roots the emitter lowers to Rust, lowered
//! to a runtime instruction tape ([`symbody_runtime::tape::Tape`]) with the same operations in
//! the same order, so interpreted and compiled results agree to the last bit in all but
//! the library functions' own rounding.

use crate::expr::{Arena, Func, Id, Node, Var};
use std::collections::{HashMap, HashSet};
use symbody_runtime::tape::{Instr, Op, Tape};

/// What node `id` computes as one instruction: `a + (−y)` becomes `a − y` (as emitted), so
/// the negation is not evaluated on its own.
fn instruction(arena: &Arena, id: Id) -> (Op, Id, Option<Id>, u32) {
    match arena.node(id) {
        Node::Add(a, b) => match (arena.node(a), arena.node(b)) {
            (_, Node::Neg(y)) => (Op::Sub, a, Some(y), 0),
            (Node::Neg(x), _) => (Op::Sub, b, Some(x), 0),
            _ => (Op::Add, a, Some(b), 0),
        },
        Node::Mul(a, b) => (Op::Mul, a, Some(b), 0),
        Node::Atan2(y, x) => (Op::Atan2, y, Some(x), 0),
        Node::Neg(a) => (Op::Neg, a, None, 0),
        Node::Recip(a) => (Op::Recip, a, None, 0),
        Node::Powi(a, 2) => (Op::Square, a, None, 0),
        Node::Powi(a, n) => (Op::Powi, a, None, n as u32),
        Node::Call(f, a) => {
            let op = match f {
                Func::Sin => Op::Sin,
                Func::Cos => Op::Cos,
                Func::Tan => Op::Tan,
                Func::Exp => Op::Exp,
                Func::Ln => Op::Ln,
                Func::Sqrt => Op::Sqrt,
                Func::Abs => Op::Abs,
                Func::Asin => Op::Asin,
                Func::Acos => Op::Acos,
                Func::Atan => Op::Atan,
            };
            (op, a, None, 0)
        }
        Node::Const(_) | Node::Var(_) => unreachable!("leaves are registers, not instructions"),
    }
}

fn is_leaf(arena: &Arena, id: Id) -> bool {
    matches!(arena.node(id), Node::Const(_) | Node::Var(_))
}

/// Lowers the roots of each output slice to one tape over `n_coords` coordinates.
pub fn lower(arena: &Arena, n_coords: usize, outputs: &[&[Id]]) -> Tape {
    // The non-leaf nodes the outputs need, through instruction operands.
    let mut needed: Vec<Id> = Vec::new();
    let mut seen: HashSet<Id> = HashSet::new();
    let mut leaves: Vec<Id> = Vec::new();
    let mut stack: Vec<Id> = outputs.iter().flat_map(|o| o.iter().copied()).collect();
    while let Some(id) = stack.pop() {
        if !seen.insert(id) {
            continue;
        }
        if is_leaf(arena, id) {
            leaves.push(id);
            continue;
        }
        needed.push(id);
        let (_, a, b, _) = instruction(arena, id);
        stack.push(a);
        stack.extend(b);
    }
    // Children precede parents in the arena, so ascending ids are an evaluation order; the
    // tape instead runs level by level (a node's level is one more than its operands'), with
    // the instructions of one level grouped by operation: runs of one operation are what the
    // interpreter dispatches once (`Tape::eval`), and no result changes, as every node still
    // reads the same operands.
    needed.sort_unstable();
    leaves.sort_unstable();
    let mut level: HashMap<Id, u32> = HashMap::new();
    for &id in &needed {
        let (_, a, b, _) = instruction(arena, id);
        let of = |x: Id| level.get(&x).copied().unwrap_or(0);
        let l = 1 + of(a).max(b.map_or(0, of));
        level.insert(id, l);
    }
    needed.sort_by_key(|&id| (level[&id], instruction(arena, id).0 as u8, id));

    let mut consts = Vec::new();
    let mut register: HashMap<Id, u32> = HashMap::new();
    for &id in &leaves {
        if let Some(c) = arena.as_const(id) {
            register.insert(id, consts.len() as u32);
            consts.push(c);
        }
    }
    let c = consts.len() as u32;
    let n = n_coords as u32;
    for &id in &leaves {
        if let Node::Var(v) = arena.node(id) {
            let r = match v {
                Var::Q(i) => c + i,
                Var::Qd(i) => c + n + i,
                Var::T => c + 2 * n,
                Var::P(_) | Var::K(_) => {
                    unreachable!("interpreted systems are built with their parameters' values")
                }
                Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => {
                    unreachable!("a direction is renamed to coordinates before lowering")
                }
            };
            register.insert(id, r);
        }
    }
    let first = c + 2 * n + 1;
    for (k, &id) in needed.iter().enumerate() {
        register.insert(id, first + k as u32);
    }
    let instrs = needed
        .iter()
        .map(|&id| {
            let (op, a, b, exponent) = instruction(arena, id);
            Instr {
                op,
                a: register[&a],
                b: b.map_or(exponent, |b| register[&b]),
            }
        })
        .collect();
    let outs = outputs
        .iter()
        .map(|o| o.iter().map(|id| register[id]).collect())
        .collect();
    Tape::new(consts, n_coords, instrs, outs).expect("operands precede their users in the DAG")
}
