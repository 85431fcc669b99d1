//! [`NarrowStats`]: counters gathered by the collision routines during one step.

/// Work and failure counters of the narrowphase (summed into `StepCounters`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NarrowStats {
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
    /// EPA runs that hit a cap or met a flat Minkowski difference (fallback used).
    pub epa_failures: u32,
    /// Pairs whose manifolds were refreshed from body-local points instead of regenerated.
    pub reused_pairs: u32,
}
