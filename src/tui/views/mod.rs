//! One file per part of the screen; each is a pure function of the state.

pub mod chart;
pub mod compact;
pub mod history;
pub mod impacts;
pub mod laws;
pub mod loops;
pub mod map;
pub mod overlay;
pub mod params;
pub mod raster;
pub mod risk;
pub mod row;
pub mod row_drawing;
pub mod row_panel;
pub mod row_params;
pub mod row_retrofit;
pub mod sets;
pub mod spectrum;
pub mod summary;
pub mod ticks;
pub mod units;
