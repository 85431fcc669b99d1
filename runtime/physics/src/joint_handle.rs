//! [`JointHandle`]: generational handle into the world's joint set.

crate::generational_handle::generational_handle! {
    /// Generational handle of a joint: slot index (low 32 bits) and generation (high 32 bits).
    ///
    /// A handle whose joint was removed (or whose body was) never resolves again, even after its
    /// slot is reused.
    JointHandle
}
