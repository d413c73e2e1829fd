//! The preset list of the picker and the number keys, with stable slots:
//! the built-ins first in their fixed order, then the user's presets in the
//! order this explorer first saw them. A preset saved here or by another
//! process is added at the end, so the digit of every other one stays put.

use std::path::Path;

use crate::model::preset::{self, Preset};

/// The built-in presets followed by the user's own in `dir`, by name (the
/// first listing; later ones go through [`merge`]).
pub fn load(dir: Option<&Path>) -> Vec<Preset> {
    let mut all = preset::builtins();
    all.extend(user_presets(dir));
    all
}

/// The user's presets in `dir`, by name.
pub fn user_presets(dir: Option<&Path>) -> Vec<Preset> {
    let Some(d) = dir else { return Vec::new() };
    preset::user_preset_names(d)
        .into_iter()
        .filter(|name| !preset::is_builtin(name))
        .filter_map(|name| Preset::load(&d.join(format!("{name}.toml"))).ok())
        .collect()
}

/// The list after a new reading of the user's folder: every preset keeps
/// its place (with its new contents), a removed one leaves, new ones
/// (by name) are appended.
pub fn merge(current: &[Preset], fresh: Vec<Preset>) -> Vec<Preset> {
    let mut out: Vec<Preset> = current
        .iter()
        .filter(|p| p.path.is_none())
        .cloned()
        .collect();
    let mut fresh = fresh;
    for old in current.iter().filter(|p| p.path.is_some()) {
        if let Some(i) = fresh.iter().position(|p| p.name == old.name) {
            out.push(fresh.remove(i));
        }
    }
    out.extend(fresh);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn user(name: &str) -> Preset {
        let mut p = preset::builtin("set1").unwrap();
        p.name = name.into();
        p.path = Some(format!("/presets/{name}.toml").into());
        p
    }

    #[test]
    fn a_new_preset_does_not_move_the_others() {
        let before = merge(&preset::builtins(), vec![user("m"), user("z")]);
        let n = preset::builtins().len();
        let after = merge(&before, vec![user("a"), user("m"), user("z")]);
        let names: Vec<&str> = after[n..].iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["m", "z", "a"]);
        assert_eq!(after[..n], before[..n]);
        let gone = merge(&after, vec![user("a"), user("z")]);
        let names: Vec<&str> = gone[n..].iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["z", "a"]);
    }
}
