//! The IFToMM benchmark problems A01–A05, each run to its shortened length: the published
//! error measure against each problem's independent reference (see `symbody::iftomm`) must
//! meet the published tolerance. The full lengths run in `mbs_benchmarks`.

use symbody::iftomm::{problems, Problem};

fn check(id: &str) {
    let p: &Problem = problems()
        .into_iter()
        .find(|p| p.spec.id == id)
        .unwrap_or_else(|| panic!("no problem {id}"));
    let o = (p.run)(p.spec.short_t_end, p.settings).unwrap_or_else(|e| panic!("{id}: {e}"));
    eprintln!(
        "{id}: error {:.3e} (tolerance {:.0e}) to t = {} s, {} steps, {} Newton iterations \
         ({} accepted at the roundoff floor)",
        o.error,
        p.spec.tolerance,
        o.t_end,
        o.stats.steps,
        o.stats.newton_iterations,
        o.stats.noise_limited
    );
    assert_eq!(o.t_end, p.spec.short_t_end);
    assert!(
        o.passed(&p.spec),
        "{id}: error {:e} over {} s exceeds the published tolerance {:e}",
        o.error,
        o.t_end,
        p.spec.tolerance
    );
}

#[test]
fn a01_simple_pendulum() {
    check("A01");
}

#[test]
fn a02_two_four_bars() {
    check("A02 (N = 2)");
}

#[test]
fn a02_forty_four_bars() {
    check("A02 (N = 40)");
}

#[test]
fn a03_andrews_squeezer() {
    check("A03");
}

#[test]
fn a04_bricard() {
    check("A04");
}

#[test]
fn a05_flyball_governor() {
    check("A05");
}
