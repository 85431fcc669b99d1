//! Lights of a frame: the sky's ambient light, one directional "sun", point and spot lights,
//! and how each casts shadows.
//!
//! - `lights`: [`Lights`], everything that lights one frame.
//! - `directional_light`: [`DirectionalLight`], a light infinitely far away (cascaded shadows).
//! - `point_light`: [`PointLight`], a light at a point, in every direction (cube shadows).
//! - `spot_light`: [`SpotLight`], a light at a point inside a cone (one shadow map).
//! - `light_shadows`: [`LightShadows`], a light's shadow switch and bias settings.
//!
//! Units: a light of `intensity` 1 and white colour gives a white diffuse surface facing it
//! the brightness 1 (before exposure and tone mapping); point and spot lights fall off with
//! the inverse square of the distance (1 at 1 m), windowed smoothly to zero at `range`.

mod directional_light;
mod light_shadows;
mod lights;
mod point_light;
mod spot_light;

pub use directional_light::DirectionalLight;
pub use light_shadows::LightShadows;
pub use lights::{Lights, MAX_POINT_LIGHTS, MAX_SPOT_LIGHTS};
pub use point_light::PointLight;
pub use spot_light::SpotLight;
