//! `--set NAME.KEY=V` (one building), `--set jointN.KEY=V` (one joint) and
//! `--set KEY=V` (the row's own keys): edits of a preset's TOML before it is
//! checked, so that an edited value meets the same checks, and the same
//! messages, as one written in the file.

use super::preset::{BuildingsError, parse};

/// The preset text with `sets` applied, parsed and checked.
pub fn parse_with(file: &str, text: &str, sets: &[String]) -> Result<super::Row, BuildingsError> {
    if sets.is_empty() {
        return parse(file, text);
    }
    let fail = |message: String| BuildingsError {
        file: file.to_string(),
        message,
    };
    let mut table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| fail(e.message().replace('\n', " ")))?;
    for set in sets {
        let (path, value) = set.split_once('=').ok_or_else(|| {
            fail(format!(
                "--set `{set}`: must be NAME.KEY=VALUE, jointN.KEY=VALUE or KEY=VALUE"
            ))
        })?;
        let value = value_of(value.trim());
        let path = path.trim();
        let target = match path.split_once('.') {
            None => &mut table,
            Some((owner, key)) => {
                let slot = find(&mut table, owner).ok_or_else(|| {
                    fail(format!(
                        "--set `{set}`: no building named `{owner}`, no joint and no link `{owner}` (joints are joint1, joint2, …; links link1, link2, …)"
                    ))
                })?;
                // `jointN.bumper.KEY`: a key of the joint's bumper table.
                match key.split_once('.') {
                    Some((inner, leaf)) => {
                        let sub = slot
                            .entry(inner.to_string())
                            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
                        let sub = sub.as_table_mut().ok_or_else(|| {
                            fail(format!("--set `{set}`: `{owner}.{inner}` is not a table"))
                        })?;
                        sub.insert(leaf.to_string(), value);
                    }
                    None => {
                        slot.insert(key.to_string(), value);
                    }
                }
                continue;
            }
        };
        target.insert(path.to_string(), value);
    }
    parse(
        file,
        &toml::to_string(&table).map_err(|e| fail(e.to_string()))?,
    )
}

/// A value as TOML reads it (a number, a list, a string), else a string.
fn value_of(text: &str) -> toml::Value {
    format!("v = {text}")
        .parse::<toml::Table>()
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| toml::Value::String(text.to_string()))
}

/// The `[[building]]` named `owner`, the `[[joint]]` `jointN` or the
/// `[[link]]` `linkN`.
fn find<'a>(table: &'a mut toml::Table, owner: &str) -> Option<&'a mut toml::Table> {
    for list in ["joint", "link"] {
        if let Some(n) = owner
            .strip_prefix(list)
            .and_then(|n| n.parse::<usize>().ok())
        {
            return table
                .get_mut(list)?
                .as_array_mut()?
                .get_mut(n.checked_sub(1)?)?
                .as_table_mut();
        }
    }
    table
        .get_mut("building")?
        .as_array_mut()?
        .iter_mut()
        .filter_map(|b| b.as_table_mut())
        .find(|b| b.get("name").and_then(|n| n.as_str()) == Some(owner))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edits_one_building_and_one_joint() {
        let text = super::super::builtin::find("block-and-frame").unwrap();
        let row = parse_with(
            "b.toml",
            text,
            &[
                "frame.alpha=0.2".into(),
                "joint1.gap=0.05".into(),
                "restitution=0.5".into(),
            ],
        )
        .unwrap();
        assert_eq!(row.buildings[1].alpha, 0.2);
        assert_eq!(row.joints[0].gap, 0.05);
        assert_eq!(row.restitution, 0.5);
        let e = parse_with("b.toml", text, &["frame.mass=[1, 2]".into()]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "b.toml: building `frame`: `mass` has 2 values: must be a number or a list of 8 (one per storey)"
        );
    }
}
