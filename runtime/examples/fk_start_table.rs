//! Writes `runtime/src/fk/start_data.rs` to standard output: the generic complex platform the
//! forward kinematics' parameter homotopy starts from, and its 40 solutions.

fn main() {
    match symbody_runtime::fk::start_table_source(0x0004_0574_7a27) {
        Ok(source) => print!("{source}"),
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    }
}
