//! Precision at every distance: reverse-Z with an infinite far plane keeps surfaces a
//! millimetre apart apart a kilometre away, and camera-relative rendering makes a scene placed
//! 100 km from the world origin render the image it renders at the origin.

mod common;

use glam::{Mat4, Quat, Vec3};
use onyx_render::{
    Camera, DirectionalLight, DrawObject, Lights, Material, PointLight, RenderScene, ShadingMode,
};

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

/// With a conventional depth buffer (near 0.01 m) the two quads below get the same depth
/// value and fight; reverse-Z keeps 1 mm apart at 1 km.
#[test]
fn quads_a_millimetre_apart_seen_from_a_kilometre_do_not_fight() {
    let mut renderer = common::renderer();
    let plane = renderer.builtin_meshes().plane;
    // The plane faces +Y; turn it to face the camera on +Z. 60 m squares.
    let facing = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    let quad = |z: f32, material: Material| {
        DrawObject::new(
            plane,
            material,
            Mat4::from_scale_rotation_translation(
                Vec3::splat(60.0),
                facing,
                Vec3::new(0.0, 0.0, z),
            ),
        )
    };
    let red = Material::color(1.0, 0.0, 0.0).with_shading(ShadingMode::Unlit);
    let green = Material::color(0.0, 1.0, 0.0).with_shading(ShadingMode::Unlit);
    // The far quad drawn last, so a depth test that cannot tell them apart shows it.
    let objects = [quad(0.001, green), quad(0.0, red)];
    let lights = Lights::default();
    // 0.1 rad: the view is 100 m high at 1 km, so the quads fill its middle.
    let camera = Camera::perspective_look_at(
        Vec3::new(0.0, 0.0, 1000.0),
        Vec3::ZERO,
        0.1,
        0.01,
        f32::INFINITY,
    );
    let scene = RenderScene::new(camera, &lights).with_objects(&objects);
    let image = common::render_image(&mut renderer, WIDTH, HEIGHT, &scene);
    let (mut inside, mut red_pixels) = (0, 0);
    for y in HEIGHT / 4..HEIGHT * 3 / 4 {
        for x in WIDTH / 4..WIDTH * 3 / 4 {
            let p = image.get_pixel(x, y).0;
            inside += 1;
            if p[0] >= p[1] {
                red_pixels += 1;
            }
        }
    }
    let centre = image.get_pixel(WIDTH / 2, HEIGHT / 2).0;
    assert!(
        centre[1] > 150 && centre[1] > centre[0] + 80,
        "centre pixel {centre:?} is not the near (green) quad"
    );
    assert_eq!(
        red_pixels, 0,
        "{red_pixels} of {inside} pixels show the far quad through the near one (depth fighting)"
    );
}

/// A ground, a box, a sphere, a sun with shadows and a point light, all shifted by `offset`,
/// and a camera shifted with them.
fn shifted_scene(
    renderer: &onyx_render::Renderer,
    offset: Vec3,
) -> (Vec<DrawObject>, Lights, Camera) {
    let meshes = *renderer.builtin_meshes();
    let at = |p: Vec3| offset + p;
    let objects = vec![
        DrawObject::new(
            meshes.plane,
            Material::color(0.7, 0.7, 0.7),
            Mat4::from_scale_rotation_translation(Vec3::splat(8.0), Quat::IDENTITY, at(Vec3::ZERO)),
        ),
        DrawObject::new(
            meshes.cube,
            Material::color(0.9, 0.35, 0.2),
            Mat4::from_rotation_translation(
                Quat::from_rotation_y(0.5),
                at(Vec3::new(-0.75, 0.5, 0.0)),
            ),
        ),
        DrawObject::new(
            meshes.sphere,
            Material::color(0.9, 0.9, 0.95).with_metallic_roughness(1.0, 0.3),
            Mat4::from_translation(at(Vec3::new(1.0, 0.5, 0.5))),
        ),
    ];
    let lights = Lights {
        ambient: Vec3::splat(0.3),
        sun: Some(DirectionalLight::new(Vec3::new(-0.4, -1.0, -0.3))),
        points: vec![PointLight::new(at(Vec3::new(1.5, 1.5, 2.0)))
            .with_color(Vec3::new(1.0, 0.6, 0.3))
            .with_intensity(3.0)],
        spots: Vec::new(),
    };
    let camera = Camera::perspective_look_at(
        at(Vec3::new(0.0, 2.5, 5.0)),
        at(Vec3::new(0.0, 0.3, 0.0)),
        0.9,
        0.1,
        200.0,
    );
    (objects, lights, camera)
}

/// Without camera-relative matrices, vertices 100 km out land on a 8 mm grid (f32) and the
/// image shears and shimmers; with them the image is the one at the origin.
#[test]
fn a_scene_100_km_from_the_origin_renders_the_image_it_renders_at_the_origin() {
    let mut renderer = common::renderer();
    let (objects, lights, camera) = shifted_scene(&renderer, Vec3::ZERO);
    let scene = RenderScene::new(camera, &lights).with_objects(&objects);
    let at_origin = common::render_image(&mut renderer, WIDTH, HEIGHT, &scene);
    common::check_golden("far_origin", &at_origin);

    let (objects, lights, camera) = shifted_scene(&renderer, Vec3::new(1.0e5, 0.0, -1.0e5));
    let scene = RenderScene::new(camera, &lights).with_objects(&objects);
    let far = common::render_image(&mut renderer, WIDTH, HEIGHT, &scene);
    let share = common::differing_share(&at_origin, &far);
    eprintln!(
        "far from the origin: {:.3} % of pixels differ",
        share * 100.0
    );
    assert!(
        share <= common::MAX_DIFF_SHARE,
        "100 km out {:.3} % of pixels differ from the image at the origin (allowed {:.3} %)",
        share * 100.0,
        common::MAX_DIFF_SHARE * 100.0
    );
}

/// The camera of [`shifted_scene`] moved by `step` small steps (1/64 m sideways, 1/128 m
/// forward: exact in f32 100 km out), always turned the same way.
fn stepped_camera(offset: Vec3, step: u32) -> Camera {
    let start = Vec3::new(0.0, 2.5, 5.0);
    let looking = Camera::perspective_look_at(start, Vec3::new(0.0, 0.3, 0.0), 0.9, 0.1, 200.0);
    let moved = Vec3::new(step as f32 / 64.0, 0.0, -(step as f32) / 128.0);
    Camera {
        position: offset + start + moved,
        ..looking
    }
}

/// While the camera moves by small steps, consecutive frames 100 km out change no more than
/// at the origin (no jitter of vertices or shadow edges), and every far frame is the frame at
/// the origin.
#[test]
fn a_camera_moving_in_small_steps_100_km_out_does_not_shimmer() {
    const STEPS: u32 = 5;
    let far_offset = Vec3::new(1.0e5, 0.0, -1.0e5);
    let frames = |offset: Vec3| {
        let mut renderer = common::renderer();
        let (objects, lights, _) = shifted_scene(&renderer, offset);
        (0..STEPS)
            .map(|step| {
                let scene =
                    RenderScene::new(stepped_camera(offset, step), &lights).with_objects(&objects);
                common::render_image(&mut renderer, WIDTH, HEIGHT, &scene)
            })
            .collect::<Vec<_>>()
    };
    let near = frames(Vec3::ZERO);
    let far = frames(far_offset);
    for step in 1..STEPS as usize {
        let near_change = common::differing_share(&near[step - 1], &near[step]);
        let far_change = common::differing_share(&far[step - 1], &far[step]);
        eprintln!(
            "step {step}: {:.3} % of pixels change at the origin, {:.3} % 100 km out",
            near_change * 100.0,
            far_change * 100.0
        );
        assert!(
            far_change <= near_change + 0.001,
            "step {step}: 100 km out {:.3} % of pixels change between frames, at the origin {:.3} %",
            far_change * 100.0,
            near_change * 100.0
        );
    }
    for (step, (a, b)) in near.iter().zip(&far).enumerate() {
        let share = common::differing_share(a, b);
        assert!(
            share <= common::MAX_DIFF_SHARE,
            "step {step}: the far frame differs from the one at the origin in {:.3} % of pixels",
            share * 100.0
        );
    }
}
