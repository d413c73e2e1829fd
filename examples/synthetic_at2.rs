//! Writes the shipped synthetic record: `cargo run --example synthetic_at2 > presets/synthetic.at2`.
fn main() {
    print!("{}", pounding::model::synthetic::at2_text());
}
