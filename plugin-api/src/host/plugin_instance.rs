//! [`PluginInstance`]: one live plugin object, called through the ABI.

use std::sync::Arc;

use abi_stable::sabi_trait::TD_Opaque;
use abi_stable::std_types::{RSlice, RStr, Tuple2};

use super::plugin_library::LibraryImage;
use crate::__ffi::{
    new_plugin_box, AttachInfoFfi, EventFfi, GuiInputFfi, HostBridge, HostObject_TO, PluginBox,
};
use crate::host::{CallError, GuiInput, GuiOutput, HostServices};
use crate::{AttachInfo, Event, Flow, Plugin};

/// A plugin object, from a library or from an in-process value — both go through the same
/// ABI adapter, so a test of an in-process plugin exercises the same path as a loaded one.
///
/// Every method passes `host` to the plugin for the duration of the call, and returns the
/// plugin's panic or error as a [`CallError`].
pub struct PluginInstance {
    object: PluginBox,
    /// The image the object's code lives in (`None` in-process); declared after `object`, so
    /// it is released after the object is dropped.
    _image: Option<Arc<LibraryImage>>,
}

impl std::fmt::Debug for PluginInstance {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PluginInstance")
            .field("name", &self.name())
            .finish()
    }
}

macro_rules! with_host {
    ($host:expr, |$h:ident| $body:expr) => {{
        let mut bridge = HostBridge($host);
        let $h = HostObject_TO::from_ptr(&mut bridge, TD_Opaque);
        $body.into_result().map_err(CallError::from)
    }};
}

impl PluginInstance {
    pub(crate) fn from_library(object: PluginBox, image: Arc<LibraryImage>) -> Self {
        Self {
            object,
            _image: Some(image),
        }
    }

    /// Wraps an in-process plugin value under `name`.
    pub fn from_plugin<P: Plugin>(name: &'static str, plugin: P) -> Result<Self, CallError> {
        let object = new_plugin_box(name, || plugin)
            .into_result()
            .map_err(CallError::from)?;
        Ok(Self {
            object,
            _image: None,
        })
    }

    /// The plugin's name.
    pub fn name(&self) -> &str {
        self.object.name().as_str()
    }

    /// Calls `on_attach`.
    pub fn on_attach<H: HostServices + ?Sized>(
        &mut self,
        host: &mut H,
        info: &AttachInfo,
    ) -> Result<(), CallError> {
        let pairs: Vec<Tuple2<RStr<'_>, RStr<'_>>> = info
            .settings
            .iter()
            .map(|(k, v)| Tuple2(k.as_str().into(), v.as_str().into()))
            .collect();
        let info = AttachInfoFfi {
            reload: info.reload,
            settings: RSlice::from_slice(&pairs),
        };
        with_host!(host, |h| self.object.on_attach(h, info))
    }

    /// Calls `on_init`.
    pub fn on_init<H: HostServices + ?Sized>(&mut self, host: &mut H) -> Result<(), CallError> {
        with_host!(host, |h| self.object.on_init(h))
    }

    /// Calls `on_event`.
    pub fn on_event<H: HostServices + ?Sized>(
        &mut self,
        host: &mut H,
        event: &Event,
    ) -> Result<(), CallError> {
        with_host!(host, |h| self.object.on_event(h, EventFfi::from(event)))
    }

    /// Calls `on_fixed_update`.
    pub fn on_fixed_update<H: HostServices + ?Sized>(
        &mut self,
        host: &mut H,
    ) -> Result<(), CallError> {
        with_host!(host, |h| self.object.on_fixed_update(h))
    }

    /// Calls `on_update`.
    pub fn on_update<H: HostServices + ?Sized>(
        &mut self,
        host: &mut H,
        dt: f32,
    ) -> Result<Flow, CallError> {
        with_host!(host, |h| self.object.on_update(h, dt))
    }

    /// Calls `on_render`.
    pub fn on_render<H: HostServices + ?Sized>(&mut self, host: &mut H) -> Result<(), CallError> {
        with_host!(host, |h| self.object.on_render(h))
    }

    /// Runs one GUI frame of the plugin (`draw_gui` inside its own egui context). `None`: the
    /// plugin does not override `draw_gui` — it will answer `None` for good, so stop calling.
    pub fn draw_gui<H: HostServices + ?Sized>(
        &mut self,
        host: &mut H,
        input: &GuiInput,
    ) -> Result<Option<GuiOutput>, CallError> {
        let json = input.to_json();
        let input = GuiInputFfi {
            raw_input_json: RSlice::from_slice(&json),
            accesskit: input.accesskit,
        };
        let output = with_host!(host, |h| self.object.draw_gui(h, input))?;
        Ok(output.active.then(|| GuiOutput::from(output)))
    }

    /// Calls `on_resize`.
    pub fn on_resize<H: HostServices + ?Sized>(
        &mut self,
        host: &mut H,
        width: u32,
        height: u32,
    ) -> Result<(), CallError> {
        with_host!(host, |h| self.object.on_resize(h, width, height))
    }

    /// Calls `on_detach`.
    pub fn on_detach<H: HostServices + ?Sized>(&mut self, host: &mut H) -> Result<(), CallError> {
        with_host!(host, |h| self.object.on_detach(h))
    }

    /// Calls `on_script` for one entity's script.
    pub fn on_script<H: HostServices + ?Sized>(
        &mut self,
        host: &mut H,
        call: &crate::ScriptCall,
    ) -> Result<(), CallError> {
        let params = call.params.to_string();
        let ffi = crate::__ffi::ScriptCallFfi {
            entity: call.entity,
            phase: call.phase,
            name: call.name.as_str().into(),
            params: params.as_str().into(),
            dt: call.dt,
        };
        with_host!(host, |h| self.object.on_script(h, ffi))
    }

    /// Calls `save_state`.
    pub fn save_state(&mut self) -> Result<Vec<u8>, CallError> {
        self.object
            .save_state()
            .into_result()
            .map(|bytes| bytes.into_vec())
            .map_err(CallError::from)
    }

    /// Calls `load_state`.
    pub fn load_state(&mut self, state: &[u8]) -> Result<(), CallError> {
        self.object
            .load_state(state.into())
            .into_result()
            .map_err(CallError::from)
    }

    /// Drops the plugin object now, inside the plugin's own image (a panic in its `Drop`
    /// comes back as an error). Call it before letting the instance go; afterwards every
    /// call answers an error.
    pub fn dispose(&mut self) -> Result<(), CallError> {
        self.object.dispose().into_result().map_err(CallError::from)
    }
}
