//! Playing a run in time: the cursor moves with the wall clock, `speed`
//! seconds of motion a second, one frame every [`FRAME`]. Pure: the main
//! loop passes the time; a late frame moves the cursor further, so the
//! motion keeps its pace whatever the frame rate.

use std::time::{Duration, Instant};

/// Time between two frames while playing (25 frames a second).
pub const FRAME: Duration = Duration::from_millis(40);

/// Speeds offered, in seconds of motion per second.
pub const SPEEDS: [f64; 7] = [0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0];

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Playback {
    pub playing: bool,
    /// Index into [`SPEEDS`].
    pub speed: usize,
    /// When the cursor last moved.
    last: Option<Instant>,
}

impl Default for Playback {
    fn default() -> Self {
        Playback {
            playing: false,
            speed: 3,
            last: None,
        }
    }
}

impl Playback {
    pub fn speed(&self) -> f64 {
        SPEEDS[self.speed]
    }

    /// One speed slower or faster.
    pub fn step_speed(&mut self, faster: bool) {
        self.speed = if faster {
            (self.speed + 1).min(SPEEDS.len() - 1)
        } else {
            self.speed.saturating_sub(1)
        };
    }

    /// Plays from `now`, or pauses.
    pub fn toggle(&mut self, now: Instant) {
        self.playing = !self.playing;
        self.last = self.playing.then_some(now);
    }

    pub fn pause(&mut self) {
        self.playing = false;
        self.last = None;
    }

    /// When the next frame is due, while playing.
    pub fn due(&self) -> Option<Instant> {
        self.last.filter(|_| self.playing).map(|t| t + FRAME)
    }

    /// The cursor at `now`, from `cursor` at the last move; playing stops
    /// at `end`.
    pub fn advance(&mut self, now: Instant, cursor: f64, end: f64) -> f64 {
        let Some(last) = self.last.filter(|_| self.playing) else {
            return cursor;
        };
        self.last = Some(now);
        let next = cursor + now.saturating_duration_since(last).as_secs_f64() * self.speed();
        if next >= end {
            self.pause();
            return end;
        }
        next
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cursor_moves_with_the_clock_and_stops_at_the_end() {
        let t0 = Instant::now();
        let mut p = Playback::default();
        assert_eq!(p.due(), None);
        p.toggle(t0);
        assert_eq!(p.due(), Some(t0 + FRAME));
        // Half a second of wall time at 0.5 s a second: a quarter second.
        let c = p.advance(t0 + Duration::from_millis(500), 1.0, 10.0);
        assert!((c - 1.25).abs() < 1e-12, "{c}");
        p.step_speed(true);
        let c = p.advance(t0 + Duration::from_millis(1500), c, 10.0);
        assert!((c - 2.25).abs() < 1e-12, "{c}");
        let c = p.advance(t0 + Duration::from_secs(60), c, 10.0);
        assert_eq!(c, 10.0);
        assert!(!p.playing);
        assert_eq!(p.due(), None);
    }
}
