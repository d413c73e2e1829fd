//! What `pounding run --buildings` reports (SPEC §13): per building its
//! periods and per floor the peaks and drift demands, per floor pair its
//! impacts, in SI (accelerations in g, forces in kN).

use std::fmt::Write as _;

use serde::Serialize;

use crate::accuracy::row_bench::RowBenchRow;
use crate::model::buildings::matrices::periods;
use crate::model::buildings::{Ground, Row};
use crate::model::record::STANDARD_GRAVITY;
use crate::output::Num;
use crate::output::report::{
    Column, Report, TableColumn, aligned, column_header, column_rows, float_or_inf, yes_no,
};
use crate::solver::buildings::RowRun;

use super::retrofit_report::{self, BumperReport, LinkReport};

#[derive(Debug, Clone, Serialize)]
pub struct FloorReport {
    pub floor: usize,
    pub peak_displacement: f64,
    pub peak_velocity: f64,
    /// g.
    pub peak_absolute_acceleration: f64,
    pub peak_drift: f64,
    pub drift_ratio: f64,
    #[serde(serialize_with = "float_or_inf")]
    pub ductility: f64,
    pub residual_drift: f64,
}

#[derive(Debug, Clone, Serialize)]
pub struct BuildingReport {
    pub name: String,
    /// s, longest first (under gravity with P-Δ, SPEC §15).
    pub periods: Vec<f64>,
    /// θ_i = P_i/(k_i h_i) per storey, bottom to top, for a building with
    /// P-Δ (SPEC §15).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stability_coefficients: Option<Vec<f64>>,
    pub floors: Vec<FloorReport>,
}

/// Where and when a building collapsed (SPEC §15).
#[derive(Debug, Clone, Serialize)]
pub struct CollapseReport {
    pub building: String,
    /// 1-based, bottom to top.
    pub storey: usize,
    /// s.
    pub time: f64,
}

#[derive(Debug, Clone, Serialize)]
pub struct PairReport {
    pub left: String,
    pub right: String,
    pub left_floor: usize,
    pub right_floor: usize,
    pub impacts: usize,
    /// kN.
    pub max_force: f64,
    /// m.
    pub max_penetration: f64,
}

/// The energy balance of SPEC §6 summed over the row, kJ.
#[derive(Debug, Clone, Serialize)]
pub struct EnergyReport {
    pub input: f64,
    pub kinetic: f64,
    pub damping: f64,
    pub spring: f64,
    pub contact: f64,
    /// Work of the bumpers and of the links (SPEC §14), for a row with a
    /// retrofit only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bumper: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub link: Option<f64>,
    pub residual: f64,
}

impl EnergyReport {
    pub fn of(e: &crate::solver::buildings::RowEnergy) -> EnergyReport {
        EnergyReport {
            input: e.input / 1e3,
            kinetic: e.kinetic / 1e3,
            damping: e.damping / 1e3,
            spring: e.spring / 1e3,
            contact: e.contact / 1e3,
            bumper: None,
            link: None,
            residual: e.residual(),
        }
    }
}

/// How the exact method's cache of linear maps was used.
#[derive(Debug, Clone, Serialize)]
pub struct CacheReport {
    /// Matrix exponentials made (distinct (configuration, h, σ)).
    pub maps: usize,
    /// Branch patterns seen out of contact.
    pub configurations: usize,
    /// Sub-steps taken by a cached map, and Taylor steps.
    pub map_steps: usize,
    pub series_steps: usize,
}

#[derive(Debug, Clone, Serialize)]
pub struct RowReport {
    pub row: String,
    pub model: String,
    pub excitation: String,
    pub method: String,
    /// s.
    pub duration: f64,
    pub buildings: Vec<BuildingReport>,
    pub pairs: Vec<PairReport>,
    /// Each bumper element and each link (SPEC §14); absent without them.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub bumpers: Vec<BumperReport>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub links: Vec<LinkReport>,
    pub impacts: usize,
    pub elapsed_ms: f64,
    pub cache: CacheReport,
    /// The energy balance (kJ), summed over buildings (exact method).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy: Option<EnergyReport>,
    /// For a row with a P-Δ building: its collapse, or `None` (null) when
    /// none collapsed; absent for a row that cannot collapse (SPEC §15).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub collapsed: Option<Option<CollapseReport>>,
    /// Set when no floors pair up: the row runs, but nothing can pound.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// What the motion imposes beyond its name ([`Ground::note`]): the type
    /// B pulse's initial velocity of every floor.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub excitation_note: Option<String>,
}

impl RowReport {
    pub fn new(
        row: &Row,
        run: &RowRun,
        (ground, excitation): (&Ground, &str),
        method: &str,
        elapsed_ms: f64,
    ) -> Self {
        let buildings = row
            .buildings
            .iter()
            .zip(&run.floors)
            .map(|(b, floors)| BuildingReport {
                name: b.name.clone(),
                periods: periods(b),
                stability_coefficients: b.p_delta.is_some().then(|| {
                    (0..b.storeys())
                        .map(|i| b.stability_coefficient(i))
                        .collect()
                }),
                floors: floors
                    .iter()
                    .enumerate()
                    .map(|(i, f)| FloorReport {
                        floor: i + 1,
                        peak_displacement: f.displacement,
                        peak_velocity: f.velocity,
                        peak_absolute_acceleration: f.absolute_acceleration / STANDARD_GRAVITY,
                        peak_drift: f.drift,
                        drift_ratio: f.drift_ratio,
                        ductility: f.ductility,
                        residual_drift: f.residual_drift,
                    })
                    .collect(),
            })
            .collect();
        let pairs: Vec<PairReport> = row
            .pairs()
            .iter()
            .zip(&run.pairs)
            .map(|(p, r)| PairReport {
                left: row.buildings[p.left].name.clone(),
                right: row.buildings[p.right].name.clone(),
                left_floor: p.left_floor,
                right_floor: p.right_floor,
                impacts: r.impacts.len(),
                max_force: r.max_force() / 1e3,
                max_penetration: r.max_penetration(),
            })
            .collect();
        let (bumpers, links) = retrofit_report::of(row, run);
        let retrofitted = row.is_retrofitted();
        let energy = run.energy.as_ref().map(|e| EnergyReport {
            bumper: retrofitted.then_some(e.bumper / 1e3),
            link: retrofitted.then_some(e.link / 1e3),
            ..EnergyReport::of(e)
        });
        let note = (pairs.is_empty() && row.buildings.len() > 1).then(|| {
            "no floors pair up (none at the same elevation within 1 mm, or every gap is inf): the buildings cannot pound".to_string()
        });
        RowReport {
            row: row.name.clone(),
            model: row.model.name().to_string(),
            excitation: excitation.to_string(),
            method: method.to_string(),
            duration: run.duration,
            buildings,
            pairs,
            bumpers,
            links,
            impacts: run.impacts(),
            elapsed_ms,
            cache: CacheReport {
                maps: run.maps_made,
                configurations: run.configurations,
                map_steps: run.map_steps,
                series_steps: run.series_steps,
            },
            energy,
            collapsed: row.can_collapse().then(|| {
                run.collapse.map(|c| CollapseReport {
                    building: row.buildings[c.building].name.clone(),
                    storey: c.storey,
                    time: c.time,
                })
            }),
            note,
            excitation_note: ground.note(),
        }
    }
}

impl RowReport {
    /// Whether the row reported any bumper or link (SPEC §14).
    fn is_retrofitted(&self) -> bool {
        !self.bumpers.is_empty() || !self.links.is_empty()
    }
}

/// The table's columns of a floor, top floor first: peaks in mm, m/s and
/// g, the drift ratio in %.
const FLOOR_TABLE: &[TableColumn<FloorReport>] = &[
    ("floor", 5, |f| f.floor.to_string()),
    ("u mm", 9, |f| format!("{:.2}", f.peak_displacement * 1e3)),
    ("v m/s", 8, |f| format!("{:.3}", f.peak_velocity)),
    ("A g", 8, |f| format!("{:.3}", f.peak_absolute_acceleration)),
    ("drift mm", 9, |f| format!("{:.2}", f.peak_drift * 1e3)),
    ("drift %", 9, |f| format!("{:.3}", f.drift_ratio * 100.0)),
    ("μ", 8, |f| format!("{:.3}", f.ductility)),
    ("resid mm", 9, |f| format!("{:.2}", f.residual_drift * 1e3)),
];

/// The table's columns of a floor pair.
const PAIR_TABLE: &[TableColumn<PairReport>] = &[
    ("pair", -28, |p| {
        format!(
            "{} {} – {} {}",
            p.left, p.left_floor, p.right, p.right_floor
        )
    }),
    ("impacts", 7, |p| p.impacts.to_string()),
    ("max force kN", 13, |p| format!("{:.0}", p.max_force)),
    ("penetration mm", 15, |p| {
        format!("{:.3}", p.max_penetration * 1e3)
    }),
];

impl Report for RowReport {
    fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: {} excitation, {} contact, {} method, {:.3} s",
            self.row, self.excitation, self.model, self.method, self.duration
        );
        if let Some(note) = &self.excitation_note {
            let _ = writeln!(s, "{}: {note}", self.excitation);
        }
        for b in &self.buildings {
            let t: Vec<String> = b
                .periods
                .iter()
                .take(3)
                .map(|p| format!("{p:.3}"))
                .collect();
            let _ = writeln!(s, "\n{} (T = {} s)", b.name, t.join(", "));
            if let Some(theta) = &b.stability_coefficients {
                let list: Vec<String> = theta.iter().map(|x| format!("{x:.3}")).collect();
                let _ = writeln!(s, "P-Δ: θ = P/(k h) by storey {}", list.join(", "));
            }
            s.push_str(&aligned(FLOOR_TABLE, b.floors.iter().rev()));
        }
        if !self.pairs.is_empty() {
            s.push('\n');
            s.push_str(&aligned(PAIR_TABLE, &self.pairs));
        }
        s.push_str(&retrofit_report::table(&self.bumpers, &self.links));
        if let Some(e) = &self.energy {
            let retrofit = match (e.bumper, e.link) {
                (Some(b), Some(l)) => format!(", bumper {b:.3}, link {l:.3}"),
                _ => String::new(),
            };
            let _ = writeln!(
                s,
                "\nenergy kJ: input {:.3}, kinetic {:.3}, damping {:.3}, spring {:.3}, contact {:.3}{retrofit}; residual {:.1e}",
                e.input, e.kinetic, e.damping, e.spring, e.contact, e.residual
            );
        }
        match &self.collapsed {
            Some(Some(c)) => {
                let _ = writeln!(
                    s,
                    "\ncollapsed: {} storey {} at t = {:.4} s (its drift ratio reached the collapse ratio; the peaks are those up to then)",
                    c.building, c.storey, c.time
                );
            }
            Some(None) => {
                let _ = writeln!(s, "\ncollapsed: none");
            }
            None => {}
        }
        if let Some(note) = &self.note {
            let _ = writeln!(s, "\n{note}");
        }
        let _ = writeln!(
            s,
            "\nimpacts {}   {:.3} ms   cache: {} maps for {} configurations, {} map steps, {} series steps",
            self.impacts,
            self.elapsed_ms,
            self.cache.maps,
            self.cache.configurations,
            self.cache.map_steps,
            self.cache.series_steps
        );
        s
    }

    fn csv_header(&self) -> Vec<&'static str> {
        let mut header = column_header(&["building"], FLOOR_COLUMNS);
        if self.is_retrofitted() {
            header.extend(retrofit_report::CSV_COLUMNS);
        }
        header
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        let retrofit = retrofit_report::CSV_COLUMNS.len() * usize::from(self.is_retrofitted());
        self.buildings
            .iter()
            .flat_map(|b| column_rows(std::slice::from_ref(&b.name), FLOOR_COLUMNS, &b.floors))
            .map(|mut r| {
                r.resize(r.len() + retrofit, String::new());
                r
            })
            .chain(retrofit_report::csv_rows(&self.bumpers, &self.links, 8))
            .collect()
    }
}

/// The CSV columns of a floor, after its building's name.
const FLOOR_COLUMNS: &[Column<FloorReport>] = &[
    ("floor", |f| f.floor.to_string()),
    ("peak_displacement", |f| {
        Num(f.peak_displacement).to_string()
    }),
    ("peak_velocity", |f| Num(f.peak_velocity).to_string()),
    ("peak_absolute_acceleration", |f| {
        Num(f.peak_absolute_acceleration).to_string()
    }),
    ("peak_drift", |f| Num(f.peak_drift).to_string()),
    ("drift_ratio", |f| Num(f.drift_ratio).to_string()),
    ("ductility", |f| Num(f.ductility).to_string()),
    ("residual_drift", |f| Num(f.residual_drift).to_string()),
];

/// `bench --buildings`: the work-precision rows of one row and ground motion.
#[derive(Debug, Clone, Serialize)]
pub struct RowBenchReport {
    pub row: String,
    pub excitation: String,
    pub duration: f64,
    pub rows: Vec<RowBenchRow>,
}

impl Report for RowBenchReport {
    fn table(&self) -> String {
        let s = format!(
            "{}: {} excitation, {:.3} s; error = largest peak difference (|u|, |u̇|, |Δ|) from the reference, relative per building; accel = the same for |ü + ü_g|\n",
            self.row, self.excitation, self.duration
        );
        s + &aligned(BENCH_TABLE, &self.rows)
    }

    fn csv_header(&self) -> Vec<&'static str> {
        column_header(&[], BENCH_COLUMNS)
    }

    fn csv_rows(&self) -> Vec<Vec<String>> {
        column_rows(&[], BENCH_COLUMNS, &self.rows)
    }
}

/// The table's columns of a row's work-precision row.
const BENCH_TABLE: &[TableColumn<RowBenchRow>] = &[
    ("method", -10, |r| r.method.clone()),
    ("setting", 10, |r| {
        if r.setting > 0.0 {
            format!("{:e}", r.setting)
        } else {
            "-".into()
        }
    }),
    ("error", 11, |r| format!("{:.3e}", r.error)),
    ("accel", 11, |r| format!("{:.3e}", r.acceleration_error)),
    ("ms", 9, |r| format!("{:.3}", r.ms)),
    ("impacts", 8, |r| r.impacts.to_string()),
    (" counts match", 0, |r| yes_no(r.impacts_match)),
];

/// The CSV columns of a row's work-precision row.
const BENCH_COLUMNS: &[Column<RowBenchRow>] = &[
    ("method", |r| r.method.clone()),
    ("setting", |r| Num(r.setting).to_string()),
    ("error", |r| Num(r.error).to_string()),
    ("acceleration_error", |r| {
        Num(r.acceleration_error).to_string()
    }),
    ("ms", |r| Num(r.ms).to_string()),
    ("impacts", |r| r.impacts.to_string()),
    ("impacts_match", |r| r.impacts_match.to_string()),
];
