//! End-to-end tests of the host with real plugins. One test binary (one link of the
//! runtime), one module per area.

mod asset_loading;
mod asset_reload;
mod cli;
mod ctx_api;
mod dev_loop;
mod editor;
mod examples;
mod faults;
mod fuzz;
mod gltf_scenes;
mod gui;
mod hardening;
mod hierarchy;
mod host_services;
mod joints;
mod lifecycle;
mod loading;
mod made_assets;
mod native_failures;
mod physics;
mod physics_presets_cli;
mod physics_scenes;
mod registry;
mod reload;
mod reload_images;
mod render;
mod scenes;
mod schema_changes;
mod shading;
