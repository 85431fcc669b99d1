//! Loading off the frame thread: model files and images read and decoded on worker threads,
//! handed back for the frame to upload when they are done.
//!
//! - `asset_loader`: [`AssetLoader`], the workers, what was asked of them and what came back.
//! - `loaded`: [`Loaded`], one finished load (a model or an image, or why it failed).

mod asset_loader;
mod loaded;

pub use asset_loader::AssetLoader;
pub use loaded::Loaded;
