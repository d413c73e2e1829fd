//! Text that must fit a width on screen: a label, a meaning, a value or a
//! title is shown whole, or gives up whole words and ends with "…" (a
//! first word too long alone is cut and ends with "…"), never cut silently.
//! A contact law's name has a short form instead, listed in the help.

use crate::model::ContactModel;

/// The explorer's short form of each contact law, for a column too
/// narrow for its name (the help lists them).
pub const SHORT_LAWS: [(ContactModel, &str); 6] = [
    (ContactModel::Kelvin, "K"),
    (ContactModel::ImprovedKelvin, "IK"),
    (ContactModel::Hertz, "H"),
    (ContactModel::HertzDamp, "HD"),
    (ContactModel::Jankowski, "J"),
    (ContactModel::HuntCrossley, "HC"),
];

/// A law in words, as a label can carry it where its column shows the
/// short form.
pub fn law_words(model: ContactModel) -> &'static str {
    match model {
        ContactModel::Kelvin => "Kelvin",
        ContactModel::ImprovedKelvin => "improved Kelvin",
        ContactModel::Hertz => "Hertz",
        ContactModel::HertzDamp => "Hertz with damping",
        ContactModel::Jankowski => "Jankowski",
        ContactModel::HuntCrossley => "Hunt–Crossley",
    }
}

/// The label of a row whose `values` are shown in columns of
/// `value_width`: where a column is too narrow for a law's name and shows
/// its short form, the label names the law in words instead (`contact
/// element: improved Kelvin`, else `contact: improved Kelvin`, else
/// `IK = improved Kelvin`, else `improved Kelvin`; each short form used,
/// when the values differ),
/// so that the screen says which laws it compares. Else the label as it is.
/// Either way fitted to `width`.
pub fn law_label(label: &str, values: &[&str], value_width: usize, width: usize) -> String {
    let law = |v: &&str| SHORT_LAWS.iter().find(|(m, _)| m.name() == *v);
    let mut shortened: Vec<&(ContactModel, &str)> = Vec::new();
    for v in values {
        if v.chars().count() > value_width
            && let Some(entry) = law(v)
            && !shortened.contains(&entry)
        {
            shortened.push(entry);
        }
    }
    let candidates: Vec<String> = match shortened.as_slice() {
        [] => return fit(label, width),
        [(model, short)] if values.iter().all(|v| law(v).map(|e| e.0) == Some(*model)) => {
            let words = law_words(*model);
            let noun = label.split(' ').next().unwrap_or(label);
            vec![
                format!("{label}: {words}"),
                format!("{noun}: {words}"),
                format!("{short} = {words}"),
                words.to_string(),
            ]
        }
        many => {
            let each = |sep: &str| {
                many.iter()
                    .map(|(m, s)| format!("{s}{sep}{}", law_words(*m)))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            vec![each(" = "), each("="), each(" ")]
        }
    };
    let last = candidates.last().cloned().unwrap_or_default();
    candidates
        .into_iter()
        .find(|c| c.chars().count() <= width)
        .unwrap_or_else(|| fit(&last, width))
}

/// The help's rows defining [`SHORT_LAWS`], two laws a row:
/// (`K / IK`, `kelvin / improved-kelvin`), …
pub fn short_laws_legend() -> Vec<(String, String)> {
    SHORT_LAWS
        .chunks(2)
        .map(|pair| {
            let shorts: Vec<&str> = pair.iter().map(|(_, s)| *s).collect();
            let names: Vec<&str> = pair.iter().map(|(m, _)| m.name()).collect();
            (shorts.join(" / "), names.join(" / "))
        })
        .collect()
}

/// The short form of a law's name, if `text` is one.
pub fn short_law(text: &str) -> Option<&'static str> {
    SHORT_LAWS
        .iter()
        .find(|(m, _)| m.name() == text)
        .map(|(_, s)| *s)
}

/// `text` in at most `width` characters: whole when it fits; else the
/// words that fit before a "…" (not ending inside a bracket they open);
/// else its first characters and "…".
pub fn fit(text: &str, width: usize) -> String {
    let n = text.chars().count();
    if n <= width {
        return text.to_string();
    }
    if width == 0 {
        return String::new();
    }
    let room = width - 1;
    let head: String = text.chars().take(room).collect();
    let at_word_end = text.chars().nth(room) == Some(' ');
    let mut kept = match head.rfind(' ') {
        _ if at_word_end => head.trim_end(),
        Some(i) if !head[..i].trim_end().is_empty() => head[..i].trim_end(),
        _ => head.as_str(),
    };
    // A bracket left open gives up what it began: "stiffness…", not
    // "stiffness (0:…".
    if kept.matches('(').count() > kept.matches(')').count()
        && let Some(i) = kept.rfind('(')
        && !kept[..i].trim_end().is_empty()
    {
        kept = kept[..i].trim_end();
    }
    format!("{kept}…")
}

/// A value for a column of `width`: whole, else a law's short form, else cut with "…".
pub fn fit_value(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    match short_law(text) {
        Some(s) if s.len() <= width => s.to_string(),
        _ => fit(text, width),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_words_then_an_ellipsis() {
        assert_eq!(
            fit("Hertz stiffness (0: from e)", 30),
            "Hertz stiffness (0: from e)"
        );
        assert_eq!(fit("Hertz stiffness (0: from e)", 24), "Hertz stiffness…");
        assert_eq!(fit("a (b) c (d e f)", 12), "a (b) c…");
        assert_eq!(fit("Hertz stiffness (0: from e)", 16), "Hertz stiffness…");
        assert_eq!(fit("Hertz stiffness", 4), "Her…");
        assert_eq!(fit("abc", 0), "");
        assert_eq!(fit("abc", 1), "…");
    }

    #[test]
    fn laws_take_their_short_form() {
        assert_eq!(fit_value("improved-kelvin", 8), "IK");
        assert_eq!(fit_value("kelvin", 8), "kelvin");
        assert_eq!(fit_value("hunt-crossley", 8), "HC");
        assert_eq!(fit_value("record:/a/long/path.AT2", 8), "record:…");
        let legend = short_laws_legend();
        assert_eq!(legend.len(), 3);
        assert_eq!(
            legend[0],
            ("K / IK".into(), "kelvin / improved-kelvin".into())
        );
    }

    #[test]
    fn a_label_names_the_law_its_narrow_column_shortens() {
        let both = ["improved-kelvin", "improved-kelvin"];
        assert_eq!(
            law_label("contact element", &both, 9, 40),
            "contact element: improved Kelvin"
        );
        assert_eq!(
            law_label("contact element", &both, 9, 24),
            "contact: improved Kelvin"
        );
        assert_eq!(
            law_label("contact element", &both, 9, 20),
            "IK = improved Kelvin"
        );
        assert_eq!(
            law_label("contact law", &["improved-kelvin"], 11, 17),
            "improved Kelvin"
        );
        // A column wide enough for the name: the label as it is.
        assert_eq!(
            law_label("contact element", &both, 15, 24),
            "contact element"
        );
        // Different laws: each short form used is named.
        let mixed = ["improved-kelvin", "kelvin"];
        assert_eq!(
            law_label("contact element", &mixed, 9, 24),
            "IK = improved Kelvin"
        );
        let two = ["improved-kelvin", "hunt-crossley"];
        assert_eq!(
            law_label("contact element", &two, 9, 40),
            "IK = improved Kelvin, HC = Hunt–Crossley"
        );
        assert_eq!(
            law_label("contact element", &two, 9, 24),
            "IK improved Kelvin, HC…"
        );
        // Not a law: fitted as any label.
        assert_eq!(law_label("restitution e", &["0.4"], 9, 24), "restitution e");
    }
}
