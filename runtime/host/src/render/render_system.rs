//! [`RenderSystem`]: draws the world with onyx-render.

use std::collections::HashMap;

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{
    Event, GraphicsEvent, Light, MeshId, MeshRenderer, ShadingMode, TextureId, Transform,
};
use onyx_render::mesh::{Model, ModelPart};
use onyx_render::{
    DebugCategories, DebugLine, DirectionalLight, DrawObject, Lights, PointLight, RenderError,
    RenderScene, RenderSettings, RenderStats, RenderTarget, Renderer, RendererInitError,
    TextureHandle,
};

use super::previous_transform::{interpolate, PreviousTransform};
use super::ShaderWatcher;
use crate::world::HostState;

/// A renderer plus what the host keeps to feed it: the GPU copies of the registered models
/// and textures, and buffers reused every frame (no per-object allocation per frame).
pub struct RenderSystem {
    renderer: Renderer,
    models: HashMap<MeshId, Model>,
    textures: HashMap<TextureId, TextureHandle>,
    rows: Vec<(Transform, MeshRenderer)>,
    objects: Vec<DrawObject>,
    lines: Vec<DebugLine>,
    shader_watcher: Option<ShaderWatcher>,
    /// Whether the editor grid is drawn.
    pub grid: bool,
    /// Whether physics debug lines (collider outlines, contacts, normals) are drawn.
    pub physics_debug: bool,
    /// The GPU side of plugin GUIs drawn with this renderer.
    pub(crate) gui: crate::gui::GuiGpu,
}

impl std::fmt::Debug for RenderSystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RenderSystem")
            .field("adapter", &self.renderer.gpu().adapter_info().name)
            .finish()
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
            renderer,
            models: HashMap::new(),
            textures: HashMap::new(),
            rows: Vec::new(),
            objects: Vec::new(),
            lines: Vec::new(),
            shader_watcher: None,
            grid: true,
            physics_debug: false,
            gui: crate::gui::GuiGpu::default(),
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

    fn poll_shaders(&mut self, state: &mut HostState) {
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
                state
                    .pending_events
                    .push(Event::Graphics(GraphicsEvent::Gpu {
                        message: error.to_string(),
                    }));
            }
        }
    }

    /// Settings for offscreen images: deterministic (MSAA off, so the same scene gives the
    /// same pixels), shaders from the source checkout's `shaders/` folder when there is one.
    pub fn offscreen_settings() -> RenderSettings {
        RenderSettings {
            shader_dir: crate::window::shader_dir(),
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

    /// Makes sure the model of `id` is on the GPU; `false` for an unknown id.
    fn ensure_model(&mut self, id: MeshId, state: &mut HostState) -> bool {
        if !self.models.contains_key(&id) {
            let builtin = self.renderer.builtin_meshes();
            let mesh = match id {
                MeshId::CUBE => Some(builtin.cube),
                MeshId::SPHERE => Some(builtin.sphere),
                MeshId::PLANE => Some(builtin.plane),
                MeshId::CAPSULE => Some(builtin.capsule),
                MeshId::CYLINDER => Some(builtin.cylinder),
                _ => None,
            };
            let model = match (mesh, state.assets.mesh_path(id)) {
                (Some(mesh), _) => Model {
                    parts: vec![ModelPart {
                        name: "builtin".into(),
                        mesh,
                        material: onyx_render::Material::color(1.0, 1.0, 1.0),
                    }],
                },
                (None, Some(path)) => {
                    let path = state.assets.resolve(path);
                    let (model, problems) = self.renderer.load_model_or_fallback(&path);
                    for problem in problems {
                        state
                            .pending_events
                            .push(Event::Graphics(GraphicsEvent::AssetFailed {
                                path: path.display().to_string(),
                                message: problem.to_string(),
                            }));
                    }
                    model
                }
                (None, None) => return false,
            };
            self.models.insert(id, model);
        }
        true
    }

    fn texture(&mut self, id: TextureId, state: &mut HostState) -> Option<TextureHandle> {
        if id == TextureId::NONE {
            return None;
        }
        if let Some(handle) = self.textures.get(&id) {
            return Some(*handle);
        }
        let path = state.assets.resolve(state.assets.texture_path(id)?);
        let (handle, problem) = self.renderer.load_texture_or_fallback(&path);
        if let Some(problem) = problem {
            state
                .pending_events
                .push(Event::Graphics(GraphicsEvent::AssetFailed {
                    path: path.display().to_string(),
                    message: problem.to_string(),
                }));
        }
        self.textures.insert(id, handle);
        Some(handle)
    }

    /// Draws the world into `target`: every visible [`MeshRenderer`] at its pose interpolated
    /// between the last two fixed steps, through the chosen camera (else the orbit camera),
    /// with the scene's lights (else a default sun), the grid and this frame's debug lines.
    /// GPU errors become graphics events.
    pub fn draw(
        &mut self,
        state: &mut HostState,
        target: &mut impl RenderTarget,
    ) -> Result<RenderStats, RenderError> {
        self.draw_with_overlay(state, target, |_| {})
    }

    /// Like [`RenderSystem::draw`], then `overlay` draws over the finished scene (the GUI).
    pub fn draw_with_overlay(
        &mut self,
        state: &mut HostState,
        target: &mut impl RenderTarget,
        overlay: impl FnOnce(&mut onyx_render::Overlay<'_>),
    ) -> Result<RenderStats, RenderError> {
        self.poll_shaders(state);
        let alpha = state.clock.time().alpha;
        let camera = self.camera(state);
        let lights = Self::lights(state);

        let mut rows = std::mem::take(&mut self.rows);
        rows.clear();
        rows.extend(
            state
                .world
                .query::<(&Transform, &MeshRenderer, Option<&PreviousTransform>)>()
                .iter()
                .filter(|(_, r, _)| r.visible)
                .map(|(t, r, p)| (p.map_or(*t, |p| interpolate(&p.0, t, alpha)), *r)),
        );
        self.objects.clear();
        for &(transform, renderer) in &rows {
            let matrix = transform.matrix();
            let texture = self.texture(renderer.material.texture, state);
            if !self.ensure_model(renderer.mesh, state) {
                continue;
            }
            let model = &self.models[&renderer.mesh];
            let [r, g, b, a] = renderer.material.color;
            for part in &model.parts {
                let pc = part.material.color;
                let mut material = onyx_render::Material {
                    color: [r * pc[0], g * pc[1], b * pc[2], a * pc[3]],
                    texture: texture.or(part.material.texture),
                    shading: to_render_shading(
                        state
                            .tools
                            .render_overrides
                            .shading
                            .into_option()
                            .unwrap_or(renderer.material.shading),
                    ),
                };
                if material.shading != onyx_render::ShadingMode::Lit {
                    material.texture = None;
                }
                self.objects
                    .push(DrawObject::new(part.mesh, material, matrix));
            }
        }
        self.rows = rows;
        self.lines.clear();
        self.lines.extend(
            state.debug_lines.iter().map(|l| {
                DebugLine::new(l.start, l.end, l.color).with_category(DebugCategories::USER)
            }),
        );
        let overrides = state.tools.render_overrides;
        if overrides
            .physics_debug
            .into_option()
            .unwrap_or(self.physics_debug)
        {
            self.lines
                .extend(state.physics.debug_lines().into_iter().map(|l| {
                    DebugLine::new(l.start, l.end, l.color).with_category(DebugCategories::PHYSICS)
                }));
        }
        let scene = RenderScene::new(camera, &lights)
            .with_objects(&self.objects)
            .with_grid(overrides.grid.into_option().unwrap_or(self.grid))
            .with_debug_lines(&self.lines);
        let result = self.renderer.render_with_overlay(target, &scene, overlay);
        self.forward_events(state);
        result
    }

    /// Moves the renderer's GPU events into the host's dispatcher.
    pub fn forward_events(&mut self, state: &mut HostState) {
        for event in self.renderer.drain_events() {
            let message = event.to_string();
            let event = match event {
                onyx_render::GraphicsEvent::DeviceLost { .. } => {
                    GraphicsEvent::DeviceLost { message }
                }
                _ => GraphicsEvent::Gpu { message },
            };
            state.pending_events.push(Event::Graphics(event));
        }
    }

    fn camera(&self, state: &HostState) -> onyx_render::Camera {
        super::active_camera(state)
    }

    fn lights(state: &HostState) -> Lights {
        let mut lights = Lights {
            ambient: Vec3::ZERO,
            sun: None,
            points: Vec::new(),
        };
        let mut any = false;
        for (light, t) in state.world.query::<(&Light, &Transform)>().iter() {
            any = true;
            match *light {
                Light::Ambient { color, intensity } => {
                    lights.ambient += Vec3::from(color) * intensity;
                }
                Light::Directional { color, intensity } => {
                    if lights.sun.is_none() {
                        lights.sun = Some(DirectionalLight {
                            direction: t.rotation * Vec3::NEG_Z,
                            color: Vec3::from(color),
                            intensity,
                        });
                    }
                }
                Light::Point {
                    color,
                    intensity,
                    range,
                } => lights.points.push(
                    PointLight::new(t.translation)
                        .with_color(Vec3::from(color))
                        .with_intensity(intensity)
                        .with_range(range),
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
