//! Property tests of the expression engine alone: derivatives of random DAGs against
//! central finite differences, and simplification against a naive evaluation of the same
//! expression (no simplification, no sharing).

use symbody_codegen::expr::{Arena, Func, Id, Var};

/// Small deterministic generator (splitmix64) so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A random expression as a plain tree, evaluated without any simplification.
#[derive(Clone, Debug)]
enum Tree {
    Const(f64),
    Var(usize),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    Neg(Box<Tree>),
    Powi(Box<Tree>, i32),
    Call(Func, Box<Tree>),
}

const NVARS: usize = 4;

fn random_tree(rng: &mut Rng, depth: usize) -> Tree {
    if depth == 0 || rng.below(5) == 0 {
        return match rng.below(4) {
            0 => Tree::Const([0.0, 1.0, -1.0, 2.5, 0.3][rng.below(5)]),
            _ => Tree::Var(rng.below(NVARS)),
        };
    }
    let sub = |rng: &mut Rng| Box::new(random_tree(rng, depth - 1));
    match rng.below(9) {
        0 => Tree::Add(sub(rng), sub(rng)),
        1 => Tree::Sub(sub(rng), sub(rng)),
        2 | 3 => Tree::Mul(sub(rng), sub(rng)),
        // Keep denominators away from zero: 2 + x^2.
        4 => Tree::Div(
            sub(rng),
            Box::new(Tree::Add(
                Box::new(Tree::Const(2.0)),
                Box::new(Tree::Powi(sub(rng), 2)),
            )),
        ),
        5 => Tree::Neg(sub(rng)),
        6 => match rng.below(3) {
            0 => Tree::Powi(sub(rng), 2),
            1 => Tree::Powi(sub(rng), 3),
            // Negative powers only of a base bounded away from zero (2 + x²), so the
            // finite-difference reference stays meaningful.
            _ => Tree::Powi(
                Box::new(Tree::Add(
                    Box::new(Tree::Const(2.0)),
                    Box::new(Tree::Powi(sub(rng), 2)),
                )),
                -2,
            ),
        },
        _ => {
            // Functions whose domain is the whole line (or made so).
            let f = [Func::Sin, Func::Cos, Func::Atan, Func::Exp][rng.below(4)];
            let inner = if f == Func::Exp {
                Tree::Call(Func::Sin, sub(rng))
            } else {
                *sub(rng)
            };
            Tree::Call(f, Box::new(inner))
        }
    }
}

fn eval_tree(t: &Tree, x: &[f64]) -> f64 {
    match t {
        Tree::Const(c) => *c,
        Tree::Var(i) => x[*i],
        Tree::Add(a, b) => eval_tree(a, x) + eval_tree(b, x),
        Tree::Sub(a, b) => eval_tree(a, x) - eval_tree(b, x),
        Tree::Mul(a, b) => eval_tree(a, x) * eval_tree(b, x),
        Tree::Div(a, b) => eval_tree(a, x) / eval_tree(b, x),
        Tree::Neg(a) => -eval_tree(a, x),
        Tree::Powi(a, n) => {
            let v = eval_tree(a, x);
            // Plain repeated multiplication, independent of `powi`.
            let p: f64 = (0..n.abs()).map(|_| v).product();
            if *n < 0 {
                1.0 / p
            } else {
                p
            }
        }
        Tree::Call(f, a) => f.apply(eval_tree(a, x)),
    }
}

fn build(arena: &mut Arena, t: &Tree) -> Id {
    match t {
        Tree::Const(c) => arena.constant(*c),
        Tree::Var(i) => arena.var(Var::Q(*i as u32)),
        Tree::Add(a, b) => {
            let (a, b) = (build(arena, a), build(arena, b));
            arena.add(a, b)
        }
        Tree::Sub(a, b) => {
            let (a, b) = (build(arena, a), build(arena, b));
            arena.sub(a, b)
        }
        Tree::Mul(a, b) => {
            let (a, b) = (build(arena, a), build(arena, b));
            arena.mul(a, b)
        }
        Tree::Div(a, b) => {
            let (a, b) = (build(arena, a), build(arena, b));
            arena.div(a, b)
        }
        Tree::Neg(a) => {
            let a = build(arena, a);
            arena.neg(a)
        }
        Tree::Powi(a, n) => {
            let a = build(arena, a);
            arena.powi(a, *n)
        }
        Tree::Call(f, a) => {
            let a = build(arena, a);
            arena.call(*f, a)
        }
    }
}

fn env(x: &[f64]) -> impl Fn(Var) -> f64 + '_ {
    move |v| match v {
        Var::Q(i) => x[i as usize],
        _ => 0.0,
    }
}

fn scale(v: f64) -> f64 {
    1.0 + v.abs()
}

#[test]
fn simplification_preserves_value() {
    let mut rng = Rng(1);
    let mut checked = 0;
    for _ in 0..2000 {
        let t = random_tree(&mut rng, 6);
        let mut arena = Arena::new();
        let id = build(&mut arena, &t);
        let x: Vec<f64> = (0..NVARS).map(|_| rng.uniform(-1.5, 1.5)).collect();
        let naive = eval_tree(&t, &x);
        if !naive.is_finite() || naive.abs() > 1e8 {
            continue;
        }
        let dag = arena.eval(id, &env(&x));
        assert!(
            (dag - naive).abs() <= 1e-12 * scale(naive),
            "DAG {dag} vs tree {naive} for {t:?} at {x:?}"
        );
        checked += 1;
    }
    assert!(checked > 1500, "too few finite samples: {checked}");
}

#[test]
fn derivatives_match_central_differences() {
    let mut rng = Rng(2);
    let mut checked = 0;
    for _ in 0..1000 {
        let t = random_tree(&mut rng, 5);
        let mut arena = Arena::new();
        let id = build(&mut arena, &t);
        let one = arena.constant(1.0);
        let x: Vec<f64> = (0..NVARS).map(|_| rng.uniform(-1.2, 1.2)).collect();
        for j in 0..NVARS {
            let target = Var::Q(j as u32);
            let d = arena.derivative(&[id], &|v| (v == target).then_some(one))[0];
            let exact = arena.eval(d, &env(&x));
            // Central difference of the naive tree: independent of the engine entirely.
            let h = 1e-6;
            let (mut xp, mut xm) = (x.clone(), x.clone());
            xp[j] += h;
            xm[j] -= h;
            let (fp, fm) = (eval_tree(&t, &xp), eval_tree(&t, &xm));
            let fd = (fp - fm) / (2.0 * h);
            if !fd.is_finite() || fd.abs() > 1e4 || fp.abs() > 1e4 {
                continue;
            }
            // Truncation O(h²·f''') plus rounding O(ε·|f|/h).
            let tol = 1e-5 * scale(fd) + 1e-9 * scale(fp) / h;
            assert!(
                (exact - fd).abs() <= tol,
                "d/dx{j}: engine {exact} vs FD {fd} for {t:?} at {x:?}"
            );
            checked += 1;
        }
    }
    assert!(checked > 2500, "too few samples: {checked}");
}

#[test]
fn directional_second_derivative_matches_differences() {
    // D²f[v, v] along a line: f(x + s v) second difference in s.
    let mut rng = Rng(3);
    let mut checked = 0;
    for _ in 0..500 {
        let t = random_tree(&mut rng, 4);
        let mut arena = Arena::new();
        let id = build(&mut arena, &t);
        let x: Vec<f64> = (0..NVARS).map(|_| rng.uniform(-1.0, 1.0)).collect();
        let v: Vec<f64> = (0..NVARS).map(|_| rng.uniform(-1.0, 1.0)).collect();
        let vid: Vec<Id> = v.iter().map(|c| arena.constant(*c)).collect();
        let seed = |var: Var| match var {
            Var::Q(i) => Some(vid[i as usize]),
            _ => None,
        };
        let d1 = arena.derivative(&[id], &seed)[0];
        let d2 = arena.derivative(&[d1], &seed)[0];
        let exact = arena.eval(d2, &env(&x));
        let h = 1e-4;
        let at = |s: f64| {
            let p: Vec<f64> = x.iter().zip(&v).map(|(a, b)| a + s * b).collect();
            eval_tree(&t, &p)
        };
        let (fp, f0, fm) = (at(h), at(0.0), at(-h));
        let fd = (fp - 2.0 * f0 + fm) / (h * h);
        if !fd.is_finite() || f0.abs() > 1e3 || fd.abs() > 1e4 {
            continue;
        }
        let tol = 1e-5 * scale(fd) + 4e-16 * scale(f0) / (h * h);
        assert!(
            (exact - fd).abs() <= tol,
            "D²: engine {exact} vs FD {fd} for {t:?}"
        );
        checked += 1;
    }
    assert!(checked > 350, "too few samples: {checked}");
}

#[test]
fn hash_consing_shares_nodes() {
    let mut a = Arena::new();
    let x = a.var(Var::Q(0));
    let y = a.var(Var::Q(1));
    let s1 = a.sin(x);
    let p1 = a.mul(s1, y);
    let before = a.len();
    let s2 = a.sin(x);
    let p2 = a.mul(y, s2);
    assert_eq!(p1, p2);
    assert_eq!(
        a.len(),
        before,
        "rebuilding an existing expression adds no node"
    );
    // Constant folding and identities.
    let zero = a.constant(0.0);
    let one = a.constant(1.0);
    assert_eq!(a.add(x, zero), x);
    assert_eq!(a.mul(x, one), x);
    assert_eq!(a.mul(x, zero), zero);
    let nx = a.neg(x);
    assert_eq!(a.neg(nx), x);
    assert!(a.is_zero(a.clone().sub(x, x)));
}
