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

/// (sin x, cos x), one argument reduction for both.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
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
