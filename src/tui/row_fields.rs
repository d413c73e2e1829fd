//! The rows of the parameter pane in the buildings scene: the contact law
//! and e, then per building its storeys, floor mass, storey stiffness, yield
//! drift, α and ξ, then per joint its gap and contact stiffness (SPEC §13)
//! and its bumper's thickness, stiffness and restitution, then per link its
//! stiffness and damping (SPEC §14).
//! Each row is one `--set` key of the CLI, so an edit meets the checks, and
//! the messages, of `pounding run --buildings --set KEY=V`.

use super::fields::StepSize;
use crate::model::ContactModel;
use crate::model::buildings::Row;

/// What a pane row holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Law,
    Restitution,
    Storeys(usize),
    Mass(usize),
    Stiffness(usize),
    YieldDrift(usize),
    Alpha(usize),
    Damping(usize),
    Gap(usize),
    JointStiffness(usize),
    /// The bumper of joint j (SPEC §14): t (m), k_b, e_b.
    BumperThickness(usize),
    BumperStiffness(usize),
    BumperRestitution(usize),
    /// Link l: k_l (N/m), c_l (N·(s/m)^α).
    LinkStiffness(usize),
    LinkDamping(usize),
}

/// One pane row: its label, the `--set` key it edits and its value shown.
#[derive(Debug, Clone, PartialEq)]
pub struct RowField {
    pub kind: Kind,
    pub label: String,
    pub key: String,
    pub value: String,
}

/// Longest building name shown in a label.
const NAME_WIDTH: usize = 7;

fn short(name: &str) -> String {
    name.chars().take(NAME_WIDTH).collect()
}

/// Shortest text of a number that reads back as the same f64 in TOML.
pub fn number(x: f64) -> String {
    if x.is_infinite() {
        return if x > 0.0 { "inf".into() } else { "-inf".into() };
    }
    format!("{x:?}")
}

/// A list as the pane shows it: the value when all agree, else the
/// bottom one marked with `~` (the list scales as a whole when nudged).
fn list_text(values: &[f64]) -> String {
    let first = values[0];
    if values.iter().all(|&v| v == first) {
        compact(first)
    } else {
        format!("~{}", compact(first))
    }
}

/// A value in at most ten columns.
fn compact(x: f64) -> String {
    if x.is_infinite() {
        return "inf".into();
    }
    let plain = format!("{x}");
    if plain.len() <= 9 {
        plain
    } else {
        format!("{x:.3e}")
    }
}

/// The pane's rows for `row`.
pub fn fields(row: &Row) -> Vec<RowField> {
    let mut out = vec![
        RowField {
            kind: Kind::Law,
            label: "contact law".into(),
            key: "model".into(),
            value: row.model.name().into(),
        },
        RowField {
            kind: Kind::Restitution,
            label: "restitution e".into(),
            key: "restitution".into(),
            value: compact(row.restitution),
        },
    ];
    for (i, b) in row.buildings.iter().enumerate() {
        let n = short(&b.name);
        let field = |kind, what: &str, key: &str, value: String| RowField {
            kind,
            label: format!("{n} {what}"),
            key: format!("{}.{key}", b.name),
            value,
        };
        out.push(field(
            Kind::Storeys(i),
            "storeys",
            "storeys",
            b.storeys().to_string(),
        ));
        out.push(field(Kind::Mass(i), "m kg", "mass", list_text(&b.mass)));
        out.push(field(
            Kind::Stiffness(i),
            "k N/m",
            "stiffness",
            list_text(&b.stiffness),
        ));
        out.push(field(
            Kind::YieldDrift(i),
            "Δy m",
            "yield_drift",
            list_text(&b.yield_drift),
        ));
        out.push(field(Kind::Alpha(i), "α", "alpha", compact(b.alpha)));
        out.push(field(Kind::Damping(i), "ξ", "damping", compact(b.damping)));
    }
    for (j, joint) in row.joints.iter().enumerate() {
        let key = |k: &str| format!("joint{}.{k}", j + 1);
        out.push(RowField {
            kind: Kind::Gap(j),
            label: format!("joint{} gap m", j + 1),
            key: key("gap"),
            value: compact(joint.gap),
        });
        out.push(RowField {
            kind: Kind::JointStiffness(j),
            label: format!("joint{} k̄ N/m", j + 1),
            key: key("stiffness"),
            value: compact(joint.stiffness),
        });
        if let Some(b) = &joint.bumper {
            let bumper = |kind, what: &str, k: &str, value: f64| RowField {
                kind,
                label: format!("joint{} bumper {what}", j + 1),
                key: key(&format!("bumper.{k}")),
                value: compact(value),
            };
            out.push(bumper(
                Kind::BumperThickness(j),
                "t m",
                "thickness",
                b.thickness,
            ));
            out.push(bumper(
                Kind::BumperStiffness(j),
                "k",
                "stiffness",
                b.stiffness,
            ));
            out.push(bumper(
                Kind::BumperRestitution(j),
                "e",
                "restitution",
                b.restitution,
            ));
        }
    }
    for (l, link) in row.links.iter().enumerate() {
        let field = |kind, what: &str, k: &str, value: f64| RowField {
            kind,
            label: format!("link{} {what}", l + 1),
            key: format!("link{}.{k}", l + 1),
            value: compact(value),
        };
        out.push(field(
            Kind::LinkStiffness(l),
            "k N/m",
            "stiffness",
            link.stiffness,
        ));
        out.push(field(Kind::LinkDamping(l), "c", "damping", link.damping));
    }
    out
}

/// Factor of one step of a scaled quantity (mass, stiffness, drift, gap).
fn factor(size: StepSize) -> f64 {
    match size {
        StepSize::Fine => 1.02,
        StepSize::Normal => 1.1,
        StepSize::Coarse => 2.0,
    }
}

/// A list with every value scaled by `f`, as TOML.
fn scaled(values: &[f64], f: f64) -> String {
    let v: Vec<String> = values.iter().map(|x| number(x * f)).collect();
    format!("[{}]", v.join(", "))
}

/// A per-storey list cut or grown to `n` values (the top value repeated).
fn resized(values: &[f64], n: usize) -> String {
    let v: Vec<String> = (0..n)
        .map(|i| number(values[i.min(values.len() - 1)]))
        .collect();
    format!("[{}]", v.join(", "))
}

/// The `--set` edits that give building `i` `n` storeys: its per-storey
/// lists cut at the top or grown by repeating the top value.
pub fn storeys_edits(row: &Row, i: usize, n: usize) -> Vec<(String, String)> {
    let b = &row.buildings[i];
    let key = |k: &str| format!("{}.{k}", b.name);
    vec![
        (key("storeys"), n.to_string()),
        (key("mass"), resized(&b.mass, n)),
        (key("stiffness"), resized(&b.stiffness, n)),
        (key("height"), resized(&b.height, n)),
        (key("yield_drift"), resized(&b.yield_drift, n)),
    ]
}

/// The contact laws in the order the law row steps through them.
const LAWS: [ContactModel; 6] = ContactModel::ALL;

/// The `--set` edits of one nudge of `field` in `direction` (±1): a step
/// of ±1 storey, ±0.01 in α, ±0.005 in ξ, ±0.05 in e, the next law, or a
/// factor on a scaled quantity (every value of a list alike). `None` where
/// the value cannot be nudged (an infinite gap or drift: type a value).
pub fn nudged(
    row: &Row,
    field: &RowField,
    direction: f64,
    size: StepSize,
) -> Option<Vec<(String, String)>> {
    let f = factor(size).powf(direction.signum());
    let steps = direction
        * match size {
            StepSize::Fine => 0.2,
            StepSize::Normal => 1.0,
            StepSize::Coarse => 5.0,
        };
    let one = |value: String| Some(vec![(field.key.clone(), value)]);
    match field.kind {
        Kind::Law => {
            let k = LAWS.iter().position(|&l| l == row.model).unwrap_or(0) as isize;
            let next = (k + direction.signum() as isize).rem_euclid(LAWS.len() as isize);
            one(format!("\"{}\"", LAWS[next as usize].name()))
        }
        Kind::Restitution => one(number(round(row.restitution + 0.05 * steps, 1e6))),
        Kind::Storeys(i) => {
            let n = row.buildings[i].storeys() as f64 + direction.signum() * steps.abs().max(1.0);
            Some(storeys_edits(row, i, n.max(1.0) as usize))
        }
        Kind::Mass(i) => one(scaled(&row.buildings[i].mass, f)),
        Kind::Stiffness(i) => one(scaled(&row.buildings[i].stiffness, f)),
        Kind::YieldDrift(i) => {
            let d = &row.buildings[i].yield_drift;
            d.iter().all(|x| x.is_finite()).then_some(())?;
            one(scaled(d, f))
        }
        Kind::Alpha(i) => one(number(round(row.buildings[i].alpha + 0.01 * steps, 1e9))),
        Kind::Damping(i) => one(number(round(row.buildings[i].damping + 0.005 * steps, 1e9))),
        Kind::Gap(j) => {
            let g = row.joints[j].gap;
            g.is_finite().then_some(())?;
            one(number(g * f))
        }
        Kind::JointStiffness(j) => one(number(row.joints[j].stiffness * f)),
        Kind::BumperThickness(j) => one(number(row.joints[j].bumper.as_ref()?.thickness * f)),
        Kind::BumperStiffness(j) => one(number(row.joints[j].bumper.as_ref()?.stiffness * f)),
        Kind::BumperRestitution(j) => {
            let e = row.joints[j].bumper.as_ref()?.restitution;
            one(number(round(e + 0.05 * steps, 1e6)))
        }
        // A link at 0 is nudged from its scale's natural start: a factor
        // cannot leave 0 (type a value instead).
        Kind::LinkStiffness(l) => one(number(row.links[l].stiffness * f)),
        Kind::LinkDamping(l) => one(number(row.links[l].damping * f)),
    }
}

/// `x` rounded to a multiple of 1/`per` (steps land on round values; the
/// division by an integer-valued `per` is correctly rounded).
fn round(x: f64, per: f64) -> f64 {
    (x * per).round() / per
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::buildings::{load, load_with};

    fn apply(edits: &[(String, String)]) -> Row {
        let sets: Vec<String> = edits.iter().map(|(k, v)| format!("{k}={v}")).collect();
        load_with("block-and-frame", &sets).unwrap()
    }

    #[test]
    fn every_row_reads_back_and_nudges_through_the_cli_keys() {
        let row = load("block-and-frame").unwrap();
        let f = fields(&row);
        assert_eq!(f.len(), 2 + 2 * 6 + 2);
        assert_eq!(f[2].label, "block storeys");
        assert_eq!(f[3].value, "~500000");
        let mass = nudged(&row, &f[3], 1.0, StepSize::Normal).unwrap();
        let next = apply(&mass);
        for (a, b) in next.buildings[0].mass.iter().zip(&row.buildings[0].mass) {
            assert!((a / b - 1.1).abs() < 1e-15);
        }
        // A storey more: the lists grow by their top value.
        let four = apply(&nudged(&row, &f[2], 1.0, StepSize::Normal).unwrap());
        assert_eq!(four.buildings[0].storeys(), 4);
        assert_eq!(four.buildings[0].mass[3], 4.0e5);
        assert_eq!(four.buildings[0].stiffness[3], 0.8e9);
        // The law steps through all six.
        let law = apply(&nudged(&row, &f[0], 1.0, StepSize::Normal).unwrap());
        assert_eq!(law.model, ContactModel::Hertz);
        let gap = f.iter().find(|f| f.kind == Kind::Gap(0)).unwrap();
        let wider = apply(&nudged(&row, gap, 1.0, StepSize::Coarse).unwrap());
        assert_eq!(wider.joints[0].gap, 0.01);
        let alpha = f.iter().find(|f| f.kind == Kind::Alpha(1)).unwrap();
        let a = apply(&nudged(&row, alpha, -1.0, StepSize::Normal).unwrap());
        assert_eq!(a.buildings[1].alpha, 0.04);
    }

    #[test]
    fn a_retrofit_lists_its_bumper_and_link_keys() {
        let row = load("block-and-frame-retrofit").unwrap();
        let f = fields(&row);
        assert_eq!(f.len(), 2 + 2 * 6 + 2 + 3 + 2);
        let keys: Vec<&str> = f[16..].iter().map(|f| f.key.as_str()).collect();
        assert_eq!(
            keys,
            [
                "joint1.bumper.thickness",
                "joint1.bumper.stiffness",
                "joint1.bumper.restitution",
                "link1.stiffness",
                "link1.damping",
            ]
        );
        let edit = |field: &RowField, d: f64| {
            let sets: Vec<String> = nudged(&row, field, d, StepSize::Normal)
                .unwrap()
                .iter()
                .map(|(k, v)| format!("{k}={v}"))
                .collect();
            load_with("block-and-frame-retrofit", &sets)
        };
        let thinner = edit(&f[16], -1.0).unwrap();
        let t = thinner.joints[0].bumper.as_ref().unwrap().thickness;
        assert!((t - 0.004 / 1.1).abs() < 1e-15);
        let e = edit(&f[18], -1.0).unwrap();
        assert_eq!(e.joints[0].bumper.as_ref().unwrap().restitution, 0.75);
        let c = edit(&f[20], 1.0).unwrap();
        assert!((c.links[0].damping - 4.4e6).abs() < 1e-6);
        // A thicker bumper than the gap is the preset's own refusal.
        let f5 = RowField {
            value: String::new(),
            ..f[16].clone()
        };
        let too_thick = nudged(&row, &f5, 1.0, StepSize::Coarse).unwrap();
        let sets: Vec<String> = too_thick.iter().map(|(k, v)| format!("{k}={v}")).collect();
        let err = load_with("block-and-frame-retrofit", &sets).unwrap_err();
        assert!(err.to_string().contains("thickness"), "{err}");
    }
}
