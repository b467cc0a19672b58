//! Diagnostics for mechanism files: every error names the file, line, column and item,
//! and says how to fix it.

use std::fmt;
use std::ops::Range;

/// One problem found in a mechanism file.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column.
    pub column: usize,
    /// The item the problem is in, e.g. ``body `platform` `` or ``driver `act1` ``.
    pub item: String,
    pub message: String,
    pub help: String,
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "error: {}\n  --> {}:{}:{}\n   = in {}",
            self.message, self.file, self.line, self.column, self.item
        )?;
        if !self.help.is_empty() {
            write!(f, "\n   = help: {}", self.help)?;
        }
        Ok(())
    }
}

/// All problems found in one file (never empty).
#[derive(Debug, Clone, PartialEq)]
pub struct Errors(pub Vec<Diagnostic>);

impl fmt::Display for Errors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, d) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{d}")?;
        }
        Ok(())
    }
}

impl std::error::Error for Errors {}

/// Turns byte spans into line/column positions of one source file.
pub struct SourceMap<'a> {
    pub file: &'a str,
    pub text: &'a str,
}

impl SourceMap<'_> {
    pub fn position(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let before = &self.text[..offset];
        let line = before.matches('\n').count() + 1;
        let column = before.rfind('\n').map_or(offset, |nl| offset - nl - 1) + 1;
        (line, column)
    }

    pub fn diag(
        &self,
        span: Range<usize>,
        item: impl Into<String>,
        message: impl Into<String>,
        help: impl Into<String>,
    ) -> Diagnostic {
        let (line, column) = self.position(span.start);
        Diagnostic {
            file: self.file.to_string(),
            line,
            column,
            item: item.into(),
            message: message.into(),
            help: help.into(),
        }
    }
}

/// The candidate a typo of `name` most likely meant: the nearest by edit distance, if it is a
/// few edits away (anything farther is not worth suggesting).
pub fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .map(|c| (edit_distance(name, c), c))
        .filter(|(d, c)| *d <= 2.max(c.len() / 3))
        .min()
        .map(|(_, c)| c)
}

/// Levenshtein distance (insertions, deletions, substitutions) between `a` and `b`.
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for i in 1..=a.len() {
        let mut cur = vec![i; b.len() + 1];
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// Help for an error of the TOML reader (`toml::de::Error::message`): the closest expected
/// field for a misspelt one (serde lists them: "unknown field `x`, expected one of `a`, `b`").
pub fn toml_error_help(message: &str) -> String {
    if let Some(rest) = message.strip_prefix("unknown field `") {
        let (got, expected) = rest.split_once('`').unwrap_or((rest, ""));
        let names: Vec<&str> = expected.split('`').skip(1).step_by(2).collect();
        return match closest(got, names.iter().copied()) {
            Some(s) => format!("did you mean `{s}`?"),
            None => "remove it, or use one of the expected fields listed".to_string(),
        };
    }
    if message.contains("missing field") {
        "add the missing field".to_string()
    } else {
        "fix the TOML syntax at this place".to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn misspelt_fields_get_the_closest_expected_one() {
        let m = "unknown field `stifness`, expected one of `name`, `stiffness`, `damping`";
        assert_eq!(toml_error_help(m), "did you mean `stiffness`?");
        let m = "unknown field `colour`, expected one of `name`, `mass`";
        assert!(toml_error_help(m).starts_with("remove it"));
        assert_eq!(
            closest("sinn", ["sin", "cos", "sqrt"].into_iter()),
            Some("sin")
        );
        assert_eq!(closest("xyz", ["sin", "cos"].into_iter()), None);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("four_bar", "fourbar"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("bricard", "bricard"), 0);
    }
}
