//! Generated mechanisms, one module each, and their registry. Regenerate with
//! `cargo xtask generate --all`.

#[rustfmt::skip]
pub mod andrews_squeezer;
#[rustfmt::skip]
pub mod bricard;
#[rustfmt::skip]
pub mod dietmaier_6_6;
#[rustfmt::skip]
pub mod flyball_governor;
#[rustfmt::skip]
pub mod four_bar;
#[rustfmt::skip]
pub mod hexapod_twist;
#[rustfmt::skip]
pub mod n_four_bar_2;
#[rustfmt::skip]
pub mod n_four_bar_40;
#[rustfmt::skip]
pub mod oscillators;
#[rustfmt::skip]
pub mod simple_pendulum;
#[rustfmt::skip]
pub mod slider_crank;
#[rustfmt::skip]
pub mod spherical_pendulum;
#[rustfmt::skip]
pub mod stewart_6_6;
#[rustfmt::skip]
pub mod ups_stewart;

use symbody_runtime::{Formulation, Mechanism};

/// Every generated mechanism: name, formulations (the first is the default), the
/// mechanism in each, and the simulation end time its file suggests.
#[rustfmt::skip]
pub static REGISTRY: &[crate::Entry] = &[
    crate::Entry {
        name: "andrews_squeezer",
        t_end: andrews_squeezer::T_END,
        formulations: &[
            (Formulation::Exact, &andrews_squeezer::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "bricard",
        t_end: bricard::T_END,
        formulations: &[
            (Formulation::Exact, &bricard::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "dietmaier_6_6",
        t_end: dietmaier_6_6::T_END,
        formulations: &[
            (Formulation::Exact, &dietmaier_6_6::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "flyball_governor",
        t_end: flyball_governor::T_END,
        formulations: &[
            (Formulation::Exact, &flyball_governor::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "four_bar",
        t_end: four_bar::T_END,
        formulations: &[
            (Formulation::Exact, &four_bar::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "hexapod_twist",
        t_end: hexapod_twist::T_END,
        formulations: &[
            (Formulation::Exact, &hexapod_twist::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "n_four_bar_2",
        t_end: n_four_bar_2::T_END,
        formulations: &[
            (Formulation::Exact, &n_four_bar_2::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "n_four_bar_40",
        t_end: n_four_bar_40::T_END,
        formulations: &[
            (Formulation::Exact, &n_four_bar_40::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "oscillators",
        t_end: oscillators::T_END,
        formulations: &[
            (Formulation::Exact, &oscillators::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "simple_pendulum",
        t_end: simple_pendulum::T_END,
        formulations: &[
            (Formulation::Exact, &simple_pendulum::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "slider_crank",
        t_end: slider_crank::T_END,
        formulations: &[
            (Formulation::Exact, &slider_crank::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "spherical_pendulum",
        t_end: spherical_pendulum::T_END,
        formulations: &[
            (Formulation::Exact, &spherical_pendulum::Exact as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "stewart_6_6",
        t_end: stewart_6_6::T_END,
        formulations: &[
            (Formulation::Exact, &stewart_6_6::Exact as &(dyn Mechanism + Sync)),
            (Formulation::Paper, &stewart_6_6::Paper as &(dyn Mechanism + Sync)),
        ],
    },
    crate::Entry {
        name: "ups_stewart",
        t_end: ups_stewart::T_END,
        formulations: &[
            (Formulation::Exact, &ups_stewart::Exact as &(dyn Mechanism + Sync)),
        ],
    },
];
