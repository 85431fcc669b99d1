//! Shadows: a box lit from above darkens the ground under it (and only because of its
//! shadow), a lit ground shows no acne, a shadow starts where its caster touches the ground
//! (no peter-panning), and goldens of each shadow kind (sun cascades near and far, spot, point).

mod common;

use glam::{Mat4, Quat, Vec3};
use onyx_render::{
    Camera, DirectionalLight, DrawObject, LightShadows, Lights, Material, PointLight, RenderScene,
    Renderer, SpotLight,
};

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

fn ground(renderer: &Renderer, size: f32) -> DrawObject {
    DrawObject::new(
        renderer.builtin_meshes().plane,
        Material::color(0.8, 0.8, 0.8),
        Mat4::from_scale(Vec3::splat(size)),
    )
}

fn cube_at(renderer: &Renderer, position: Vec3, size: f32) -> DrawObject {
    DrawObject::new(
        renderer.builtin_meshes().cube,
        Material::color(0.9, 0.35, 0.2),
        Mat4::from_scale_rotation_translation(Vec3::splat(size), Quat::IDENTITY, position),
    )
}

fn sun_lights(direction: Vec3, shadows: bool) -> Lights {
    let sun = DirectionalLight::new(direction);
    let sun = sun.with_shadows(sun.shadows.with_enabled(shadows));
    Lights {
        ambient: Vec3::splat(0.2),
        sun: Some(sun),
        points: Vec::new(),
        spots: Vec::new(),
    }
}

/// Pixel of world point `p` seen by `camera` in a WIDTH × HEIGHT image.
fn pixel_of(camera: &Camera, p: Vec3) -> (u32, u32) {
    let clip = camera.view_projection(WIDTH as f32 / HEIGHT as f32) * p.extend(1.0);
    let ndc = clip.truncate() / clip.w;
    let x = ((ndc.x * 0.5 + 0.5) * WIDTH as f32) as u32;
    let y = ((0.5 - ndc.y * 0.5) * HEIGHT as f32) as u32;
    (x.min(WIDTH - 1), y.min(HEIGHT - 1))
}

/// Mean luminance (0..255) of the 3 × 3 pixels around `p`'s pixel.
fn brightness(image: &image::RgbaImage, camera: &Camera, p: Vec3) -> f32 {
    let (cx, cy) = pixel_of(camera, p);
    let mut sum = 0.0;
    for y in cy.saturating_sub(1)..=(cy + 1).min(HEIGHT - 1) {
        for x in cx.saturating_sub(1)..=(cx + 1).min(WIDTH - 1) {
            let [r, g, b, _] = image.get_pixel(x, y).0;
            sum += 0.2126 * f32::from(r) + 0.7152 * f32::from(g) + 0.0722 * f32::from(b);
        }
    }
    sum / 9.0
}

/// Brightness in a shadow on the floor and beside it, printed.
fn shadow_and_beside(
    image: &image::RgbaImage,
    camera: &Camera,
    shadow: Vec3,
    beside: Vec3,
) -> (f32, f32) {
    let (a, b) = (
        brightness(image, camera, shadow),
        brightness(image, camera, beside),
    );
    eprintln!("in the shadow {a:.1}, beside it {b:.1}");
    (a, b)
}

fn render(
    renderer: &mut Renderer,
    camera: Camera,
    lights: &Lights,
    objects: &[DrawObject],
) -> image::RgbaImage {
    let scene = RenderScene::new(camera, lights).with_objects(objects);
    common::render_image(renderer, WIDTH, HEIGHT, &scene)
}

#[test]
fn a_box_lit_from_above_casts_a_shadow_on_the_ground_under_it() {
    let mut renderer = common::renderer();
    let objects = [
        ground(&renderer, 12.0),
        cube_at(&renderer, Vec3::new(0.0, 1.5, 0.0), 1.0),
    ];
    let camera = Camera::perspective_look_at(Vec3::new(0.0, 4.0, 6.0), Vec3::ZERO, 0.9, 0.1, 100.0);
    let under = Vec3::new(0.0, 0.0, 0.2);
    let away = Vec3::new(2.5, 0.0, 0.2);
    for shadows in [true, false] {
        let lights = sun_lights(Vec3::NEG_Y, shadows);
        let image = render(&mut renderer, camera, &lights, &objects);
        let (dark, lit) = (
            brightness(&image, &camera, under),
            brightness(&image, &camera, away),
        );
        eprintln!("shadows {shadows}: under the box {dark:.1}, beside it {lit:.1}");
        if shadows {
            common::check_golden("shadow_under_box", &image);
            assert!(
                dark < 0.6 * lit,
                "ground under the box ({dark:.1}) is not in shadow (beside it {lit:.1})"
            );
        } else {
            assert!(
                (dark - lit).abs() < 0.1 * lit,
                "without shadows the ground should be even: {dark:.1} vs {lit:.1}"
            );
        }
    }
}

/// Acne darkens a lit surface in speckles and stripes where it shadows itself: with the
/// default biases, a ground lit at a grazing 25° must look the same with shadows on and off.
#[test]
fn a_lit_ground_at_a_grazing_angle_shows_no_shadow_acne() {
    let mut renderer = common::renderer();
    let objects = [ground(&renderer, 40.0)];
    let camera = Camera::perspective_look_at(
        Vec3::new(0.0, 3.0, 8.0),
        Vec3::new(0.0, 0.0, -4.0),
        0.9,
        0.1,
        100.0,
    );
    let direction = Vec3::new(1.0, -25f32.to_radians().tan(), 0.3);
    let on = render(
        &mut renderer,
        camera,
        &sun_lights(direction, true),
        &objects,
    );
    let off = render(
        &mut renderer,
        camera,
        &sun_lights(direction, false),
        &objects,
    );
    let mut worst = 0u8;
    let mut darker = 0usize;
    // Ground pixels only: the lower half of the image.
    for y in HEIGHT / 2..HEIGHT {
        for x in 0..WIDTH {
            let (a, b) = (on.get_pixel(x, y).0, off.get_pixel(x, y).0);
            let delta = b[1].saturating_sub(a[1]);
            worst = worst.max(delta);
            if delta > 6 {
                darker += 1;
            }
        }
    }
    assert_eq!(
        darker, 0,
        "{darker} ground pixels are darker with shadows on (acne), worst by {worst}/255"
    );
}

/// Peter-panning: too much bias detaches a shadow from its caster. A box standing on the
/// ground, lit at 45°, must shadow the ground right beside its foot.
#[test]
fn a_shadow_starts_at_the_foot_of_its_caster() {
    let mut renderer = common::renderer();
    let objects = [
        ground(&renderer, 12.0),
        cube_at(&renderer, Vec3::new(0.0, 0.5, 0.0), 1.0),
    ];
    let camera = Camera::perspective_look_at(
        Vec3::new(2.5, 3.0, 5.0),
        Vec3::new(0.8, 0.0, 0.0),
        0.7,
        0.1,
        100.0,
    );
    let lights = sun_lights(Vec3::new(1.0, -1.0, 0.0), true);
    let image = render(&mut renderer, camera, &lights, &objects);
    // The shadow covers x in 0.5..1.5, z in -0.5..0.5; a point 8 cm from the foot.
    let foot = brightness(&image, &camera, Vec3::new(0.58, 0.0, 0.3));
    let lit = brightness(&image, &camera, Vec3::new(0.58, 0.0, 1.2));
    eprintln!("beside the foot {foot:.1}, out of the shadow {lit:.1}");
    assert!(
        foot < 0.6 * lit,
        "ground 8 cm from the box's foot is lit ({foot:.1} vs {lit:.1}): the shadow is detached"
    );
}

/// Boxes 4 m to 45 m away along a long ground: each cascade draws its share, edges stay soft.
#[test]
fn sun_cascades_shadow_near_and_far() {
    let mut renderer = common::renderer();
    let mut objects = vec![ground(&renderer, 120.0)];
    for (i, distance) in [4.0f32, 10.0, 20.0, 32.0, 45.0].into_iter().enumerate() {
        let side = if i % 2 == 0 { -1.5 } else { 1.5 };
        let size = 0.8 + distance * 0.05;
        objects.push(cube_at(
            &renderer,
            Vec3::new(side, size * 0.5, -distance),
            size,
        ));
    }
    let camera = Camera::perspective_look_at(
        Vec3::new(0.0, 2.5, 2.0),
        Vec3::new(0.0, 0.0, -20.0),
        0.8,
        0.1,
        200.0,
    );
    let lights = sun_lights(Vec3::new(0.6, -1.0, 0.4), true);
    let image = render(&mut renderer, camera, &lights, &objects);
    common::check_golden("shadow_cascades", &image);
    let stats = renderer.stats();
    assert_eq!(stats.shadow_views, 3, "three cascades by default");
}

#[test]
fn spot_light_shadow() {
    let mut renderer = common::renderer();
    let objects = [
        ground(&renderer, 12.0),
        cube_at(&renderer, Vec3::new(0.0, 0.75, 0.0), 0.5),
    ];
    // From the left, so the shadow falls on the floor to the right of the box, in view.
    let spot = SpotLight::new(Vec3::new(-1.5, 3.0, 0.0), Vec3::new(0.6, -1.0, 0.0))
        .with_intensity(12.0)
        .with_cone(25f32.to_radians(), 40f32.to_radians())
        .with_shadows(LightShadows::local().with_enabled(true));
    let lights = Lights {
        ambient: Vec3::splat(0.05),
        sun: None,
        points: Vec::new(),
        spots: vec![spot],
    };
    let camera = Camera::perspective_look_at(Vec3::new(0.0, 4.0, 5.0), Vec3::ZERO, 0.9, 0.1, 100.0);
    let image = render(&mut renderer, camera, &lights, &objects);
    common::check_golden("shadow_spot", &image);
    // The ray from the light through the box's centre meets the floor at x ≈ 0.55.
    let (under, beside) = shadow_and_beside(
        &image,
        &camera,
        Vec3::new(0.6, 0.0, 0.0),
        Vec3::new(0.6, 0.0, 1.0),
    );
    assert!(
        under < 0.6 * beside,
        "spot shadow missing: in it {under:.1}, beside it {beside:.1}"
    );
}

#[test]
fn point_light_shadow() {
    let mut renderer = common::renderer();
    let objects = [
        ground(&renderer, 12.0),
        cube_at(&renderer, Vec3::new(0.0, 0.75, 0.0), 0.5),
    ];
    // From the left, so the shadow falls on the floor to the right of the box, in view.
    let point = PointLight::new(Vec3::new(-1.5, 2.5, 0.0))
        .with_intensity(10.0)
        .with_range(12.0)
        .with_shadows(LightShadows::local().with_enabled(true));
    let lights = Lights {
        ambient: Vec3::splat(0.05),
        sun: None,
        points: vec![point],
        spots: Vec::new(),
    };
    let camera = Camera::perspective_look_at(Vec3::new(0.0, 4.0, 5.0), Vec3::ZERO, 0.9, 0.1, 100.0);
    let image = render(&mut renderer, camera, &lights, &objects);
    common::check_golden("shadow_point", &image);
    // The ray from the light through the box's centre meets the floor at x ≈ 0.64.
    let (under, beside) = shadow_and_beside(
        &image,
        &camera,
        Vec3::new(0.65, 0.0, 0.0),
        Vec3::new(0.65, 0.0, 1.0),
    );
    assert!(
        under < 0.6 * beside,
        "point-light shadow missing: in it {under:.1}, beside it {beside:.1}"
    );
    assert_eq!(renderer.stats().shadow_views, 6, "one pass per cube face");
}
