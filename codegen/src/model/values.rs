//! Numbers, vectors and expressions in mechanism files: parameters (with cycle
//! detection), constants, expressions in `t`, item names and body references.

use super::raw::{SScalar, SStr, SVec, Scalar};
use super::{BodyRef, ParamState, Validator};
use crate::expr::{Arena, Id, Var};
use crate::parse::parse_expr;
use std::collections::HashMap;
use std::ops::Range;

pub(super) fn is_keyword(s: &str) -> bool {
    KEYWORDS.contains(&s)
}

impl Validator<'_> {
    pub(super) fn required_scalar(
        &mut self,
        s: &Option<SScalar>,
        span: &Range<usize>,
        item: &str,
        field: &str,
        unit: &str,
    ) -> Option<f64> {
        match s {
            Some(s) => self.scalar(s, item, field),
            None => {
                self.err(
                    span.clone(),
                    item,
                    format!("{item} is missing `{field}`"),
                    &format!("add `{field} = <value in {unit}>`"),
                );
                None
            }
        }
    }

    pub(super) fn vec3(&mut self, v: &SVec, item: &str, field: &str) -> Option<[f64; 3]> {
        let comps = v.get_ref();
        if comps.len() != 3 {
            self.err(
                v.span(),
                item,
                format!(
                    "`{field}` has {} component{}, expected 3",
                    comps.len(),
                    if comps.len() == 1 { "" } else { "s" }
                ),
                &format!("write `{field} = [x, y, z]`"),
            );
            return None;
        }
        let mut out = [0.0; 3];
        for (k, c) in comps.iter().enumerate() {
            out[k] = self.scalar(c, item, field)?;
        }
        Some(out)
    }

    pub(super) fn scalar(&mut self, s: &SScalar, item: &str, field: &str) -> Option<f64> {
        match s.get_ref() {
            Scalar::Int(i) => Some(*i as f64),
            Scalar::Float(f) => self.finite(*f, s.span(), item, field),
            Scalar::Expr(src) => self.constant_expr(src, s.span(), item, field),
        }
    }

    /// TOML accepts `inf` and `nan`; no physical quantity here may be either.
    pub(super) fn finite(
        &mut self,
        v: f64,
        span: Range<usize>,
        item: &str,
        field: &str,
    ) -> Option<f64> {
        if v.is_finite() {
            Some(v)
        } else {
            self.err(
                span,
                item,
                format!("`{field}` is {v}"),
                "give a finite number",
            );
            None
        }
    }

    /// Evaluates an expression of parameters (no `t`) to a number.
    pub(super) fn constant_expr(
        &mut self,
        src: &str,
        span: Range<usize>,
        item: &str,
        field: &str,
    ) -> Option<f64> {
        let mut arena = Arena::new();
        let mut missing: Vec<String> = Vec::new();
        // Resolve names first (needs &mut self), then build.
        let names = referenced_names(src);
        let mut values: HashMap<String, f64> = HashMap::new();
        for n in names {
            if self.params.contains_key(&n) {
                self.uses
                    .entry(n.clone())
                    .or_default()
                    .insert(item.to_string());
                self.fields
                    .entry(n.clone())
                    .or_default()
                    .insert((item.to_string(), field.to_string()));
                self.reads.entry(n.clone()).or_default().push(span.clone());
                if let Some(v) = self.param_value(&n) {
                    values.insert(n, v);
                } else {
                    return None;
                }
            } else {
                missing.push(n);
            }
        }
        let mut resolve = |a: &mut Arena, n: &str| values.get(n).map(|v| a.constant(*v));
        match parse_expr(&mut arena, src, &mut resolve) {
            Ok(id) => match arena.as_const(id) {
                Some(v) if v.is_finite() => Some(v),
                Some(v) => {
                    self.err(
                        span,
                        item,
                        format!("`{field}` evaluates to {v}"),
                        "check the expression for a division by zero or a domain error",
                    );
                    None
                }
                None => {
                    self.err(
                        span,
                        item,
                        format!("`{field}` depends on `t`, but must be a constant"),
                        "only driver values may depend on time",
                    );
                    None
                }
            },
            Err(e) => {
                let help = if e.message.starts_with("unknown name") && !self.params.is_empty() {
                    let mut known: Vec<&str> = self.params.keys().map(|s| s.as_str()).collect();
                    known.sort();
                    match missing
                        .first()
                        .and_then(|m| closest(m, known.iter().copied()))
                    {
                        Some(s) => format!("did you mean `{s}`? {}", e.help),
                        None => e.help.clone(),
                    }
                } else {
                    e.help.clone()
                };
                self.err(span, item, format!("in `{field}`: {}", e.message), &help);
                None
            }
        }
    }

    pub(super) fn param_value(&mut self, name: &str) -> Option<f64> {
        match self.values.get(name) {
            Some(ParamState::Done(v)) => return Some(*v),
            Some(ParamState::Busy) => {
                let span = self.params[name].0.clone();
                self.err(
                    span,
                    &format!("parameter `{name}`"),
                    format!("parameter `{name}` depends on itself"),
                    "break the cycle: give one of the parameters a number",
                );
                return None;
            }
            None => {}
        }
        let (span, value) = self.params.get(name)?.clone();
        self.values.insert(name.to_string(), ParamState::Busy);
        let item = format!("parameter `{name}`");
        let v = match value {
            Scalar::Int(i) => Some(i as f64),
            Scalar::Float(f) => self.finite(f, span, &item, name),
            Scalar::Expr(src) => self.constant_expr(&src, span, &item, name),
        };
        match v {
            Some(v) => {
                self.values.insert(name.to_string(), ParamState::Done(v));
                Some(v)
            }
            None => {
                // Leave it busy-free but unresolved so later uses do not report a false cycle.
                self.values
                    .insert(name.to_string(), ParamState::Done(f64::NAN));
                None
            }
        }
    }

    pub(super) fn positive(&mut self, v: f64, span: Range<usize>, item: &str, field: &str) -> bool {
        if v > 0.0 {
            return true;
        }
        self.err(
            span,
            item,
            format!("`{field}` must be positive, got {v}"),
            &format!("give `{field}` a positive value"),
        );
        false
    }

    pub(super) fn non_negative(
        &mut self,
        s: &Option<SScalar>,
        item: &str,
        field: &str,
    ) -> Option<f64> {
        let Some(s) = s else { return Some(0.0) };
        let v = self.scalar(s, item, field)?;
        if v < 0.0 {
            self.err(
                s.span(),
                item,
                format!("`{field}` must not be negative, got {v}"),
                &format!("give `{field}` a value ≥ 0"),
            );
            return None;
        }
        Some(v)
    }

    /// A unit vector from `v` (error for a zero vector).
    pub(super) fn direction(&mut self, v: &SVec, item: &str, field: &str) -> Option<[f64; 3]> {
        let d = self.vec3(v, item, field)?;
        let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if !(n > 1e-12) {
            self.err(
                v.span(),
                item,
                format!("`{field}` is the zero vector"),
                &format!("give `{field}` a direction, e.g. [0, 0, 1]"),
            );
            return None;
        }
        Some(d.map(|x| x / n))
    }

    /// An expression in `t` (and the parameters, and `initial` when given), built in the
    /// model's arena; it must be finite at t = 0.
    pub(super) fn time_expr(
        &mut self,
        src: &SStr,
        item: &str,
        field: &str,
        initial: Option<f64>,
    ) -> Option<Id> {
        for n in referenced_names(src.get_ref()) {
            if self.params.contains_key(&n) {
                self.uses
                    .entry(n.clone())
                    .or_default()
                    .insert(item.to_string());
                self.fields
                    .entry(n.clone())
                    .or_default()
                    .insert((item.to_string(), field.to_string()));
                self.reads.entry(n).or_default().push(src.span());
            }
        }
        let params: Vec<(String, f64)> = self
            .values
            .iter()
            .filter_map(|(k, v)| match v {
                ParamState::Done(x) => Some((k.clone(), *x)),
                ParamState::Busy => None,
            })
            .collect();
        let mut resolve = |arena: &mut Arena, n: &str| -> Option<Id> {
            match n {
                "t" => Some(arena.var(Var::T)),
                "initial" => initial.map(|v| arena.constant(v)),
                _ => params
                    .iter()
                    .find(|(k, _)| k == n)
                    .map(|(_, v)| arena.constant(*v)),
            }
        };
        match parse_expr(&mut self.arena, src.get_ref(), &mut resolve) {
            Ok(id) if self.has_non_finite_constant(id) => {
                self.err(
                    src.span(),
                    item,
                    format!("`{field}` folds to an infinite or NaN constant"),
                    "check the expression for an overflow or a division by zero",
                );
                None
            }
            Ok(id) if !self.arena.eval(id, &|_| 0.0).is_finite() => {
                self.err(
                    src.span(),
                    item,
                    format!(
                        "`{field}` is not finite at t = 0 ({})",
                        self.arena.eval(id, &|_| 0.0)
                    ),
                    "check the expression for a division by zero or a domain error",
                );
                None
            }
            Ok(id) => Some(id),
            Err(e) => {
                let help = if e.message.starts_with("unknown name `initial`") {
                    format!("`initial` is only defined for drivers; {}", e.help)
                } else {
                    e.help.clone()
                };
                self.err(
                    src.span(),
                    item,
                    format!("in `{field}`: {}", e.message),
                    &help,
                );
                None
            }
        }
    }

    /// A scalar given as a number or as an expression in `t`.
    pub(super) fn time_scalar(&mut self, s: &SScalar, item: &str, field: &str) -> Option<Id> {
        match s.get_ref() {
            Scalar::Expr(src) => {
                let spanned = SStr::new(s.span(), src.clone());
                self.time_expr(&spanned, item, field, None)
            }
            _ => {
                let v = self.scalar(s, item, field)?;
                Some(self.arena.constant(v))
            }
        }
    }

    /// Whether constant folding produced ±∞ or NaN anywhere under `id` (it cannot be emitted).
    fn has_non_finite_constant(&self, id: Id) -> bool {
        self.arena
            .reachable(&[id])
            .iter()
            .enumerate()
            .any(|(i, &m)| {
                m && self
                    .arena
                    .as_const(Id(i as u32))
                    .is_some_and(|c| !c.is_finite())
            })
    }

    /// Checks the name of the `index`-th item of `kind` and registers it.
    pub(super) fn item_name(
        &mut self,
        name: &Option<SStr>,
        span: Range<usize>,
        kind: &str,
        index: usize,
        names: &mut HashMap<String, Range<usize>>,
    ) -> Option<String> {
        let Some(n) = name else {
            self.err(
                span,
                &format!("[[{kind}]] number {}", index + 1),
                format!("{kind} number {} has no `name`", index + 1),
                "add `name = \"...\"`; names are unique across bodies, joints, drivers and forces",
            );
            return None;
        };
        let s = n.get_ref().clone();
        if !is_identifier(&s) {
            self.err(
                n.span(),
                &format!("{kind} `{s}`"),
                format!("{kind} name `{s}` is not a valid identifier"),
                "use letters, digits and underscores, starting with a letter",
            );
            return None;
        }
        if let Some(prev) = names.get(&s) {
            let (line, _) = self.map.position(prev.start);
            let help = if s == "ground" {
                "`ground` is reserved for the fixed frame; rename this item".to_string()
            } else {
                format!(
                    "names must be unique; the first `{s}` is on line {line}: rename one of them"
                )
            };
            self.err(
                n.span(),
                &format!("{kind} `{s}`"),
                format!("duplicate name `{s}`"),
                &help,
            );
            return None;
        }
        names.insert(s.clone(), n.span());
        Some(s)
    }

    /// Resolves a body name (`ground` is `None`).
    pub(super) fn body_ref(
        &mut self,
        name: &Option<SStr>,
        span: &Range<usize>,
        item: &str,
        field: &str,
        body_index: &HashMap<String, usize>,
    ) -> Option<BodyRef> {
        let Some(n) = name else {
            self.err(
                span.clone(),
                item,
                format!("{item} is missing `{field}`"),
                &format!("add `{field} = \"<body name>\"` (or \"ground\")"),
            );
            return None;
        };
        if n.get_ref() == "ground" {
            return Some(None);
        }
        match body_index.get(n.get_ref()) {
            Some(&i) => Some(Some(i)),
            None => {
                let mut known: Vec<&String> = body_index.keys().collect();
                known.sort();
                let suggestion = closest(n.get_ref(), known.iter().map(|s| s.as_str()));
                let help = match suggestion {
                    Some(s) => format!("did you mean `{s}`? bodies are declared with [[body]]; `ground` is the fixed frame"),
                    None => "declare the body with [[body]], or use `ground`".to_string(),
                };
                self.err(
                    n.span(),
                    item,
                    format!("unknown body `{}` in `{field}`", n.get_ref()),
                    &help,
                );
                None
            }
        }
    }
}

/// Identifiers that appear in an expression (syntax errors are reported by the parser later).
fn referenced_names(src: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut prev_dot = false;
    let mut in_number = false;
    for ch in src.chars().chain(std::iter::once(' ')) {
        if ch.is_alphanumeric() || ch == '_' {
            if cur.is_empty() && ch.is_ascii_digit() {
                in_number = true;
            }
            cur.push(ch);
        } else {
            if !cur.is_empty() && !in_number && !prev_dot && ch != '(' {
                out.push(cur.clone());
            }
            if !cur.is_empty() || ch != ' ' {
                prev_dot = ch == '.' && !in_number;
            }
            cur.clear();
            in_number = false;
        }
    }
    out
}

/// Rust keywords cannot name a generated module.
const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut",
    "pub", "ref", "return", "self", "static", "struct", "super", "trait", "true", "try", "type",
    "unsafe", "use", "where", "while", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield",
];

pub(super) fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

pub(super) use crate::diag::closest;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_in_expressions() {
        assert_eq!(referenced_names("c0 + 0.02 * sin(t)"), vec!["c0", "t"]);
        assert_eq!(
            referenced_names("(phi1).to_radians() * r_b"),
            vec!["phi1", "r_b"]
        );
        assert_eq!(referenced_names("1e-3 * x"), vec!["x"]);
    }
}
