//! [`BodyHandle`]: generational handle into the world's body set.

crate::generational_handle::generational_handle! {
    /// Generational handle of a body: slot index (low 32 bits) and generation (high 32 bits).
    ///
    /// A handle whose body was removed never resolves again, even after its slot is reused.
    BodyHandle
}
