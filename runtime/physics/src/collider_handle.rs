//! [`ColliderHandle`]: generational handle into the world's collider set.

crate::generational_handle::generational_handle! {
    /// Generational handle of a collider: slot index (low 32 bits) and generation (high 32 bits).
    ///
    /// A handle whose collider was removed never resolves again, even after its slot is reused.
    ColliderHandle
}
