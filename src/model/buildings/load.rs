//! Where a row preset comes from: a built-in name (`presets/buildings/`) or
//! a path, with `--set` edits applied before the checks.

use std::path::Path;

use super::preset::BuildingsError;
use super::row::Row;

/// Reads a preset: a built-in name (`presets/buildings/NAME.toml`) or a path.
pub fn load(name_or_path: &str) -> Result<Row, BuildingsError> {
    load_with(name_or_path, &[])
}

/// As [`load`], with `--set` edits applied before the checks.
pub fn load_with(name_or_path: &str, sets: &[String]) -> Result<Row, BuildingsError> {
    let (file, text) = text_of(name_or_path)?;
    super::edit::parse_with(&file, &text, sets)
}

/// The file a preset is named by in messages, and its text: a built-in
/// name (`presets/buildings/NAME.toml`) or a path.
pub fn text_of(name_or_path: &str) -> Result<(String, String), BuildingsError> {
    if let Some(text) = super::builtin::find(name_or_path) {
        let file = format!("presets/buildings/{name_or_path}.toml");
        return Ok((file, text.to_string()));
    }
    let path = Path::new(name_or_path);
    let text = std::fs::read_to_string(path).map_err(|e| BuildingsError {
        file: name_or_path.to_string(),
        message: format!(
            "{e} (built-in rows: {})",
            super::builtin::names().join(", ")
        ),
    })?;
    Ok((name_or_path.to_string(), text))
}
