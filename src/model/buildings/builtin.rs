//! The building presets shipped in `presets/buildings/`, compiled into the binary.

/// (name, contents) of every built-in row.
pub static BUILTIN: &[(&str, &str)] = &[
    (
        "two-buildings",
        include_str!("../../../presets/buildings/two-buildings.toml"),
    ),
    (
        "block-and-frame",
        include_str!("../../../presets/buildings/block-and-frame.toml"),
    ),
    (
        "three-in-series",
        include_str!("../../../presets/buildings/three-in-series.toml"),
    ),
    (
        "block-and-frame-pdelta",
        include_str!("../../../presets/buildings/block-and-frame-pdelta.toml"),
    ),
    (
        "block-and-frame-retrofit",
        include_str!("../../../presets/buildings/block-and-frame-retrofit.toml"),
    ),
];

/// The text of the built-in row `name`.
pub fn find(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// Names of the built-in rows.
pub fn names() -> Vec<&'static str> {
    BUILTIN.iter().map(|(n, _)| *n).collect()
}

/// The `description` line of the built-in row `name`.
pub fn description(name: &str) -> Option<String> {
    let table: toml::Table = find(name)?.parse().ok()?;
    table.get("description")?.as_str().map(str::to_string)
}
