//! The sine and cosine every generated evaluation, the interpreter and the generator's
//! constant folding use: the `libm` crate's (musl's kernels, < 1 ulp), whose `sin_cos`
//! costs 83–91 instructions a call where glibc's `sincos` costs 119 (callgrind, the Stewart
//! model's evaluations), and gives the same bits as its `sin` and `cos` apart, so a pair
//! fused in one place and split in another agrees to the last bit.

/// sin x.
#[inline]
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// cos x.
#[inline]
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// (sin x, cos x), one argument reduction for both; the bits of `libm`'s, remembered per
/// thread for the last arguments ([`MEMO_SLOTS`]).
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    let bits = x.to_bits();
    let slot = (bits.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> (64 - MEMO_BITS)) as usize;
    MEMO.with(|memo| {
        let entry = &memo[slot];
        let (seen, s, c) = entry.get();
        if seen == bits {
            return (s, c);
        }
        let (s, c) = libm::sincos(x);
        entry.set((bits, s, c));
        (s, c)
    })
}

/// The generated evaluations at one state each take the sines and cosines of the same
/// angles, the coordinates themselves (the kinematic path evaluates Φ, Φq, M, γ and Q at
/// each output: five calls per angle), so the last result of each argument is kept: a hit
/// costs about a tenth of a call, a miss about a tenth more. Exact: the same bits as
/// computing it again. One slot per argument value: the Stewart model's 23 angles in 64
/// slots collided often enough that each output computed ~14 of them twice (callgrind's
/// calls from the later evaluations); in 256 (6 KiB a thread) rarely.
const MEMO_BITS: u32 = 8;
const MEMO_SLOTS: usize = 1 << MEMO_BITS;

thread_local! {
    /// By slot: an argument's bits and its sine and cosine. Empty slots hold NaN's, whose
    /// sine and cosine are NaN.
    static MEMO: [std::cell::Cell<(u64, f64, f64)>; MEMO_SLOTS] =
        const { [const { std::cell::Cell::new((0x7ff8_0000_0000_0000, f64::NAN, f64::NAN)) }; MEMO_SLOTS] };
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Units in the last place between `a` and the reference `b`.
    fn ulps(a: f64, b: f64) -> f64 {
        if a == b {
            return 0.0;
        }
        let ulp = f64::from_bits(b.abs().to_bits() + 1) - b.abs();
        (a - b).abs() / ulp
    }

    /// Arguments over the ranges angles and times take, and beyond.
    fn samples() -> impl Iterator<Item = f64> {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        (0..200_000).map(move |i| {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let u = (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            [8.0, 200.0, 2e6, 1e-6][i % 4] * u
        })
    }

    #[test]
    fn sin_cos_gives_the_bits_of_sin_and_cos() {
        for x in samples() {
            let (s, c) = sin_cos(x);
            assert_eq!(
                (s.to_bits(), c.to_bits()),
                (sin(x).to_bits(), cos(x).to_bits()),
                "{x}"
            );
        }
    }

    /// The reference is the platform library's (glibc's: correctly rounded in practice);
    /// two faithfully rounded results differ by at most one ulp.
    #[test]
    fn within_one_ulp_of_the_platform_library() {
        let worst = samples()
            .map(|x| ulps(sin(x), x.sin()).max(ulps(cos(x), x.cos())))
            .fold(0.0, f64::max);
        assert!(worst <= 1.0, "{worst} ulp");
    }

    /// Remembered results are the computed ones: each argument twice, the second time
    /// mostly from the memo, and collisions in between.
    #[test]
    fn remembered_results_are_the_computed_bits() {
        let xs: Vec<f64> = samples().take(1000).chain([0.0, -0.0, 1.0]).collect();
        for pass in 0..2 {
            for &x in &xs {
                let (s, c) = sin_cos(x);
                let (s0, c0) = libm::sincos(x);
                assert_eq!(
                    (s.to_bits(), c.to_bits()),
                    (s0.to_bits(), c0.to_bits()),
                    "{x}, pass {pass}"
                );
            }
        }
    }

    #[test]
    fn special_values() {
        assert_eq!(sin(0.0), 0.0);
        assert_eq!(cos(0.0), 1.0);
        assert!(sin(-0.0).is_sign_negative());
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let (s, c) = sin_cos(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
        }
    }
}
