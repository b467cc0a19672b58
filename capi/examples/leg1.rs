//! The number `examples/c/main.c` prints, computed in Rust without the C ABI and printed in
//! C's `%.15e` format, so `examples/c/build.sh` can compare the two lines as text.
//!
//! Run with `cargo run --release -p symbody-capi --example leg1`.

/// `x` as C's `printf("%.15e", x)` writes it: Rust's `{:.15e}` gives the same digits but
/// writes the exponent as `e2` or `e-3` where C writes `e+02` and `e-03`.
fn c_exp(x: f64) -> String {
    let s = format!("{x:.15e}");
    match s.split_once('e') {
        Some((mantissa, exp)) => {
            let exp: i32 = exp.parse().expect("Rust writes an integer exponent");
            let sign = if exp < 0 { '-' } else { '+' };
            format!("{mantissa}e{sign}{:02}", exp.abs())
        }
        None => s.to_lowercase(), // C writes inf, nan
    }
}

fn main() -> Result<(), symbody::session::Error> {
    let force = symbody::session::paper_leg1_force_at_1s(&symbody_mechanisms::REGISTRY)?;
    println!("leg 1 force at t = 1 s: {} N", c_exp(force));
    Ok(())
}
