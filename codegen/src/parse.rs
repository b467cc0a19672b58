//! Expressions in mechanism files: Rust expression syntax parsed with `syn` into the DAG.
//!
//! Accepted: float and integer literals, names (resolved by the caller), `+ - * /`, unary
//! minus, parentheses, the functions of [`Func`] called as `sin(x)` or `x.sin()`,
//! `powi(x, n)` / `x.powi(n)` with an integer `n`, `atan2(y, x)` / `y.atan2(x)`,
//! `x.to_radians()`, `x.to_degrees()`, and the constant `pi`.

use crate::expr::{Arena, Func, Id};
use syn::{BinOp, Expr, Lit, UnOp};

/// Why an expression could not be turned into the DAG.
#[derive(Debug, Clone, PartialEq)]
pub struct ExprError {
    pub message: String,
    pub help: String,
}

impl ExprError {
    fn new(message: impl Into<String>, help: impl Into<String>) -> Self {
        ExprError {
            message: message.into(),
            help: help.into(),
        }
    }
}

/// Largest |n| accepted in `powi(x, n)`: derivatives form `n − 2` and `n·(n − 1)`, and no
/// mechanism needs more.
const MAX_POWI: i32 = 64;

/// The callable names [`FUNC_HELP`] lists, for suggestions.
const FUNC_NAMES: [&str; 14] = [
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "atan2",
    "exp",
    "ln",
    "sqrt",
    "abs",
    "powi",
    "to_radians",
    "to_degrees",
];

const FUNC_HELP: &str = "known functions: sin, cos, tan, asin, acos, atan, atan2, exp, ln, sqrt, abs, powi, to_radians, to_degrees; constant: pi";

/// Parses `src` and builds it in `arena`; `resolve` maps a name to its node.
pub fn parse_expr(
    arena: &mut Arena,
    src: &str,
    resolve: &mut dyn FnMut(&mut Arena, &str) -> Option<Id>,
) -> Result<Id, ExprError> {
    let expr: Expr = syn::parse_str(src).map_err(|e| {
        ExprError::new(
            format!("malformed expression `{src}`: {e}"),
            "write a Rust arithmetic expression, e.g. `c0 + 0.02 * sin(t)`",
        )
    })?;
    build(arena, &expr, resolve)
}

fn build(
    arena: &mut Arena,
    e: &Expr,
    resolve: &mut dyn FnMut(&mut Arena, &str) -> Option<Id>,
) -> Result<Id, ExprError> {
    match e {
        Expr::Lit(l) => literal(arena, &l.lit),
        Expr::Paren(p) => build(arena, &p.expr, resolve),
        Expr::Group(g) => build(arena, &g.expr, resolve),
        Expr::Unary(u) => match u.op {
            UnOp::Neg(_) => {
                let a = build(arena, &u.expr, resolve)?;
                Ok(arena.neg(a))
            }
            _ => Err(unsupported(e)),
        },
        Expr::Binary(b) => {
            let l = build(arena, &b.left, resolve)?;
            let r = build(arena, &b.right, resolve)?;
            match b.op {
                BinOp::Add(_) => Ok(arena.add(l, r)),
                BinOp::Sub(_) => Ok(arena.sub(l, r)),
                BinOp::Mul(_) => Ok(arena.mul(l, r)),
                BinOp::Div(_) => Ok(arena.div(l, r)),
                _ => Err(unsupported(e)),
            }
        }
        Expr::Path(p) => {
            let name = path_name(&p.path);
            if let Some(id) = resolve(arena, &name) {
                return Ok(id);
            }
            match name.as_str() {
                "pi" | "PI" | "std::f64::consts::PI" | "f64::consts::PI" => {
                    Ok(arena.constant(std::f64::consts::PI))
                }
                _ => Err(ExprError::new(
                    format!("unknown name `{name}`"),
                    "use `t`, a parameter defined under [parameters], or `pi`",
                )),
            }
        }
        Expr::Call(c) => {
            let Expr::Path(p) = &*c.func else {
                return Err(unsupported(e));
            };
            let name = path_name(&p.path);
            let args: Vec<&Expr> = c.args.iter().collect();
            call(arena, &name, &args, resolve)
        }
        Expr::MethodCall(m) => {
            let mut args: Vec<&Expr> = vec![&m.receiver];
            args.extend(m.args.iter());
            call(arena, &m.method.to_string(), &args, resolve)
        }
        _ => Err(unsupported(e)),
    }
}

fn call(
    arena: &mut Arena,
    name: &str,
    args: &[&Expr],
    resolve: &mut dyn FnMut(&mut Arena, &str) -> Option<Id>,
) -> Result<Id, ExprError> {
    let arity = |n: usize| -> Result<(), ExprError> {
        if args.len() == n {
            Ok(())
        } else {
            Err(ExprError::new(
                format!(
                    "`{name}` takes {n} argument{}, got {}",
                    if n == 1 { "" } else { "s" },
                    args.len()
                ),
                FUNC_HELP,
            ))
        }
    };
    match name {
        "powi" => {
            arity(2)?;
            let base = build(arena, args[0], resolve)?;
            let n = integer_literal(args[1])
                .filter(|n| n.abs() <= MAX_POWI)
                .ok_or_else(|| {
                    ExprError::new(
                        format!("`powi` needs an integer literal exponent within ±{MAX_POWI}"),
                        "write e.g. `powi(x, 2)`; use `exp(y * ln(x))` for other powers",
                    )
                })?;
            Ok(arena.powi(base, n))
        }
        "atan2" => {
            arity(2)?;
            let y = build(arena, args[0], resolve)?;
            let x = build(arena, args[1], resolve)?;
            Ok(arena.atan2(y, x))
        }
        "to_radians" | "to_degrees" => {
            arity(1)?;
            let x = build(arena, args[0], resolve)?;
            let k = if name == "to_radians" {
                std::f64::consts::PI / 180.0
            } else {
                180.0 / std::f64::consts::PI
            };
            let k = arena.constant(k);
            Ok(arena.mul(x, k))
        }
        _ => {
            let f = Func::from_name(name).ok_or_else(|| {
                let help = match crate::diag::closest(name, FUNC_NAMES.iter().copied()) {
                    Some(s) => format!("did you mean `{s}`? {FUNC_HELP}"),
                    None => FUNC_HELP.to_string(),
                };
                ExprError::new(format!("unknown function `{name}`"), help)
            })?;
            arity(1)?;
            let x = build(arena, args[0], resolve)?;
            Ok(arena.call(f, x))
        }
    }
}

fn literal(arena: &mut Arena, lit: &Lit) -> Result<Id, ExprError> {
    let v = match lit {
        Lit::Float(f) => f.base10_parse::<f64>().ok(),
        Lit::Int(i) => i.base10_parse::<f64>().ok(),
        _ => None,
    };
    match v {
        Some(v) if v.is_finite() => Ok(arena.constant(v)),
        Some(_) => Err(ExprError::new(
            "numeric literal out of the range of f64",
            "write a number below 1.8e308 in magnitude",
        )),
        None => Err(ExprError::new(
            "only numeric literals are allowed in expressions",
            "write numbers like `0.02` or `3`",
        )),
    }
}

fn integer_literal(e: &Expr) -> Option<i32> {
    match e {
        Expr::Lit(l) => match &l.lit {
            Lit::Int(i) => i.base10_parse().ok(),
            _ => None,
        },
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => integer_literal(&u.expr).map(|n| -n),
        Expr::Paren(p) => integer_literal(&p.expr),
        _ => None,
    }
}

fn path_name(p: &syn::Path) -> String {
    p.segments
        .iter()
        .map(|s| s.ident.to_string())
        .collect::<Vec<_>>()
        .join("::")
}

fn unsupported(e: &Expr) -> ExprError {
    let text = quote::quote!(#e).to_string();
    ExprError::new(
        format!("unsupported syntax `{text}` in expression"),
        "only + - * /, unary minus, parentheses, numbers, names and the known functions are allowed",
    )
}
