//! [`RenderSystem`]: draws the world with onyx-render.

use std::time::Duration;

use onyx_plugin_api::glam::{Affine3A, Mat4, Vec3};
use onyx_plugin_api::{
    AlphaMode, Event, GraphicsEvent, Light, MeshId, MeshRenderer, ShadingMode, Transform,
};
use onyx_render::{
    DebugCategories, DebugLine, DirectionalLight, DrawObject, LightShadows, Lights, PointLight,
    RenderError, RenderScene, RenderSettings, RenderStats, RenderTarget, Renderer,
    RendererInitError, SpotLight,
};

use super::asset_watcher::AssetWatcher;
use super::previous_pose::{interpolate, PreviousPose};
use super::render_assets::RenderAssets;
use super::{ShaderWatcher, ViewState};
use crate::assets::AssetRegistry;
use crate::physics::PhysicsSystem;
use crate::world::WorldState;

/// The material a part of an entity's mesh is drawn with: a built-in shape takes the
/// entity's material whole; a model part keeps its file's material, with the entity's colour
/// multiplying it, its emission added, its alpha mode (when not opaque) replacing it and its
/// double-sidedness added (see [`onyx_plugin_api::Material`]).
fn part_material(
    entity: &onyx_plugin_api::Material,
    part: &onyx_render::Material,
    builtin: bool,
) -> onyx_render::Material {
    let alpha_mode = match entity.alpha_mode {
        AlphaMode::Opaque => None,
        AlphaMode::Mask => Some(onyx_render::AlphaMode::Mask {
            cutoff: entity.alpha_cutoff,
        }),
        AlphaMode::Blend => Some(onyx_render::AlphaMode::Blend),
    };
    let [r, g, b, a] = entity.color;
    let pc = part.color;
    let mut material = onyx_render::Material {
        color: [r * pc[0], g * pc[1], b * pc[2], a * pc[3]],
        emissive: std::array::from_fn(|i| part.emissive[i] + entity.emissive[i]),
        alpha_mode: alpha_mode.unwrap_or(part.alpha_mode),
        double_sided: part.double_sided || entity.double_sided,
        ..*part
    };
    if builtin {
        material.metallic = entity.metallic;
        material.roughness = entity.roughness;
        material.alpha_mode = alpha_mode.unwrap_or(onyx_render::AlphaMode::Opaque);
    }
    material
}

/// What a frame is drawn from: the world (poses from its scene graph), how it is looked at,
/// this frame's debug lines, physics (for its debug lines) and the interpolation factor
/// between the last two fixed steps.
#[derive(Clone, Copy)]
pub struct RenderInput<'a> {
    /// Entities, scene graph, assets.
    pub world: &'a WorldState,
    /// Camera choice and view switches.
    pub view: &'a ViewState,
    /// Lines plugins drew this frame.
    pub debug_lines: &'a [onyx_plugin_api::DebugLine],
    /// Physics, whose collider outlines and contacts are drawn when asked.
    pub physics: &'a PhysicsSystem,
    /// Blend between the previous and the current fixed step, `[0, 1]`.
    pub alpha: f32,
}

/// A renderer plus what the host keeps to feed it: the GPU copies of the registered models
/// and textures (loaded off the frame thread: a model is drawn once it is uploaded, a texture
/// shows the missing-texture checker until then), and buffers reused every frame (no
/// per-object allocation per frame).
pub struct RenderSystem {
    renderer: Renderer,
    assets: RenderAssets,
    /// Set while drawing a screenshot: every asset the frame draws is waited for (at most
    /// this long), so the image shows the final assets.
    pub(crate) await_loads: Option<Duration>,
    rows: Vec<(Affine3A, MeshRenderer)>,
    objects: Vec<DrawObject>,
    lines: Vec<DebugLine>,
    shader_watcher: Option<ShaderWatcher>,
    /// Watches the drawn assets' files, with the asset generation it watches for.
    asset_watcher: Option<(AssetWatcher, u64)>,
    /// Whether the editor grid is drawn.
    pub grid: bool,
    /// Whether physics debug lines (collider outlines, contacts, normals) are drawn.
    pub physics_debug: bool,
    /// The GPU side of plugin GUIs drawn with this renderer.
    pub(crate) gui: super::GuiGpu,
}

impl std::fmt::Debug for RenderSystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RenderSystem")
            .field("adapter", &self.renderer.gpu().adapter_info().name)
            .finish()
    }
}

/// Calls `f` with every visible [`MeshRenderer`] and the world pose it is drawn at: its
/// entity's world pose interpolated by `alpha` from the previous fixed step's (the scene
/// graph's world poses must be up to date).
pub fn drawn_poses(
    world: &WorldState,
    alpha: f32,
    mut f: impl FnMut(hecs::Entity, Affine3A, &MeshRenderer),
) {
    let hierarchy = &world.hierarchy;
    for (e, t, renderer, previous) in world
        .ecs
        .query::<(
            hecs::Entity,
            &Transform,
            &MeshRenderer,
            Option<&PreviousPose>,
        )>()
        .iter()
    {
        if renderer.visible {
            let pose = hierarchy.world_of(e, t);
            f(
                e,
                previous.map_or(pose, |p| interpolate(&p.0, &pose, alpha)),
                renderer,
            );
        }
    }
}

fn to_render_shading(mode: ShadingMode) -> onyx_render::ShadingMode {
    match mode {
        ShadingMode::Unlit => onyx_render::ShadingMode::Unlit,
        ShadingMode::LitLow => onyx_render::ShadingMode::LitLow,
        ShadingMode::Lit => onyx_render::ShadingMode::Lit,
        ShadingMode::Normal => onyx_render::ShadingMode::Normal,
        ShadingMode::Wireframe => onyx_render::ShadingMode::Wireframe,
    }
}

impl RenderSystem {
    /// A render system drawing with `renderer`.
    pub fn new(renderer: Renderer) -> Self {
        Self {
            assets: RenderAssets::new(&renderer),
            await_loads: None,
            renderer,
            rows: Vec::new(),
            objects: Vec::new(),
            lines: Vec::new(),
            shader_watcher: None,
            asset_watcher: None,
            grid: true,
            physics_debug: false,
            gui: super::GuiGpu::default(),
        }
    }

    /// Recompiles the shaders whenever a file in the renderer's shader folder changes (when
    /// it reads shaders from a folder rather than from the binary). A shader that fails to
    /// compile keeps its last good version and raises a graphics event.
    pub fn watch_shaders(&mut self) -> Result<(), notify::Error> {
        if let Some(dir) = self.renderer.settings().shader_dir.clone() {
            self.shader_watcher = Some(ShaderWatcher::new(&dir)?);
            tracing::info!(dir = %dir.display(), "watching shaders");
        }
        Ok(())
    }

    /// Loads a model or texture again whenever its file changes on disk (a model also
    /// when a material library, image or buffer beside it changes). What is drawn is kept
    /// until the new version is uploaded, and kept for good if it fails to load (a
    /// graphics event says why).
    pub fn watch_assets(&mut self) -> Result<(), notify::Error> {
        self.asset_watcher = Some((AssetWatcher::new()?, u64::MAX));
        Ok(())
    }

    /// Loads again the assets whose files changed.
    fn poll_asset_files(&mut self, registry: &AssetRegistry) {
        if let Some((watcher, _)) = &mut self.asset_watcher {
            for key in watcher.poll() {
                self.assets.reload(key, registry);
            }
        }
    }

    /// Watches the files of the assets on the GPU, when they changed (after the uploads of
    /// a frame, so an edit right after the first frame that shows an asset is seen).
    fn watch_asset_files(&mut self, registry: &AssetRegistry) {
        if let Some((watcher, watched)) = &mut self.asset_watcher {
            if *watched != self.assets.generation() {
                watcher.watch(&self.assets.files(registry));
                *watched = self.assets.generation();
            }
        }
    }

    fn poll_shaders(&mut self, events: &mut Vec<Event>) {
        let Some(watcher) = &mut self.shader_watcher else {
            return;
        };
        if !watcher.poll() {
            return;
        }
        match self.renderer.reload_shaders() {
            Ok(()) => tracing::info!("shaders reloaded"),
            Err(error) => {
                tracing::error!("{error}");
                events.push(Event::Graphics(GraphicsEvent::Gpu {
                    message: error.to_string(),
                }));
            }
        }
    }

    /// Settings for offscreen images: deterministic (MSAA off, so the same scene gives the
    /// same pixels), shaders from the source checkout's `shaders/` folder when there is one.
    pub fn offscreen_settings() -> RenderSettings {
        RenderSettings {
            shader_dir: super::shader_dir(),
            ..RenderSettings::deterministic()
        }
    }

    /// A render system on an adapter chosen from the environment, for offscreen drawing.
    pub fn new_headless(settings: RenderSettings) -> Result<Self, RendererInitError> {
        Renderer::new_headless(settings).map(Self::new)
    }

    /// The renderer.
    pub fn renderer(&self) -> &Renderer {
        &self.renderer
    }

    /// The renderer, mutably (shader reload, settings).
    pub fn renderer_mut(&mut self) -> &mut Renderer {
        &mut self.renderer
    }

    /// Loads in flight (models and textures being read and decoded off the frame thread).
    pub fn pending_loads(&self) -> usize {
        self.assets.pending()
    }

    /// Draws the world into `target`: every visible [`MeshRenderer`] at its world pose
    /// interpolated between the last two fixed steps, through the chosen camera (else the
    /// orbit camera), with the scene's lights (else a default sun), the grid and this
    /// frame's debug lines. GPU errors and assets that fail to load become `events`.
    pub(crate) fn draw(
        &mut self,
        input: RenderInput<'_>,
        events: &mut Vec<Event>,
        target: &mut impl RenderTarget,
    ) -> Result<RenderStats, RenderError> {
        self.draw_with_overlay(input, events, target, |_| {})
    }

    /// Like [`RenderSystem::draw`], then `overlay` draws over the finished scene (the GUI).
    pub(crate) fn draw_with_overlay(
        &mut self,
        input: RenderInput<'_>,
        events: &mut Vec<Event>,
        target: &mut impl RenderTarget,
        overlay: impl FnOnce(&mut onyx_render::Overlay<'_>),
    ) -> Result<RenderStats, RenderError> {
        self.poll_shaders(events);
        let RenderInput {
            world,
            view,
            debug_lines,
            physics,
            alpha,
        } = input;
        self.poll_asset_files(&world.assets);
        self.assets.upload_finished(&mut self.renderer, events);
        let camera = super::active_camera(world, view);
        let lights = Self::lights(world);
        let mut rows = std::mem::take(&mut self.rows);
        rows.clear();
        drawn_poses(world, alpha, |_, pose, renderer| {
            rows.push((pose, *renderer))
        });
        let assets = &world.assets;
        if let Some(timeout) = self.await_loads {
            for (_, renderer) in &rows {
                self.assets
                    .texture(renderer.material.texture, &self.renderer, assets);
                self.assets.model(renderer.mesh, &self.renderer, assets);
            }
            self.assets
                .finish_loading(&mut self.renderer, events, timeout);
        }
        self.objects.clear();
        let shading_override = view.overrides.shading.into_option();
        for &(pose, renderer) in &rows {
            let matrix = Mat4::from(pose);
            let texture = self
                .assets
                .texture(renderer.material.texture, &self.renderer, assets);
            let Some(model) = self.assets.model(renderer.mesh, &self.renderer, assets) else {
                continue;
            };
            let builtin = MeshId::BUILTIN.iter().any(|(id, _)| *id == renderer.mesh);
            let shading = to_render_shading(shading_override.unwrap_or(renderer.material.shading));
            for part in &model.parts {
                let mut material = part_material(&renderer.material, &part.material, builtin);
                material.texture = texture.or(part.material.texture);
                material.shading = shading;
                self.objects.push(DrawObject::new(
                    part.mesh,
                    material,
                    matrix * part.transform,
                ));
            }
        }
        self.rows = rows;
        self.watch_asset_files(assets);
        self.lines.clear();
        self.lines.extend(
            debug_lines.iter().map(|l| {
                DebugLine::new(l.start, l.end, l.color).with_category(DebugCategories::USER)
            }),
        );
        let overrides = view.overrides;
        if overrides
            .physics_debug
            .into_option()
            .unwrap_or(self.physics_debug)
        {
            self.lines
                .extend(physics.debug_lines().into_iter().map(|l| {
                    DebugLine::new(l.start, l.end, l.color).with_category(DebugCategories::PHYSICS)
                }));
        }
        let scene = RenderScene::new(camera, &lights)
            .with_objects(&self.objects)
            .with_grid(overrides.grid.into_option().unwrap_or(self.grid))
            .with_debug_lines(&self.lines);
        let result = self.renderer.render_with_overlay(target, &scene, overlay);
        self.forward_events(events);
        result
    }

    /// Moves the renderer's GPU events into the host's dispatcher.
    pub(crate) fn forward_events(&mut self, events: &mut Vec<Event>) {
        for event in self.renderer.drain_events() {
            let message = event.to_string();
            let event = match event {
                onyx_render::GraphicsEvent::DeviceLost { .. } => {
                    GraphicsEvent::DeviceLost { message }
                }
                _ => GraphicsEvent::Gpu { message },
            };
            events.push(Event::Graphics(event));
        }
    }

    /// The scene's lights at their world poses (directional and spot lights shine along
    /// their local -Z, point and spot lights sit at their origin). An ambient light needs no
    /// [`Transform`]; the others without one sit at the origin, unrotated.
    fn lights(world: &WorldState) -> Lights {
        let mut lights = Lights::none();
        let mut any = false;
        for (e, light, t) in world
            .ecs
            .query::<(hecs::Entity, &Light, Option<&Transform>)>()
            .iter()
        {
            any = true;
            let pose = world
                .hierarchy
                .world_of(e, t.unwrap_or(&Transform::IDENTITY));
            let forward = pose
                .transform_vector3(Vec3::NEG_Z)
                .normalize_or(Vec3::NEG_Z);
            match *light {
                Light::Ambient { color, intensity } => {
                    lights.ambient += Vec3::from(color) * intensity;
                }
                Light::Directional {
                    color,
                    intensity,
                    shadows,
                } => {
                    if lights.sun.is_none() {
                        lights.sun = Some(
                            DirectionalLight::new(forward)
                                .with_color(Vec3::from(color))
                                .with_intensity(intensity)
                                .with_shadows(LightShadows::directional().with_enabled(shadows)),
                        );
                    }
                }
                Light::Point {
                    color,
                    intensity,
                    range,
                    shadows,
                } => lights.points.push(
                    PointLight::new(pose.translation.into())
                        .with_color(Vec3::from(color))
                        .with_intensity(intensity)
                        .with_range(range)
                        .with_shadows(LightShadows::local().with_enabled(shadows)),
                ),
                Light::Spot {
                    color,
                    intensity,
                    range,
                    inner_angle,
                    outer_angle,
                    shadows,
                } => lights.spots.push(
                    SpotLight::new(pose.translation.into(), forward)
                        .with_color(Vec3::from(color))
                        .with_intensity(intensity)
                        .with_range(range)
                        .with_cone(inner_angle, outer_angle)
                        .with_shadows(LightShadows::local().with_enabled(shadows)),
                ),
            }
        }
        if any {
            lights
        } else {
            Lights::default()
        }
    }
}
