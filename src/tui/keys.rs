//! Every key of the explorer, as the help overlay and the guide (docs/src/explorer.md) list
//! them, and the help's lines (data only: the app scrolls the help by
//! them, the overlay draws them).

/// Every key, as the help overlay and the guide lists them.
pub const KEYS: [(&str, &str); 34] = [
    ("?", "this help (↑↓ scroll; other keys close)"),
    ("↑/↓, k/j", "select a parameter"),
    ("←/→, h/l, -/+", "nudge it by one step"),
    ("Shift+←/→, H/L", "nudge by ten steps"),
    (", / .  (Ctrl+←/→)", "nudge by a tenth of a step"),
    ("Enter", "type an exact value (typing replaces it)"),
    ("Tab", "switch the active set"),
    ("m", "Kelvin ↔ improved Kelvin (row: all six)"),
    ("r", "reset the active set to its preset"),
    ("1-9", "recall preset 1-9 into the active set"),
    ("p", "preset picker"),
    ("s", "save the active set as a user preset"),
    ("e", "export a history as CSV (asks where)"),
    ("g", "write the scene as an SVG figure"),
    ("t", "scene: time histories"),
    ("f", "scene: force-drift loops"),
    (
        "v",
        "scene: contact laws (b: paper pair, all six, own vs one)",
    ),
    ("c", "scene: set 1 vs set 2 (o overlays them)"),
    ("w", "scene: spectrum against Π_ω1"),
    ("i", "scene: impact table and energy terms"),
    ("a", "scene: map (y axis, o ratio, [ ]{ })"),
    (
        "x",
        "scene: risk over a suite ([ ] level, o PGA/Sa, y joint)",
    ),
    (
        "d",
        "scene: a row of buildings (o panel, | both laws, b no retrofit)",
    ),
    ("space, ( / )", "row: play / pause, slower / faster"),
    ("< / >", "row: displacements drawn ÷2 / ×2"),
    ("u", "physical units (presets with [physical])"),
    ("[ / ]", "move the time cursor ({ } by ten)"),
    ("n / N", "cursor to the next / previous impact"),
    ("z / Z", "zoom in around the cursor / out"),
    ("Esc", "hide the cursor (never quits)"),
    ("mouse", "click: select or cursor; wheel: nudge"),
    ("M", "mouse on/off (off: select text)"),
    ("q", "quit (asks if a set is unsaved)"),
    ("Ctrl-C", "quit at once"),
];

/// The help's lines: each key and what it does; under `m`, the short
/// forms a narrow pane gives the laws' names.
pub fn help_lines() -> Vec<String> {
    let mut lines = Vec::new();
    for (k, what) in KEYS {
        lines.push(format!("{k:>18}  {what}"));
        if k == "m" {
            lines.extend(
                super::fit::short_laws_legend()
                    .into_iter()
                    .map(|(short, name)| format!("{short:>18}  law {name}")),
            );
        }
    }
    lines
}

/// Columns inside the help box (62 wide, two borders).
pub const HELP_COLUMNS: usize = 60;

/// The last first line of a help that scrolls on a screen `height` rows
/// tall (the box's two borders off): from it on, every line shows, a line
/// longer than the box taking two rows or more.
pub fn help_top_max(height: u16) -> usize {
    let rows = height.saturating_sub(2) as usize;
    let lines = help_lines();
    let mut used = 0;
    for (i, line) in lines.iter().enumerate().rev() {
        used += line.chars().count().div_ceil(HELP_COLUMNS).max(1);
        if used > rows {
            return i + 1;
        }
    }
    0
}
