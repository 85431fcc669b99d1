//! [`PluginObject`]: a plugin as a `#[sabi_trait]` object, and [`PluginAdapter`], which
//! builds it from any safe [`Plugin`] and catches every panic inside the plugin's image.

// `#[sabi_trait]` expands to impls of abi_stable traits inside a generated module.
#![allow(missing_docs, non_camel_case_types, non_local_definitions)]

use std::cell::RefCell;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Once;

use abi_stable::{
    sabi_trait,
    std_types::{RBox, RResult, RSlice, RStr, RString, RVec},
};

use super::gui_ffi::{GuiInputFfi, GuiOutputFfi};
use super::plugin_gui::PluginGui;
use super::{AttachInfoFfi, CallFailure, EventFfi, FailureKind, HostRef, ScriptCallFfi};
use crate::{AttachInfo, Ctx, Event, Flow, Plugin};

#[sabi_trait]
pub trait PluginObject: Send {
    fn name(&self) -> RStr<'_>;
    fn on_attach<'a>(
        &mut self,
        host: HostRef<'a>,
        info: AttachInfoFfi<'a>,
    ) -> RResult<(), CallFailure>;
    fn on_init<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure>;
    fn on_event<'a>(&mut self, host: HostRef<'a>, event: EventFfi<'a>) -> RResult<(), CallFailure>;
    fn on_fixed_update<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure>;
    fn on_update<'a>(&mut self, host: HostRef<'a>, dt: f32) -> RResult<Flow, CallFailure>;
    fn on_render<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure>;
    fn draw_gui<'a>(
        &mut self,
        host: HostRef<'a>,
        input: GuiInputFfi<'a>,
    ) -> RResult<GuiOutputFfi, CallFailure>;
    fn on_resize<'a>(
        &mut self,
        host: HostRef<'a>,
        width: u32,
        height: u32,
    ) -> RResult<(), CallFailure>;
    fn on_detach<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure>;
    fn save_state(&mut self) -> RResult<RVec<u8>, CallFailure>;
    fn load_state(&mut self, state: RSlice<'_, u8>) -> RResult<(), CallFailure>;
    fn on_script<'a>(
        &mut self,
        host: HostRef<'a>,
        call: ScriptCallFfi<'a>,
    ) -> RResult<(), CallFailure>;
    /// Drops the plugin (and its GUI) now, inside this image's `catch_unwind`: a panic in
    /// the plugin's `Drop` becomes an error instead of aborting the process at the boundary.
    /// Every later call answers an error.
    fn dispose(&mut self) -> RResult<(), CallFailure>;
}

/// An owned plugin object.
pub type PluginBox = PluginObject_TO<'static, RBox<()>>;

thread_local! {
    /// Where the last panic on this thread happened, recorded by this image's panic hook.
    static LAST_PANIC_LOCATION: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Installs (once per image) a panic hook that records the panic's location so the fault
/// report can name it, then defers to the previous hook.
fn install_panic_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if let Some(location) = info.location() {
                let text = format!(
                    "{}:{}:{}",
                    location.file(),
                    location.line(),
                    location.column()
                );
                LAST_PANIC_LOCATION.with(|l| *l.borrow_mut() = Some(text));
            }
            previous(info);
        }));
    });
}

fn panic_message(payload: Box<dyn std::any::Any + Send>) -> String {
    let message = if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic with a non-string payload".to_owned()
    };
    match LAST_PANIC_LOCATION.with(|l| l.borrow_mut().take()) {
        Some(location) => format!("{message} (at {location})"),
        None => message,
    }
}

/// Runs `f`, turning a panic into a [`CallFailure`] so it never crosses `extern "C"`.
pub fn catch<T>(f: impl FnOnce() -> T) -> RResult<T, CallFailure> {
    install_panic_hook();
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(value) => RResult::ROk(value),
        Err(payload) => RResult::RErr(CallFailure {
            kind: FailureKind::Panicked,
            message: panic_message(payload).into(),
        }),
    }
}

fn returned(error: impl std::fmt::Display) -> CallFailure {
    CallFailure {
        kind: FailureKind::Returned,
        message: RString::from(error.to_string()),
    }
}

/// Holds a safe [`Plugin`] and exposes it as a [`PluginObject`], with the plugin's own
/// egui context. `None` once disposed.
pub struct PluginAdapter<P> {
    pub plugin: Option<P>,
    pub name: &'static str,
    pub gui: Option<PluginGui>,
}

fn disposed() -> CallFailure {
    CallFailure {
        kind: FailureKind::Returned,
        message: "the plugin was already dropped".into(),
    }
}

/// Runs `f` on the plugin inside `catch_unwind`, or answers an error once it was dropped.
fn live<P, T>(plugin: &mut Option<P>, f: impl FnOnce(&mut P) -> T) -> RResult<T, CallFailure> {
    match plugin {
        Some(plugin) => catch(|| f(plugin)),
        None => RResult::RErr(disposed()),
    }
}

impl<P> Drop for PluginAdapter<P> {
    /// A host that did not [`PluginObject::dispose`] the plugin first still must not abort:
    /// the drop runs inside `catch_unwind` (the panic is printed by the panic hook).
    fn drop(&mut self) {
        let (plugin, gui) = (self.plugin.take(), self.gui.take());
        if plugin.is_some() || gui.is_some() {
            let _ = catch(move || drop((plugin, gui)));
        }
    }
}

impl<P: Plugin> PluginObject for PluginAdapter<P> {
    fn name(&self) -> RStr<'_> {
        self.name.into()
    }

    fn on_attach<'a>(
        &mut self,
        host: HostRef<'a>,
        info: AttachInfoFfi<'a>,
    ) -> RResult<(), CallFailure> {
        let info = AttachInfo::from(info);
        live(&mut self.plugin, |p| {
            p.on_attach(&mut Ctx::new(host), &info)
        })
        .and_then(|r| r.map_err(returned).into())
    }

    fn on_init<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| p.on_init(&mut Ctx::new(host)))
    }

    fn on_event<'a>(&mut self, host: HostRef<'a>, event: EventFfi<'a>) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| {
            let event = Event::from(event);
            p.on_event(&mut Ctx::new(host), &event)
        })
    }

    fn on_fixed_update<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| p.on_fixed_update(&mut Ctx::new(host)))
    }

    fn on_update<'a>(&mut self, host: HostRef<'a>, dt: f32) -> RResult<Flow, CallFailure> {
        live(&mut self.plugin, |p| p.on_update(&mut Ctx::new(host), dt))
    }

    fn on_render<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| p.on_render(&mut Ctx::new(host)))
    }

    fn draw_gui<'a>(
        &mut self,
        host: HostRef<'a>,
        input: GuiInputFfi<'a>,
    ) -> RResult<GuiOutputFfi, CallFailure> {
        let Self { plugin, gui, .. } = self;
        let Some(gui) = gui else {
            return RResult::RErr(disposed());
        };
        live(plugin, |p| {
            let mut ctx = Ctx::new(host);
            gui.run(input, |ui| p.draw_gui(&mut ctx, ui))
        })
    }

    fn on_resize<'a>(
        &mut self,
        host: HostRef<'a>,
        width: u32,
        height: u32,
    ) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| {
            p.on_resize(&mut Ctx::new(host), width, height)
        })
    }

    fn on_detach<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| p.on_detach(&mut Ctx::new(host)))
    }

    fn save_state(&mut self) -> RResult<RVec<u8>, CallFailure> {
        live(&mut self.plugin, |p| p.save_state())
            .and_then(|r| r.map(RVec::from).map_err(returned).into())
    }

    fn load_state(&mut self, state: RSlice<'_, u8>) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| p.load_state(state.as_slice()))
            .and_then(|r| r.map_err(returned).into())
    }

    fn on_script<'a>(
        &mut self,
        host: HostRef<'a>,
        call: ScriptCallFfi<'a>,
    ) -> RResult<(), CallFailure> {
        live(&mut self.plugin, |p| {
            let call = crate::ScriptCall::from(call);
            p.on_script(&mut Ctx::new(host), &call)
        })
    }

    fn dispose(&mut self) -> RResult<(), CallFailure> {
        let (plugin, gui) = (self.plugin.take(), self.gui.take());
        catch(move || drop((plugin, gui)))
    }
}

/// Builds the plugin with `make` (inside `catch_unwind`) and boxes it as a [`PluginBox`].
pub fn new_plugin_box<P: Plugin>(
    name: &'static str,
    make: impl FnOnce() -> P,
) -> RResult<PluginBox, CallFailure> {
    catch(|| {
        PluginObject_TO::from_value(
            PluginAdapter {
                plugin: Some(make()),
                name,
                gui: Some(PluginGui::default()),
            },
            abi_stable::sabi_trait::TD_Opaque,
        )
    })
}
