//! Running envelopes of a row (SPEC §13): per floor |u|, |u̇|, |ü + ü_g|, per
//! storey |Δ|; updated at every accepted point and at every turning point
//! located inside a step.

#[derive(Debug, Clone)]
pub struct Envelope {
    pub displacement: Vec<f64>,
    pub velocity: Vec<f64>,
    pub acceleration: Vec<f64>,
    pub drift: Vec<f64>,
    /// max over time of u_A − u_B at each facing floor pair (signed).
    pub relative: Vec<f64>,
}

impl Envelope {
    pub fn new(dofs: usize, storeys: usize, facing: usize) -> Envelope {
        Envelope {
            displacement: vec![0.0; dofs],
            velocity: vec![0.0; dofs],
            acceleration: vec![0.0; dofs],
            drift: vec![0.0; storeys],
            relative: vec![0.0; facing],
        }
    }
}

#[inline]
pub fn raise(peak: &mut f64, value: f64) {
    if value.abs() > *peak {
        *peak = value.abs();
    }
}
