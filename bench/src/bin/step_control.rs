//! Work-precision of HHT's step-size control beside fixed steps: error against wall time
//! for rtol = atol = 1e-3 … 1e-9 and a sweep of fixed steps, on `spherical_pendulum`
//! (error: largest |q − q_ref| of the bob's position coordinates at the outputs, against a
//! fixed-step run at 1/16 of the smallest swept step) and on the IFToMM problems A03–A05
//! (their published error measures against their independent references, shortened
//! lengths). Writes `bench-results/step_control.csv`.
//!
//! `cargo run --release -p symbody-bench --bin step_control`

use std::io::Write;
use std::time::Instant;
use symbody_bench::iftomm::{problems, Settings};
use symbody_runtime::HhtBuilder;

const RTOLS: [f64; 7] = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9];
/// Runs per point; the median wall time is reported.
const RUNS: usize = 3;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The spherical pendulum's position coordinates at every 0.01 s up to `t_end`.
fn pendulum(
    builder: HhtBuilder,
    t_end: f64,
) -> Result<(Vec<Vec<f64>>, f64, symbody_runtime::Stats), String> {
    let entry = symbody::generic::find(&symbody_bench::REGISTRY, "spherical_pendulum")
        .map_err(|e| e.to_string())?;
    let mech = entry.default_mechanism();
    let start = Instant::now();
    let mut it = builder.build(mech).map_err(|e| e.to_string())?;
    let n = (t_end / 0.01).round() as usize;
    let mut out = Vec::with_capacity(n);
    for k in 1..=n {
        it.advance_to(k as f64 * 0.01).map_err(|e| e.to_string())?;
        out.push(it.q()[..3].to_vec());
    }
    Ok((out, start.elapsed().as_secs_f64(), it.stats()))
}

fn main() {
    let mut rows = Vec::new();
    let base = || HhtBuilder::new().alpha(0.0).project_velocities(true);
    let t_end = 5.0;
    let fixed_steps = [4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4];
    let (reference, _, _) = pendulum(base().step(1.25e-4 / 16.0), t_end).unwrap();
    let mut point = |label: String, b: &dyn Fn() -> HhtBuilder| {
        let mut walls = Vec::new();
        let mut last = None;
        for _ in 0..RUNS {
            match pendulum(b(), t_end) {
                Ok((q, wall, s)) => {
                    walls.push(wall);
                    let err = q
                        .iter()
                        .zip(&reference)
                        .flat_map(|(a, r)| a.iter().zip(r).map(|(x, y)| (x - y).abs()))
                        .fold(0.0, f64::max);
                    last = Some((err, s));
                }
                Err(e) => {
                    eprintln!("spherical_pendulum {label}: {e}");
                    return;
                }
            }
        }
        let (err, s) = last.unwrap();
        let wall = median(walls);
        eprintln!(
            "spherical_pendulum {label}: error {err:.3e}, {} steps, {:.2} ms",
            s.steps,
            wall * 1e3
        );
        rows.push(format!(
            "spherical_pendulum,{label},{t_end},{err:e},{},{},{},{:e},{:e},{:.4}",
            s.steps,
            s.rejected_steps,
            s.error_test_failures,
            s.smallest_step,
            s.largest_step,
            wall * 1e3
        ));
    };
    for &rtol in &RTOLS {
        point(format!("rtol,{rtol:e}"), &|| base().tolerances(rtol, rtol));
    }
    for &h in &fixed_steps {
        point(format!("fixed,{h:e}"), &|| base().step(h));
    }
    for p in problems() {
        if !["A03", "A04", "A05"].contains(&p.spec.id) {
            continue;
        }
        let t_end = p.spec.short_t_end;
        let fixed: Vec<f64> = [4.0, 2.0, 1.0, 0.5]
            .iter()
            .map(|f| f * p.settings.step)
            .collect();
        let runs = RTOLS
            .iter()
            .map(|&r| {
                (
                    format!("rtol,{r:e}"),
                    Settings {
                        tolerances: Some((r, r)),
                        ..p.settings
                    },
                )
            })
            .chain(fixed.iter().map(|&h| {
                (
                    format!("fixed,{h:e}"),
                    Settings {
                        step: h,
                        tolerances: None,
                        ..p.settings
                    },
                )
            }));
        for (label, settings) in runs {
            let mut walls = Vec::new();
            let mut last = None;
            for _ in 0..RUNS {
                match (p.run)(t_end, settings) {
                    Ok(o) => {
                        walls.push(o.cpu.as_secs_f64());
                        last = Some(o);
                    }
                    Err(e) => {
                        eprintln!("{} {label}: {e}", p.spec.id);
                        break;
                    }
                }
            }
            let Some(o) = last else { continue };
            let s = o.stats;
            let wall = median(walls);
            eprintln!(
                "{} {label}: error {:.3e} (tolerance {:.0e}), {} steps, {:.2} ms",
                p.spec.id,
                o.error,
                p.spec.tolerance,
                s.steps,
                wall * 1e3
            );
            rows.push(format!(
                "{},{label},{t_end},{:e},{},{},{},{:e},{:e},{:.4}",
                p.spec.id,
                o.error,
                s.steps,
                s.rejected_steps,
                s.error_test_failures,
                s.smallest_step,
                s.largest_step,
                wall * 1e3
            ));
        }
    }
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../bench-results/step_control.csv");
    let mut f = std::fs::File::create(&path).unwrap();
    writeln!(f, "problem,mode,setting,t_end,error,steps,rejected,error_test_failures,smallest_step,largest_step,wall_ms_median").unwrap();
    for r in rows {
        writeln!(f, "{r}").unwrap();
    }
    eprintln!("wrote {}", path.display());
}
