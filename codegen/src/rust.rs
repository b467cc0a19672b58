//! Assembles one generated Rust module per mechanism: header, constant patterns and names,
//! the emitted functions, and the `Mechanism` implementations (one per formulation).

use crate::assembly::Assembly;
use crate::emit::{self, Function, Input, Output};
use crate::equations::{Dynamics, System};
use crate::expr::{Id, Node, Var};
use crate::model::{DriverTarget, Formulation, Model, Rotation};
use crate::symbolic::Entry;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use symbody_runtime::kkt::KktPattern;
use symbody_runtime::JointKind;

fn ident(s: &str) -> Ident {
    Ident::new(s, Span::call_site())
}

fn values(entries: &[Entry]) -> Vec<Id> {
    entries.iter().map(|e| e.2).collect()
}

fn pattern(entries: &[Entry]) -> (Vec<u32>, Vec<u32>) {
    entries.iter().map(|e| (e.0, e.1)).unzip()
}

/// `s` safe inside one `//!` line: the file's free text (descriptions, driver expressions)
/// is data, so a line break or any other control character in it is written escaped and can
/// never end the comment and start code. Unicode line and paragraph separators too, for
/// every reader of the file that treats them as line ends.
pub fn comment_text(s: &str) -> String {
    s.chars()
        .map(|c| match c {
            c if c.is_control() || matches!(c, '\u{2028}' | '\u{2029}') => {
                c.escape_default().to_string()
            }
            c => c.to_string(),
        })
        .collect()
}

/// The header comment: provenance, regeneration command, coordinate and row order.
fn header(model: &Model, sys: &System, asm: &Assembly, source: &str) -> String {
    let mut h = String::new();
    let mut line = |s: &str| {
        h.push_str("//!");
        if !s.is_empty() {
            h.push(' ');
        }
        h.push_str(&comment_text(s));
        h.push('\n');
    };
    line(&format!(
        "Generated equations of `{}` ({}). Do not edit.",
        model.name, model.description
    ));
    line("");
    line(&format!(
        "Regenerate with `cargo xtask generate {}` from `{source}`.",
        model.name
    ));
    line("");
    line(&format!(
        "{} coordinates, {} constraints, {} structural nonzeros in Φq.",
        sys.n_coords,
        sys.n_constraints,
        sys.phi_q.len()
    ));
    let r = &asm.report;
    line(&format!(
        "Rank {} at the initial pose; mobility {} (Grübler count {}), {} DOF left with drivers.",
        r.rank, r.mobility, r.grubler, r.dof
    ));
    if !r.redundant.is_empty() {
        let names: Vec<&str> = r.redundant.iter().map(|(_, n)| n.as_str()).collect();
        line(&format!(
            "Redundant rows (dropped by the solvers): {}.",
            names.join(", ")
        ));
    }
    line("Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))");
    line("or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.");
    line("Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).");
    line("");
    line("Coordinates:");
    for body in &model.bodies {
        line(&format!(
            "- `{}..{}` {} ({})",
            body.offset,
            body.offset + body.n_coords(),
            body.name,
            body.rotation.name()
        ));
    }
    line("");
    line("Constraint rows:");
    for (k, j) in model.joints.iter().enumerate() {
        let start = sys.joint_rows[k];
        let (b1, b2) = j.bodies();
        line(&format!(
            "- `{}..{}` {} ({}, {} – {})",
            start,
            start + j.rows(),
            j.name,
            j.kind.name(),
            model.body_name(b1),
            model.body_name(b2)
        ));
    }
    for (k, d) in model.drivers.iter().enumerate() {
        let row = sys.joint_rows[model.joints.len() + k];
        let what = match &d.target {
            DriverTarget::JointAngle(j) => format!("sin(f − θ) of `{}`", model.joints[*j].name),
            DriverTarget::JointSlide(j) => {
                format!("distance along `{}` − f", model.joints[*j].name)
            }
            DriverTarget::BodyCoordinate { body, coord } => {
                format!(
                    "coordinate `{}` − f",
                    sys.coord_names[model.bodies[*body].offset + coord]
                )
            }
            DriverTarget::PointDistance { .. } => "point distance − f".to_string(),
        };
        line(&format!(
            "- `{row}` {} (driver): {what}, f = {}, initial = {:.9}",
            d.name, d.source, d.initial
        ));
    }
    for (k, &b) in sys.normalized_bodies.iter().enumerate() {
        let row = sys.joint_rows[model.joints.len() + model.drivers.len() + k];
        line(&format!("- `{row}` {}.norm: eᵀe − 1", model.bodies[b].name));
    }
    h
}

/// Generates the module source for `model`, read from `source` (a path shown in the header).
const QT: &[Input] = &[Input::Q, Input::T];
const QQDT: &[Input] = &[Input::Q, Input::Qd, Input::T];
/// The same, for functions of the dynamics: they read `k` where the system has hoisted values.
const KQQDT: &[Input] = &[Input::K, Input::Q, Input::Qd, Input::T];
const KQ: &[Input] = &[Input::K, Input::Q];
const KQT: &[Input] = &[Input::K, Input::Q, Input::T];
/// The functions of a point and a direction (`tangents`).
const TANGENT: &[Input] = &[
    Input::K,
    Input::Q,
    Input::Qd,
    Input::T,
    Input::Dq,
    Input::Dqd,
    Input::Dp,
];

/// Whether Φ, Φq, Φt or γ of `sys` read hoisted values: the model's numbers that parameters
/// reach are in the constraints ([`crate::slots`]); masses and springs' constants are not.
fn kinematics_read_k(sys: &System) -> bool {
    let mut roots = [sys.phi.as_slice(), &sys.phi_t, &sys.gamma].concat();
    roots.extend(sys.phi_q.iter().map(|e| e.2));
    let reached = sys.arena.reachable(&roots);
    reached
        .iter()
        .enumerate()
        .any(|(i, &r)| r && matches!(sys.arena.node(Id(i as u32)), Node::Var(Var::K(_))))
}

/// One emitted function of `sys`; one that reads per-step values of the dynamics (`k`
/// marks it) takes the hoisted values first where the system has any.
fn function(
    sys: &System,
    name: &str,
    doc: &str,
    inputs: &[Input],
    outputs: Vec<Output<'_>>,
) -> TokenStream {
    let (n_p, n_k) = sys.value_lengths();
    // `p` reaches the per-step functions only through `k` (hoisting), so without hoisted
    // values a direction `dp` has nothing to move either.
    let inputs: Vec<Input> = inputs
        .iter()
        .copied()
        .filter(|&i| !matches!(i, Input::K | Input::Dp) || n_k > 0)
        .collect();
    emit::function(
        &sys.arena,
        &Function {
            name,
            doc,
            inputs: &inputs,
            outputs,
            n_coords: sys.n_coords,
            n_p,
            n_k,
        },
    )
}

/// The argument that passes `k` to a function of `sys` (nothing where it has none).
fn k_arg(sys: &System, k: &TokenStream) -> TokenStream {
    match sys.value_lengths().1 {
        0 => quote!(),
        _ => quote!(#k,),
    }
}

/// The argument that passes `k` to the kinematic functions of `sys` (nothing where they
/// read none).
fn kinematic_k_arg(sys: &System, k: &TokenStream) -> TokenStream {
    match kinematics_read_k(sys) {
        true => quote!(#k,),
        false => quote!(),
    }
}

/// The parameter `k` of the helpers that wrap functions reading it (nothing where none do).
fn k_param(sys: &System) -> TokenStream {
    match sys.value_lengths().1 {
        0 => quote!(),
        _ => quote!(k: &[f64],),
    }
}

/// Per system with hoisted values: how many, their values at the file's parameters (`K`,
/// read by the types without parameters) and `setup`, which computes them from `p`.
fn hoisted_items(sys: &System, hoisted: &[Id], p_values: &[f64]) -> TokenStream {
    if hoisted.is_empty() {
        return quote!();
    }
    let env = |v: Var| match v {
        Var::P(i) => p_values[i as usize],
        _ => f64::NAN,
    };
    let k_values = sys.arena.eval_many(hoisted, &env).into_iter().map(float);
    let nk = Literal::usize_unsuffixed(hoisted.len());
    let setup = function(
        sys,
        "setup",
        " The values the per-step functions read (`k`), from the run-time parameters `p`.",
        &[Input::P],
        vec![Output::new("k", hoisted)],
    );
    quote! {
        /// Number of values `setup` computes from the run-time parameters.
        pub const N_K: usize = #nk;
        /// `setup` at the file's parameter values: what the types without parameters read.
        pub static K: [f64; #nk] = [#(#k_values),*];
        #setup
    }
}

/// `<Type>At` of the reduced model (where the mechanism has run-time parameters): the hoisted
/// values of the reduced system, computed from the full model's `Parameters`.
fn reduced_at_type(model: &Model, r: &System, type_name: &Ident, modname: &Ident) -> TokenStream {
    if model.run_time_values().is_empty() || r.value_lengths().1 == 0 {
        return quote!();
    }
    let at = ident(&format!("{type_name}At"));
    let k = quote!(&self.k);
    let at_impl = mechanism_impl(
        &at,
        modname,
        &k_arg(r, &k),
        &kinematic_k_arg(r, &k),
        quote!(),
    );
    quote! {
        /// The reduced model at run-time parameter values.
        #[derive(Debug, Clone)]
        pub struct #at {
            k: [f64; N_K],
        }
        impl #at {
            /// At the parameter values of `p` (checked when they were set).
            pub fn new(p: &Parameters) -> Self {
                let mut k = [0.0; N_K];
                setup(p.values(), &mut k);
                #at { k }
            }
        }
        #at_impl
    }
}

/// The run-time parameters of the full model: names, the file's values, the checks of a
/// new set, and `Parameters` (one set and its hoisted values) that the `<Type>At` types hold.
fn parameters_items(model: &Model, sys: &System, reduced: Option<&System>) -> TokenStream {
    let (np, nk) = sys.value_lengths();
    if np == 0 || nk == 0 {
        return quote!();
    }
    let run_time = model.run_time_parameters();
    let names: Vec<&str> = run_time.iter().map(|p| p.name.as_str()).collect();
    let values = run_time.iter().map(|p| float(p.value));
    let others: Vec<&str> = model
        .parameters
        .iter()
        .filter(|p| !p.run_time)
        .map(|p| p.name.as_str())
        .collect();
    let no = Literal::usize_unsuffixed(others.len());
    let bodies: Vec<&str> = model.bodies.iter().map(|b| b.name.as_str()).collect();
    let nb = Literal::usize_unsuffixed(bodies.len());
    let props: Vec<Id> = sys.mass_props.iter().flatten().copied().collect();
    let mass_properties = function(
        sys,
        "mass_properties",
        " Each body's mass and principal inertias at the run-time parameters `p`.",
        &[Input::P],
        vec![Output::new("out", &props)],
    );
    let n4 = Literal::usize_unsuffixed(4 * bodies.len());
    let forces: Vec<&str> = model.forces.iter().map(|f| f.name.as_str()).collect();
    let nf = Literal::usize_unsuffixed(forces.len());
    let n2 = Literal::usize_unsuffixed(2 * forces.len());
    let constants: Vec<Id> = sys.force_constants.iter().flatten().copied().collect();
    let force_constants = function(
        sys,
        "force_constants",
        " Each force's stiffness and damping at the run-time parameters `p`.",
        &[Input::P],
        vec![Output::new("out", &constants)],
    );
    let at_forms = model.formulations.iter().map(|&f| {
        let (_, type_name, form) = formulation_names(f);
        let at = ident(&format!("{type_name}At"));
        quote!((#form, Box::new(#at(p.clone())) as Box<dyn Mechanism + Sync>))
    });
    let (reduced_fn, build_reduced, build_reduced_values) = match reduced.map(System::value_lengths)
    {
        Some((_, nk)) if nk > 0 => {
            let forms = model.formulations.iter().map(|&f| {
                let (_, type_name, form) = formulation_names(f);
                let at = ident(&format!("{type_name}At"));
                quote!((#form, Box::new(reduced::#at::new(&p)) as Box<dyn Mechanism + Sync>))
            });
            (
                quote! {
                    fn built_reduced(p: Parameters) -> symbody_runtime::registry::Built {
                        vec![#(#forms),*]
                    }
                    fn at_parameters_reduced(
                        set: &[(&str, f64)],
                    ) -> Result<symbody_runtime::registry::Built, ParameterError> {
                        Parameters::at(set).map(built_reduced)
                    }
                    fn at_values_reduced(
                        values: &[f64],
                    ) -> Result<symbody_runtime::registry::Built, ParameterError> {
                        Parameters::from_values(values).map(built_reduced)
                    }
                },
                quote!(Some(at_parameters_reduced)),
                quote!(Some(at_values_reduced)),
            )
        }
        _ => (quote!(), quote!(None), quote!(None)),
    };
    let n_named = Literal::usize_unsuffixed(names.len());
    let p0 = model.run_time_values().into_iter().map(float);
    let data = &model.data_slots;
    let n_data = Literal::usize_unsuffixed(data.len());
    let np = Literal::usize_unsuffixed(np);
    quote! {
        /// The parameters the generated code takes at run time by name: the file's
        /// `[parameters]` entries that reach only masses, inertias and springs' constants.
        pub static PARAMETERS: [&str; #n_named] = [#(#names),*];
        /// Their values in the file.
        pub static PARAMETER_VALUES: [f64; #n_named] = [#(#values),*];
        /// Number of values `p` holds: the parameters by name, then the model's numbers that
        /// the other parameters reach (read off the file loaded at their values: `DATA`).
        pub const N_P: usize = #np;
        /// `p` at the file's values.
        pub static P0: [f64; #np] = [#(#p0),*];
        /// Where the numbers after the named parameters come from in the model (positions in
        /// the generator's `slots::numbers`).
        pub static DATA: [u32; #n_data] = [#(#data),*];
        static OTHER_PARAMETERS: [&str; #no] = [#(#others),*];
        static BODY_NAMES: [&str; #nb] = [#(#bodies),*];
        static FORCE_NAMES: [&str; #nf] = [#(#forces),*];
        /// What a new parameter set is checked with.
        pub static RUN_TIME: RunTimeParameters = RunTimeParameters {
            names: &PARAMETERS,
            others: &OTHER_PARAMETERS,
            bodies: &BODY_NAMES,
            mass_properties,
            forces: &FORCE_NAMES,
            force_constants,
        };
        #mass_properties
        #force_constants
        /// One set of run-time parameter values and the values `setup` computed from it.
        #[derive(Debug, Clone)]
        pub struct Parameters {
            p: [f64; N_P],
            k: [f64; N_K],
        }
        impl Parameters {
            /// The file's values.
            pub fn file_values() -> Self {
                Parameters { p: P0, k: K }
            }
            /// All of `p` at once (`N_P` values: the named parameters, then the model's
            /// numbers `DATA` names, as the mechanism file loaded at other values gives them),
            /// checked as [`Parameters::set`] checks.
            pub fn from_values(values: &[f64]) -> Result<Self, ParameterError> {
                let mut p = [0.0; N_P];
                RUN_TIME.assign_all(&mut p, values)?;
                let (mut props, mut constants) = ([0.0; #n4], [0.0; #n2]);
                RUN_TIME.check(&p, &[], &mut props, &mut constants)?;
                let mut k = [0.0; N_K];
                setup(&p, &mut k);
                Ok(Parameters { p, k })
            }
            /// The file's values with `set` applied ([`Parameters::set`]).
            pub fn at(set: &[(&str, f64)]) -> Result<Self, ParameterError> {
                let mut p = Self::file_values();
                p.set(set)?;
                Ok(p)
            }
            /// Sets parameters by name. Checked first (known names, finite values, positive
            /// masses, inertias of a rigid body): a refused set changes nothing. Allocates
            /// nothing unless it is refused.
            pub fn set(&mut self, set: &[(&str, f64)]) -> Result<(), ParameterError> {
                let mut p = self.p;
                RUN_TIME.assign(&mut p, set)?;
                let (mut props, mut constants) = ([0.0; #n4], [0.0; #n2]);
                RUN_TIME.check(&p, set, &mut props, &mut constants)?;
                self.p = p;
                setup(&self.p, &mut self.k);
                Ok(())
            }
            /// The values: those of `PARAMETERS`, then the numbers `DATA` names.
            pub fn values(&self) -> &[f64] {
                &self.p
            }
        }
        fn built(p: Parameters) -> symbody_runtime::registry::Built {
            vec![#(#at_forms),*]
        }
        fn at_parameters(
            set: &[(&str, f64)],
        ) -> Result<symbody_runtime::registry::Built, ParameterError> {
            Parameters::at(set).map(built)
        }
        fn at_values(values: &[f64]) -> Result<symbody_runtime::registry::Built, ParameterError> {
            Parameters::from_values(values).map(built)
        }
        #reduced_fn
        /// This mechanism at other values of its run-time parameters, for the registries.
        pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime =
            symbody_runtime::registry::RunTime {
                parameters: &RUN_TIME,
                build: at_parameters,
                build_reduced: #build_reduced,
                data: &DATA,
                p0: &P0,
                build_values: at_values,
                build_reduced_values: #build_reduced_values,
            };
    }
}

/// `v` as a literal, or as the constant naming it when it is not finite.
fn float(v: f64) -> TokenStream {
    match v {
        v if v.is_nan() => quote!(f64::NAN),
        v if v == f64::INFINITY => quote!(f64::INFINITY),
        v if v == f64::NEG_INFINITY => quote!(f64::NEG_INFINITY),
        v => quote!(#v),
    }
}

/// Φ, Φq, Φt, γ, their fused evaluation, the potential and the non-conservative power.
fn kinematic_functions(sys: &System) -> Vec<TokenStream> {
    let (qt, qqdt) = match kinematics_read_k(sys) {
        true => (KQT, KQQDT),
        false => (QT, QQDT),
    };
    let phi_q_vals = values(&sys.phi_q);
    let (pq_rows, _) = pattern(&sys.phi_q);
    let row_index: Vec<u32> = (0..sys.n_constraints as u32).collect();
    let pot = [sys.potential];
    let power = [sys.power_nc];
    let tangents = sys.tangent.as_ref().map(|d| {
        function(
            sys,
            "kinematic_tangents",
            " Directional derivatives of Φ, Φq's nonzeros, Φt and γ along `(dq, dqd, dp)`.",
            TANGENT,
            vec![
                Output::by_rows("phi", &d.phi, &row_index),
                Output::by_rows("phi_q", &d.phi_q, &pq_rows),
                Output::by_rows("phi_t", &d.phi_t, &row_index),
                Output::by_rows("gamma", &d.gamma, &row_index),
            ],
        )
    });
    let mut fns = vec![
        function(
            sys,
            "phi",
            " Constraint residual Φ(q, t).",
            qt,
            vec![Output::new("out", &sys.phi)],
        ),
        function(
            sys,
            "phi_q",
            " Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.",
            qt,
            vec![Output::new("out", &phi_q_vals)],
        ),
        function(
            sys,
            "phi_t",
            " Partial time derivative Φt(q, t).",
            qt,
            vec![Output::new("out", &sys.phi_t)],
        ),
        function(
            sys,
            "gamma",
            " Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].",
            qqdt,
            vec![Output::new("out", &sys.gamma)],
        ),
        function(
            sys,
            "eval_kinematics",
            " Φ, Φq, Φt and γ at one state in one pass, sharing every subexpression.",
            qqdt,
            vec![
                Output::by_rows("phi", &sys.phi, &row_index),
                Output::by_rows("phi_q", &phi_q_vals, &pq_rows),
                Output::by_rows("phi_t", &sys.phi_t, &row_index),
                Output::by_rows("gamma", &sys.gamma, &row_index),
            ],
        ),
        function(
            sys,
            "potential_into",
            " Potential energy of gravity and springs, written to `out[0]`.",
            KQ,
            vec![Output::new("out", &pot)],
        ),
        function(
            sys,
            "power_nc_into",
            " Power of the non-conservative loads, written to `out[0]`.",
            KQQDT,
            vec![Output::new("out", &power)],
        ),
    ];
    fns.extend(tangents);
    fns
}

/// M, Q and their fused evaluation with Φ and Φq, for one formulation.
fn dynamics_functions(sys: &System, dynamics: &Dynamics) -> Vec<TokenStream> {
    let phi_q_vals = values(&sys.phi_q);
    let (pq_rows, _) = pattern(&sys.phi_q);
    let row_index: Vec<u32> = (0..sys.n_constraints as u32).collect();
    let mass_vals = values(&dynamics.mass);
    let (force_q, force_qd) = (values(&dynamics.force_q), values(&dynamics.force_qd));
    let tangents = sys.tangent.as_ref().map(|_| {
        function(
            sys,
            "tangents",
            " Directional derivatives of M's nonzeros and Q along `(dq, dqd, dp)`.",
            TANGENT,
            vec![
                Output::new("mass", &dynamics.tangent.mass),
                Output::new("force", &dynamics.tangent.force),
            ],
        )
    });
    let mut fns = vec![
        function(
            sys,
            "force_jacobian",
            " Nonzeros of ∂Q/∂q and ∂Q/∂q̇ in the order of `FORCE_Q_*` and `FORCE_QD_*`.",
            KQQDT,
            vec![Output::new("dq", &force_q), Output::new("dqd", &force_qd)],
        ),
        function(
            sys,
            "mass",
            " Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.",
            KQ,
            vec![Output::new("out", &mass_vals)],
        ),
        function(
            sys,
            "force",
            " Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.",
            KQQDT,
            vec![Output::new("out", &dynamics.force)],
        ),
        function(
            sys,
            "eval_newton",
            " Φ, Φq, M and Q at one state in one pass: what one Newton iteration needs.",
            KQQDT,
            vec![
                Output::by_rows("phi", &sys.phi, &row_index),
                Output::by_rows("phi_q", &phi_q_vals, &pq_rows),
                Output::new("mass", &mass_vals),
                Output::new("force", &dynamics.force),
            ],
        ),
    ];
    fns.extend(tangents);
    fns
}

/// `impl Mechanism for #type_name`, delegating to the functions of module `#modname` and of
/// its parent; `k` is the argument passing the hoisted values (empty without any).
/// `k`: the argument passing the hoisted values to the functions that read them; `kk` the
/// same for the kinematic functions (nothing where they read none).
fn mechanism_impl(
    type_name: &Ident,
    modname: &Ident,
    k: &TokenStream,
    kk: &TokenStream,
    extra: TokenStream,
) -> TokenStream {
    quote! {
        impl Mechanism for #type_name {
            #extra
            fn info(&self) -> &'static MechanismInfo { &#modname::INFO }
            fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) { phi(#kk q, t, out) }
            fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) { phi_q(#kk q, t, out) }
            fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) { phi_t(#kk q, t, out) }
            fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) { gamma(#kk q, qd, t, out) }
            fn mass(&self, q: &[f64], out: &mut [f64]) { #modname::mass(#k q, out) }
            fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) { #modname::force(#k q, qd, t, out) }
            fn force_jacobian(&self, q: &[f64], qd: &[f64], t: f64, dq: &mut [f64], dqd: &mut [f64]) {
                #modname::force_jacobian(#k q, qd, t, dq, dqd)
            }
            fn potential(&self, q: &[f64]) -> f64 { potential(#k q) }
            fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 { power_nc(#k q, qd, t) }
            fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
                #modname::eval_newton(#k q, qd, t, out.phi, out.phi_q, out.mass, out.force)
            }
            fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
                eval_kinematics(#kk q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
            }
        }
    }
}

/// The `Mechanism` methods of a full model's type whose run-time values are `p` (an
/// expression of `self`) and hoisted values the argument `k` (the tokens [`k_arg`] gives):
/// its values, and `tangents`, which take `dp` where the system has hoisted values.
fn tangent_methods(sys: &System, modname: &Ident, k: &TokenStream, p: TokenStream) -> TokenStream {
    let dp = k_arg(sys, &quote!(dir.dp));
    quote! {
        fn run_time_values(&self) -> &[f64] { #p }
        fn tangents(&self, q: &[f64], qd: &[f64], t: f64, dir: Direction<'_>, out: TangentOutputs<'_>) -> bool {
            kinematic_tangents(#k q, qd, t, dir.dq, dir.dqd, #dp out.phi, out.phi_q, out.phi_t, out.gamma);
            #modname::tangents(#k q, qd, t, dir.dq, dir.dqd, #dp out.mass, out.force);
            true
        }
    }
}

/// The unit type of one formulation (the file's parameter values) and, where the system
/// has run-time parameters, `<Type>At` (any values) with `<Type>::with_parameters`.
fn formulation_types(
    sys: &System,
    type_name: &Ident,
    modname: &Ident,
    doc: &str,
    with_at: bool,
) -> TokenStream {
    let file_values = match sys.value_lengths() {
        (np, nk) if np > 0 && nk > 0 => quote!(&P0),
        _ => quote!(&[]),
    };
    let tangents = |k: &TokenStream, p: TokenStream| match sys.tangent {
        Some(_) => tangent_methods(sys, modname, &k_arg(sys, k), p),
        None => quote!(),
    };
    let unit_impl = mechanism_impl(
        type_name,
        modname,
        &k_arg(sys, &quote!(&K)),
        &kinematic_k_arg(sys, &quote!(&K)),
        tangents(&quote!(&K), file_values),
    );
    let unit = quote! {
        #[doc = #doc]
        #[derive(Debug, Clone, Copy, Default)]
        pub struct #type_name;
        #unit_impl
    };
    if !with_at || sys.value_lengths().1 == 0 {
        return unit;
    }
    let at = ident(&format!("{type_name}At"));
    let k = quote!(&self.0.k);
    let at_impl = mechanism_impl(
        &at,
        modname,
        &k_arg(sys, &k),
        &kinematic_k_arg(sys, &k),
        tangents(&k, quote!(self.0.values())),
    );
    let at_doc = format!("{doc} At run-time parameter values (`{type_name}::with_parameters`).");
    quote! {
        #unit
        impl #type_name {
            /// This formulation with some run-time parameters (`PARAMETERS`) set, the others
            /// at the file's values; a name or value that is refused changes nothing.
            pub fn with_parameters(set: &[(&str, f64)]) -> Result<#at, ParameterError> {
                Parameters::at(set).map(#at)
            }
        }
        #[doc = #at_doc]
        #[derive(Debug, Clone)]
        pub struct #at(pub Parameters);
        #at_impl
    }
}

fn formulation_names(f: Formulation) -> (Ident, Ident, TokenStream) {
    match f {
        Formulation::Paper => (ident("paper"), ident("Paper"), quote!(Formulation::Paper)),
        Formulation::Exact => (ident("exact"), ident("Exact"), quote!(Formulation::Exact)),
    }
}

/// What a model's KKT pattern takes besides its Φq and mass patterns (as
/// `KktPattern::from_info` reads them from `INFO`).
struct KktRows {
    redundant: Vec<u32>,
    normalization: Vec<u32>,
    semidefinite: bool,
}

/// `pub mod exact` / `pub mod paper`: one formulation's mass pattern, `INFO` and functions.
/// `bodies`, `joints` and `platform` are the tokens of those `MechanismInfo` fields.
#[allow(clippy::too_many_arguments)]
fn formulation_module(
    sys: &System,
    dynamics: &Dynamics,
    doc: &str,
    mech_name: &str,
    gravity: [f64; 3],
    bodies: TokenStream,
    joints: TokenStream,
    platform: TokenStream,
    rows: &KktRows,
) -> TokenStream {
    let (modname, _, form) = formulation_names(dynamics.formulation);
    let (m_rows, m_cols) = pattern(&dynamics.mass);
    let (pq_rows, pq_cols) = pattern(&sys.phi_q);
    let mnnz = m_rows.len();
    let (fq_rows, fq_cols) = pattern(&dynamics.force_q);
    let (fqd_rows, fqd_cols) = pattern(&dynamics.force_qd);
    let (fq_nnz, fqd_nnz) = (fq_rows.len(), fqd_rows.len());
    // The pattern `KktPattern::from_info` builds from this module's `INFO`, and the one HHT
    // factors with the loads' stiffness.
    let pattern = KktPattern {
        n: sys.n_coords,
        m: sys.n_constraints,
        mass_rows: m_rows.clone(),
        mass_cols: m_cols.clone(),
        phi_q_rows: pq_rows,
        phi_q_cols: pq_cols,
        redundant_rows: rows.redundant.clone(),
        normalization_rows: rows.normalization.clone(),
        mass_semidefinite: rows.semidefinite,
        kernels: &[],
    };
    let mut patterns = vec![pattern.clone()];
    patterns.extend(pattern.with_loads((&fq_rows, &fq_cols), (&fqd_rows, &fqd_cols)));
    let kkt = crate::kkt::kernels(&patterns, [(&fq_rows, &fq_cols), (&fqd_rows, &fqd_cols)]);
    let kkt_field = match kkt {
        Some(_) => quote!(&KKT),
        None => quote!(&[]),
    };
    let constant = dynamics.mass_is_constant;
    let fns = dynamics_functions(sys, dynamics);
    quote! {
        #[doc = #doc]
        pub mod #modname {
            use super::*;
            /// Row of each mass-matrix nonzero (both triangles).
            pub static MASS_ROWS: [u32; #mnnz] = [#(#m_rows),*];
            /// Column of each mass-matrix nonzero.
            pub static MASS_COLS: [u32; #mnnz] = [#(#m_cols),*];
            /// Row and column of each ∂Q/∂q nonzero.
            pub static FORCE_Q_ROWS: [u32; #fq_nnz] = [#(#fq_rows),*];
            pub static FORCE_Q_COLS: [u32; #fq_nnz] = [#(#fq_cols),*];
            /// Row and column of each ∂Q/∂q̇ nonzero.
            pub static FORCE_QD_ROWS: [u32; #fqd_nnz] = [#(#fqd_rows),*];
            pub static FORCE_QD_COLS: [u32; #fqd_nnz] = [#(#fqd_cols),*];
            /// Sizes, patterns and names for this formulation.
            pub static INFO: MechanismInfo = MechanismInfo {
                name: #mech_name,
                n_coords: N_COORDS,
                n_constraints: N_CONSTRAINTS,
                formulation: #form,
                gravity: [#(#gravity),*],
                phi_q_rows: &PHI_Q_ROWS,
                phi_q_cols: &PHI_Q_COLS,
                mass_rows: &MASS_ROWS,
                mass_cols: &MASS_COLS,
                mass_is_constant: #constant,
                force_q_rows: &FORCE_Q_ROWS,
                force_q_cols: &FORCE_Q_COLS,
                force_qd_rows: &FORCE_QD_ROWS,
                force_qd_cols: &FORCE_QD_COLS,
                bodies: #bodies,
                joints: #joints,
                coord_names: &COORD_NAMES,
                row_names: &ROW_NAMES,
                q0: &Q0,
                qd0: &QD0,
                redundant_rows: &REDUNDANT_ROWS,
                platform: #platform,
                kkt: #kkt_field,
            };
            #kkt
            #(#fns)*
        }
    }
}

/// `pub mod reduced`: the system after the substitution pass (`crate::reduce`) as its own
/// `Mechanism` per formulation, with the `REDUCTION` that maps it back to the full model. Its
/// `MechanismInfo` lists no bodies or joints: those are read on the full model after
/// `REDUCTION.expand`.
fn reduced_module(
    model: &Model,
    sys: &System,
    asm: &Assembly,
    red: &crate::reduce::Reduced,
    (r, hoisted): &(System, Vec<Id>),
) -> TokenStream {
    let k_items = hoisted_items(r, hoisted, &model.run_time_values());
    let kp = k_param(r);
    let ka = k_arg(r, &quote!(k));
    let (n, m) = (r.n_coords, r.n_constraints);
    let (pq_rows, pq_cols) = pattern(&r.phi_q);
    let nnz = pq_rows.len();
    let fns = kinematic_functions(r);
    let coords: Vec<u32> = red.coords.iter().map(|&c| c as u32).collect();
    let rows: Vec<u32> = red.rows.iter().map(|&c| c as u32).collect();
    let q0: Vec<f64> = red.coords.iter().map(|&c| asm.q0[c]).collect();
    let qd_full = model.qd0();
    let qd0: Vec<f64> = red.coords.iter().map(|&c| qd_full[c]).collect();
    let redundant: Vec<u32> = match &red.redundant {
        Some(own) => own.iter().map(|&k| k as u32).collect(),
        None => asm
            .redundant_rows
            .iter()
            .filter_map(|&row| {
                red.rows
                    .iter()
                    .position(|&k| k == row as usize)
                    .map(|k| k as u32)
            })
            .collect(),
    };
    let n_red = redundant.len();
    let coord_names = &r.coord_names;
    let row_names = &r.row_names;
    let subs = red.substitutions.iter().map(|s| {
        let (coord, w, a) = (s.coord as u32, s.weight, s.slope);
        let row = match s.row {
            Some(r) => {
                let r = r as u32;
                quote!(Some(#r))
            }
            None => quote!(None),
        };
        let target = match s.target {
            Some(j) => {
                let j = j as u32;
                quote!(Some(#j))
            }
            None => quote!(None),
        };
        quote!(Substitution { row: #row, coord: #coord, target: #target, weight: #w, slope: #a })
    });
    let n_sub = red.substitutions.len();
    let offsets: Vec<Id> = red.substitutions.iter().flat_map(|s| s.offset).collect();
    let reads_p = offsets
        .iter()
        .any(|&o| r.arena.variables(o).iter().any(|v| matches!(v, Var::P(_))));
    // Offsets that the model's numbers reach (a slider's line at y = e) take them from the
    // file's `p`: the reduced model is the file's; other values run the file derived again.
    let (offset_inputs, offsets_at): (&[Input], _) = match reads_p {
        true => (
            &[Input::P, Input::T],
            quote! {
                fn offsets_at_file_values(t: f64, out: &mut [f64]) {
                    offsets_into(&super::P0, t, out)
                }
            },
        ),
        false => (&[Input::T], quote!()),
    };
    let offsets_name = ident(match reads_p {
        true => "offsets_at_file_values",
        false => "offsets_into",
    });
    let offsets_fn = function(
        r,
        "offsets_into",
        " `c, ċ, c̈` of each substitution at time `t`, three per substitution.",
        offset_inputs,
        vec![Output::new("out", &offsets)],
    );
    let (n_full, m_full) = (sys.n_coords, sys.n_constraints);
    let mech_name = format!("{}_reduced", model.name);
    let gx = model.gravity;
    let mut forms = Vec::new();
    for dynamics in &r.dynamics {
        let (modname, type_name, _) = formulation_names(dynamics.formulation);
        let type_doc = format!(
            " `{}` reduced by substitution, with the `{}` formulation.",
            model.name,
            dynamics.formulation.name()
        );
        forms.push(formulation_module(
            r,
            dynamics,
            " The reduced system's mass matrix and forces in this formulation.",
            &mech_name,
            gx,
            quote!(&[]),
            quote!(&[]),
            quote!(None),
            &KktRows {
                redundant: redundant.clone(),
                normalization: Vec::new(),
                semidefinite: false,
            },
        ));
        forms.push(formulation_types(r, &type_name, &modname, &type_doc, false));
        forms.push(reduced_at_type(model, r, &type_name, &modname));
    }
    quote! {
        /// The system after substituting rows `a·qᵢ + b·qⱼ + g(t) = 0` away (docs/design.md,
        /// decision 24): fewer coordinates and rows, the same motion and multipliers once
        /// mapped back with `REDUCTION`.
        pub mod reduced {
            use super::*;
            /// Number of reduced coordinates.
            pub const N_COORDS: usize = #n;
            /// Number of reduced rows.
            pub const N_CONSTRAINTS: usize = #m;
            /// Row of each Φq nonzero.
            pub static PHI_Q_ROWS: [u32; #nnz] = [#(#pq_rows),*];
            /// Column of each Φq nonzero.
            pub static PHI_Q_COLS: [u32; #nnz] = [#(#pq_cols),*];
            /// Name of each reduced coordinate (its full model's name).
            pub static COORD_NAMES: [&str; #n] = [#(#coord_names),*];
            /// Name of each reduced row (its full model's name).
            pub static ROW_NAMES: [&str; #m] = [#(#row_names),*];
            /// Initial coordinates, from the full model's assembled ones.
            pub static Q0: [f64; #n] = [#(#q0),*];
            /// Initial velocities from the file.
            pub static QD0: [f64; #n] = [#(#qd0),*];
            /// Rows dependent on others at the initial pose.
            pub static REDUNDANT_ROWS: [u32; #n_red] = [#(#redundant),*];
            /// Full index of each reduced coordinate.
            pub static COORDS: [u32; #n] = [#(#coords),*];
            /// Full index of each reduced row.
            pub static ROWS: [u32; #m] = [#(#rows),*];
            /// The eliminated rows.
            pub static SUBSTITUTIONS: [Substitution; #n_sub] = [#(#subs),*];
            /// The way back to the full model.
            pub static REDUCTION: Reduction = Reduction {
                n_full: #n_full,
                m_full: #m_full,
                coords: &COORDS,
                rows: &ROWS,
                substitutions: &SUBSTITUTIONS,
                offsets: #offsets_name,
                offsets_read_parameters: #reads_p,
            };
            #offsets_fn
            #offsets_at
            #k_items
            #(#fns)*
            /// Potential energy of gravity and springs.
            pub fn potential(#kp q: &[f64]) -> f64 {
                let mut out = [0.0];
                potential_into(#ka q, &mut out);
                out[0]
            }
            /// Power of the non-conservative loads.
            pub fn power_nc(#kp q: &[f64], qd: &[f64], t: f64) -> f64 {
                let mut out = [0.0];
                power_nc_into(#ka q, qd, t, &mut out);
                out[0]
            }
            #(#forms)*
        }
    }
}

/// `pub static ENTRY`: the mechanism in each formulation (the file's order, default first)
/// and its reduced model, for the registries that link this module.
fn registry_entry(
    model: &Model,
    reduced: Option<&crate::reduce::Reduced>,
    run_time: bool,
    source: &str,
    hash: u64,
) -> TokenStream {
    let list = |prefix: TokenStream| {
        let items = model.formulations.iter().map(|&f| {
            let (_, type_name, form) = formulation_names(f);
            quote!((#form, &#prefix #type_name as &(dyn Mechanism + Sync)))
        });
        quote!(&[#(#items),*])
    };
    let full = list(quote!());
    let reduced = match reduced {
        Some(_) => {
            let forms = list(quote!(reduced::));
            quote!(Some(symbody_runtime::registry::Reduced { formulations: #forms, reduction: &reduced::REDUCTION }))
        }
        None => quote!(None),
    };
    let run_time = match run_time {
        true => quote!(Some(&RUN_TIME_ENTRY)),
        false => quote!(None),
    };
    let name = &model.name;
    // The crate sits at `mechanisms/generated/<name>/`, three folders below the root that
    // `source` is relative to.
    let file = quote!(concat!(env!("CARGO_MANIFEST_DIR"), "/../../../", #source));
    quote! {
        /// This mechanism in the registries (`symbody_runtime::Registry`).
        pub static ENTRY: Entry = Entry {
            name: #name,
            t_end: T_END,
            formulations: #full,
            reduced: #reduced,
            origin: Origin::Compiled { file: #file, hash: #hash, parameters: &[] },
            run_time: #run_time,
        };
    }
}

/// `hash` is the [`symbody_runtime::source_hash`] of the file's text.
pub fn module(model: &Model, sys: &System, asm: &Assembly, source: &str, hash: u64) -> String {
    // A planar model takes the place of the substitution pass's (a planar file's bodies are
    // in Euler angles, where that pass finds only what the plane already pins).
    let reduced = asm
        .planar
        .clone()
        .or_else(|| crate::reduce::substitute(sys));
    let unhoisted = sys;
    let mut sys = sys.clone();
    let hoisted = crate::hoist::system(&mut sys);
    let sys = &sys;
    let p_values = model.run_time_values();
    let n = sys.n_coords;
    let m = sys.n_constraints;
    let (pq_rows, pq_cols) = pattern(&sys.phi_q);
    let nnz = pq_rows.len();
    let mut items: Vec<TokenStream> = kinematic_functions(sys);

    let gx = model.gravity;
    let body_infos: Vec<TokenStream> = model
        .bodies
        .iter()
        .map(|body| {
            let name = &body.name;
            let off = body.offset;
            let mass = body.mass;
            let [ix, iy, iz] = body.inertia;
            let rot = match body.rotation {
                Rotation::Euler => quote!(Rotation::Euler),
                Rotation::Quaternion => quote!(Rotation::Quaternion),
            };
            quote!(BodyInfo { name: #name, coord_offset: #off, rotation: #rot, mass: #mass, inertia: [#ix, #iy, #iz] })
        })
        .collect();
    let opt = |b: Option<usize>| match b {
        Some(i) => quote!(Some(#i)),
        None => quote!(None),
    };
    let joint_infos: Vec<TokenStream> = crate::info::joints(model, sys)
        .iter()
        .map(|j| {
            let (name, kind) = (&j.name, ident(&format!("{:?}", j.kind)));
            let (b1, b2) = (opt(j.body1), opt(j.body2));
            let (start, rows, p1, p2) = (j.row_start, j.rows, j.point1, j.point2);
            let (sign, unit) = (j.effort_sign, j.effort_unit);
            quote!(JointInfo { name: #name, kind: JointKind::#kind, body1: #b1, body2: #b2, row_start: #start, rows: #rows, point1: [#(#p1),*], point2: [#(#p2),*], effort_sign: #sign, effort_unit: #unit })
        })
        .collect();
    let nb = model.bodies.len();
    let nj = joint_infos.len();
    let coord_names = &sys.coord_names;
    let row_names = &sys.row_names;
    let q0 = &asm.q0;
    let qd0 = model.qd0();
    let redundant = &asm.redundant_rows;
    let n_red = redundant.len();
    let t_end = model.t_end;
    let mech_name = &model.name;
    let platform = match crate::info::platform(model, sys, asm) {
        None => quote!(None),
        Some((body, legs)) => {
            let legs = legs.iter().map(|l| {
                let (driver, base, top, row) = (&l.driver, l.base, l.platform, l.row);
                quote!(LegInfo { driver: #driver, base: [#(#base),*], platform: [#(#top),*], row: #row })
            });
            quote!(Some(PlatformInfo { body: #body, legs: &[#(#legs),*] }))
        }
    };
    let leg_import = asm.platform.as_ref().map(|_| quote!(LegInfo,));
    let (kp, ka) = (k_param(sys), k_arg(sys, &quote!(k)));
    items.push(quote! {
        /// Number of generalized coordinates.
        pub const N_COORDS: usize = #n;
        /// Number of constraint rows.
        pub const N_CONSTRAINTS: usize = #m;
        /// Row of each Φq nonzero.
        pub static PHI_Q_ROWS: [u32; #nnz] = [#(#pq_rows),*];
        /// Column of each Φq nonzero.
        pub static PHI_Q_COLS: [u32; #nnz] = [#(#pq_cols),*];
        /// Bodies in coordinate order.
        pub static BODIES: [BodyInfo; #nb] = [#(#body_infos),*];
        /// Joints in row order, then drivers.
        pub static JOINTS: [JointInfo; #nj] = [#(#joint_infos),*];
        /// Name of each coordinate.
        pub static COORD_NAMES: [&str; #n] = [#(#coord_names),*];
        /// Name of each constraint row.
        pub static ROW_NAMES: [&str; #m] = [#(#row_names),*];
        /// Initial coordinates: the file's pose, assembled.
        pub static Q0: [f64; #n] = [#(#q0),*];
        /// Initial velocities from the file (to be projected onto the constraints).
        pub static QD0: [f64; #n] = [#(#qd0),*];
        /// Constraint rows dependent on others at the initial pose (dropped by the solvers).
        pub static REDUNDANT_ROWS: [u32; #n_red] = [#(#redundant),*];
        /// Simulation end time suggested by the mechanism file (s).
        pub const T_END: f64 = #t_end;
        /// The platform held by six legs of driven length, for forward kinematics (`None`:
        /// not such a mechanism).
        pub const PLATFORM: Option<PlatformInfo> = #platform;
        /// Potential energy of gravity and springs.
        pub fn potential(#kp q: &[f64]) -> f64 {
            let mut out = [0.0];
            potential_into(#ka q, &mut out);
            out[0]
        }
        /// Power of the non-conservative loads.
        pub fn power_nc(#kp q: &[f64], qd: &[f64], t: f64) -> f64 {
            let mut out = [0.0];
            power_nc_into(#ka q, qd, t, &mut out);
            out[0]
        }
    });
    items.push(hoisted_items(sys, &hoisted, &p_values));
    // The reduced system over its own hoisted values.
    let reduced_hoisted = reduced.as_ref().map(|red| {
        let mut r = red.system.clone();
        let hoisted = crate::hoist::system(&mut r);
        (r, hoisted)
    });
    items.push(parameters_items(
        model,
        sys,
        reduced_hoisted.as_ref().map(|(r, _)| r),
    ));

    let kkt_rows = KktRows {
        redundant: redundant.clone(),
        normalization: crate::info::joints(model, sys)
            .iter()
            .filter(|j| j.kind == JointKind::Normalization)
            .flat_map(|j| (j.row_start..j.row_start + j.rows).map(|r| r as u32))
            .collect(),
        semidefinite: model.bodies.iter().any(|b| b.inertia.contains(&0.0)),
    };
    let mut impls = Vec::new();
    for dynamics in &sys.dynamics {
        let (modname, type_name, _) = formulation_names(dynamics.formulation);
        let doc = format!(
            " The `{}` formulation: mass matrix and forces{}.",
            dynamics.formulation.name(),
            match dynamics.formulation {
                Formulation::Paper => " of the paper (diagonal, Euler-angle accelerations)",
                Formulation::Exact => " derived from the exact kinetic energy",
            }
        );
        let type_doc = format!(
            " `{}` with the `{}` formulation.",
            model.name,
            dynamics.formulation.name()
        );
        items.push(formulation_module(
            sys,
            dynamics,
            &doc,
            mech_name,
            gx,
            quote!(&BODIES),
            quote!(&JOINTS),
            quote!(PLATFORM),
            &kkt_rows,
        ));
        impls.push(formulation_types(
            sys, &type_name, &modname, &type_doc, true,
        ));
    }
    if let (Some(red), Some(h)) = (&reduced, &reduced_hoisted) {
        items.push(reduced_module(model, unhoisted, asm, red, h));
    }
    let reduction_import = reduced.as_ref().map(|_| quote!(Reduction, Substitution,));
    let parameter_import = match sys.value_lengths() {
        (0, _) | (_, 0) => quote!(),
        _ => quote!(
            use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
        ),
    };
    let default_type = ident(match model.formulations[0] {
        Formulation::Paper => "Paper",
        Formulation::Exact => "Exact",
    });

    let (np, nk) = sys.value_lengths();
    let entry = registry_entry(model, reduced.as_ref(), np > 0 && nk > 0, source, hash);
    let file = quote! {
        #![allow(clippy::approx_constant, clippy::excessive_precision, clippy::too_many_arguments, clippy::unreadable_literal)]
        use symbody_runtime::{BodyInfo, Direction, Entry, Formulation, JointInfo, JointKind, KinematicOutputs, #leg_import Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, #reduction_import Rotation, TangentOutputs};
        #parameter_import
        #(#items)*
        #(#impls)*
        /// The formulation listed first in the mechanism file.
        pub type DefaultFormulation = #default_type;
        #entry
    };
    let syntax: syn::File = syn::parse2(file).expect("generated tokens form a valid Rust file");
    let body = prettyplease::unparse(&syntax);
    format!("{}{}", header(model, sys, asm, source), body)
}
