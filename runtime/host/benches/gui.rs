//! The cost of plugin GUIs per frame.
//!
//! - a frame of a host with one plugin that draws no GUI (the default `draw_gui`: asked once,
//!   then skipped) vs one whose GUI is a window of a dozen widgets (its egui run inside the
//!   plugin, tessellation, the meshes and input crossing the boundary, the host gathering
//!   them), with and without the AccessKit tree tests use;
//! - painting that GUI over a 640 × 360 offscreen frame on the adapter the environment
//!   names (Mesa's CPU Vulkan driver here), vs the same frame without GUI.
//!
//! `cargo bench -p onyx-runtime --bench gui`

use std::hint::black_box;
use std::time::Instant;

use onyx_plugin_api::{egui, Ctx, Flow, Plugin};
use onyx_runtime::HeadlessHost;

/// Draws no GUI.
#[derive(Default)]
struct Idle;
impl Plugin for Idle {
    fn on_update(&mut self, _: &mut Ctx, dt: f32) -> Flow {
        black_box(dt);
        Flow::Continue
    }
}

/// A window with a dozen widgets, as a small tool panel has.
#[derive(Default)]
struct Panel {
    value: f32,
    checked: bool,
    text: String,
}
impl Plugin for Panel {
    fn draw_gui(&mut self, _: &mut Ctx, ui: &mut egui::Ui) {
        self.ui(ui);
    }
}

impl Panel {
    fn ui(&mut self, ui: &mut egui::Ui) {
        egui::Window::new("Inspector").show(ui.ctx(), |ui| {
            for i in 0..4 {
                ui.label(format!("Entity {i}"));
            }
            ui.add(egui::Slider::new(&mut self.value, 0.0..=10.0).text("mass"));
            ui.checkbox(&mut self.checked, "visible");
            ui.text_edit_singleline(&mut self.text);
            ui.horizontal(|ui| {
                for name in ["Play", "Pause", "Step"] {
                    let _ = ui.button(name);
                }
            });
            ui.separator();
            ui.collapsing("Transform", |ui| ui.label("x 0.0  y 1.0  z 0.0"));
        });
    }
}

fn host_with<P: Plugin>(plugin: P, accesskit: bool) -> HeadlessHost {
    let mut host = HeadlessHost::new();
    host.host_mut().gui_mut().set_accesskit(accesskit);
    host.add_plugin("bench", plugin).expect("attaches");
    host.step(5);
    host
}

/// Median time of one call of `f`, microseconds, over `runs` runs of `iters` calls.
fn median_us(runs: usize, iters: u32, mut f: impl FnMut()) -> f64 {
    let mut samples: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..iters {
                f();
            }
            start.elapsed().as_secs_f64() * 1e6 / f64::from(iters)
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[runs / 2]
}

/// The same UI run by egui directly in the host's image (the peer): one pass plus
/// tessellation, nothing crossing a boundary.
fn direct_egui_frame_us() -> f64 {
    let context = egui::Context::default();
    let mut panel = Panel::default();
    let mut time = 0.0;
    let mut frame = move || {
        time += 1.0 / 60.0;
        let raw = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 720.0),
            )),
            time: Some(time),
            ..Default::default()
        };
        let mut full = context.run_ui(raw, |ui| panel.ui(ui));
        full.textures_delta.clear();
        black_box(context.tessellate(std::mem::take(&mut full.shapes), full.pixels_per_point));
    };
    for _ in 0..5 {
        frame();
    }
    median_us(21, 100, frame)
}

fn main() {
    let mut idle = host_with(Idle, false);
    let idle_frame = median_us(21, 2_000, || {
        idle.step(1);
    });
    let mut panel = host_with(Panel::default(), false);
    let panel_frame = median_us(21, 100, || {
        panel.step(1);
    });
    let mut panel_ak = host_with(Panel::default(), true);
    let panel_ak_frame = median_us(21, 100, || {
        panel_ak.step(1);
    });
    let triangles: usize = panel
        .host()
        .gui()
        .frame()
        .primitives
        .iter()
        .map(|p| match &p.primitive {
            egui::epaint::Primitive::Mesh(m) => m.indices.len() / 3,
            egui::epaint::Primitive::Callback(_) => 0,
        })
        .sum();

    let direct = direct_egui_frame_us();
    println!("GUI cost per frame (median, µs)");
    println!("  frame, one plugin without GUI        {idle_frame:9.2}");
    println!(
        "  frame, one plugin with a tool window {panel_frame:9.2}  (+{:.2} for the GUI, {triangles} triangles)",
        panel_frame - idle_frame
    );
    println!(
        "  same, with the AccessKit tree        {panel_ak_frame:9.2}  (+{:.2})",
        panel_ak_frame - panel_frame
    );
    println!(
        "  peer: the same UI run by egui in-process (pass + tessellate) {direct:9.2}  (boundary + host: +{:.2})",
        panel_frame - idle_frame - direct
    );

    let (Ok(_), Ok(_)) = (idle.screenshot(640, 360), panel.screenshot(640, 360)) else {
        println!("  painting: no adapter, skipped");
        return;
    };
    let paint_idle = median_us(7, 5, || {
        black_box(idle.screenshot(640, 360).ok());
    });
    let paint_panel = median_us(7, 5, || {
        black_box(panel.screenshot(640, 360).ok());
    });
    println!("  640x360 offscreen frame + readback, no GUI   {paint_idle:9.1}");
    println!(
        "  640x360 offscreen frame + readback, with GUI {paint_panel:9.1}  (+{:.1} to paint the GUI)",
        paint_panel - paint_idle
    );
}
