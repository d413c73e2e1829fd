//! Accuracy and speed, measured against the independent reference.
//!
//! - [`method`]: the schemes compared (Newmark plain, located, sub-stepped in
//!   contact; the reference at a given tolerance);
//! - [`timing`]: median wall time per run, warm-up excluded;
//! - [`work_precision`]: the rows of `pounding bench` (time against error
//!   measured on the reference at its tightest tolerance, observed order);
//! - [`plot`]: error against time on log–log axes in Braille;
//! - [`stress`]: the corner and random cases of `pounding stress` and the
//!   invariants each must keep;
//! - [`random`]: a small seeded generator for the random cases;
//! - [`floor`] and [`record_speed`]: the exact method under a record against
//!   the plain Nigam–Jennings pass over its samples (`bench --excitation`);
//! - [`row_floor`] and [`row_speed`]: a row run against the dense pass of
//!   its elastic state map over the same pieces, with the run's profile.

pub mod figure_spectra;
pub mod floor;
pub mod method;
pub mod plot;
pub mod random;
pub mod record_speed;
pub mod row_bench;
pub mod row_floor;
pub mod row_speed;
pub mod stress;
pub mod timing;
pub mod work_precision;
