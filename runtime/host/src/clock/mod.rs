//! Time: the fixed-step clock.
//!
//! - `clock_settings.rs`: [`ClockSettings`], rate, cap, time scale.
//! - `fixed_clock.rs`: [`FixedClock`], the accumulator.

mod clock_settings;
mod fixed_clock;

pub use clock_settings::ClockSettings;
pub use fixed_clock::FixedClock;

#[cfg(test)]
mod tests {
    /// The defaults documented on each field of `ClockSettings`.
    #[test]
    fn documented_defaults_match_default() {
        let d = super::ClockSettings::default();
        assert_eq!(d.fixed_hz, 60.0);
        assert_eq!(d.max_steps_per_frame, 8);
        assert_eq!(d.max_frame_time, 0.25);
        assert_eq!(d.time_scale, 1.0);
    }
}
