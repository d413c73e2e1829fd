//! The typeface every figure is drawn with: DejaVu Sans, compiled into the
//! binary (the `dejavu` crate), so text renders the same on a machine with
//! no system fonts. It covers the Greek letters and subscripts of the
//! axis labels (Π, ω, τ, μ, ξ, α).

use std::sync::Once;

use plotters::style::{FontStyle, register_font};

/// The family name the figures ask for; the SVG names it too, so a viewer
/// without DejaVu falls back to its own sans-serif.
pub const FAMILY: &str = "sans-serif";

/// Registers the embedded font with plotters (once per process).
pub fn register() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TrueType file shipped by the crate; a
        // failure here would be a packaging error, and the text would then
        // be missing rather than the program aborting.
        let _ = register_font(FAMILY, FontStyle::Normal, dejavu::sans::regular());
        let _ = register_font(FAMILY, FontStyle::Bold, dejavu::sans::bold());
    });
}
