//! [`BodySet`]: flat generational storage of rigid bodies.

use crate::body_handle::BodyHandle;
use crate::handle_set::HandleSet;
use crate::rigid_body::RigidBody;

/// All bodies of a world, addressed by [`BodyHandle`].
pub type BodySet = HandleSet<BodyHandle, RigidBody>;
