//! [`GpuContext`]: the wgpu instance, adapter, device and queue, plus the queue of
//! [`GraphicsEvent`]s captured from the device.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex, PoisonError};

use crate::gpu_init_error::GpuInitError;
use crate::graphics_event::GraphicsEvent;

/// Most events kept before the oldest are dropped (a host that never drains them must not
/// grow without bound).
const MAX_QUEUED_EVENTS: usize = 256;

/// Shared, thread-safe queue of graphics events.
#[derive(Clone, Debug, Default)]
pub(crate) struct EventQueue(Arc<Mutex<VecDeque<GraphicsEvent>>>);

impl EventQueue {
    pub(crate) fn push(&self, event: GraphicsEvent) {
        let mut queue = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        if queue.len() >= MAX_QUEUED_EVENTS {
            queue.pop_front();
        }
        queue.push_back(event);
    }

    fn drain(&self) -> Vec<GraphicsEvent> {
        let mut queue = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        queue.drain(..).collect()
    }
}

/// The graphics device: instance, adapter, device, queue.
///
/// Created once by the host. wgpu validation errors and device loss are captured into a
/// queue of [`GraphicsEvent`]s (and logged) instead of panicking; drain it each frame with
/// [`GpuContext::drain_events`].
pub struct GpuContext {
    instance: wgpu::Instance,
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
    events: EventQueue,
}

impl std::fmt::Debug for GpuContext {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GpuContext")
            .field("adapter", &self.adapter.get_info())
            .finish_non_exhaustive()
    }
}

impl GpuContext {
    /// A wgpu instance configured from the environment (`WGPU_BACKEND`, ...), without a
    /// display handle. Create window surfaces from it, then pass it to
    /// [`GpuContext::from_instance`].
    #[must_use]
    pub fn create_instance() -> wgpu::Instance {
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env())
    }

    /// A wgpu instance configured from the environment, holding the platform's display
    /// handle (from `EventLoop::owned_display_handle()`); needed by the GL backend for
    /// windows, harmless elsewhere.
    #[must_use]
    pub fn create_instance_with_display(
        display: Box<dyn wgpu::wgt::WgpuHasDisplayHandle>,
    ) -> wgpu::Instance {
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_with_display_handle_from_env(
            display,
        ))
    }

    /// Opens a device with no window (offscreen rendering, tests, screenshots).
    ///
    /// The adapter follows `WGPU_ADAPTER_NAME` / `WGPU_BACKEND` / `WGPU_POWER_PREF` when set;
    /// otherwise the default adapter, then a CPU (fallback) adapter.
    ///
    /// # Errors
    /// [`GpuInitError`] when no adapter or device is available.
    pub fn new_headless() -> Result<Self, GpuInitError> {
        Self::from_instance(Self::create_instance(), None)
    }

    /// Opens a device on `instance`, on an adapter able to present to `compatible_surface`
    /// when given (create the surface from this same instance).
    ///
    /// # Errors
    /// [`GpuInitError`] when no adapter or device is available.
    pub fn from_instance(
        instance: wgpu::Instance,
        compatible_surface: Option<&wgpu::Surface<'_>>,
    ) -> Result<Self, GpuInitError> {
        let adapter = pollster::block_on(select_adapter(&instance, compatible_surface))?;
        let info = adapter.get_info();
        tracing::info!(
            adapter = %info.name,
            backend = ?info.backend,
            device_type = ?info.device_type,
            driver = %info.driver,
            driver_info = %info.driver_info,
            "graphics adapter selected"
        );
        let descriptor = wgpu::DeviceDescriptor {
            label: Some("onyx-render device"),
            required_features: wgpu::Features::empty(),
            required_limits: wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits()),
            ..Default::default()
        };
        let (device, queue) =
            pollster::block_on(adapter.request_device(&descriptor)).map_err(|source| {
                GpuInitError::RequestDevice {
                    adapter: info.name.clone(),
                    source,
                }
            })?;

        let events = EventQueue::default();
        let error_events = events.clone();
        device.on_uncaptured_error(Arc::new(move |error: wgpu::Error| {
            let event = match error {
                wgpu::Error::OutOfMemory { .. } => GraphicsEvent::OutOfMemory,
                wgpu::Error::Validation { description, .. } => {
                    GraphicsEvent::Validation { description }
                }
                wgpu::Error::Internal { description, .. } => {
                    GraphicsEvent::Internal { description }
                }
            };
            tracing::error!(%event, "uncaptured GPU error");
            error_events.push(event);
        }));
        let lost_events = events.clone();
        device.set_device_lost_callback(move |reason, message| {
            let event = GraphicsEvent::DeviceLost {
                reason: format!("{reason:?}"),
                message,
            };
            if reason == wgpu::DeviceLostReason::Destroyed {
                tracing::debug!(%event, "GPU device destroyed");
            } else {
                tracing::error!(%event, "GPU device lost");
            }
            lost_events.push(event);
        });

        Ok(Self {
            instance,
            adapter,
            device,
            queue,
            events,
        })
    }

    /// The wgpu instance (create window surfaces from it).
    #[must_use]
    pub fn instance(&self) -> &wgpu::Instance {
        &self.instance
    }

    /// The adapter in use.
    #[must_use]
    pub fn adapter(&self) -> &wgpu::Adapter {
        &self.adapter
    }

    /// Name, backend, driver and type of the adapter in use.
    #[must_use]
    pub fn adapter_info(&self) -> wgpu::AdapterInfo {
        self.adapter.get_info()
    }

    /// The device.
    #[must_use]
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The queue.
    #[must_use]
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// Blocks until the GPU has finished all submitted work (for timing and screenshots).
    ///
    /// # Errors
    /// `wgpu::PollError` when waiting fails (device lost).
    pub fn wait_idle(&self) -> Result<(), wgpu::PollError> {
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map(|_| ())
    }

    /// Takes every event queued since the last call (oldest first).
    #[must_use]
    pub fn drain_events(&self) -> Vec<GraphicsEvent> {
        self.events.drain()
    }

    pub(crate) fn events(&self) -> &EventQueue {
        &self.events
    }

    /// Largest MSAA sample count ≤ `requested` the adapter supports for `format` (1, 2, 4, 8).
    #[must_use]
    pub fn supported_sample_count(&self, format: wgpu::TextureFormat, requested: u32) -> u32 {
        let flags = self.adapter.get_texture_format_features(format).flags;
        let depth_flags = self
            .adapter
            .get_texture_format_features(crate::DEPTH_FORMAT)
            .flags;
        [8, 4, 2]
            .into_iter()
            .find(|&n| {
                n <= requested
                    && flags.sample_count_supported(n)
                    && depth_flags.sample_count_supported(n)
            })
            .unwrap_or(1)
    }
}

/// `WGPU_ADAPTER_NAME` when set, else the default adapter, else the CPU fallback adapter.
async fn select_adapter(
    instance: &wgpu::Instance,
    surface: Option<&wgpu::Surface<'_>>,
) -> Result<wgpu::Adapter, GpuInitError> {
    if let Ok(requested) = std::env::var("WGPU_ADAPTER_NAME") {
        // Checked here because wgpu's own helper panics when the named adapter is absent.
        let wanted = requested.to_lowercase();
        let adapters = instance.enumerate_adapters(wgpu::Backends::all()).await;
        let mut names = Vec::new();
        for adapter in adapters {
            let info = adapter.get_info();
            if surface.is_some_and(|s| !adapter.is_surface_supported(s)) {
                continue;
            }
            if info.name.to_lowercase().contains(&wanted) {
                return Ok(adapter);
            }
            names.push(format!("{} ({:?})", info.name, info.backend));
        }
        return Err(GpuInitError::NamedAdapterMissing {
            requested,
            available: if names.is_empty() {
                "none".to_owned()
            } else {
                names.join(", ")
            },
        });
    }
    match wgpu::util::initialize_adapter_from_env_or_default(instance, surface).await {
        Ok(adapter) => Ok(adapter),
        Err(first) => {
            tracing::warn!(error = %first, "no hardware adapter, trying the CPU fallback adapter");
            instance
                .request_adapter(&wgpu::RequestAdapterOptions {
                    power_preference: wgpu::PowerPreference::None,
                    force_fallback_adapter: true,
                    compatible_surface: surface,
                    ..Default::default()
                })
                .await
                .map_err(|fallback| GpuInitError::NoAdapter {
                    reason: format!("{first}; fallback: {fallback}"),
                })
        }
    }
}
