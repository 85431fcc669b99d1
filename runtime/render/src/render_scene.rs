//! [`RenderScene`] and [`DrawObject`]: the plain data the host fills each frame.

use glam::Mat4;

use crate::camera::Camera;
use crate::debug_lines::DebugLine;
use crate::light::Lights;
use crate::material::Material;
use crate::mesh::MeshHandle;

/// One object to draw: a mesh, its material and its world transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawObject {
    /// Mesh to draw.
    pub mesh: MeshHandle,
    /// How it looks.
    pub material: Material,
    /// Model-to-world transform (already interpolated by the host if it interpolates).
    pub transform: Mat4,
}

impl DrawObject {
    /// An object from its parts.
    #[must_use]
    pub fn new(mesh: MeshHandle, material: Material, transform: Mat4) -> Self {
        Self {
            mesh,
            material,
            transform,
        }
    }
}

/// Everything one frame shows. Borrowed plain data, built by the host each frame from its
/// world (no ECS here); the renderer copies what it needs, so the slices can be reused.
///
/// ```
/// # use onyx_render::{Camera, Lights, RenderScene};
/// let lights = Lights::default();
/// let scene = RenderScene::new(Camera::default(), &lights).with_grid(true);
/// assert!(scene.objects.is_empty());
/// ```
#[derive(Clone, Copy, Debug)]
pub struct RenderScene<'a> {
    /// Where the scene is seen from.
    pub camera: Camera,
    /// Lights.
    pub lights: &'a Lights,
    /// Objects to draw (culled and batched by the renderer).
    pub objects: &'a [DrawObject],
    /// Draw the editor grid on Y = 0.
    pub grid: bool,
    /// Debug lines, filtered by [`crate::RenderSettings::debug_categories`].
    pub debug_lines: &'a [DebugLine],
}

impl<'a> RenderScene<'a> {
    /// A scene with no objects, no grid, no debug lines.
    #[must_use]
    pub fn new(camera: Camera, lights: &'a Lights) -> Self {
        Self {
            camera,
            lights,
            objects: &[],
            grid: false,
            debug_lines: &[],
        }
    }

    /// Sets the objects.
    #[must_use]
    pub fn with_objects(mut self, objects: &'a [DrawObject]) -> Self {
        self.objects = objects;
        self
    }

    /// Turns the grid on or off.
    #[must_use]
    pub fn with_grid(mut self, grid: bool) -> Self {
        self.grid = grid;
        self
    }

    /// Sets the debug lines.
    #[must_use]
    pub fn with_debug_lines(mut self, lines: &'a [DebugLine]) -> Self {
        self.debug_lines = lines;
        self
    }
}
