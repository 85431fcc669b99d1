//! [`ColliderSet`]: flat generational storage of colliders.

use crate::collider::Collider;
use crate::collider_handle::ColliderHandle;
use crate::handle_set::HandleSet;

/// All colliders of a world, addressed by [`ColliderHandle`].
pub type ColliderSet = HandleSet<ColliderHandle, Collider>;
