//! Independent reference for the paper scenario's joint and actuator forces: the inverse
//! dynamics of the 6-6 Stewart platform by Newton–Euler, derived by hand from
//! docs/paper-scenario.md (not from the generated code or the 78-coordinate model).
//!
//! Given the six leg lengths Lᵢ(t) (joint centre Bᵢ to Tᵢ) and their first two derivatives,
//! the platform's pose, twist and acceleration follow from six-equation kinematics; each leg's
//! motion follows from the platform's; the forces follow from the Newton–Euler equations of
//! the platform (6 equations for the 6 axial leg forces) and of each leg (moment about Bᵢ for
//! the transverse part of the force at Tᵢ, the leg's Newton equation for the force at Bᵢ, the
//! piston's axial equation for the actuator force). Everything is analytic: the only
//! iteration is Newton on the leg lengths, converged to roundoff.
//!
//! Assumption: the legs do not spin about their own axes. Each leg part is axisymmetric
//! (Ixx = Izz), the spherical joints' forces and gravity act on the axis, and the prismatic
//! joint locks the two parts' rotation, so the whole leg's axial angular momentum is
//! conserved (Euler: I_yy ω̇_y = (I_zz − I_xx) ω_z ω_x + τ_y = 0). The scenario starts from
//! the velocity of least kinetic energy, which has zero spin, so the spin stays zero and the
//! leg's angular velocity is the one that turns its axis, ωₗ = u × u̇.

use nalgebra::{Matrix3, Matrix6, Rotation3, Vector3, Vector6};

/// Number of legs.
pub const LEGS: usize = 6;

// docs/paper-scenario.md, typed in from the document (not read from the mechanism file).
const BASE_DEG: [f64; LEGS] = [10.5, 109.5, 130.5, 229.5, 250.5, 349.5];
const PLATFORM_DEG: [f64; LEGS] = [49.5, 70.5, 169.5, 190.5, 289.5, 310.5];
const AMPLITUDE: [f64; LEGS] = [0.02, -0.06, 0.02, -0.02, 0.08, -0.02];
const R_BASE: f64 = 0.27;
const R_PLATFORM: f64 = 0.105;
/// Initial platform height (level, centred).
const Y0: f64 = 0.3466575;
const G: f64 = 9.81;
const M_PLATFORM: f64 = 1.79;
const I_PLATFORM: [f64; 3] = [0.0326, 0.065, 0.0326];
/// Leg parts: uniform solid cylinders 0.25 m long; each centre of mass is `HALF` from its
/// joint along the leg.
const PART_LENGTH: f64 = 0.25;
const HALF: f64 = 0.125;
const M_CYLINDER: f64 = 0.30;
const R_CYLINDER: f64 = 0.015;
const M_PISTON: f64 = 0.20;
const R_PISTON: f64 = 0.010;

/// Transverse moment of inertia of a uniform solid cylinder about its centre. The axial one
/// never enters: the legs' angular velocity and acceleration are both perpendicular to the
/// axis (module doc).
fn transverse_inertia(m: f64, r: f64) -> f64 {
    m * (3.0 * r * r + PART_LENGTH * PART_LENGTH) / 12.0
}

fn gravity() -> Vector3<f64> {
    Vector3::new(0.0, -G, 0.0)
}

/// Point at radius `r` and angle `deg` counter-clockwise from +X seen from above (a positive
/// rotation about +Y, which is up).
fn circle_point(r: f64, deg: f64) -> Vector3<f64> {
    let a = deg.to_radians();
    Vector3::new(r * a.cos(), 0.0, -r * a.sin())
}

fn base_joint(i: usize) -> Vector3<f64> {
    circle_point(R_BASE, BASE_DEG[i])
}

/// Upper joint Tᵢ in the platform frame.
fn platform_joint(i: usize) -> Vector3<f64> {
    circle_point(R_PLATFORM, PLATFORM_DEG[i])
}

/// Forces of the inverse dynamics at one instant, in the conventions of
/// `symbody::scenario::Run` (global frame, N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forces {
    /// Force on the platform at each upper spherical joint Tᵢ.
    pub upper: [[f64; 3]; LEGS],
    /// Force on each lower cylinder at its base spherical joint Bᵢ (from the ground).
    pub lower: [[f64; 3]; LEGS],
    /// Actuator forces, positive pushing the platform away from the base (compression).
    pub actuators: [f64; LEGS],
    /// Platform `[X, Y, Z, θ, β, γ]`, A = Rz(γ)·Ry(β)·Rx(θ).
    pub pose: [f64; 6],
}

/// Platform pose as position of the centre of mass and local-to-global rotation.
#[derive(Debug, Clone, Copy)]
pub struct Pose {
    pub r: Vector3<f64>,
    pub a: Rotation3<f64>,
}

impl Pose {
    /// The scenario's starting pose: level, centred, at Y0.
    pub fn initial() -> Self {
        Pose {
            r: Vector3::new(0.0, Y0, 0.0),
            a: Rotation3::identity(),
        }
    }

    /// `[X, Y, Z, θ, β, γ]` with A = Rz(γ)·Ry(β)·Rx(θ): nalgebra's (roll, pitch, yaw) are
    /// exactly these angles (R = Rz(yaw)·Ry(pitch)·Rx(roll)), unique for |β| < π/2.
    pub fn coordinates(&self) -> [f64; 6] {
        let (theta, beta, gamma) = self.a.euler_angles();
        [self.r.x, self.r.y, self.r.z, theta, beta, gamma]
    }

    /// Platform joint Tᵢ relative to the centre of mass, global frame.
    fn arm(&self, i: usize) -> Vector3<f64> {
        self.a * platform_joint(i)
    }

    /// Vector from Bᵢ to Tᵢ.
    fn leg(&self, i: usize) -> Vector3<f64> {
        self.r + self.arm(i) - base_joint(i)
    }

    /// Leg-rate Jacobian: L̇ᵢ = uᵢ·(v + ω × ρᵢ) = [uᵢᵀ, (ρᵢ × uᵢ)ᵀ]·[v; ω], with the twist
    /// (velocity of the centre of mass, angular velocity) in the global frame.
    fn jacobian(&self) -> Matrix6<f64> {
        let mut j = Matrix6::zeros();
        for i in 0..LEGS {
            let u = self.leg(i).normalize();
            let m = self.arm(i).cross(&u);
            for k in 0..3 {
                j[(i, k)] = u[k];
                j[(i, 3 + k)] = m[k];
            }
        }
        j
    }
}

/// Leg lengths of the starting pose: the drivers' `initial` values plus the two 0.125 m
/// joint-to-centre offsets (c = L − 0.25).
pub fn initial_lengths() -> [f64; LEGS] {
    let p = Pose::initial();
    std::array::from_fn(|i| p.leg(i).norm())
}

/// Leg lengths Lᵢ(t) = Lᵢ(0) + aᵢ sin t and their first two derivatives.
pub fn paper_lengths(t: f64) -> ([f64; LEGS], [f64; LEGS], [f64; LEGS]) {
    let l0 = initial_lengths();
    (
        std::array::from_fn(|i| l0[i] + AMPLITUDE[i] * t.sin()),
        std::array::from_fn(|i| AMPLITUDE[i] * t.cos()),
        std::array::from_fn(|i| -AMPLITUDE[i] * t.sin()),
    )
}

/// Forward kinematics: Newton on the six leg-length equations from `guess`, with the
/// analytic Jacobian. The correction is a twist (δr, δφ) applied as r += δr,
/// A ← exp(δφ)·A, so the rotation stays orthonormal and no Euler-angle singularity enters.
pub fn forward_kinematics(guess: Pose, lengths: &[f64; LEGS]) -> Pose {
    let mut p = guess;
    let mut converged = 0;
    for _ in 0..50 {
        let residual = Vector6::from_fn(|i, _| lengths[i] - p.leg(i).norm());
        let delta = p
            .jacobian()
            .lu()
            .solve(&residual)
            .expect("leg Jacobian is regular along the paper's motion");
        p.r += delta.fixed_rows::<3>(0);
        p.a = Rotation3::new(delta.fixed_rows::<3>(3).into_owned()) * p.a;
        // Quadratic convergence: once the correction is 1e-11 the next one is at roundoff,
        // so one more iteration leaves the pose converged to the last bits.
        if delta.amax() < 1e-11 {
            converged += 1;
            if converged == 2 {
                return p;
            }
        }
    }
    panic!(
        "forward kinematics did not converge at {:?}",
        p.coordinates()
    );
}

/// Platform pose at time t, continued from the start in steps of at most 0.05 s so Newton
/// stays on the scenario's branch (the platform turns up to about 1 rad about Y).
pub fn paper_pose(t: f64) -> Pose {
    let n = ((t.abs() / 0.05).ceil() as usize).max(1);
    let mut p = Pose::initial();
    for k in 1..=n {
        let s = t * k as f64 / n as f64;
        p = forward_kinematics(p, &paper_lengths(s).0);
    }
    p
}

/// The paper scenario's forces at time t (drivers Lᵢ(t) = Lᵢ(0) + aᵢ sin t).
pub fn paper_forces(t: f64) -> Forces {
    let (_, rates, accelerations) = paper_lengths(t);
    inverse_dynamics(&paper_pose(t), &rates, &accelerations)
}

/// Newton–Euler inverse dynamics at a platform pose (which must match the leg lengths) with
/// the given leg rates L̇ᵢ and accelerations L̈ᵢ. With zero rates and accelerations this is
/// the static problem.
pub fn inverse_dynamics(pose: &Pose, rates: &[f64; LEGS], accelerations: &[f64; LEGS]) -> Forces {
    let g = gravity();
    let jac = pose.jacobian();
    let lu = jac.lu();

    // Platform twist from J·[v; ω] = L̇.
    let twist = lu
        .solve(&Vector6::from_column_slice(rates))
        .expect("leg Jacobian is regular");
    let v: Vector3<f64> = twist.fixed_rows::<3>(0).into_owned();
    let w: Vector3<f64> = twist.fixed_rows::<3>(3).into_owned();

    // Platform acceleration. For each leg d = Tᵢ − Bᵢ = L u with Bᵢ fixed:
    //   L̈ = u·d̈ + L|u̇|²   (differentiate L² = d·d twice; the transverse part of ḋ is L u̇),
    //   d̈ = a + α × ρ + ω × (ω × ρ),
    // so J·[a; α] = L̈ − L|u̇|² − u·(ω × (ω × ρ)): the J̇·twist term, analytic.
    let mut rhs = Vector6::zeros();
    for i in 0..LEGS {
        let rho = pose.arm(i);
        let d = pose.leg(i);
        let l = d.norm();
        let u = d / l;
        let vt = v + w.cross(&rho);
        let u_dot = (vt - u * u.dot(&vt)) / l;
        rhs[i] = accelerations[i] - l * u_dot.norm_squared() - u.dot(&w.cross(&w.cross(&rho)));
    }
    let acc = lu.solve(&rhs).expect("leg Jacobian is regular");
    let a: Vector3<f64> = acc.fixed_rows::<3>(0).into_owned();
    let alpha: Vector3<f64> = acc.fixed_rows::<3>(3).into_owned();

    let it_cyl = transverse_inertia(M_CYLINDER, R_CYLINDER);
    let it_pis = transverse_inertia(M_PISTON, R_PISTON);

    // Per leg: axis, transverse part of the force on the platform at Tᵢ, and the inertial
    // terms needed afterwards.
    let mut u = [Vector3::zeros(); LEGS];
    let mut transverse = [Vector3::zeros(); LEGS];
    // m_c (a_c − g) + m_p (a_p − g): the leg's Newton equation without the joint forces.
    let mut leg_inertial = [Vector3::zeros(); LEGS];
    // m_p u·(a_p − g): the piston's axial equation without the joint forces.
    let mut piston_axial = [0.0; LEGS];
    for i in 0..LEGS {
        let rho = pose.arm(i);
        let d = pose.leg(i);
        let l = d.norm();
        let ui = d / l;
        let vt = v + w.cross(&rho);
        let at = a + alpha.cross(&rho) + w.cross(&w.cross(&rho));
        let l_dot = ui.dot(&vt);
        let u_dot = (vt - ui * l_dot) / l;
        let l_ddot = ui.dot(&at) + l * u_dot.norm_squared();
        // d̈ = L̈ u + 2 L̇ u̇ + L ü.
        let u_ddot = (at - ui * l_ddot - u_dot * (2.0 * l_dot)) / l;
        // Zero spin (module doc): ω = u × u̇, so ω·u = 0 at all times and α = u × ü; α is
        // perpendicular to u too (α·u = −ω·u̇ = −ω·(ω × u) = 0).
        let alpha_leg = ui.cross(&u_ddot);
        // Centres of mass: cylinder at Bᵢ + h u, piston at Tᵢ − h u.
        let a_cyl = u_ddot * HALF;
        let a_pis = at - u_ddot * HALF;
        // Moment of the whole leg about the fixed point Bᵢ: for each part
        // dH/dt = I α + ω × (I ω) + (r − Bᵢ) × m a. With ω, α ⊥ u, I ω = I_t ω (so the
        // gyroscopic term ω × I ω vanishes) and I α = I_t α. The prismatic joint's force,
        // moment and the actuator force are internal to the leg; the force at Bᵢ has no
        // moment about Bᵢ; the platform pushes on the piston with −F_T at Tᵢ = Bᵢ + L u:
        //   L u × (−F_T) = M = (I_tc + I_tp) α + h u × m_c (a_c − g) + (L − h) u × m_p (a_p − g)
        // which fixes F_T's part across the axis: (u × F_T) × u = u × M / L. The part along
        // u has no moment about Bᵢ; the platform's equations fix it below.
        let moment = alpha_leg * (it_cyl + it_pis)
            + ui.cross(&(a_cyl - g)) * (HALF * M_CYLINDER)
            + ui.cross(&(a_pis - g)) * ((l - HALF) * M_PISTON);
        transverse[i] = ui.cross(&moment) / l;
        u[i] = ui;
        leg_inertial[i] = (a_cyl - g) * M_CYLINDER + (a_pis - g) * M_PISTON;
        piston_axial[i] = M_PISTON * ui.dot(&(a_pis - g));
    }

    // Platform Newton–Euler, global frame: Σ F_T = m (a − g) and
    // Σ ρ × F_T = I_w α + ω × I_w ω with I_w = A I_body Aᵀ. Writing F_T = F⊥ + sᵢ u gives
    // Jᵀ s = [m (a − g) − Σ F⊥; I_w α + ω × I_w ω − Σ ρ × F⊥].
    let a_mat = pose.a.matrix();
    let i_world = a_mat * Matrix3::from_diagonal(&Vector3::from(I_PLATFORM)) * a_mat.transpose();
    let mut force = (a - g) * M_PLATFORM;
    let mut torque = i_world * alpha + w.cross(&(i_world * w));
    for (i, f) in transverse.iter().enumerate() {
        force -= f;
        torque -= pose.arm(i).cross(f);
    }
    let mut b = Vector6::zeros();
    b.fixed_rows_mut::<3>(0).copy_from(&force);
    b.fixed_rows_mut::<3>(3).copy_from(&torque);
    let axial = jac
        .transpose()
        .lu()
        .solve(&b)
        .expect("leg Jacobian is regular");

    let mut out = Forces {
        upper: [[0.0; 3]; LEGS],
        lower: [[0.0; 3]; LEGS],
        actuators: [0.0; LEGS],
        pose: pose.coordinates(),
    };
    for i in 0..LEGS {
        let f_upper = transverse[i] + u[i] * axial[i];
        // Whole leg, Newton: F_B − F_T + (m_c + m_p) g = m_c a_c + m_p a_p.
        let f_lower = f_upper + leg_inertial[i];
        out.upper[i] = f_upper.into();
        out.lower[i] = f_lower.into();
        // Piston along u: −u·F_T + m_p u·g + f = m_p u·a_p, with f the actuator's push on
        // the piston along +u (away from the base, so positive in compression). The
        // prismatic joint's force is across u and its moment does not enter a force balance,
        // so the actuator is the only axial force between the two parts.
        out.actuators[i] = piston_axial[i] + axial[i];
    }
    out
}
