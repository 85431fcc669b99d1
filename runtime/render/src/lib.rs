//! `onyx-render`: the wgpu renderer of the Onyx engine.
//!
//! Draws plain-data scenes — meshes with per-object shading modes, lights, an editor grid and
//! debug lines — into a window surface or an offscreen texture with the same code. It knows
//! nothing of plugins, physics or ECS: the host fills a [`RenderScene`] each frame.
//!
//! ```
//! use onyx_render::{Camera, DrawObject, Lights, Material, OffscreenTarget, RenderScene, RenderSettings, Renderer};
//! use glam::{Mat4, Vec3};
//!
//! let mut renderer = match Renderer::new_headless(RenderSettings::default()) {
//!     Ok(renderer) => renderer,
//!     // No GPU and no CPU adapter: a host keeps running without rendering.
//!     Err(error) => return Ok(eprintln!("rendering disabled: {error}")),
//! };
//! let mut target = OffscreenTarget::new(renderer.gpu(), 320, 240);
//! let cube = renderer.builtin_meshes().cube;
//! let objects = [DrawObject::new(cube, Material::color(0.9, 0.3, 0.2), Mat4::from_rotation_y(0.5))];
//! let lights = Lights::default();
//! let camera = Camera::perspective_look_at(Vec3::new(2.0, 2.0, 3.0), Vec3::ZERO, 1.0, 0.1, 100.0);
//! let scene = RenderScene::new(camera, &lights).with_objects(&objects).with_grid(true);
//! let stats = renderer.render(&mut target, &scene)?;
//! let image = target.read_image(renderer.gpu())?; // an image::RgbaImage
//! // The cube, the sky and the grid; the sun's three shadow cascades draw the cube once each.
//! assert_eq!((image.width(), stats.draw_calls, stats.shadow_views), (320, 3, 3));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! For a window: create the instance with [`GpuContext::create_instance`], a
//! `wgpu::Surface<'static>` from the window with it, then
//! [`GpuContext::from_instance`]`(instance, Some(&surface))`, [`Renderer::new`] and
//! [`SurfaceTarget::new`]; call [`SurfaceTarget::resize`] on resize and
//! [`Renderer::render`] each frame. See `NOTES.md` at the workspace root.
//!
//! # What a frame does
//! Shadow passes (the sun's cascades, shadowed spot lights, point-light cube faces), then the
//! scene in linear HDR (physically based materials lit by the sky's image-based light and the
//! direct lights; opaque, masked, then blended objects back to front), then exposure and tone
//! mapping (AgX by default) into the sRGB target. MSAA (4× by default) applies to the HDR
//! scene.
//!
//! # Conventions
//! - Y up, right-handed; the camera looks down -Z in view space.
//! - Units: metres, radians; colours are linear RGB(A) (targets are sRGB). A light of
//!   intensity 1 lights a white diffuse surface facing it to brightness 1.
//! - Reverse-Z: clip-space depth 1 at the near plane, 0 at infinity (perspective cameras have
//!   no far plane); depth test `Greater`, cleared to 0.
//! - Camera-relative: object, light and line positions are made relative to the camera on the
//!   CPU, so precision does not depend on the distance from the world origin.
//! - Triangles are counter-clockwise when seen from the front; back faces are culled
//!   (except in wireframe and for double-sided materials).
//! - Textures: (0, 0) is the top-left of the image; OBJ texture coordinates are flipped on load.
//!   Normal maps are tangent space with +Y up the image (glTF, Blender); tangents are
//!   MikkTSpace, generated when a mesh has none.
//!
//! # Errors and events
//! Each fallible operation has its own error enum naming the file or object at fault.
//! GPU validation errors and device loss never panic: they are logged with `tracing` and
//! queued as [`GraphicsEvent`]s for the host to drain ([`Renderer::drain_events`]).
//! Failed assets have visible fallbacks (the missing-texture placeholder, a placeholder cube).
//!
//! # Modules
//! Each file holds one type named after it.

/// Depth buffer format of every target.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Reading asset files: regular files only, any text encoding, paths from other systems.
pub mod asset_io;
/// Handles of the procedural meshes every renderer uploads.
mod builtin_meshes;
/// Perspective / orthographic camera.
mod camera;
/// Debug lines and their categories.
mod debug_lines;
/// The sky's image-based light: prefiltered specular and irradiance cubes, BRDF table.
mod environment;
/// Per-frame GPU data: uniforms, instances, batching, attachments (internal).
mod frame;
/// Frustum planes for culling.
mod frustum;
/// Instance, adapter, device, queue and the graphics event queue.
mod gpu_context;
/// Error of opening a device.
mod gpu_init_error;
/// Events (validation errors, device loss, shader failures) for the host.
mod graphics_event;
/// Sky light, sun, point and spot lights, and their shadow settings.
mod light;
/// Model files and images read and decoded on worker threads, uploaded when done.
mod loading;
/// Object material (metallic-roughness, maps, alpha mode, shading mode).
mod material;
/// Meshes: data, procedural shapes, model files (OBJ, glTF), cache.
pub mod mesh;
/// Materials as model files describe them (metallic-roughness), carried in loaded models.
pub mod model_material;
/// Offscreen render target with image readback.
mod offscreen;
/// What a caller draws over a finished frame.
mod overlay;
/// Shader sources, compilation and pipelines.
pub mod pipeline;
/// Texture → image readback.
mod readback;
/// Error of reading back an image.
mod readback_error;
/// Error of rendering a frame.
mod render_error;
/// The scene the host fills each frame.
mod render_scene;
/// Every renderer tunable.
mod render_settings;
/// Counters of the last frame.
mod render_stats;
/// The trait of render targets.
mod render_target;
/// The renderer: entry point.
mod renderer;
/// Error of creating a renderer.
mod renderer_init_error;
/// Shading modes.
mod shading_mode;
/// Shadow views (cascades, spot and point lights) and shadow maps.
mod shadow;
/// The sky around the scene.
mod sky;
/// Window surface render target.
mod surface_target;
/// Error of wrapping a window surface.
mod surface_target_error;
/// Textures: loading, mipmaps, cache, fallbacks.
pub mod texture;
/// Tone-mapping operators.
mod tone_mapping;

pub use asset_io::{AssetReadError, AssetWarning};
pub use builtin_meshes::{BuiltinMeshes, BUILTIN_RINGS, BUILTIN_SEGMENTS};
pub use camera::{Camera, Projection};
pub use debug_lines::{DebugCategories, DebugLine};
pub use frustum::Frustum;
pub use glam;
pub use gpu_context::GpuContext;
pub use gpu_init_error::GpuInitError;
pub use graphics_event::GraphicsEvent;
pub use image;
pub use light::{
    DirectionalLight, LightShadows, Lights, PointLight, SpotLight, MAX_POINT_LIGHTS,
    MAX_SPOT_LIGHTS,
};
pub use loading::{AssetLoader, Loaded};
pub use material::Material;
pub use mesh::{
    GltfFileLease, GltfFiles, ImportSettings, InvalidMeshError, MeshData, MeshHandle, Model,
    ModelLoadError, ModelPart, ModelSource, NormalMode, PartSource, SubAsset, UpAxis, Vertex,
};
pub use model_material::{AlphaMode, ModelMaterial};
pub use offscreen::{OffscreenTarget, OFFSCREEN_FORMAT};
pub use overlay::Overlay;
pub use pipeline::{ShaderError, ShaderReloadError, ShaderSource};
pub use readback_error::ReadbackError;
pub use render_error::RenderError;
pub use render_scene::{DrawObject, RenderScene};
pub use render_settings::RenderSettings;
pub use render_stats::RenderStats;
pub use render_target::RenderTarget;
pub use renderer::Renderer;
pub use renderer_init_error::RendererInitError;
pub use shading_mode::ShadingMode;
pub use shadow::MAX_CASCADES;
pub use sky::Sky;
pub use surface_target::SurfaceTarget;
pub use surface_target_error::SurfaceTargetError;
pub use texture::{TextureHandle, TextureLoadError, TextureSource};
pub use tone_mapping::ToneMapping;
pub use wgpu;
