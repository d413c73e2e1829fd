//! Which time integrator a run uses. Both share the model (parameters,
//! springs, contact laws, excitation), the observers and [`RunResult`]; they
//! share no stepping code.
//!
//! - [`Method::Newmark`]: Newmark-β (γ = 1/2, β = 1/4, SPEC §5) at Δτ, the
//!   paper's method, with located contact and sub-steps in contact.
//! - [`Method::Exact`]: event-driven. Out of contact each structure follows
//!   its closed-form response on its current branch of the bilinear law
//!   (SPEC §2–3); contact phases are integrated by a high-order Taylor
//!   series whose error is controlled on the contact's own scale.
//!
//! It lives in the model, beside Δτ, because a parameter set names it.
//!
//! [`RunResult`]: crate::solver::RunResult

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// A production time integrator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Newmark-β at Δτ (the paper's method; default of single runs).
    #[default]
    Newmark,
    /// Event-driven, closed form out of contact (default of everything that runs many cases).
    Exact,
}

impl Method {
    pub const ALL: [Method; 2] = [Method::Newmark, Method::Exact];

    pub fn name(self) -> &'static str {
        match self {
            Method::Newmark => "newmark",
            Method::Exact => "exact",
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.trim() {
            "newmark" => Ok(Method::Newmark),
            "exact" => Ok(Method::Exact),
            other => Err(format!(
                "unknown method `{other}`: must be `newmark` or `exact`"
            )),
        }
    }
}
