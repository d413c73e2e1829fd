//! A progress bar with a time estimate on stderr, for work estimated at
//! over a second, and only when stderr is a terminal (never in a pipe or a log).
//!
//! Without the `app` feature (the commands built for the Python module)
//! there is no terminal to draw on, and no bar is ever shown.

#[cfg(feature = "app")]
use indicatif::ProgressBar;

use super::budget::Work;
use crate::solver::{Observer, Sample};

/// Work estimated below this many seconds gets no bar.
pub const SHOW_ABOVE_SECONDS: f64 = 1.0;

/// Without a terminal front end there is no bar: a type with no values.
#[cfg(not(feature = "app"))]
enum ProgressBar {}

#[cfg(not(feature = "app"))]
impl ProgressBar {
    fn set_position(&self, _: u64) {
        match *self {}
    }
    fn inc(&self, _: u64) {
        match *self {}
    }
    fn finish_and_clear(&self) {
        match *self {}
    }
}

/// Progress in steps of a request; hidden when not shown.
pub struct Progress {
    bar: Option<ProgressBar>,
}

impl Progress {
    /// A bar for `work` if it is worth one and stderr is a terminal.
    pub fn start(work: &Work) -> Progress {
        Progress { bar: bar_for(work) }
    }

    pub fn is_shown(&self) -> bool {
        self.bar.is_some()
    }

    /// `steps` of the work are done.
    pub fn set(&self, steps: f64) {
        if let Some(bar) = &self.bar {
            bar.set_position(steps as u64);
        }
    }

    /// `steps` more of the work are done.
    pub fn add(&self, steps: f64) {
        if let Some(bar) = &self.bar {
            bar.inc(steps as u64);
        }
    }
}

#[cfg(feature = "app")]
fn bar_for(work: &Work) -> Option<ProgressBar> {
    use indicatif::{ProgressDrawTarget, ProgressStyle};
    use std::io::IsTerminal;
    let show = work.seconds() > SHOW_ABOVE_SECONDS && std::io::stderr().is_terminal();
    show.then(|| {
        let bar = ProgressBar::with_draw_target(
            Some(work.steps.max(1.0) as u64),
            ProgressDrawTarget::stderr_with_hz(4),
        );
        if let Ok(style) = ProgressStyle::with_template(
            "{elapsed:>4} [{wide_bar}] {percent:>3}%  about {eta} left",
        ) {
            bar.set_style(style.progress_chars("=> "));
        }
        bar.enable_steady_tick(std::time::Duration::from_millis(250));
        bar
    })
}

#[cfg(not(feature = "app"))]
fn bar_for(_: &Work) -> Option<ProgressBar> {
    None
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// An observer that tells a [`Progress`] how far its run has come, then
/// passes every state on to `inner`.
pub struct Tracked<'a, O> {
    pub inner: O,
    progress: &'a Progress,
    /// Steps done before this run.
    offset: f64,
    /// Steps of work per unit τ ([`super::budget::steps_per_tau`]).
    rate: f64,
    tau: f64,
}

impl<'a, O: Observer> Tracked<'a, O> {
    pub fn new(inner: O, progress: &'a Progress, offset: f64, rate: f64) -> Self {
        Tracked {
            inner,
            progress,
            offset,
            rate,
            tau: 0.0,
        }
    }
}

impl<O: Observer> Observer for Tracked<'_, O> {
    const RECORDS: bool = O::RECORDS;

    fn reached(&mut self, tau: f64) {
        self.tau = tau;
        self.inner.reached(tau);
    }

    #[inline]
    fn record(&mut self, sample: &Sample) {
        self.tau = sample.tau;
        self.inner.record(sample);
    }

    fn keep_going(&mut self) -> bool {
        self.progress.set(self.offset + self.tau * self.rate);
        self.inner.keep_going()
    }
}
