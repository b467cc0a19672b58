//! Numbers in the CSV files: the shortest text that reads back to the same f64, exactly as
//! `format!("{v:?}")` prints it, without its cost (most of a live-written run's time went
//! to formatting).

use std::fmt::Write as _;

/// Formats f64's as `{:?}` does: the shortest digits that read back to the same f64, the
/// closest of them to its value. `zmij` writes them as `{:?}` does where both write plain
/// decimals, `1e-4 ≤ |v| < 1e15` here, and where both write exponents below, |v| < 1e-5
/// (`1.5e-7`), and zero; `{:?}` itself writes the rest (between 1e-5 and 1e-4 `zmij` still
/// writes decimals, and from 1e16 its exponents carry a `+`), and every value that may be a
/// tie ([`may_tie`]), which the two break differently.
#[derive(Default)]
pub struct Shortest {
    fast: zmij::Buffer,
    slow: String,
}

impl Shortest {
    /// `v` as `format!("{v:?}")`.
    pub fn format(&mut self, v: f64) -> &str {
        let a = v.abs();
        if a < 1e-5 || ((1e-4..1e15).contains(&a) && !may_tie(v)) {
            self.fast.format_finite(v)
        } else {
            self.slow.clear();
            let _ = write!(self.slow, "{v:?}");
            &self.slow
        }
    }
}

/// Whether `v` (finite, nonzero, 1e-4 ≤ |v| < 1e15) may lie exactly halfway between two shortest
/// texts (`-1149636667324797.25`: `{:?}` writes `.3`, `zmij` `.2`). That needs its exact
/// decimal expansion to have 17 or 18 significant digits: one more than the shortest text,
/// ending in 5, and close enough to it that the shorter text reads back. With `v = m·2^e`
/// (`m` odd) the expansion of `m·5^(−e)/10^(−e)` has about `log₁₀ m − e·log₁₀ 5` digits,
/// estimated here from `m`'s bit length to within one; an integer (`e ≥ 0`, at most 15
/// digits here) is its own shortest text. Values a simulation computes have 19 or more
/// digits below |v| ≈ 1e14; short binary fractions (`n/8`) and larger values go to `{:?}`.
fn may_tie(v: f64) -> bool {
    let bits = v.to_bits();
    let (biased, fraction) = (((bits >> 52) & 0x7ff) as i32, bits & ((1 << 52) - 1));
    let (m, e) = match biased {
        0 => (fraction, -1074),
        _ => (fraction | 1 << 52, biased - 1075),
    };
    let tz = m.trailing_zeros() as i32;
    let (m, e) = (m >> tz, e + tz);
    if e >= 0 {
        return false;
    }
    let digits = f64::from(64 - m.leading_zeros() as i32) * std::f64::consts::LOG10_2
        + f64::from(-e) * 0.698_970_004_336_018_8;
    (15.5..=19.5).contains(&digits)
}

/// Writes `values` as one CSV record of `w`: their texts joined by commas, then a newline,
/// as `csv::Writer` writes them. A number's text never needs quoting, so it goes to `w` as
/// is: through `csv::Writer`, the check of each byte for quoting and the field bookkeeping
/// cost more than formatting the number.
pub fn write_record<W: std::io::Write>(
    w: &mut W,
    values: impl IntoIterator<Item = f64>,
    num: &mut Shortest,
) -> std::io::Result<()> {
    let mut separator: &[u8] = b"";
    for v in values {
        w.write_all(separator)?;
        w.write_all(num.format(v).as_bytes())?;
        separator = b",";
    }
    w.write_all(b"\n")
}

/// Writes `columns` as the header record of `w`, quoted where CSV needs it (the names come
/// from users' files).
pub fn write_header<W: std::io::Write, S: AsRef<[u8]>>(
    w: &mut W,
    columns: &[S],
) -> std::io::Result<()> {
    let mut header = csv::Writer::from_writer(w);
    header.write_record(columns)?;
    header.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What [`write_header`] and [`write_record`] write is what `csv::Writer` writes for
    /// the same fields (each number's text as `{:?}` gives it): a header quoted where CSV
    /// needs it, then records of every kind of number.
    #[test]
    fn records_are_what_csv_writes() {
        let columns = ["t", "a,b", "say \"hi\"", "line\nbreak"];
        let values = [
            0.0,
            -0.0,
            1.5,
            -2.25e-7,
            1e300,
            5e-324,
            123_456.789,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        let (mut ours, mut num) = (Vec::new(), Shortest::default());
        write_header(&mut ours, &columns).unwrap();
        write_record(&mut ours, values, &mut num).unwrap();
        write_record(&mut ours, [1.0], &mut num).unwrap();
        let mut csv = csv::WriterBuilder::new()
            .flexible(true)
            .from_writer(Vec::new());
        csv.write_record(columns).unwrap();
        csv.write_record(values.map(|v| format!("{v:?}"))).unwrap();
        csv.write_record(["1.0"]).unwrap();
        let theirs = csv.into_inner().unwrap();
        assert_eq!(String::from_utf8(ours), String::from_utf8(theirs));
    }

    /// Against `{:?}` itself, byte for byte: random bit patterns (every exponent), random
    /// values in the plain-decimal range, values with short binary fractions (where ties
    /// live: the test first shows that `zmij` alone differs on some of them), values around
    /// the bounds, and the special values.
    #[test]
    fn the_text_is_debugs() {
        let mut num = Shortest::default();
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut values = Vec::new();
        for _ in 0..300_000 {
            values.push(f64::from_bits(next()));
            let u = (next() >> 11) as f64 / (1u64 << 53) as f64;
            values.push((u - 0.5) * 10f64.powi((next() % 40) as i32 - 22));
            let int = (next() >> 11) % (1u64 << 50);
            values.push(int as f64 / (1u64 << (next() % 12)) as f64);
        }
        let differs = |v: &f64| zmij::Buffer::new().format(*v) != format!("{v:?}");
        let tie = values
            .iter()
            .find(|v| v.abs() < 1e15 && v.abs() >= 1e-4 && differs(v));
        assert!(
            tie.is_some(),
            "no tie among the samples: the test would not see one"
        );
        for b in [1e-4f64, 1e15, 1e16, 1e-5, 0.1, 1.0, 100.0] {
            let mut v = f64::from_bits(b.to_bits() - 50);
            for _ in 0..100 {
                values.extend([v, -v]);
                v = f64::from_bits(v.to_bits() + 1);
            }
        }
        values.extend([
            0.0,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            5e-324,
        ]);
        for v in values {
            assert_eq!(num.format(v), format!("{v:?}"), "bits {:#x}", v.to_bits());
        }
    }
}
