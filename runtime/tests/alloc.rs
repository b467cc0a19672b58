//! The hot paths (HHT steps, KKT factor/solve, kinematic solves, watchdogs) must not touch
//! the heap: a counting global allocator fails the test on any allocation.

use symbody_testkit::alloc::CountingAllocator;

use symbody_runtime::{
    joint_wrench, DenseKkt, EnergyMeter, EulerLimits, HhtBuilder, Kinematics, Mechanism,
    ResidualWatch, SchurKkt,
};
use symbody_testkit::models::{CircleDriver, Pendulum, TwoBallHinge};

#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

fn allocations(f: impl FnOnce()) -> usize {
    CountingAllocator::count(f)
}

#[test]
fn hot_paths_do_not_allocate() {
    // The counter itself works.
    assert!(allocations(|| drop(std::hint::black_box(vec![1u8; 10]))) > 0);

    // HHT with configuration-dependent mass, both KKT solvers, with and without reuse.
    let q0 = [0.0, 0.0, 0.0, 0.5, 0.1, -0.4];
    let mut a = HhtBuilder::new().q0(&q0).build(Pendulum::exact()).unwrap();
    let mut b = HhtBuilder::new()
        .q0(&q0)
        .reuse_factorization(true)
        .build_with_solver::<_, DenseKkt>(Pendulum::paper())
        .unwrap();
    let n = allocations(|| {
        for _ in 0..500 {
            a.step().unwrap();
            b.step().unwrap();
        }
        a.advance_to(0.7531).unwrap();
        b.advance_to(0.7531).unwrap();
        let _ = a.joint_force(0, 0).unwrap();
        let _ = a.joint_wrench(0).unwrap();
        let _ = a.energy();
    });
    assert_eq!(n, 0, "HHT steps allocated {n} times");

    // Rejected attempts and step halving (a step far too long for two Newton
    // iterations) allocate nothing either.
    let mut c = HhtBuilder::new()
        .step(0.2)
        .max_iterations(3)
        .q0(&q0)
        .build(Pendulum::exact())
        .unwrap();
    let n = allocations(|| c.advance_to(1.0).unwrap());
    assert_eq!(n, 0, "HHT with step cuts allocated {n} times");
    assert!(c.stats().rejected_steps > 0, "{:?}", c.stats());

    // Kinematic analyses and watchdogs.
    let mech = Pendulum::exact();
    let info = mech.info();
    let mut kin = Kinematics::<SchurKkt>::new(info).unwrap();
    let mut watch = ResidualWatch::new(info);
    let limits = EulerLimits::default();
    let mut q = [0.05, -0.45, 0.02, 0.1, 0.0, 0.0];
    let (mut qd, mut qdd, mut lam) = ([0.3; 6], [0.0; 6], [0.0; 3]);
    let n = allocations(|| {
        kin.position(&mech, 0.0, &mut q).unwrap();
        kin.project_velocity(&mech, 0.0, &q, &mut qd).unwrap();
        kin.acceleration(&mech, 0.0, &q, &qd, &mut qdd, &mut lam)
            .unwrap();
        let r = watch.check(&mech, 0.0, &q, &qd).unwrap();
        assert!(r.position < 1e-10 && r.velocity < 1e-12);
        limits.check(info, 0.0, &q).unwrap();
    });
    assert_eq!(n, 0, "kinematics allocated {n} times");

    // Energy records (with their saddle-point solve) and wrenches from their multipliers.
    let mut d = HhtBuilder::new().build(CircleDriver).unwrap();
    let mut meter = EnergyMeter::<SchurKkt>::new(CircleDriver.info()).unwrap();
    let n = allocations(|| {
        for _ in 0..50 {
            d.step().unwrap();
            meter.record(&CircleDriver, d.t(), d.q(), d.qd()).unwrap();
            let _ =
                joint_wrench(CircleDriver.info(), d.q(), meter.phi_q(), meter.lambda(), 0).unwrap();
            let _ = d.driver_effort(1).unwrap();
        }
    });
    assert_eq!(n, 0, "energy records allocated {n} times");

    // Redundant rows: HHT and the position analysis on the two-ball hinge.
    let hinge = TwoBallHinge::new(0.0);
    let mut e = HhtBuilder::new()
        .q0(&[0.2, -0.45, 0.0, 0.0, 0.0, 0.4])
        .build(hinge)
        .unwrap();
    let mut kin = Kinematics::<DenseKkt>::new(hinge.info()).unwrap();
    let mut q = [0.03, -0.47, 0.02, 0.05, -0.04, 0.3];
    let n = allocations(|| {
        for _ in 0..50 {
            e.step().unwrap();
        }
        kin.position(&hinge, 0.0, &mut q).unwrap();
    });
    assert_eq!(n, 0, "redundant rows allocated {n} times");
}
