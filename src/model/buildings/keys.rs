//! Reading a preset's TOML tables: unknown keys, arrays of tables, numbers
//! (or `"inf"`), each failure one line naming the key.

pub fn unknown_keys(t: &toml::Table, allowed: &[&str], whose: &str) -> Result<(), String> {
    match t.keys().find(|k| !allowed.contains(&k.as_str())) {
        Some(k) => Err(format!(
            "{whose}unknown key `{k}`: allowed are {}",
            allowed.join(", ")
        )),
        None => Ok(()),
    }
}

pub fn tables<'a>(t: &'a toml::Table, key: &str) -> Result<Vec<&'a toml::Table>, String> {
    match t.get(key) {
        None => Ok(Vec::new()),
        Some(toml::Value::Array(items)) => items
            .iter()
            .map(|v| {
                v.as_table()
                    .ok_or_else(|| format!("`{key}` must be an array of tables ([[{key}]])"))
            })
            .collect(),
        Some(_) => Err(format!("`{key}` must be an array of tables ([[{key}]])")),
    }
}

/// A number, or `"inf"`, as f64.
pub fn as_f64(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        toml::Value::String(s) if s == "inf" => Some(f64::INFINITY),
        _ => None,
    }
}

pub fn number(
    t: &toml::Table,
    key: &str,
    whose: &str,
    default: Option<f64>,
) -> Result<f64, String> {
    match (t.get(key), default) {
        (None, Some(d)) => Ok(d),
        (None, None) => Err(format!("{whose}missing key `{key}`")),
        (Some(v), _) => as_f64(v).ok_or_else(|| format!("{whose}`{key}` = {v}: must be a number")),
    }
}
