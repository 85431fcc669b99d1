//! [`FixedClock`]: the fixed-step accumulator behind `on_fixed_update`.

use onyx_plugin_api::Time;

use super::ClockSettings;

/// Slack when dividing the accumulator into steps, so that adding `1/hz` exactly `hz` times
/// yields `hz` steps despite rounding.
const STEP_EPSILON: f64 = 1e-9;

/// Turns real frame times into a whole number of fixed steps per frame, with pause, single
/// step, time scale and a cap on steps per frame.
#[derive(Clone, Debug)]
pub struct FixedClock {
    settings: ClockSettings,
    fixed_delta: f64,
    accumulator: f64,
    total: f64,
    delta: f64,
    real_total: f64,
    real_delta: f64,
    ticks: u64,
    frame: u64,
    steps_this_frame: u32,
    dropped_steps: u64,
    paused: bool,
    step_requests: u32,
}

impl FixedClock {
    /// A clock with `settings` (invalid values fall back to the defaults, with a warning).
    pub fn new(mut settings: ClockSettings) -> Self {
        let defaults = ClockSettings::default();
        if !(settings.fixed_hz.is_finite() && settings.fixed_hz > 0.0) {
            tracing::warn!(
                fixed_hz = settings.fixed_hz,
                "invalid fixed rate; using 60 Hz"
            );
            settings.fixed_hz = defaults.fixed_hz;
        }
        if settings.max_steps_per_frame == 0 {
            settings.max_steps_per_frame = 1;
        }
        if !(settings.time_scale.is_finite() && settings.time_scale >= 0.0) {
            settings.time_scale = defaults.time_scale;
        }
        Self {
            fixed_delta: 1.0 / settings.fixed_hz,
            settings,
            accumulator: 0.0,
            total: 0.0,
            delta: 0.0,
            real_total: 0.0,
            real_delta: 0.0,
            ticks: 0,
            frame: 0,
            steps_this_frame: 0,
            dropped_steps: 0,
            paused: false,
            step_requests: 0,
        }
    }

    /// Starts a frame that took `real_dt` seconds: returns how many fixed steps to run.
    pub fn begin_frame(&mut self, real_dt: f64) -> u32 {
        let real_dt = if real_dt.is_finite() {
            real_dt.clamp(0.0, self.settings.max_frame_time)
        } else {
            0.0
        };
        self.real_delta = real_dt;
        self.real_total += real_dt;
        let max = self.settings.max_steps_per_frame;
        let steps = if self.paused {
            self.delta = 0.0;
            std::mem::take(&mut self.step_requests).min(max)
        } else {
            self.delta = real_dt * f64::from(self.settings.time_scale);
            self.accumulator += self.delta;
            let due = (self.accumulator / self.fixed_delta + STEP_EPSILON).floor();
            let due = if due > f64::from(u32::MAX) {
                u32::MAX
            } else {
                due as u32
            };
            let extra = std::mem::take(&mut self.step_requests);
            let wanted = due.saturating_add(extra);
            if wanted > max {
                self.dropped_steps += u64::from(wanted - max);
                // Keep only the fraction of a step: the excess time is dropped.
                self.accumulator = self.accumulator.rem_euclid(self.fixed_delta);
            } else {
                self.accumulator = (self.accumulator - f64::from(due) * self.fixed_delta).max(0.0);
            }
            wanted.min(max)
        };
        self.total += self.delta;
        self.steps_this_frame = steps;
        steps
    }

    /// Real time since the clock started and this frame's real time, seconds: neither
    /// scaled nor paused (a paused scene's editor still animates, flies and double-clicks).
    pub fn real_time(&self) -> (f64, f32) {
        (self.real_total, self.real_delta as f32)
    }

    /// Marks one fixed step as done.
    pub fn tick(&mut self) {
        self.ticks += 1;
    }

    /// Ends the frame.
    pub fn end_frame(&mut self) {
        self.frame += 1;
    }

    /// The clock as plugins see it.
    pub fn time(&self) -> Time {
        Time {
            delta: self.delta as f32,
            fixed_delta: self.fixed_delta as f32,
            total: self.total,
            ticks: self.ticks,
            frame: self.frame,
            fixed_steps_this_frame: self.steps_this_frame,
            alpha: (self.accumulator / self.fixed_delta).clamp(0.0, 1.0) as f32,
            time_scale: self.settings.time_scale,
            paused: self.paused,
        }
    }

    /// Length of one fixed step, seconds.
    pub fn fixed_delta(&self) -> f64 {
        self.fixed_delta
    }

    /// Fixed steps dropped so far by the per-frame cap.
    pub fn dropped_steps(&self) -> u64 {
        self.dropped_steps
    }

    /// Pauses or resumes.
    pub fn set_paused(&mut self, paused: bool) {
        self.paused = paused;
    }

    /// Whether paused.
    pub fn paused(&self) -> bool {
        self.paused
    }

    /// Asks for one extra fixed step next frame (runs even while paused).
    pub fn step_once(&mut self) {
        self.step_requests = self.step_requests.saturating_add(1);
    }

    /// Sets the time scale; `false` if `scale` is negative or not finite.
    pub fn set_time_scale(&mut self, scale: f32) -> bool {
        if scale.is_finite() && scale >= 0.0 {
            self.settings.time_scale = scale;
            true
        } else {
            false
        }
    }

    /// Sets the fixed step rate (a scene's physics preset does); `false` if `hz` is not
    /// finite and positive. Time already accumulated carries over to the new step length.
    pub fn set_fixed_hz(&mut self, hz: f64) -> bool {
        if hz.is_finite() && hz > 0.0 {
            self.settings.fixed_hz = hz;
            self.fixed_delta = 1.0 / hz;
            true
        } else {
            false
        }
    }

    /// The settings in force.
    pub fn settings(&self) -> &ClockSettings {
        &self.settings
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clock(hz: f64, cap: u32) -> FixedClock {
        FixedClock::new(ClockSettings {
            fixed_hz: hz,
            max_steps_per_frame: cap,
            ..Default::default()
        })
    }

    fn run(clock: &mut FixedClock, dt: f64, frames: usize) -> Vec<u32> {
        (0..frames)
            .map(|_| {
                let n = clock.begin_frame(dt);
                for _ in 0..n {
                    clock.tick();
                }
                clock.end_frame();
                n
            })
            .collect()
    }

    #[test]
    fn frames_at_the_fixed_rate_run_one_step_each() {
        let mut c = clock(60.0, 8);
        assert_eq!(run(&mut c, 1.0 / 60.0, 600), vec![1; 600]);
        assert_eq!(c.time().ticks, 600);
    }

    #[test]
    fn thirty_hz_frames_run_two_steps_and_120_hz_frames_alternate() {
        let mut c = clock(60.0, 8);
        assert_eq!(run(&mut c, 1.0 / 30.0, 10), vec![2; 10]);
        let mut c = clock(60.0, 8);
        let steps = run(&mut c, 1.0 / 120.0, 10);
        assert_eq!(steps.iter().sum::<u32>(), 5, "{steps:?}");
        assert!(steps.iter().all(|&s| s <= 1), "{steps:?}");
        assert!((c.time().alpha - 0.0).abs() < 1e-6 || (c.time().alpha - 0.5).abs() < 1e-6);
    }

    #[test]
    fn one_second_of_uneven_frames_runs_sixty_steps() {
        let mut c = clock(60.0, 8);
        let pattern = [0.010, 0.020, 0.013, 0.007, 0.0166, 0.0334];
        let mut elapsed = 0.0;
        let mut steps = 0;
        let mut i = 0;
        while elapsed + pattern[i % pattern.len()] <= 1.0 + 1e-12 {
            let dt = pattern[i % pattern.len()];
            elapsed += dt;
            steps += c.begin_frame(dt);
            i += 1;
        }
        let expected = (elapsed * 60.0 + 1e-9).floor() as u32;
        assert_eq!(steps, expected, "elapsed {elapsed}");
    }

    #[test]
    fn a_long_frame_is_capped_and_the_excess_dropped() {
        let mut c = clock(60.0, 4);
        assert_eq!(c.begin_frame(0.2), 4, "0.2 s = 12 steps, capped at 4");
        assert_eq!(c.dropped_steps(), 8);
        assert!(c.time().alpha < 1.0);
        assert_eq!(c.begin_frame(1.0 / 60.0), 1, "no backlog after the cap");
    }

    #[test]
    fn frames_longer_than_max_frame_time_count_as_max_frame_time() {
        let mut c = FixedClock::new(ClockSettings {
            max_steps_per_frame: 1000,
            ..Default::default()
        });
        assert_eq!(c.begin_frame(10.0), 15, "clamped to 0.25 s");
    }

    #[test]
    fn pause_stops_steps_and_step_once_runs_exactly_one() {
        let mut c = clock(60.0, 8);
        c.set_paused(true);
        assert_eq!(run(&mut c, 1.0 / 30.0, 5), vec![0; 5]);
        assert_eq!(c.time().delta, 0.0);
        c.step_once();
        assert_eq!(run(&mut c, 1.0 / 30.0, 2), vec![1, 0]);
        c.set_paused(false);
        assert_eq!(run(&mut c, 1.0 / 30.0, 1), vec![2]);
    }

    #[test]
    fn time_scale_scales_steps_and_total() {
        let mut c = clock(60.0, 8);
        assert!(c.set_time_scale(2.0));
        assert_eq!(run(&mut c, 1.0 / 60.0, 30), vec![2; 30]);
        assert!((c.time().total - 1.0).abs() < 1e-9);
        assert!(!c.set_time_scale(f32::NAN));
        assert!(!c.set_time_scale(-1.0));
        assert!(c.set_time_scale(0.0));
        assert_eq!(run(&mut c, 1.0 / 60.0, 3), vec![0; 3]);
    }

    #[test]
    fn real_time_runs_on_while_paused_or_scaled() {
        let mut c = clock(60.0, 8);
        c.set_paused(true);
        run(&mut c, 0.1, 3);
        assert!(c.set_time_scale(0.5));
        c.set_paused(false);
        run(&mut c, 0.1, 2);
        let (total, delta) = c.real_time();
        assert!((total - 0.5).abs() < 1e-9, "{total}");
        assert!((delta - 0.1).abs() < 1e-6);
        assert!(
            (c.time().total - 0.1).abs() < 1e-9,
            "scaled time only while running"
        );
    }

    #[test]
    fn invalid_settings_fall_back_to_defaults() {
        let c = clock(f64::NAN, 0);
        assert_eq!(c.settings().fixed_hz, 60.0);
        assert_eq!(c.settings().max_steps_per_frame, 1);
    }

    #[test]
    fn non_finite_frame_times_count_as_zero() {
        let mut c = clock(60.0, 8);
        assert_eq!(c.begin_frame(f64::NAN), 0);
        assert_eq!(c.begin_frame(f64::INFINITY), 0);
        assert_eq!(c.begin_frame(-1.0), 0);
    }
}
