//! Independent reference solution (issue 5): an adaptive high-order integrator with event location, sharing no code path with the Newmark solver.
