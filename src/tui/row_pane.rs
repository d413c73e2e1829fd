//! The buildings scene's state: the row preset and the edits made to it,
//! the ground it stands on, and how it is shown (time cursor, playback,
//! exaggeration, side panel, Kelvin against improved Kelvin). Edits are
//! `--set KEY=V` strings applied to the preset's text, so a value refused
//! here is refused with the CLI's own line, and the previous row stays.

use std::sync::Arc;
use std::time::Instant;

use super::fields::StepSize;
use super::playback::Playback;
use super::row_fields::{self, RowField};
use super::row_job::{self, RowSpec};
use crate::model::ContactModel;
use crate::model::buildings::matrices::default_tail;
use crate::model::buildings::{Ground, Row, edit, load};

/// What the panel beside the drawing shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Panel {
    /// Peak floor displacement over height, with and without pounding.
    Displacement,
    /// Peak storey drift ratio over height.
    DriftRatio,
    /// Peak floor absolute acceleration over height.
    Acceleration,
    /// The impacts of the row: pair, floor, time, force.
    Impacts,
}

impl Panel {
    pub fn next(self) -> Panel {
        match self {
            Panel::Displacement => Panel::DriftRatio,
            Panel::DriftRatio => Panel::Acceleration,
            Panel::Acceleration => Panel::Impacts,
            Panel::Impacts => Panel::Displacement,
        }
    }
}

/// The row explored, and its view.
#[derive(Debug, Clone)]
pub struct RowPane {
    /// The preset as named (a built-in name or a path).
    pub source: String,
    /// The file messages name.
    file: String,
    text: String,
    /// `--set` edits in the order made (a key edited again is replaced).
    pub edits: Vec<(String, String)>,
    /// The row with the edits applied.
    pub row: Row,
    pub ground: Arc<Ground>,
    /// The ground's name (`synthetic:2000`, `record:PATH`, `sine`).
    pub ground_name: String,
    /// Free vibration after the ground (s); `None`: four fundamental periods.
    pub tail: Option<f64>,
    /// Selected pane row.
    pub selected: usize,
    /// Time cursor (s).
    pub cursor: f64,
    pub play: Playback,
    /// Factor on displacements in the drawing; `None`: chosen from the peaks.
    pub exaggeration: Option<f64>,
    /// Kelvin and improved Kelvin drawn side by side.
    pub side_by_side: bool,
    /// The envelopes' grey line is the row without its retrofits (SPEC
    /// §14) rather than the row without pounding.
    pub bare: bool,
    pub panel: Panel,
}

impl RowPane {
    /// The row preset `source` under `ground`; the preset's one-line error otherwise.
    pub fn open(
        source: &str,
        ground: Arc<Ground>,
        ground_name: &str,
        tail: Option<f64>,
    ) -> Result<RowPane, String> {
        let (file, text) = load::text_of(source).map_err(|e| e.to_string())?;
        let row = edit::parse_with(&file, &text, &[]).map_err(|e| e.to_string())?;
        let pane = RowPane {
            source: source.to_string(),
            file,
            text,
            edits: Vec::new(),
            row,
            ground,
            ground_name: ground_name.to_string(),
            tail,
            selected: 0,
            cursor: 0.0,
            play: Playback::default(),
            exaggeration: None,
            side_by_side: false,
            bare: false,
            panel: Panel::Displacement,
        };
        pane.check(&pane.row)?;
        Ok(pane)
    }

    /// The same ground and view on another preset.
    pub fn reopen(&self, source: &str) -> Result<RowPane, String> {
        let mut next = RowPane::open(source, self.ground.clone(), &self.ground_name, self.tail)?;
        next.side_by_side = self.side_by_side;
        next.bare = self.bare;
        next.panel = self.panel;
        next.play.speed = self.play.speed;
        Ok(next)
    }

    /// The name shown for the row.
    pub fn name(&self) -> &str {
        &self.row.name
    }

    /// The run's length (s).
    pub fn duration(&self) -> f64 {
        self.duration_of(&self.row)
    }

    fn duration_of(&self, row: &Row) -> f64 {
        self.ground.end() + self.tail.unwrap_or_else(|| default_tail(row))
    }

    /// The pane's rows.
    pub fn fields(&self) -> Vec<RowField> {
        row_fields::fields(&self.row)
    }

    /// The laws run with pounding: the row's own, and beside it the other
    /// of the Kelvin pair when side by side.
    pub fn laws(&self) -> Vec<ContactModel> {
        let own = self.row.model;
        let mut laws = vec![own];
        if self.side_by_side {
            laws.push(own.toggled());
        }
        laws
    }

    /// What the scene asks the worker for.
    pub fn spec(&self) -> RowSpec {
        RowSpec {
            row: self.row.clone(),
            ground: self.ground.clone(),
            duration: self.duration(),
            laws: self.laws(),
            bare: self.bare && self.row.is_retrofitted(),
        }
    }

    /// Refuses a row the explorer would wait on too long.
    fn check(&self, row: &Row) -> Result<(), String> {
        let spec = RowSpec {
            row: row.clone(),
            ground: self.ground.clone(),
            duration: self.duration_of(row),
            laws: self.laws(),
            bare: self.bare && row.is_retrofitted(),
        };
        let seconds = spec.seconds();
        if seconds > row_job::MAX_SECONDS {
            return Err(format!(
                "{}: {} floors{} over {:.0} s would take about {seconds:.1} s a change: at most {} s in the explorer (pounding run --buildings takes it)",
                self.file,
                row.dofs(),
                if row.has_fluid_damper() {
                    " with a fluid viscous damper"
                } else {
                    ""
                },
                spec.duration,
                row_job::MAX_SECONDS
            ));
        }
        Ok(())
    }

    /// Applies `edits` (`--set` keys and values): the new row, or the CLI's
    /// one line on why not, with the row unchanged.
    pub fn apply(&mut self, edits: Vec<(String, String)>) -> Result<(), String> {
        let mut all = self.edits.clone();
        for (key, value) in edits {
            all.retain(|(k, _)| *k != key);
            all.push((key, value));
        }
        let sets: Vec<String> = all.iter().map(|(k, v)| format!("{k}={v}")).collect();
        let row = edit::parse_with(&self.file, &self.text, &sets).map_err(|e| e.to_string())?;
        self.check(&row)?;
        self.cursor = self.cursor.min(self.duration_of(&row));
        self.row = row;
        self.edits = all;
        Ok(())
    }

    /// Typed text for the selected row: a storey count resizes the lists.
    pub fn type_value(&mut self, text: &str) -> Result<(), String> {
        let fields = self.fields();
        let field = &fields[self.selected.min(fields.len() - 1)];
        let text = text.trim();
        let edits = match field.kind {
            row_fields::Kind::Storeys(i) => match text.parse::<usize>() {
                Ok(n) if n >= 1 => row_fields::storeys_edits(&self.row, i, n),
                _ => vec![(field.key.clone(), text.to_string())],
            },
            row_fields::Kind::Law => vec![(field.key.clone(), format!("\"{text}\""))],
            _ => vec![(field.key.clone(), text.to_string())],
        };
        self.apply(edits)
    }

    /// One nudge of the selected row.
    pub fn nudge(&mut self, direction: f64, size: StepSize) -> Result<(), String> {
        let fields = self.fields();
        let field = &fields[self.selected.min(fields.len() - 1)];
        match row_fields::nudged(&self.row, field, direction, size) {
            Some(edits) => self.apply(edits),
            None => Err(format!(
                "`{}` is inf: press Enter to type a finite value",
                field.key
            )),
        }
    }

    /// Back to the preset as loaded.
    pub fn reset(&mut self) {
        self.edits.clear();
        self.row = edit::parse_with(&self.file, &self.text, &[]).expect("the preset was checked");
        self.cursor = self.cursor.min(self.duration());
    }

    /// Whether the row differs from its preset.
    pub fn modified(&self) -> bool {
        !self.edits.is_empty()
    }

    /// Space: plays from the cursor (from 0 when it stands at the end), or pauses.
    pub fn toggle_play(&mut self, now: Instant) {
        if !self.play.playing && self.cursor >= self.duration() {
            self.cursor = 0.0;
        }
        self.play.toggle(now);
    }

    /// Moves the cursor with the clock while playing; whether it moved.
    pub fn tick(&mut self, now: Instant) -> bool {
        if !self.play.playing {
            return false;
        }
        let end = self.duration();
        self.cursor = self.play.advance(now, self.cursor, end);
        true
    }

    /// Moves the cursor by `steps` of `1/columns` of the run.
    pub fn move_cursor(&mut self, steps: f64, columns: u16) {
        let end = self.duration();
        let step = end / f64::from(columns.max(1));
        self.cursor = (self.cursor + steps * step).clamp(0.0, end);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pane() -> RowPane {
        let ground = Ground::sine(3.0, 6.0, 5.0);
        RowPane::open("block-and-frame", Arc::new(ground), "sine", None).unwrap()
    }

    #[test]
    fn a_refused_edit_says_the_clis_line_and_keeps_the_row() {
        let mut p = pane();
        let before = p.row.clone();
        let stiffness = p
            .fields()
            .iter()
            .position(|f| f.key == "frame.stiffness")
            .unwrap();
        p.selected = stiffness;
        let e = p.type_value("-1").unwrap_err();
        let cli = load::load_with("block-and-frame", &["frame.stiffness=-1".into()])
            .unwrap_err()
            .to_string();
        assert_eq!(e, cli);
        assert_eq!(p.row, before);
        p.selected = 2;
        let e = p.type_value("0").unwrap_err();
        assert!(e.contains("storeys"), "{e}");
        assert_eq!(p.row, before);
        assert!(!p.modified());
        p.type_value("5").unwrap();
        assert_eq!(p.row.buildings[0].storeys(), 5);
        assert!(p.modified());
        p.reset();
        assert_eq!(p.row, before);
    }

    #[test]
    fn a_row_too_large_for_the_explorer_is_refused() {
        let mut p = pane();
        p.selected = p
            .fields()
            .iter()
            .position(|f| f.key == "frame.storeys")
            .unwrap();
        let e = p.type_value("200").unwrap_err();
        assert!(e.contains("at most 2 s in the explorer"), "{e}");
        assert_eq!(p.row.buildings[1].storeys(), 8);
    }

    /// A fluid viscous damper takes the exact method's series and collocated
    /// steps for the whole run, some 25 times the linear row's map: over the
    /// explorer's budget under a record twice as long as its default one
    /// (60 s, about 5 s of runs), and said so.
    #[test]
    fn a_fluid_damper_is_refused_as_too_slow_and_named() {
        let ground = Ground::sine(3.0, 6.0, 60.0);
        let mut p =
            RowPane::open("block-and-frame-retrofit", Arc::new(ground), "sine", None).unwrap();
        let before = p.row.clone();
        let e = p
            .apply(vec![("link1.exponent".into(), "0.35".into())])
            .unwrap_err();
        assert!(e.contains("with a fluid viscous damper"), "{e}");
        assert!(e.contains("at most 2 s in the explorer"), "{e}");
        assert_eq!(p.row, before);
        p.apply(vec![("link1.exponent".into(), "0.9999".into())])
            .unwrap_err();
        p.apply(vec![("link1.exponent".into(), "1".into())])
            .unwrap();
    }
}
