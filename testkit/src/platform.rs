//! An independent reference for a six-leg platform's forward-kinematics conditioning: the
//! leg-length Jacobian by central differences of the lengths, and its condition number.

use nalgebra::{Matrix3, Matrix6, Rotation3, Vector3};
use symbody_runtime::LegInfo;

/// The 2-norm condition number of the platform's leg-length Jacobian at the platform's
/// centre of mass `p` and rotation `r`, by central differences of the lengths
/// `|p + R b − a|` over moves `(δp, δθ)` (δθ a rotation vector turning the platform about its
/// centre of mass), the rotation columns divided by the platform points' RMS radius about
/// their centroid so every column is in metres.
pub fn fk_condition(legs: &[LegInfo], p: Vector3<f64>, r: Matrix3<f64>) -> f64 {
    let lengths = |d: &[f64; 6]| -> Vec<f64> {
        let turn = Rotation3::new(Vector3::new(d[3], d[4], d[5]));
        let (p, r) = (p + Vector3::new(d[0], d[1], d[2]), turn.matrix() * r);
        legs.iter()
            .map(|l| (p + r * Vector3::from(l.platform) - Vector3::from(l.base)).norm())
            .collect()
    };
    let tops: Vec<Vector3<f64>> = legs.iter().map(|l| Vector3::from(l.platform)).collect();
    let centre = tops.iter().sum::<Vector3<f64>>() / tops.len() as f64;
    let radius = (tops
        .iter()
        .map(|b| (b - centre).norm_squared())
        .sum::<f64>()
        / tops.len() as f64)
        .sqrt();
    let h = 1e-6;
    let j = Matrix6::from_fn(|i, k| {
        let (mut plus, mut minus) = ([0.0; 6], [0.0; 6]);
        plus[k] = h;
        minus[k] = -h;
        let slope = (lengths(&plus)[i] - lengths(&minus)[i]) / (2.0 * h);
        if k >= 3 {
            slope / radius
        } else {
            slope
        }
    });
    let s = j.singular_values();
    s.max() / s.min()
}
