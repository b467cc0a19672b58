//! Generated mechanisms, one module each, and their registry. Regenerate with
//! `cargo xtask generate --all`.

#[rustfmt::skip]
pub mod stewart_6_6;

use symbody_runtime::{Formulation, Mechanism};

/// Every generated mechanism: name, formulations (the first is the default), the
/// mechanism in each, and the simulation end time its file suggests.
pub static REGISTRY: &[crate::Entry] = &[
    crate::Entry {
        name: "stewart_6_6",
        t_end: stewart_6_6::T_END,
        formulations: &[
            (Formulation::Exact, &stewart_6_6::Exact as &(dyn Mechanism + Sync)),
            (Formulation::Paper, &stewart_6_6::Paper as &(dyn Mechanism + Sync)),
        ],
    },
];
