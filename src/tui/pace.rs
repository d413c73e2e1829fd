//! When to draw. Every frame costs bytes on a slow link, so a frame is drawn
//! for what the user would see, not for every step of a computation:
//!
//! - a job that ends within [`GRACE`] of its start is drawn once, with the
//!   input that asked for it: no frame shows "computing…" and then, a few
//!   milliseconds later, the result (a nudge is one frame, not two or three);
//! - a longer job (a map, a spectrum) shows "computing…" and its progress
//!   from [`GRACE`] on, at most once per [`PERIOD`], and its end at once;
//! - input while a long job runs is drawn at once (the keys stay live).
//!
//! Pure: the main loop passes the time and whether a job runs.

use std::time::{Duration, Instant};

/// How long a new job may take before the screen says it is computing.
pub const GRACE: Duration = Duration::from_millis(100);

/// Least time between two frames of a running job's progress.
pub const PERIOD: Duration = Duration::from_millis(250);

/// What the main loop does next.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Step {
    /// Draw a frame now.
    Draw,
    /// Wait for an event until then, and ask again.
    WaitUntil(Instant),
    /// Nothing to draw: wait for the next event.
    Sleep,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Hold {
    None,
    /// A job just started: nothing is drawn before this, unless it ends.
    Grace(Instant),
    /// Progress was just drawn: the next progress frame waits until this.
    Period(Instant),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pace {
    /// Something changed since the last frame.
    dirty: bool,
    /// The change came from the user (keys, mouse, resize, an effect's end).
    urgent: bool,
    hold: Hold,
}

impl Default for Pace {
    fn default() -> Self {
        Pace {
            dirty: true,
            urgent: false,
            hold: Hold::None,
        }
    }
}

impl Pace {
    /// The user did something.
    pub fn input(&mut self) {
        self.dirty = true;
        self.urgent = true;
    }

    /// A running job reported results.
    pub fn progress(&mut self) {
        self.dirty = true;
    }

    /// A job started at `now` while none was running: the change that
    /// started it waits for its result, up to [`GRACE`].
    pub fn started(&mut self, now: Instant) {
        self.hold = Hold::Grace(now + GRACE);
        self.urgent = false;
    }

    /// What to do at `now`, with a job running or not.
    pub fn next(&mut self, now: Instant, computing: bool) -> Step {
        if !self.dirty {
            return Step::Sleep;
        }
        if computing {
            match self.hold {
                Hold::Grace(t) if now < t => return Step::WaitUntil(t),
                Hold::Period(t) if now < t && !self.urgent => return Step::WaitUntil(t),
                _ => {}
            }
        }
        self.dirty = false;
        self.urgent = false;
        self.hold = if computing {
            Hold::Period(now + PERIOD)
        } else {
            Hold::None
        };
        Step::Draw
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MS: Duration = Duration::from_millis(1);

    #[test]
    fn a_quick_job_is_drawn_once_with_the_key_that_asked_for_it() {
        let t0 = Instant::now();
        let mut p = Pace::default();
        assert_eq!(p.next(t0, false), Step::Draw);
        // A nudge starts a job: nothing is drawn while it runs...
        p.input();
        p.started(t0);
        assert_eq!(p.next(t0, true), Step::WaitUntil(t0 + GRACE));
        // ...not even when its run arrives before its end...
        p.progress();
        assert_eq!(p.next(t0 + 5 * MS, true), Step::WaitUntil(t0 + GRACE));
        // ...and its end draws one frame.
        p.progress();
        assert_eq!(p.next(t0 + 6 * MS, false), Step::Draw);
        assert_eq!(p.next(t0 + 7 * MS, false), Step::Sleep);
    }

    #[test]
    fn a_long_job_shows_progress_at_most_once_a_period_and_keys_at_once() {
        let t0 = Instant::now();
        let mut p = Pace::default();
        p.input();
        p.started(t0);
        assert_eq!(p.next(t0 + 10 * MS, true), Step::WaitUntil(t0 + GRACE));
        // The grace ends with the job still running: it says so.
        assert_eq!(p.next(t0 + GRACE, true), Step::Draw);
        let t1 = t0 + GRACE;
        p.progress();
        assert_eq!(p.next(t1 + MS, true), Step::WaitUntil(t1 + PERIOD));
        assert_eq!(p.next(t1 + PERIOD, true), Step::Draw);
        // A key during the job is drawn at once.
        let t2 = t1 + PERIOD;
        p.input();
        assert_eq!(p.next(t2 + MS, true), Step::Draw);
        // Nothing new: nothing drawn, whatever the time.
        assert_eq!(p.next(t2 + 10 * PERIOD, true), Step::Sleep);
        // The end is drawn at once.
        p.progress();
        assert_eq!(p.next(t2 + 2 * MS, false), Step::Draw);
    }
}
