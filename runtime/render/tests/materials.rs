//! Goldens of the physically based material and the output path: a metallic × roughness
//! sphere grid, a normal map under a grazing light, blended quads sorted back to front, an
//! alpha mask, double-sided faces, and each tone-mapping operator on an HDR scene.

mod common;

use glam::{Mat4, Quat, Vec3};
use image::{Rgba, RgbaImage};
use onyx_render::{
    AlphaMode, Camera, DirectionalLight, DrawObject, Lights, Material, RenderScene, RenderSettings,
    Renderer, ShadingMode, ToneMapping,
};

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

fn render(
    renderer: &mut Renderer,
    camera: Camera,
    lights: &Lights,
    objects: &[DrawObject],
) -> RgbaImage {
    let scene = RenderScene::new(camera, lights).with_objects(objects);
    common::render_image(renderer, WIDTH, HEIGHT, &scene)
}

fn front_camera(distance: f32) -> Camera {
    Camera::perspective_look_at(Vec3::new(0.0, 0.0, distance), Vec3::ZERO, 0.8, 0.1, 100.0)
}

/// Rows: dielectric (bottom) and metal (top); columns: roughness 0.05 → 1.
#[test]
fn metallic_roughness_sphere_grid() {
    let mut renderer = common::renderer();
    let sphere = renderer.builtin_meshes().sphere;
    let mut objects = Vec::new();
    for (row, metallic) in [0.0f32, 1.0].into_iter().enumerate() {
        for column in 0..5 {
            let roughness = 0.05 + 0.95 * column as f32 / 4.0;
            objects.push(DrawObject::new(
                sphere,
                Material::color(0.9, 0.6, 0.3).with_metallic_roughness(metallic, roughness),
                Mat4::from_translation(Vec3::new(
                    column as f32 * 1.1 - 2.2,
                    row as f32 * 1.1 - 0.55,
                    0.0,
                )),
            ));
        }
    }
    let lights = Lights {
        sun: Some(DirectionalLight::new(Vec3::new(-0.5, -0.6, -1.0))),
        ..Lights::default()
    };
    let image = render(&mut renderer, front_camera(5.0), &lights, &objects);
    common::check_golden("pbr_sphere_grid", &image);
    // Smooth dielectric has a sharp bright highlight; the rough one none as bright.
    let smooth = image
        .pixels()
        .take((WIDTH * HEIGHT) as usize)
        .map(|p| p.0[1])
        .max()
        .unwrap_or(0);
    assert!(
        smooth > 200,
        "no specular highlight anywhere (brightest green {smooth})"
    );
}

/// A tangent-space normal map of bumps: rows of hemispheres.
fn bump_map(size: u32, bumps: u32) -> RgbaImage {
    let cell = size as f32 / bumps as f32;
    RgbaImage::from_fn(size, size, |x, y| {
        let u = (x as f32 + 0.5) % cell / cell * 2.0 - 1.0;
        let v = (y as f32 + 0.5) % cell / cell * 2.0 - 1.0;
        let r2 = u * u + v * v;
        // +Y up the image: v grows downwards, so the normal's y is -v.
        let n = if r2 < 0.8 {
            Vec3::new(u, -v, (1.0 - r2).max(0.0).sqrt() + 0.2).normalize()
        } else {
            Vec3::Z
        };
        let byte = |c: f32| ((c * 0.5 + 0.5) * 255.0).round() as u8;
        Rgba([byte(n.x), byte(n.y), byte(n.z), 255])
    })
}

#[test]
fn normal_map_under_a_grazing_light() {
    let mut renderer = common::renderer();
    let normals = renderer.add_data_texture(&bump_map(128, 4), "bumps");
    let plane = renderer.builtin_meshes().plane;
    let facing = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    let objects = [
        DrawObject::new(
            plane,
            Material::color(0.8, 0.8, 0.8).with_normal_map(Some(normals), 1.0),
            Mat4::from_scale_rotation_translation(
                Vec3::splat(2.0),
                facing,
                Vec3::new(-1.1, 0.0, 0.0),
            ),
        ),
        DrawObject::new(
            plane,
            Material::color(0.8, 0.8, 0.8),
            Mat4::from_scale_rotation_translation(
                Vec3::splat(2.0),
                facing,
                Vec3::new(1.1, 0.0, 0.0),
            ),
        ),
    ];
    // Light from the upper left, grazing the quads.
    let lights = Lights {
        ambient: Vec3::splat(0.1),
        sun: Some(DirectionalLight::new(Vec3::new(1.0, -1.0, -0.4))),
        ..Lights::default()
    };
    let image = render(&mut renderer, front_camera(4.0), &lights, &objects);
    common::check_golden("normal_map", &image);
    let spread = |x0: u32, x1: u32| {
        let values: Vec<u8> = (HEIGHT / 3..HEIGHT * 2 / 3)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .map(|(x, y)| image.get_pixel(x, y).0[1])
            .collect();
        values.iter().max().copied().unwrap_or(0) - values.iter().min().copied().unwrap_or(0)
    };
    let (mapped, flat) = (
        spread(WIDTH / 8, WIDTH * 3 / 8),
        spread(WIDTH * 5 / 8, WIDTH * 7 / 8),
    );
    assert!(
        mapped > flat + 40,
        "the normal map adds no relief: spread {mapped} vs flat {flat}"
    );
}

/// Three overlapping half-transparent quads given in a scrambled order: drawn back to front,
/// the nearest colour dominates where they overlap.
#[test]
fn blended_quads_are_sorted_back_to_front() {
    let mut renderer = common::renderer();
    let plane = renderer.builtin_meshes().plane;
    let facing = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    let quad = |x: f32, z: f32, color: [f32; 3]| {
        DrawObject::new(
            plane,
            Material::color(color[0], color[1], color[2])
                .with_shading(ShadingMode::Unlit)
                .with_alpha_mode(AlphaMode::Blend)
                .with_alpha(0.6),
            Mat4::from_scale_rotation_translation(Vec3::splat(1.6), facing, Vec3::new(x, 0.0, z)),
        )
    };
    let objects = [
        quad(0.0, 0.0, [0.0, 1.0, 0.0]),
        quad(0.6, 0.5, [0.0, 0.0, 1.0]),
        quad(-0.6, -0.5, [1.0, 0.0, 0.0]),
    ];
    let lights = Lights::default();
    let camera = front_camera(4.0);
    let image = render(&mut renderer, camera, &lights, &objects);
    common::check_golden("transparency_order", &image);
    assert_eq!(renderer.stats().blended, 3);
    // Where red (back) and green (middle) overlap, green is on top: green > red.
    let p = image.get_pixel(WIDTH / 2 - 12, HEIGHT / 2).0;
    assert!(
        p[1] > p[0],
        "green (nearer) under red (farther) at the overlap: {p:?}"
    );
    // Where green and blue (front) overlap, blue wins.
    let q = image.get_pixel(WIDTH / 2 + 14, HEIGHT / 2).0;
    assert!(
        q[2] > q[1],
        "blue (nearest) under green at the overlap: {q:?}"
    );
}

/// A checkerboard alpha cut at 0.5: holes show what is behind; back faces of a double-sided
/// quad are drawn, a single-sided one's are culled.
#[test]
fn alpha_mask_and_double_sided() {
    let mut settings = RenderSettings::deterministic();
    settings.sky_background = false;
    settings.clear_color = [0.0, 0.0, 0.0, 1.0];
    let mut renderer = common::renderer_with(settings);
    // 8 × 8 cells of 8 texels: crisp squares when magnified.
    let checker = RgbaImage::from_fn(64, 64, |x, y| {
        let a = if (x / 8 + y / 8) % 2 == 0 { 255 } else { 40 };
        Rgba([255, 255, 255, a])
    });
    let texture = renderer.add_texture(&checker, "checker");
    let meshes = *renderer.builtin_meshes();
    // Facing away from the camera (+Y plane turned to face -Z).
    let away = Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2);
    let objects = [
        DrawObject::new(
            meshes.plane,
            Material::textured(texture)
                .with_shading(ShadingMode::Unlit)
                .with_alpha_mode(AlphaMode::Mask {
                    cutoff: AlphaMode::DEFAULT_CUTOFF,
                })
                .with_double_sided(true),
            Mat4::from_scale_rotation_translation(
                Vec3::splat(1.8),
                away,
                Vec3::new(-1.0, 0.0, 0.0),
            ),
        ),
        DrawObject::new(
            meshes.plane,
            Material::color(1.0, 1.0, 1.0).with_shading(ShadingMode::Unlit),
            Mat4::from_scale_rotation_translation(Vec3::splat(1.8), away, Vec3::new(1.0, 0.0, 0.0)),
        ),
    ];
    let image = render(
        &mut renderer,
        front_camera(4.0),
        &Lights::default(),
        &objects,
    );
    common::check_golden("alpha_mask", &image);
    let left: Vec<u8> = (0..WIDTH / 2)
        .map(|x| image.get_pixel(x, HEIGHT / 2).0[0])
        .collect();
    let (white, black) = (
        left.iter().filter(|&&v| v > 120).count(),
        left.iter().filter(|&&v| v < 30).count(),
    );
    assert!(
        white > 10 && black > 10,
        "the double-sided masked quad shows no checker: {white} white, {black} black pixels"
    );
    let right = image.get_pixel(WIDTH * 3 / 4, HEIGHT / 2).0;
    assert!(
        right[0] < 30,
        "the single-sided quad's back face was drawn: {right:?}"
    );
}

/// A sun of intensity 6 and an emissive sphere of 8: each operator keeps its own curve.
#[test]
fn tone_mapping_operators() {
    let mut previous: Option<RgbaImage> = None;
    for (name, tone_mapping) in [
        ("tone_mapping_agx", ToneMapping::AgX),
        ("tone_mapping_aces", ToneMapping::Aces),
        ("tone_mapping_reinhard", ToneMapping::Reinhard),
    ] {
        let mut renderer =
            common::renderer_with(RenderSettings::deterministic().with_tone_mapping(tone_mapping));
        let meshes = *renderer.builtin_meshes();
        let objects = [
            DrawObject::new(
                meshes.sphere,
                Material::color(0.9, 0.2, 0.1),
                Mat4::from_translation(Vec3::new(-0.7, 0.0, 0.0)),
            ),
            DrawObject::new(
                meshes.sphere,
                Material::color(0.1, 0.1, 0.1).with_emissive([8.0, 4.0, 1.0]),
                Mat4::from_translation(Vec3::new(0.7, 0.0, 0.0)),
            ),
        ];
        let lights = Lights {
            sun: Some(DirectionalLight::new(Vec3::new(-0.3, -0.5, -1.0)).with_intensity(6.0)),
            ..Lights::default()
        };
        let image = render(&mut renderer, front_camera(3.0), &lights, &objects);
        common::check_golden(name, &image);
        if let Some(previous) = &previous {
            assert!(
                common::differing_share(previous, &image) > 0.05,
                "{name} looks like the previous operator"
            );
        }
        previous = Some(image);
    }
}
