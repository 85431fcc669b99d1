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
/// egui context.
pub struct PluginAdapter<P> {
    pub plugin: P,
    pub name: &'static str,
    pub gui: PluginGui,
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
        catch(|| self.plugin.on_attach(&mut Ctx::new(host), &info))
            .and_then(|r| r.map_err(returned).into())
    }

    fn on_init<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        catch(|| self.plugin.on_init(&mut Ctx::new(host)))
    }

    fn on_event<'a>(&mut self, host: HostRef<'a>, event: EventFfi<'a>) -> RResult<(), CallFailure> {
        catch(|| {
            let event = Event::from(event);
            self.plugin.on_event(&mut Ctx::new(host), &event)
        })
    }

    fn on_fixed_update<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        catch(|| self.plugin.on_fixed_update(&mut Ctx::new(host)))
    }

    fn on_update<'a>(&mut self, host: HostRef<'a>, dt: f32) -> RResult<Flow, CallFailure> {
        catch(|| self.plugin.on_update(&mut Ctx::new(host), dt))
    }

    fn on_render<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        catch(|| self.plugin.on_render(&mut Ctx::new(host)))
    }

    fn draw_gui<'a>(
        &mut self,
        host: HostRef<'a>,
        input: GuiInputFfi<'a>,
    ) -> RResult<GuiOutputFfi, CallFailure> {
        let Self { plugin, gui, .. } = self;
        catch(|| {
            let mut ctx = Ctx::new(host);
            gui.run(input, |ui| plugin.draw_gui(&mut ctx, ui))
        })
    }

    fn on_resize<'a>(
        &mut self,
        host: HostRef<'a>,
        width: u32,
        height: u32,
    ) -> RResult<(), CallFailure> {
        catch(|| self.plugin.on_resize(&mut Ctx::new(host), width, height))
    }

    fn on_detach<'a>(&mut self, host: HostRef<'a>) -> RResult<(), CallFailure> {
        catch(|| self.plugin.on_detach(&mut Ctx::new(host)))
    }

    fn save_state(&mut self) -> RResult<RVec<u8>, CallFailure> {
        catch(|| self.plugin.save_state()).and_then(|r| r.map(RVec::from).map_err(returned).into())
    }

    fn load_state(&mut self, state: RSlice<'_, u8>) -> RResult<(), CallFailure> {
        catch(|| self.plugin.load_state(state.as_slice())).and_then(|r| r.map_err(returned).into())
    }

    fn on_script<'a>(
        &mut self,
        host: HostRef<'a>,
        call: ScriptCallFfi<'a>,
    ) -> RResult<(), CallFailure> {
        catch(|| {
            let call = crate::ScriptCall::from(call);
            self.plugin.on_script(&mut Ctx::new(host), &call)
        })
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
                plugin: make(),
                name,
                gui: PluginGui::default(),
            },
            abi_stable::sabi_trait::TD_Opaque,
        )
    })
}
