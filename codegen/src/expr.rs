//! Hash-consed expression DAG: an arena of nodes whose children always precede their
//! parents, with local simplification at construction so shared subexpressions are shared
//! nodes and no expression ever swells into a tree.

use std::collections::HashMap;
use std::fmt;

/// Index of a node in an [`Arena`]. Children always have smaller ids than their parents.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Id(pub u32);

impl Id {
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// An independent variable of the generated functions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Var {
    /// Generalized coordinate `q[i]`.
    Q(u32),
    /// Generalized velocity `qd[i]`.
    Qd(u32),
    /// Time.
    T,
    /// Run-time value `p[i]` of the generated code: first the file's `[parameters]` entries
    /// that reach only masses, inertias and springs' constants
    /// ([`crate::model::Parameter::run_time`]), then the numbers of the model that the other
    /// parameters reach ([`crate::slots`]).
    P(u32),
    /// Hoisted value `k[i]`: a function of the parameters alone, computed once per parameter
    /// set by the generated `setup` ([`crate::hoist`]).
    K(u32),
    /// Direction of `q[i]`, `qd[i]` and `p[i]` along which the generated `tangents` take
    /// directional derivatives ([`crate::tangent`]).
    Dq(u32),
    Dqd(u32),
    Dp(u32),
}

/// Unary functions the engine knows how to evaluate, differentiate and emit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Exp,
    Ln,
    Sqrt,
    Abs,
    Asin,
    Acos,
    Atan,
}

impl Func {
    /// Name as written in mechanism files and as the `f64` method emitted.
    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Exp => "exp",
            Func::Ln => "ln",
            Func::Sqrt => "sqrt",
            Func::Abs => "abs",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan => "atan",
        }
    }

    pub const ALL: [Func; 10] = [
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Exp,
        Func::Ln,
        Func::Sqrt,
        Func::Abs,
        Func::Asin,
        Func::Acos,
        Func::Atan,
    ];

    pub fn from_name(name: &str) -> Option<Func> {
        Func::ALL.into_iter().find(|f| f.name() == name)
    }

    pub fn apply(self, x: f64) -> f64 {
        match self {
            Func::Sin => symbody_runtime::trig::sin(x),
            Func::Cos => symbody_runtime::trig::cos(x),
            Func::Tan => x.tan(),
            Func::Exp => x.exp(),
            Func::Ln => x.ln(),
            Func::Sqrt => x.sqrt(),
            Func::Abs => x.abs(),
            Func::Asin => x.asin(),
            Func::Acos => x.acos(),
            Func::Atan => x.atan(),
        }
    }
}

/// Bits of a number of the model marked as run-time value `p[i]` ([`marked`]): a signalling
/// NaN, whose upper half no arithmetic result has (any operation on it gives a quiet NaN, and
/// negation sets the sign bit), so a marked number that is computed with instead of being
/// passed to [`Arena::constant`] shows up as a non-finite constant, never as a variable.
const MARK: u64 = 0x7FF0_05A5_0000_0000;

/// The number that [`Arena::constant`] turns into `Var::P(i)`: how the equation stages, which
/// read the model's points, axes and lengths as `f64`, write the ones parameters reach as
/// variables ([`crate::slots`]).
pub fn marked(i: u32) -> f64 {
    f64::from_bits(MARK | u64::from(i))
}

/// `i` where `x` is [`marked`]`(i)`.
pub fn marked_index(x: f64) -> Option<u32> {
    let bits = x.to_bits();
    (bits & 0xFFFF_FFFF_0000_0000 == MARK).then_some(bits as u32)
}

/// One node of the DAG. Constants are stored by their bit pattern so nodes can be hashed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Node {
    Const(u64),
    Var(Var),
    Add(Id, Id),
    Mul(Id, Id),
    Neg(Id),
    /// `1 / x`.
    Recip(Id),
    /// `x^n` for a small integer `n` (emitted as `powi`).
    Powi(Id, i32),
    /// `atan2(y, x)`.
    Atan2(Id, Id),
    Call(Func, Id),
}

impl Node {
    /// The node's children, in order.
    pub fn children(&self) -> impl Iterator<Item = Id> {
        let (a, b) = match *self {
            Node::Const(_) | Node::Var(_) => (None, None),
            Node::Add(a, b) | Node::Mul(a, b) | Node::Atan2(a, b) => (Some(a), Some(b)),
            Node::Neg(a) | Node::Recip(a) | Node::Powi(a, _) | Node::Call(_, a) => (Some(a), None),
        };
        a.into_iter().chain(b)
    }
}

/// The expression arena. Building a node that already exists returns the existing id.
#[derive(Default, Clone)]
pub struct Arena {
    nodes: Vec<Node>,
    lookup: HashMap<Node, Id>,
}

impl fmt::Debug for Arena {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Arena({} nodes)", self.nodes.len())
    }
}

impl Arena {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    pub fn node(&self, id: Id) -> Node {
        self.nodes[id.index()]
    }

    /// The constant value of `id`, if it is a constant.
    pub fn as_const(&self, id: Id) -> Option<f64> {
        match self.node(id) {
            Node::Const(bits) => Some(f64::from_bits(bits)),
            _ => None,
        }
    }

    pub fn is_zero(&self, id: Id) -> bool {
        self.as_const(id) == Some(0.0)
    }

    fn intern(&mut self, node: Node) -> Id {
        if let Some(&id) = self.lookup.get(&node) {
            return id;
        }
        let id = Id(u32::try_from(self.nodes.len()).expect("expression arena exceeds u32 ids"));
        self.nodes.push(node);
        self.lookup.insert(node, id);
        id
    }

    pub fn constant(&mut self, value: f64) -> Id {
        if let Some(i) = marked_index(value) {
            return self.var(Var::P(i));
        }
        // One zero: -0.0 and 0.0 behave identically in every expression we build.
        let value = if value == 0.0 { 0.0 } else { value };
        self.intern(Node::Const(value.to_bits()))
    }

    pub fn var(&mut self, v: Var) -> Id {
        self.intern(Node::Var(v))
    }

    pub fn add(&mut self, a: Id, b: Id) -> Id {
        match (self.as_const(a), self.as_const(b)) {
            (Some(x), Some(y)) => return self.constant(x + y),
            (Some(0.0), _) => return b,
            (_, Some(0.0)) => return a,
            _ => {}
        }
        // x + (-x) = 0 exactly in floating point as well.
        if self.node(b) == Node::Neg(a) || self.node(a) == Node::Neg(b) {
            return self.constant(0.0);
        }
        // (-x) + (-y) = -(x + y): keeps negations outermost so they can cancel.
        if let (Node::Neg(x), Node::Neg(y)) = (self.node(a), self.node(b)) {
            let s = self.add(x, y);
            return self.neg(s);
        }
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Add(a, b))
    }

    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        let nb = self.neg(b);
        self.add(a, nb)
    }

    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        match (self.as_const(a), self.as_const(b)) {
            (Some(x), Some(y)) => return self.constant(x * y),
            (Some(0.0), _) => return a,
            (_, Some(0.0)) => return b,
            (Some(1.0), _) => return b,
            (_, Some(1.0)) => return a,
            (Some(-1.0), _) => return self.neg(b),
            (_, Some(-1.0)) => return self.neg(a),
            _ => {}
        }
        // Pull negations out of products so that sign-only differences share nodes.
        match (self.node(a), self.node(b)) {
            (Node::Neg(x), Node::Neg(y)) => return self.mul(x, y),
            (Node::Neg(x), _) => {
                let p = self.mul(x, b);
                return self.neg(p);
            }
            (_, Node::Neg(y)) => {
                let p = self.mul(a, y);
                return self.neg(p);
            }
            _ => {}
        }
        // A negative constant factor becomes a negation of the positive one, for the same reason.
        if let Some(x) = self.as_const(a).filter(|x| *x < 0.0) {
            let c = self.constant(-x);
            let p = self.mul(c, b);
            return self.neg(p);
        }
        if let Some(y) = self.as_const(b).filter(|y| *y < 0.0) {
            let c = self.constant(-y);
            let p = self.mul(a, c);
            return self.neg(p);
        }
        if a == b {
            return self.powi(a, 2);
        }
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Mul(a, b))
    }

    pub fn neg(&mut self, a: Id) -> Id {
        match self.node(a) {
            Node::Const(bits) => self.constant(-f64::from_bits(bits)),
            Node::Neg(x) => x,
            _ => self.intern(Node::Neg(a)),
        }
    }

    pub fn recip(&mut self, a: Id) -> Id {
        match self.node(a) {
            Node::Const(bits) => self.constant(1.0 / f64::from_bits(bits)),
            Node::Recip(x) => x,
            Node::Neg(x) => {
                let r = self.recip(x);
                self.neg(r)
            }
            _ => self.intern(Node::Recip(a)),
        }
    }

    pub fn div(&mut self, a: Id, b: Id) -> Id {
        if let (Some(x), Some(y)) = (self.as_const(a), self.as_const(b)) {
            return self.constant(x / y);
        }
        let r = self.recip(b);
        self.mul(a, r)
    }

    pub fn powi(&mut self, a: Id, n: i32) -> Id {
        match n {
            0 => return self.constant(1.0),
            1 => return a,
            -1 => return self.recip(a),
            _ => {}
        }
        match self.node(a) {
            Node::Const(bits) => self.constant(f64::from_bits(bits).powi(n)),
            Node::Neg(x) if n % 2 == 0 => self.powi(x, n),
            Node::Neg(x) => {
                let p = self.powi(x, n);
                self.neg(p)
            }
            _ => self.intern(Node::Powi(a, n)),
        }
    }

    pub fn atan2(&mut self, y: Id, x: Id) -> Id {
        if let (Some(a), Some(b)) = (self.as_const(y), self.as_const(x)) {
            return self.constant(a.atan2(b));
        }
        self.intern(Node::Atan2(y, x))
    }

    pub fn call(&mut self, f: Func, a: Id) -> Id {
        if let Some(x) = self.as_const(a) {
            return self.constant(f.apply(x));
        }
        // Odd and even symmetries keep sin(-x) and sin(x) on one node.
        if let Node::Neg(x) = self.node(a) {
            match f {
                Func::Sin | Func::Tan | Func::Asin | Func::Atan => {
                    let v = self.call(f, x);
                    return self.neg(v);
                }
                Func::Cos | Func::Abs => return self.call(f, x),
                _ => {}
            }
        }
        self.intern(Node::Call(f, a))
    }

    pub fn sin(&mut self, a: Id) -> Id {
        self.call(Func::Sin, a)
    }

    pub fn cos(&mut self, a: Id) -> Id {
        self.call(Func::Cos, a)
    }

    /// Sum of many terms.
    pub fn sum(&mut self, terms: impl IntoIterator<Item = Id>) -> Id {
        let zero = self.constant(0.0);
        terms.into_iter().fold(zero, |acc, t| self.add(acc, t))
    }

    /// Dot product of two 3-vectors of expressions.
    pub fn dot3(&mut self, a: [Id; 3], b: [Id; 3]) -> Id {
        let p: Vec<Id> = (0..3).map(|i| self.mul(a[i], b[i])).collect();
        self.sum(p)
    }

    /// Evaluates every node up to and including `roots` under the given variable values.
    pub fn eval_many(&self, roots: &[Id], env: &dyn Fn(Var) -> f64) -> Vec<f64> {
        let top = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
        let needed = self.reachable(roots);
        let mut vals = vec![0.0; top];
        for i in 0..top {
            if needed[i] {
                vals[i] = self.eval_node(self.nodes[i], &vals, env);
            }
        }
        roots.iter().map(|r| vals[r.index()]).collect()
    }

    pub fn eval(&self, root: Id, env: &dyn Fn(Var) -> f64) -> f64 {
        self.eval_many(&[root], env)[0]
    }

    fn eval_node(&self, node: Node, v: &[f64], env: &dyn Fn(Var) -> f64) -> f64 {
        match node {
            Node::Const(bits) => f64::from_bits(bits),
            Node::Var(x) => env(x),
            Node::Add(a, b) => v[a.index()] + v[b.index()],
            Node::Mul(a, b) => v[a.index()] * v[b.index()],
            Node::Neg(a) => -v[a.index()],
            Node::Recip(a) => 1.0 / v[a.index()],
            Node::Powi(a, n) => v[a.index()].powi(n),
            Node::Atan2(y, x) => v[y.index()].atan2(v[x.index()]),
            Node::Call(f, a) => f.apply(v[a.index()]),
        }
    }

    /// Marks every node reachable from `roots` (a vector as long as the largest root + 1).
    pub fn reachable(&self, roots: &[Id]) -> Vec<bool> {
        let top = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
        let mut mark = vec![false; top];
        for r in roots {
            mark[r.index()] = true;
        }
        // Children precede parents, so one backward sweep finds everything.
        for i in (0..top).rev() {
            if mark[i] {
                for c in self.nodes[i].children() {
                    mark[c.index()] = true;
                }
            }
        }
        mark
    }

    /// Forward-mode derivative of every root along a seed: `seed(v)` is the derivative of
    /// variable `v` (`None` means zero). Applying it with `Q(j) ↦ 1` gives ∂/∂q_j; with
    /// `Q(j) ↦ qd_j, T ↦ 1` it gives the total time derivative for fixed velocities.
    pub fn derivative(&mut self, roots: &[Id], seed: &dyn Fn(Var) -> Option<Id>) -> Vec<Id> {
        let mark = self.reachable(roots);
        let zero = self.constant(0.0);
        let mut d: Vec<Id> = vec![zero; mark.len()];
        for i in 0..mark.len() {
            if !mark[i] {
                continue;
            }
            let id = Id(i as u32);
            d[i] = match self.nodes[i] {
                Node::Const(_) => zero,
                Node::Var(v) => seed(v).unwrap_or(zero),
                Node::Add(a, b) => self.add(d[a.index()], d[b.index()]),
                Node::Mul(a, b) => {
                    let l = self.mul(d[a.index()], b);
                    let r = self.mul(a, d[b.index()]);
                    self.add(l, r)
                }
                Node::Neg(a) => self.neg(d[a.index()]),
                Node::Recip(a) => {
                    // d(1/a) = -da / a^2 = -da * r^2 with r = 1/a already in the DAG.
                    let r2 = self.powi(id, 2);
                    let p = self.mul(d[a.index()], r2);
                    self.neg(p)
                }
                Node::Powi(a, n) => {
                    let pm1 = self.powi(a, n - 1);
                    let c = self.constant(f64::from(n));
                    let k = self.mul(c, pm1);
                    self.mul(k, d[a.index()])
                }
                Node::Atan2(y, x) => {
                    // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
                    let x2 = self.powi(x, 2);
                    let y2 = self.powi(y, 2);
                    let den = self.add(x2, y2);
                    let xdy = self.mul(x, d[y.index()]);
                    let ydx = self.mul(y, d[x.index()]);
                    let num = self.sub(xdy, ydx);
                    self.div(num, den)
                }
                Node::Call(f, a) => {
                    let da = d[a.index()];
                    if self.is_zero(da) {
                        zero
                    } else {
                        let fp = self.func_derivative(f, a, id);
                        self.mul(fp, da)
                    }
                }
            };
        }
        roots.iter().map(|r| d[r.index()]).collect()
    }

    /// f'(a) for `node = f(a)`.
    fn func_derivative(&mut self, f: Func, a: Id, node: Id) -> Id {
        let one = self.constant(1.0);
        match f {
            Func::Sin => self.cos(a),
            Func::Cos => {
                let s = self.sin(a);
                self.neg(s)
            }
            Func::Tan => {
                let t2 = self.powi(node, 2);
                self.add(one, t2)
            }
            Func::Exp => node,
            Func::Ln => self.recip(a),
            Func::Sqrt => {
                let two = self.constant(2.0);
                let den = self.mul(two, node);
                self.recip(den)
            }
            Func::Abs => {
                // sign(a) = a / |a|; undefined at 0 like the function's derivative itself.
                let r = self.recip(node);
                self.mul(a, r)
            }
            Func::Asin | Func::Acos => {
                let a2 = self.powi(a, 2);
                let m = self.sub(one, a2);
                let s = self.call(Func::Sqrt, m);
                let r = self.recip(s);
                if f == Func::Asin {
                    r
                } else {
                    self.neg(r)
                }
            }
            Func::Atan => {
                let a2 = self.powi(a, 2);
                let den = self.add(one, a2);
                self.recip(den)
            }
        }
    }

    /// The variables each root depends on structurally, sorted.
    /// Every root rebuilt with each variable `v` replaced by `map(v)` (kept where `None`):
    /// the substitution a reduction pass performs. Nodes are rebuilt through the simplifying
    /// constructors, so substituted constants fold.
    pub fn substitute(&mut self, roots: &[Id], map: &dyn Fn(Var) -> Option<Id>) -> Vec<Id> {
        let mark = self.reachable(roots);
        let mut new: Vec<Id> = (0..mark.len()).map(|i| Id(i as u32)).collect();
        for i in 0..mark.len() {
            if !mark[i] {
                continue;
            }
            let r = |x: Id| new[x.index()];
            new[i] = match self.nodes[i] {
                Node::Const(_) => Id(i as u32),
                Node::Var(v) => map(v).unwrap_or(Id(i as u32)),
                Node::Add(a, b) => self.add(r(a), r(b)),
                Node::Mul(a, b) => self.mul(r(a), r(b)),
                Node::Neg(a) => self.neg(r(a)),
                Node::Recip(a) => self.recip(r(a)),
                Node::Powi(a, n) => self.powi(r(a), n),
                Node::Atan2(y, x) => self.atan2(r(y), r(x)),
                Node::Call(f, a) => self.call(f, r(a)),
            };
        }
        roots.iter().map(|r| new[r.index()]).collect()
    }

    pub fn variables(&self, root: Id) -> Vec<Var> {
        let mark = self.reachable(&[root]);
        let mut vars: Vec<Var> = mark
            .iter()
            .enumerate()
            .filter(|(_, m)| **m)
            .filter_map(|(i, _)| match self.nodes[i] {
                Node::Var(v) => Some(v),
                _ => None,
            })
            .collect();
        vars.sort();
        vars
    }
}
