//! [`PipelineLibrary`]: compiles shaders inside error scopes, builds pipelines on demand per
//! (shader, target format, sample count) and keeps the last good ones when a reload fails.

use std::collections::HashMap;

use super::layouts::{self, Layouts};
use super::shader_error::ShaderError;
use super::shader_kind::ShaderKind;
use super::shader_source::ShaderSource;
use crate::frame::{AlphaClass, HDR_FORMAT};
use crate::shading_mode::ShadingMode;

/// Identifies one pipeline: shader, colour format, MSAA sample count, and how alpha and back
/// faces are treated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PipelineKey {
    pub(crate) kind: ShaderKind,
    pub(crate) format: wgpu::TextureFormat,
    pub(crate) samples: u32,
    /// Opaque, masked (cut at the cutoff) or blended (mesh and shadow shaders).
    pub(crate) alpha: AlphaClass,
    /// Back faces drawn too (no culling).
    pub(crate) double_sided: bool,
}

impl PipelineKey {
    /// A pipeline of the HDR scene pass.
    pub(crate) fn scene(kind: ShaderKind, samples: u32) -> Self {
        Self {
            kind,
            format: HDR_FORMAT,
            samples,
            alpha: AlphaClass::Opaque,
            double_sided: false,
        }
    }

    /// With this alpha treatment and sidedness.
    pub(crate) fn with_alpha(mut self, alpha: AlphaClass, double_sided: bool) -> Self {
        self.alpha = alpha;
        self.double_sided = double_sided;
        self
    }
}

/// All shader modules and pipelines.
#[derive(Debug)]
pub(crate) struct PipelineLibrary {
    source: ShaderSource,
    layouts: Layouts,
    modules: HashMap<ShaderKind, wgpu::ShaderModule>,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
}

impl PipelineLibrary {
    /// Compiles every shader from `source`. A shader that fails from the folder falls back to
    /// its embedded copy (and is reported in the returned list); an embedded shader that
    /// fails is an error.
    pub(crate) fn new(
        device: &wgpu::Device,
        source: ShaderSource,
    ) -> Result<(Self, Vec<ShaderError>), ShaderError> {
        let layouts = Layouts::new(device);
        let mut modules = HashMap::new();
        let mut warnings = Vec::new();
        for kind in ShaderKind::ALL {
            let from_source = source
                .read_with(kind.file(), kind.preludes())
                .and_then(|text| compile(device, kind, &text));
            let module = match from_source {
                Ok(module) => module,
                Err(error) => {
                    tracing::warn!(%error, shader = kind.file(), "using the embedded shader instead");
                    warnings.push(error);
                    compile(
                        device,
                        kind,
                        &ShaderSource::read_embedded(kind.file(), kind.preludes()),
                    )?
                }
            };
            modules.insert(kind, module);
        }
        Ok((
            Self {
                source,
                layouts,
                modules,
                pipelines: HashMap::new(),
            },
            warnings,
        ))
    }

    pub(crate) fn layouts(&self) -> &Layouts {
        &self.layouts
    }

    /// The pipeline for `key`, built on first use. `None` only if building it failed (logged).
    pub(crate) fn get(
        &mut self,
        device: &wgpu::Device,
        key: PipelineKey,
    ) -> Option<&wgpu::RenderPipeline> {
        if !self.pipelines.contains_key(&key) {
            let module = self.modules.get(&key.kind)?;
            match build_pipeline(device, &self.layouts, module, key) {
                Ok(pipeline) => {
                    self.pipelines.insert(key, pipeline);
                }
                Err(message) => {
                    tracing::error!(shader = key.kind.file(), %message, "could not build pipeline");
                    return None;
                }
            }
        }
        self.pipelines.get(&key)
    }

    /// Re-reads and recompiles every shader. A shader that fails keeps its last good module
    /// and pipelines; the failures are returned.
    pub(crate) fn reload(&mut self, device: &wgpu::Device) -> Vec<ShaderError> {
        let mut failures = Vec::new();
        for kind in ShaderKind::ALL {
            match self.reload_one(device, kind) {
                Ok(()) => tracing::debug!(shader = kind.file(), "shader reloaded"),
                Err(error) => {
                    tracing::warn!(%error, "shader reload failed, keeping the previous version");
                    failures.push(error);
                }
            }
        }
        failures
    }

    fn reload_one(&mut self, device: &wgpu::Device, kind: ShaderKind) -> Result<(), ShaderError> {
        let text = self.source.read_with(kind.file(), kind.preludes())?;
        let module = compile(device, kind, &text)?;
        let keys: Vec<PipelineKey> = self
            .pipelines
            .keys()
            .filter(|k| k.kind == kind)
            .copied()
            .collect();
        let mut rebuilt = Vec::with_capacity(keys.len());
        for key in keys {
            let pipeline =
                build_pipeline(device, &self.layouts, &module, key).map_err(|message| {
                    ShaderError::Compile {
                        shader: kind.file().to_owned(),
                        message,
                    }
                })?;
            rebuilt.push((key, pipeline));
        }
        self.modules.insert(kind, module);
        self.pipelines.extend(rebuilt);
        Ok(())
    }
}

/// Creates a shader module inside a validation error scope, so bad WGSL is an error value.
fn compile(
    device: &wgpu::Device,
    kind: ShaderKind,
    text: &str,
) -> Result<wgpu::ShaderModule, ShaderError> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(kind.file()),
        source: wgpu::ShaderSource::Wgsl(text.into()),
    });
    match pollster::block_on(scope.pop()) {
        None => Ok(module),
        Some(error) => Err(ShaderError::Compile {
            shader: kind.file().to_owned(),
            message: error.to_string(),
        }),
    }
}

/// Builds one pipeline inside a validation error scope.
fn build_pipeline(
    device: &wgpu::Device,
    layouts: &Layouts,
    module: &wgpu::ShaderModule,
    key: PipelineKey,
) -> Result<wgpu::RenderPipeline, String> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let pipeline = create_pipeline(device, layouts, module, key);
    match pollster::block_on(scope.pop()) {
        None => Ok(pipeline),
        Some(error) => Err(error.to_string()),
    }
}

fn create_pipeline(
    device: &wgpu::Device,
    layouts: &Layouts,
    module: &wgpu::ShaderModule,
    key: PipelineKey,
) -> wgpu::RenderPipeline {
    let mesh_buffers = [
        Some(layouts::vertex_layout()),
        Some(layouts::instance_layout()),
    ];
    let line_buffers = [Some(layouts::line_layout())];
    // The wireframe pulls vertices from storage buffers; slot 1 stays the instances.
    let wire_buffers = [None, Some(layouts::instance_layout())];
    let cull = if key.double_sided {
        None
    } else {
        Some(wgpu::Face::Back)
    };
    let alpha_entry = match key.alpha {
        AlphaClass::Opaque => "fs_opaque",
        AlphaClass::Mask => "fs_mask",
        AlphaClass::Blend => "fs_blend",
    };
    // Reverse-Z: nearer is greater. Blended surfaces test but do not write depth.
    let scene_depth = |write| {
        Some(wgpu::DepthStencilState {
            format: crate::DEPTH_FORMAT,
            depth_write_enabled: Some(write),
            depth_compare: Some(if write {
                wgpu::CompareFunction::Greater
            } else {
                wgpu::CompareFunction::GreaterEqual
            }),
            stencil: wgpu::StencilState::default(),
            bias: wgpu::DepthBiasState::default(),
        })
    };
    let blend_over = Some(wgpu::BlendState::ALPHA_BLENDING);
    struct Shape<'a> {
        layout: &'a wgpu::PipelineLayout,
        buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>],
        cull: Option<wgpu::Face>,
        fragment: Option<&'static str>,
        blend: Option<wgpu::BlendState>,
        depth: Option<wgpu::DepthStencilState>,
        samples: u32,
    }
    let samples = key.samples;
    let shape = match key.kind {
        ShaderKind::Mesh(ShadingMode::Wireframe) => Shape {
            layout: &layouts.wireframe,
            buffers: &wire_buffers,
            cull: None,
            fragment: Some("fs_main"),
            blend: None,
            depth: scene_depth(true),
            samples,
        },
        ShaderKind::Mesh(ShadingMode::Normal) => Shape {
            layout: &layouts.frame_only,
            buffers: &mesh_buffers,
            cull,
            fragment: Some("fs_main"),
            blend: None,
            depth: scene_depth(true),
            samples,
        },
        ShaderKind::Placeholder => Shape {
            layout: &layouts.lit,
            buffers: &mesh_buffers,
            cull,
            fragment: Some("fs_main"),
            blend: None,
            depth: scene_depth(true),
            samples,
        },
        ShaderKind::Mesh(mode) => Shape {
            layout: if mode == ShadingMode::Unlit {
                &layouts.textured
            } else {
                &layouts.lit
            },
            buffers: &mesh_buffers,
            cull,
            fragment: Some(alpha_entry),
            blend: (key.alpha == AlphaClass::Blend).then_some(wgpu::BlendState::ALPHA_BLENDING),
            depth: scene_depth(key.alpha != AlphaClass::Blend),
            samples,
        },
        ShaderKind::Grid | ShaderKind::Sky => Shape {
            layout: if key.kind == ShaderKind::Sky {
                &layouts.lit
            } else {
                &layouts.frame_only
            },
            buffers: &[],
            cull: None,
            fragment: Some("fs_main"),
            blend: if key.kind == ShaderKind::Grid {
                blend_over
            } else {
                None
            },
            depth: scene_depth(false),
            samples,
        },
        ShaderKind::DebugLines => Shape {
            layout: &layouts.frame_only,
            buffers: &line_buffers,
            cull: None,
            fragment: Some("fs_main"),
            blend: blend_over,
            depth: scene_depth(false),
            samples,
        },
        ShaderKind::Shadow => Shape {
            layout: if key.alpha == AlphaClass::Mask {
                &layouts.shadow_masked
            } else {
                &layouts.shadow
            },
            buffers: &mesh_buffers,
            cull,
            fragment: (key.alpha == AlphaClass::Mask).then_some("fs_mask"),
            blend: None,
            depth: Some(wgpu::DepthStencilState {
                format: crate::shadow::SHADOW_FORMAT,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState::default(),
            }),
            samples: 1,
        },
        ShaderKind::Tonemap => Shape {
            layout: &layouts.tonemap_layout,
            buffers: &[],
            cull: None,
            fragment: Some("fs_main"),
            blend: None,
            depth: None,
            samples: 1,
        },
    };
    let targets = [Some(wgpu::ColorTargetState {
        format: key.format,
        blend: shape.blend,
        write_mask: wgpu::ColorWrites::ALL,
    })];
    let depth_only = key.kind == ShaderKind::Shadow;
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(key.kind.file()),
        layout: Some(shape.layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            buffers: shape.buffers,
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            front_face: wgpu::FrontFace::Ccw,
            cull_mode: shape.cull,
            ..Default::default()
        },
        depth_stencil: shape.depth,
        multisample: wgpu::MultisampleState {
            count: shape.samples,
            ..Default::default()
        },
        fragment: shape.fragment.map(|entry| wgpu::FragmentState {
            module,
            entry_point: Some(entry),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            targets: if depth_only { &[] } else { &targets },
        }),
        multiview_mask: None,
        cache: None,
    })
}

impl PipelineLibrary {
    /// Changes where shaders are read from (takes effect at the next reload).
    pub(crate) fn set_source(&mut self, source: ShaderSource) {
        self.source = source;
    }

    /// A pipeline already built by [`PipelineLibrary::get`].
    pub(crate) fn cached(&self, key: &PipelineKey) -> Option<&wgpu::RenderPipeline> {
        self.pipelines.get(key)
    }
}
