//! The `symbody` command-line tool's library: the paper's scenario on the generated Stewart
//! platform, and its CSV and PNG outputs.

pub mod output;
pub mod plot;
pub mod scenario;
