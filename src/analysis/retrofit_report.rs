//! What `pounding run --buildings` reports of a row's retrofits (SPEC §14):
//! per bumper element its contacts, peak force (kN), peak compression (m)
//! and whether it bottomed out (compression beyond its thickness); per link
//! its peak |F| (kN), stroke (m), peak |Δv| (m/s) and the energy its
//! dashpot dissipated (kJ). A row without retrofits reports none of these.

use serde::Serialize;

use crate::model::buildings::Row;
use crate::output::Num;
use crate::output::report::{TableColumn, aligned, yes_no};
use crate::solver::buildings::RowRun;

#[derive(Debug, Clone, Serialize)]
pub struct BumperReport {
    /// The floor pair: `block 3 – frame 3`.
    pub floors: String,
    /// m.
    pub thickness: f64,
    pub contacts: usize,
    /// kN.
    pub max_force_kn: f64,
    /// m: the largest c = u_A − u_B − (d − t).
    pub max_compression: f64,
    /// Whether the compression exceeded the thickness (the joint's own
    /// element then closed too).
    pub bottomed_out: bool,
}

#[derive(Debug, Clone, Serialize)]
pub struct LinkReport {
    /// link1, link2, … in file order.
    pub name: String,
    pub floors: String,
    /// kN.
    pub max_force_kn: f64,
    /// m: max |Δu|.
    pub stroke: f64,
    /// m/s: max |Δv|.
    pub max_rate: f64,
    /// kJ: E_l = ∫ c_l |Δv|^(α+1) dt (null where the run took no energy balance).
    pub energy_kj: f64,
}

/// The bumpers' and links' reports of `run` on `row`, in the order of
/// [`Row::bumper_elements`] and of the links.
pub fn of(row: &Row, run: &RowRun) -> (Vec<BumperReport>, Vec<LinkReport>) {
    let bumpers = row
        .bumper_elements()
        .iter()
        .zip(&run.bumpers)
        .map(|(e, r)| {
            let thickness = e.thickness.unwrap_or(0.0);
            BumperReport {
                floors: row.pair_name(&e.pair),
                thickness,
                contacts: r.impacts.len(),
                max_force_kn: r.max_force() / 1e3,
                max_compression: r.max_penetration(),
                bottomed_out: r.max_penetration() > thickness,
            }
        })
        .collect();
    let links = row
        .link_elements()
        .iter()
        .zip(&run.links)
        .enumerate()
        .map(|(i, (l, r))| LinkReport {
            name: format!("link{}", i + 1),
            floors: row.pair_name(&l.pair),
            max_force_kn: r.max_force / 1e3,
            stroke: r.stroke,
            max_rate: r.max_rate,
            energy_kj: r.energy / 1e3,
        })
        .collect();
    (bumpers, links)
}

/// The table's section of the retrofits (empty without them).
pub fn table(bumpers: &[BumperReport], links: &[LinkReport]) -> String {
    let mut s = String::new();
    if !bumpers.is_empty() {
        s = s + "\n" + &aligned(BUMPER_TABLE, bumpers);
    }
    if !links.is_empty() {
        s = s + "\n" + &aligned(LINK_TABLE, links);
    }
    s
}

/// The table's columns of a bumper element (thickness and compression in mm).
const BUMPER_TABLE: &[TableColumn<BumperReport>] = &[
    ("bumper", -24, |b| b.floors.clone()),
    ("t mm", 7, |b| format!("{:.1}", b.thickness * 1e3)),
    ("contacts", 9, |b| b.contacts.to_string()),
    ("max force kN", 13, |b| format!("{:.0}", b.max_force_kn)),
    ("compression mm", 15, |b| {
        format!("{:.3}", b.max_compression * 1e3)
    }),
    (" bottomed out", 0, |b| yes_no(b.bottomed_out)),
];

/// The table's columns of a link (stroke in mm).
const LINK_TABLE: &[TableColumn<LinkReport>] = &[
    ("link", -7, |l| l.name.clone()),
    ("floors", -24, |l| l.floors.clone()),
    ("max |F| kN", 11, |l| format!("{:.1}", l.max_force_kn)),
    ("stroke mm", 10, |l| format!("{:.2}", l.stroke * 1e3)),
    ("max |Δv| m/s", 13, |l| format!("{:.4}", l.max_rate)),
    ("energy kJ", 10, |l| format!("{:.3}", l.energy_kj)),
];

/// The CSV columns the retrofits add after the floors' (a row with a
/// retrofit only): one row per bumper and per link, its floor pair in
/// `building` and the floors' columns empty.
pub const CSV_COLUMNS: [&str; 8] = [
    "element",
    "contacts",
    "max_force_kn",
    "max_compression",
    "bottomed_out",
    "stroke",
    "max_rate",
    "energy_kj",
];

/// CSV rows of the retrofits, `floor_columns` empty cells after `building`.
pub fn csv_rows(
    bumpers: &[BumperReport],
    links: &[LinkReport],
    floor_columns: usize,
) -> Vec<Vec<String>> {
    let row = |floors: &str, cells: [String; 8]| {
        let mut r = vec![floors.to_string()];
        r.extend(std::iter::repeat_n(String::new(), floor_columns));
        r.extend(cells);
        r
    };
    let bumper_rows = bumpers.iter().map(|b| {
        row(
            &b.floors,
            [
                "bumper".into(),
                b.contacts.to_string(),
                Num(b.max_force_kn).to_string(),
                Num(b.max_compression).to_string(),
                b.bottomed_out.to_string(),
                String::new(),
                String::new(),
                String::new(),
            ],
        )
    });
    let link_rows = links.iter().map(|l| {
        row(
            &l.floors,
            [
                l.name.clone(),
                String::new(),
                Num(l.max_force_kn).to_string(),
                String::new(),
                String::new(),
                Num(l.stroke).to_string(),
                Num(l.max_rate).to_string(),
                Num(l.energy_kj).to_string(),
            ],
        )
    });
    bumper_rows.chain(link_rows).collect()
}
