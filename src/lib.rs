//! The `symbody` command-line tool's library: any registered mechanism simulated
//! ([`generic`]), the paper's scenario on the generated Stewart platform ([`scenario`]), and
//! their CSV and PNG outputs.

pub mod fk;
pub mod generic;
pub mod iftomm;
pub mod output;
pub mod plot;
pub mod scenario;
pub mod scene;
pub mod session;
pub mod viewer;
