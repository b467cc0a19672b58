//! `meta.json` beside a run's tables: what the CSV headers cannot say (each column's unit)
//! and what made the files (mechanism, formulation, solver settings, tool version, command
//! line), so a folder of outputs can be read and reproduced on its own. Written before the
//! first step, so a stopped run has it too.

use serde_json::{json, Map, Value};
use std::path::{Path, PathBuf};

/// The file name, beside the CSVs.
pub const FILE: &str = "meta.json";

/// What a run's `meta.json` says besides its files' columns.
#[derive(Clone, Debug)]
pub struct Meta {
    /// The solver settings as run (`t_end`, `step`, `alpha`, `output_step`, and what else
    /// the route has: a scene's file and path).
    pub settings: Map<String, Value>,
}

impl Meta {
    pub fn new(settings: Value) -> Self {
        Meta {
            settings: match settings {
                Value::Object(m) => m,
                _ => Map::new(),
            },
        }
    }

    /// Writes `dir/meta.json` for `mechanism` in `formulation`, whose files are `files`:
    /// each file name with its columns in order and their units.
    pub fn write(
        &self,
        dir: &Path,
        mechanism: &str,
        formulation: &str,
        files: &[(String, Vec<(String, &str)>)],
    ) -> Result<PathBuf, String> {
        let files: Map<String, Value> = files
            .iter()
            .map(|(file, columns)| {
                let names: Vec<&str> = columns.iter().map(|(c, _)| c.as_str()).collect();
                let units: Map<String, Value> = columns
                    .iter()
                    .map(|(c, u)| (c.clone(), Value::from(*u)))
                    .collect();
                (file.clone(), json!({ "columns": names, "units": units }))
            })
            .collect();
        let doc = json!({
            "tool": "symbody",
            "version": env!("CARGO_PKG_VERSION"),
            "command_line": std::env::args_os()
                .map(|a| a.to_string_lossy().into_owned())
                .collect::<Vec<_>>(),
            "mechanism": mechanism,
            "formulation": formulation,
            "settings": self.settings,
            "files": files,
        });
        let path = dir.join(FILE);
        let text = serde_json::to_string_pretty(&doc).expect("a JSON value always serializes");
        std::fs::write(&path, text + "\n").map_err(|e| {
            format!(
                "cannot write {}: {e}; choose another folder with --out",
                path.display()
            )
        })?;
        Ok(path)
    }
}
