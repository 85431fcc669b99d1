//! [`StepCounters`]: timings and work counts of the last step (for a diagnostics panel).

use std::time::Duration;

/// Durations of each stage and counts of the work done in the last step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepCounters {
    /// Whole step.
    pub total: Duration,
    /// Proxy updates and new-pair search.
    pub broadphase: Duration,
    /// Contact generation.
    pub narrowphase: Duration,
    /// Constraint setup and the substep loop (includes integration inside substeps).
    pub solve: Duration,
    /// Writing poses back, bounds refresh, NaN checks.
    pub integrate: Duration,
    /// Continuous collision (time of impact).
    pub ccd: Duration,
    /// Island building and sleeping.
    pub sleep: Duration,
    /// Awake (simulated) dynamic and kinematic bodies.
    pub awake_bodies: u32,
    /// Broadphase pairs alive (overlapping fat boxes).
    pub pairs: u32,
    /// New pairs found this step.
    pub new_pairs: u32,
    /// Contact manifolds solved.
    pub manifolds: u32,
    /// Pairs whose manifolds were refreshed (bodies barely moved) instead of regenerated.
    pub reused_pairs: u32,
    /// Contact points solved.
    pub contacts: u32,
    /// Joints solved.
    pub joints: u32,
    /// GJK runs.
    pub gjk_calls: u32,
    /// GJK iterations summed.
    pub gjk_iterations: u32,
    /// GJK runs that hit their iteration cap.
    pub gjk_not_converged: u32,
    /// EPA runs.
    pub epa_calls: u32,
    /// EPA iterations summed.
    pub epa_iterations: u32,
    /// EPA runs that failed to converge or were degenerate (fallback used).
    pub epa_failures: u32,
    /// Bodies moved back by continuous collision.
    pub ccd_hits: u32,
    /// CCD searches that hit their iteration cap.
    pub ccd_not_converged: u32,
    /// Free-rotation (midpoint) solves that hit their iteration cap, summed over substeps.
    pub gyro_not_converged: u32,
    /// Bodies clamped to a speed cap this step (every time; `StepOutput::speed_caps` names
    /// each body and cap once).
    pub speed_capped: u32,
    /// Islands put to sleep this step.
    pub islands_slept: u32,
    /// Bodies quarantined this step.
    pub quarantined: u32,
}
