//! Golden-image tests: each shading mode, the grid, the Spot model with its texture, point
//! lights, an orthographic camera and debug lines, rendered on the CPU adapter with MSAA off
//! and compared with `tests/golden/*.png` (tolerance in `common`). Regenerate the references
//! with `ONYX_UPDATE_GOLDEN=1 cargo test --test golden`, then look at them.

mod common;

use glam::{Mat4, Quat, Vec3};
use onyx_render::{
    Camera, DebugCategories, DebugLine, DirectionalLight, DrawObject, Lights, Material, MeshData,
    PointLight, RenderScene, Renderer, ShadingMode,
};

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

fn camera() -> Camera {
    Camera::perspective_look_at(
        Vec3::new(0.0, 2.2, 4.5),
        Vec3::new(0.0, 0.3, 0.0),
        0.9,
        0.1,
        100.0,
    )
}

/// A cube, a sphere and a capsule in a row, all with `shading`.
fn three_shapes(renderer: &Renderer, shading: ShadingMode) -> Vec<DrawObject> {
    let meshes = *renderer.builtin_meshes();
    let tilt = Quat::from_rotation_y(0.6) * Quat::from_rotation_x(0.3);
    vec![
        DrawObject::new(
            meshes.cube,
            Material::color(0.9, 0.35, 0.2).with_shading(shading),
            Mat4::from_rotation_translation(tilt, Vec3::new(-1.5, 0.5, 0.0)),
        ),
        DrawObject::new(
            meshes.sphere,
            Material::color(0.2, 0.7, 0.3).with_shading(shading),
            Mat4::from_translation(Vec3::new(0.0, 0.5, 0.0)),
        ),
        DrawObject::new(
            meshes.capsule,
            Material::color(0.25, 0.4, 0.9).with_shading(shading),
            Mat4::from_translation(Vec3::new(1.5, 0.5, 0.0)),
        ),
    ]
}

fn render_mode(shading: ShadingMode) -> image::RgbaImage {
    let mut renderer = common::renderer();
    let objects = three_shapes(&renderer, shading);
    let lights = Lights::default();
    let scene = RenderScene::new(camera(), &lights).with_objects(&objects);
    common::render_image(&mut renderer, WIDTH, HEIGHT, &scene)
}

#[test]
fn unlit() {
    common::check_golden("unlit", &render_mode(ShadingMode::Unlit));
}

#[test]
fn lit_low() {
    common::check_golden("lit_low", &render_mode(ShadingMode::LitLow));
}

#[test]
fn normal() {
    common::check_golden("normal", &render_mode(ShadingMode::Normal));
}

#[test]
fn wireframe() {
    // Low-poly shapes so the edges stay apart at this size.
    let mut renderer = common::renderer();
    let sphere = renderer.add_mesh(&MeshData::sphere(0.5, 10, 6), "low-poly sphere");
    let capsule = renderer.add_mesh(&MeshData::capsule(0.3, 0.5, 8, 4), "low-poly capsule");
    let (Ok(sphere), Ok(capsule)) = (sphere, capsule) else {
        panic!("procedural meshes must be valid")
    };
    let mut objects = three_shapes(&renderer, ShadingMode::Wireframe);
    objects[1].mesh = sphere;
    objects[1].transform *= Mat4::from_scale(Vec3::splat(1.4));
    objects[2].mesh = capsule;
    let lights = Lights::default();
    let scene = RenderScene::new(camera(), &lights).with_objects(&objects);
    common::check_golden(
        "wireframe",
        &common::render_image(&mut renderer, WIDTH, HEIGHT, &scene),
    );
}

#[test]
fn lit_textured() {
    let mut renderer = common::renderer();
    let texture = match renderer.load_texture(common::assets().join("textures/uv_grid.png")) {
        Ok(texture) => texture,
        Err(error) => panic!("{error}"),
    };
    let meshes = *renderer.builtin_meshes();
    let objects = [
        DrawObject::new(
            meshes.cube,
            Material::textured(texture),
            Mat4::from_rotation_translation(Quat::from_rotation_y(0.7), Vec3::new(-0.9, 0.6, 0.0))
                * Mat4::from_scale(Vec3::splat(1.2)),
        ),
        DrawObject::new(
            meshes.sphere,
            Material::textured(texture),
            Mat4::from_translation(Vec3::new(1.0, 0.6, 0.0)) * Mat4::from_scale(Vec3::splat(1.2)),
        ),
    ];
    let lights = Lights::default();
    let scene = RenderScene::new(camera(), &lights).with_objects(&objects);
    common::check_golden(
        "lit_textured",
        &common::render_image(&mut renderer, WIDTH, HEIGHT, &scene),
    );
}

#[test]
fn grid() {
    let mut renderer = common::renderer();
    let lights = Lights::default();
    let camera = Camera::perspective_look_at(Vec3::new(4.0, 3.0, 6.0), Vec3::ZERO, 0.9, 0.1, 200.0);
    let scene = RenderScene::new(camera, &lights).with_grid(true);
    common::check_golden(
        "grid",
        &common::render_image(&mut renderer, WIDTH, HEIGHT, &scene),
    );
}

#[test]
fn spot_textured_cow() {
    let mut renderer = common::renderer();
    let model = match renderer.load_model(common::fixtures().join("spot/spot_triangulated.obj")) {
        Ok(model) => model,
        Err(error) => panic!("{error}"),
    };
    let objects: Vec<DrawObject> = model.draw_objects(Mat4::from_rotation_y(-2.3)).collect();
    let lights = Lights {
        ambient: Vec3::splat(0.3),
        ..Lights::default()
    };
    let camera = Camera::perspective_look_at(
        Vec3::new(0.0, 0.5, 2.6),
        Vec3::new(0.0, 0.05, 0.0),
        0.8,
        0.1,
        50.0,
    );
    let scene = RenderScene::new(camera, &lights)
        .with_objects(&objects)
        .with_grid(true);
    common::check_golden(
        "spot",
        &common::render_image(&mut renderer, WIDTH, HEIGHT, &scene),
    );
}

#[test]
fn point_lights() {
    let mut renderer = common::renderer();
    let meshes = *renderer.builtin_meshes();
    let white = Material::color(0.9, 0.9, 0.9);
    let objects = [
        DrawObject::new(
            meshes.plane,
            white,
            Mat4::from_scale(Vec3::new(8.0, 1.0, 8.0)),
        ),
        DrawObject::new(
            meshes.sphere,
            white,
            Mat4::from_translation(Vec3::new(0.0, 0.5, 0.0)),
        ),
        DrawObject::new(
            meshes.cylinder,
            white,
            Mat4::from_translation(Vec3::new(-1.6, 0.5, -0.5)),
        ),
        DrawObject::new(
            meshes.cube,
            white,
            Mat4::from_translation(Vec3::new(1.6, 0.5, -0.5)),
        ),
    ];
    let lights = Lights {
        ambient: Vec3::splat(0.03),
        sun: None,
        points: vec![
            PointLight::new(Vec3::new(-1.5, 1.2, 1.0))
                .with_color(Vec3::new(1.0, 0.2, 0.1))
                .with_intensity(4.0)
                .with_range(6.0),
            PointLight::new(Vec3::new(1.5, 1.2, 1.0))
                .with_color(Vec3::new(0.1, 0.3, 1.0))
                .with_intensity(4.0)
                .with_range(6.0),
            PointLight::new(Vec3::new(0.0, 2.0, -1.5))
                .with_color(Vec3::new(0.2, 1.0, 0.2))
                .with_intensity(3.0)
                .with_range(5.0),
        ],
        spots: Vec::new(),
    };
    let scene = RenderScene::new(camera(), &lights).with_objects(&objects);
    common::check_golden(
        "point_lights",
        &common::render_image(&mut renderer, WIDTH, HEIGHT, &scene),
    );
}

#[test]
fn orthographic_camera() {
    let mut renderer = common::renderer();
    let objects = three_shapes(&renderer, ShadingMode::LitLow);
    let lights = Lights {
        sun: Some(DirectionalLight {
            direction: Vec3::new(-0.3, -1.0, -0.5),
            ..DirectionalLight::default()
        }),
        ..Lights::default()
    };
    let camera = Camera::orthographic_look_at(
        Vec3::new(3.0, 3.0, 3.0),
        Vec3::new(0.0, 0.3, 0.0),
        4.0,
        -20.0,
        20.0,
    );
    let scene = RenderScene::new(camera, &lights)
        .with_objects(&objects)
        .with_grid(true);
    common::check_golden(
        "orthographic",
        &common::render_image(&mut renderer, WIDTH, HEIGHT, &scene),
    );
}

#[test]
fn debug_lines_by_category() {
    let mut renderer = common::renderer();
    let lights = Lights::default();
    let lines = [
        DebugLine::new(Vec3::ZERO, Vec3::new(1.5, 0.0, 0.0), [1.0, 0.0, 0.0, 1.0])
            .with_category(DebugCategories::GIZMOS),
        DebugLine::new(Vec3::ZERO, Vec3::new(0.0, 1.5, 0.0), [0.0, 1.0, 0.0, 1.0])
            .with_category(DebugCategories::GIZMOS),
        DebugLine::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.5), [0.0, 0.4, 1.0, 1.0])
            .with_category(DebugCategories::GIZMOS),
        // Hidden: its category is switched off below.
        DebugLine::new(
            Vec3::new(-1.0, 1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            [1.0, 1.0, 0.0, 1.0],
        )
        .with_category(DebugCategories::PHYSICS),
    ];
    let settings = renderer.settings().clone();
    let hide_physics = onyx_render::RenderSettings {
        debug_categories: DebugCategories::ALL.with(DebugCategories::PHYSICS, false),
        debug_line_width: 3.0,
        ..settings
    };
    if let Err(error) = renderer.set_settings(hide_physics) {
        panic!("{error}");
    }
    let scene = RenderScene::new(camera(), &lights).with_debug_lines(&lines);
    let image = common::render_image(&mut renderer, WIDTH, HEIGHT, &scene);
    assert_eq!(
        renderer.stats().debug_lines,
        3,
        "the physics line must be filtered out"
    );
    common::check_golden("debug_lines", &image);
}
