//! OBJ / MTL / texture files as people have them — the loaders' own test suites in
//! `../shared/fixtures/obj/` and files the tests write (a BOM, Windows paths, a FIFO):
//! each defect issue 16 lists, shown on a file. Reading needs no GPU; the few that draw say so.

mod common;

use std::path::{Path, PathBuf};

use glam::{DVec3, Vec3};
use onyx_render::{
    AssetReadError, ImportSettings, ModelLoadError, ModelSource, NormalMode, TextureLoadError,
    UpAxis,
};

/// The OBJ fixtures, or `None` (the test then skips, saying so).
fn fixture(relative: &str) -> Option<PathBuf> {
    common::fixture(&format!("obj/{relative}"))
}

fn load(path: &Path) -> ModelSource {
    load_with(path, &ImportSettings::default())
}

fn load_with(path: &Path, settings: &ImportSettings) -> ModelSource {
    match ModelSource::load(path, settings, 8192) {
        Ok(model) => model,
        Err(error) => panic!("{} did not load: {error}", path.display()),
    }
}

/// Triangles tobj reads from the same file (triangulated), the reference count.
fn tobj_triangles(path: &Path) -> Option<usize> {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj(path, &options).ok()?;
    Some(models.iter().map(|m| m.mesh.indices.len() / 3).sum())
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("onyx-obj-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    dir
}

fn write(path: &Path, bytes: impl AsRef<[u8]>) {
    if let Some(parent) = path.parent() {
        let _ = std::fs::create_dir_all(parent);
    }
    std::fs::write(path, bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
}

fn png(width: u32, height: u32, rgba: [u8; 4]) -> Vec<u8> {
    let image = image::RgbaImage::from_pixel(width, height, image::Rgba(rgba));
    let mut bytes = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .unwrap_or_else(|e| panic!("{e}"));
    bytes
}

fn material_names(model: &ModelSource) -> Vec<(String, [f32; 4])> {
    model
        .parts
        .iter()
        .map(|p| (p.material.name.clone(), p.material.base_color))
        .collect()
}

#[test]
fn counts_match_tobj_on_files_it_reads() {
    let files = [
        "tinyobj/cube.obj",
        "tinyobj/cornell_box.obj",
        "tinyobj/cornell_box_multimaterial.obj",
        "tobj/cornell_box.obj",
        "tobj/quad.obj",
        "tobj/triangle.obj",
        "assimp/box.obj",
        "assimp/spider.obj",
        "assimp/WusonOBJ.obj",
        "assimp/regr01.obj",
        "assimp/cube_usemtl.obj",
        "tinyobj/issue-92.obj",
    ];
    let mut checked = 0;
    for file in files {
        let Some(path) = fixture(file) else { return };
        let Some(expected) = tobj_triangles(&path) else {
            eprintln!("tobj does not read {file}; not compared");
            continue;
        };
        let model = load(&path);
        assert_eq!(
            model.triangle_count(),
            expected,
            "{file}: triangles against tobj"
        );
        checked += 1;
    }
    assert!(checked >= 8, "only {checked} files compared");
}

#[test]
fn a_latin1_comment_no_longer_rejects_the_file() {
    //! A single non-UTF-8 byte made the whole OBJ a "read error".
    let (Some(latin1), Some(plain)) = (
        fixture("derived/latin1_comment.obj"),
        fixture("tinyobj/cube.obj"),
    ) else {
        return;
    };
    let model = load(&latin1);
    assert_eq!(Some(model.triangle_count()), tobj_triangles(&plain));
    assert!(
        model.warnings.iter().any(|w| w.message.contains("Latin-1")),
        "expected a warning saying how it was read: {:?}",
        model.warnings
    );
    let names = material_names(&model);
    assert!(
        names
            .iter()
            .any(|(n, c)| n == "red" && c[..3] == [1.0, 0.0, 0.0]),
        "{names:?}"
    );
}

#[test]
fn a_utf8_bom_keeps_the_mtllib_line() {
    //! The BOM glued itself to `mtllib`, which was then silently dropped.
    let Some(path) = fixture("derived/utf8_bom.obj") else {
        return;
    };
    let model = load(&path);
    let names = material_names(&model);
    assert!(
        names
            .iter()
            .any(|(n, c)| n == "red" && c[..3] == [1.0, 0.0, 0.0]),
        "materials: {names:?}"
    );
    assert!(model.problems.is_empty(), "{:?}", model.problems);
}

#[test]
fn a_utf16_file_is_read_like_its_utf8_twin() {
    let (Some(utf16), Some(utf8)) = (fixture("assimp/box_UTF16BE.obj"), fixture("assimp/box.obj"))
    else {
        return;
    };
    let model = load(&utf16);
    assert_eq!(model.triangle_count(), load(&utf8).triangle_count());
    assert!(
        model.warnings.iter().any(|w| w.message.contains("UTF-16")),
        "{:?}",
        model.warnings
    );
}

#[test]
fn windows_texture_paths_are_found_beside_the_file() {
    //! `.\a.png`, `tex\b.png` and `C:\…\c.png` were never found.
    let dir = temp_dir("winpath");
    write(&dir.join("tex/b.png"), png(2, 2, [0, 255, 0, 255]));
    write(&dir.join("a.png"), png(2, 2, [255, 0, 0, 255]));
    write(&dir.join("c.png"), png(2, 2, [0, 0, 255, 255]));
    write(
        &dir.join("m.mtl"),
        "newmtl a\nmap_Kd .\\a.png\nnewmtl b\nmap_Kd tex\\b.png\nnewmtl c\nmap_Kd C:\\Users\\artist\\Desktop\\c.png\n",
    );
    let mut obj = String::from("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for m in ["a", "b", "c"] {
        obj.push_str(&format!("usemtl {m}\nf 1 2 3\n"));
    }
    write(&dir.join("model.obj"), obj);
    let model = load(&dir.join("model.obj"));
    assert!(model.problems.is_empty(), "{:?}", model.problems);
    assert_eq!(model.images.len(), 3);
    assert!(
        model.images.values().all(Option::is_some),
        "every texture decoded"
    );
}

#[test]
fn texture_options_are_not_part_of_the_file_name_and_scale_offset_apply() {
    let Some(path) = fixture("tinyobj/texture-options-issue-85.obj") else {
        return;
    };
    let model = load(&path);
    for problem in &model.problems {
        let text = problem.to_string();
        assert!(
            !text.contains("-o ") && !text.contains("-blendu"),
            "an option was read as a file name: {text}"
        );
    }
    assert!(
        model.warnings.iter().any(|w| w.message.contains("-blendu")),
        "{:?}",
        model.warnings
    );

    // `-s 2 2 -o 0.5 0`: u' = 2u + 0.5, v' = 2v, then v flipped to a top-left origin.
    let dir = temp_dir("texopt");
    write(&dir.join("t.png"), png(2, 2, [255; 4]));
    write(
        &dir.join("m.mtl"),
        "newmtl m\nmap_Kd -s 2 2 -o 0.5 0 t.png\n",
    );
    write(
        &dir.join("q.obj"),
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n",
    );
    let model = load(&dir.join("q.obj"));
    let uvs: Vec<[f32; 2]> = model.parts[0].mesh.vertices.iter().map(|v| v.uv).collect();
    assert_eq!(uvs, vec![[0.5, 1.0], [2.5, 1.0], [0.5, -1.0]]);
}

#[test]
fn every_mtllib_name_is_read_and_escaped_spaces_kept() {
    for file in [
        "tinyobj/mtllib-multiple-files-issue-112.obj",
        "tinyobj/mtl filename with whitespace issue46.obj",
    ] {
        let Some(path) = fixture(file) else { return };
        let model = load(&path);
        let libraries: Vec<_> = model
            .problems
            .iter()
            .filter(|p| matches!(p, ModelLoadError::Mtl { .. }))
            .collect();
        assert!(libraries.is_empty(), "{file}: {libraries:?}");
        assert!(
            !model
                .warnings
                .iter()
                .any(|w| w.message.contains("is not defined")),
            "{file}: a material was not found in any library: {:?}",
            model.warnings
        );
        assert!(model.parts.iter().all(|p| !p.material_missing));
    }
}

#[test]
fn polylines_are_skipped_with_one_warning_naming_the_line() {
    let Some(path) = fixture("tinyobj/line-prim.obj") else {
        return;
    };
    match ModelSource::load(&path, &ImportSettings::default(), 8192) {
        Ok(model) => {
            let lines: Vec<_> = model
                .warnings
                .iter()
                .filter(|w| w.message.contains("`l`"))
                .collect();
            assert_eq!(lines.len(), 1, "{:?}", model.warnings);
            assert_eq!(lines[0].line, Some(15));
        }
        Err(ModelLoadError::Empty { .. }) => {}
        Err(other) => panic!("{other}"),
    }
    // Lines only: no invisible triangles, a clear error.
    let Some(lines) = fixture("tobj/lines.obj") else {
        return;
    };
    match ModelSource::load(&lines, &ImportSettings::default(), 8192) {
        Err(error @ ModelLoadError::Empty { .. }) => {
            assert!(error.to_string().contains("lines.obj"))
        }
        other => panic!("a file of lines only must be Empty, got {other:?}"),
    }
}

#[test]
fn degenerate_faces_are_warned_not_turned_into_invisible_triangles() {
    // tinyobj's file has only one- and two-corner faces: nothing to draw, said plainly.
    let Some(path) = fixture("tinyobj/invalid-face-definition.obj") else {
        return;
    };
    match ModelSource::load(&path, &ImportSettings::default(), 8192) {
        Err(error @ ModelLoadError::Empty { .. }) => {
            assert!(error.to_string().contains("invalid-face-definition.obj"))
        }
        other => panic!("expected Empty, got {other:?}"),
    }
    let dir = temp_dir("degenerate");
    write(
        &dir.join("d.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1\nf 2 3\n",
    );
    let model = load(&dir.join("d.obj"));
    assert_eq!(model.triangle_count(), 1);
    let short: Vec<_> = model
        .warnings
        .iter()
        .filter(|w| w.message.contains("fewer than three corners"))
        .collect();
    assert_eq!(short.len(), 1, "{:?}", model.warnings);
    assert_eq!(short[0].line, Some(5));
    assert!(
        short[0].message.starts_with("2 face(s)"),
        "{}",
        short[0].message
    );
}

#[test]
fn a_concave_polygon_is_cut_inside_its_outline() {
    //! It was fan-triangulated: triangles folded over the outside (a washer became a disk).
    let Some(path) = fixture("assimp/concave_polygon.obj") else {
        return;
    };
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    let points: Vec<DVec3> = text
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let c: Vec<f64> = l
                .split_whitespace()
                .filter_map(|t| t.parse().ok())
                .collect();
            DVec3::new(c[0], c[1], c[2])
        })
        .collect();
    let face: Vec<usize> = text
        .lines()
        .find_map(|l| l.strip_prefix("f "))
        .map(|l| {
            l.split_whitespace()
                .filter_map(|t| t.split('/').next()?.parse::<usize>().ok())
                .map(|i| i - 1)
                .collect()
        })
        .unwrap_or_default();
    // Newell normal: its length is twice the polygon's area.
    let mut newell = DVec3::ZERO;
    for k in 0..face.len() {
        let (a, b) = (points[face[k]], points[face[(k + 1) % face.len()]]);
        newell += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    let area = newell.length() / 2.0;
    let model = load(&path);
    let mesh = &model.parts[0].mesh;
    let mut covered = 0.0;
    for t in mesh.indices.chunks_exact(3) {
        let p = |i: u32| Vec3::from(mesh.vertices[i as usize].position).as_dvec3();
        let n = (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
        assert!(
            n.dot(newell) >= 0.0,
            "triangle {t:?} is folded over the outline"
        );
        covered += n.length() / 2.0;
    }
    assert_eq!(mesh.triangle_count(), face.len() - 2);
    assert!(
        (covered - area).abs() < area * 1e-4,
        "triangles cover {covered}, the polygon is {area}"
    );
}

#[test]
fn generated_normals_keep_sharp_edges_and_honour_smoothing_groups() {
    // A cube without normals: every generated normal is its face's axis (90° > crease).
    let dir = temp_dir("crease");
    let mut cube = String::new();
    for z in [0, 1] {
        for y in [0, 1] {
            for x in [0, 1] {
                cube.push_str(&format!("v {x} {y} {z}\n"));
            }
        }
    }
    cube.push_str("f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
    write(&dir.join("cube.obj"), &cube);
    let model = load(&dir.join("cube.obj"));
    for v in &model.parts[0].mesh.vertices {
        let n = Vec3::from(v.normal);
        assert!(
            n.abs().max_element() > 0.9999,
            "normal {n} is rounded across an edge"
        );
    }
    let smooth = load_with(
        &dir.join("cube.obj"),
        &ImportSettings {
            normals: NormalMode::Smooth,
            ..Default::default()
        },
    );
    assert_eq!(
        smooth.parts[0].mesh.vertices.len(),
        8,
        "smooth: one vertex per corner"
    );

    // The same cube in one smoothing group is smooth whatever the crease angle.
    write(&dir.join("s1.obj"), format!("s 1\n{cube}"));
    let grouped = load(&dir.join("s1.obj"));
    assert_eq!(grouped.parts[0].mesh.vertices.len(), 8);
    let Some(path) = fixture("tinyobj/smoothing-group-two-squares.obj") else {
        return;
    };
    assert!(!load(&path).parts.is_empty());
}

#[test]
fn d_tr_and_bump_maps_are_carried_into_the_material() {
    let (Some(tr), Some(bump)) = (
        fixture("tinyobj/tr-and-d-issue-43.obj"),
        fixture("tinyobj/map-bump.obj"),
    ) else {
        return;
    };
    let model = load(&tr);
    assert!(
        model.parts.iter().any(|p| p.material.base_color[3] < 1.0),
        "{:?}",
        material_names(&model)
    );
    let model = load(&bump);
    assert!(
        model
            .parts
            .iter()
            .any(|p| p.material.bump_texture.is_some()),
        "no bump map carried"
    );
}

#[test]
fn real_world_oddities_load_with_a_warning_and_line() {
    //! `1.#IND`, an empty `usemtl` (Blender) and colours on some vertices rejected the file.
    let Some(nan) = fixture("tinyobj/test-nan.obj") else {
        return;
    };
    let model = load(&nan);
    assert!(
        model
            .warnings
            .iter()
            .any(|w| w.message.contains("NaN") && w.line.is_some()),
        "{:?}",
        model.warnings
    );
    let Some(colours) = fixture("assimp/only_a_part_of_vertexcolors.obj") else {
        return;
    };
    assert!(load(&colours).triangle_count() > 0);
    let dir = temp_dir("usemtl");
    write(
        &dir.join("e.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \nf 1 2 3\n",
    );
    assert_eq!(load(&dir.join("e.obj")).triangle_count(), 1);
    // What is really broken names its line.
    write(&dir.join("bad.obj"), "v 0 0 0\nv 1 0 0\n\nv 0 one 0\n");
    match ModelSource::load(&dir.join("bad.obj"), &ImportSettings::default(), 8192) {
        Err(error @ ModelLoadError::ObjParse { line: 4, .. }) => {
            assert!(
                error.to_string().contains("bad.obj") && error.to_string().contains("line 4"),
                "{error}"
            );
        }
        other => panic!("expected ObjParse at line 4, got {other:?}"),
    }
}

#[test]
fn import_settings_scale_and_turn_z_up_files() {
    let dir = temp_dir("import");
    write(&dir.join("z.obj"), "v 0 0 0\nv 1 0 0\nv 0 0 2\nf 1 2 3\n");
    let settings = ImportSettings {
        scale: 0.5,
        up_axis: UpAxis::Z,
        ..Default::default()
    };
    let model = load_with(&dir.join("z.obj"), &settings);
    let top = model.parts[0]
        .mesh
        .vertices
        .iter()
        .map(|v| v.position)
        .find(|p| p[1] > 0.0);
    assert_eq!(
        top,
        Some([0.0, 1.0, 0.0]),
        "+Z (2 units) must become +Y (1 m at scale 0.5)"
    );
}

#[cfg(unix)]
#[test]
fn devices_fifos_and_folders_are_refused_without_reading() {
    //! `/dev/zero` read until memory ran out; a FIFO hung the host forever.
    let dir = temp_dir("hostile");
    let fifo = dir.join("pipe.obj");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    let mut paths = vec![PathBuf::from("/dev/zero"), dir.clone()];
    if made.is_ok_and(|s| s.success()) {
        paths.push(fifo.clone());
    } else {
        eprintln!("mkfifo unavailable: FIFO case not checked");
    }
    for path in &paths {
        match ModelSource::load(path, &ImportSettings::default(), 8192) {
            Err(
                error @ ModelLoadError::Read {
                    source: AssetReadError::NotAFile { .. },
                    ..
                },
            ) => {
                assert!(
                    error.to_string().contains(&path.display().to_string()),
                    "{error}"
                );
            }
            other => panic!("{} must be refused unread, got {other:?}", path.display()),
        }
    }
    // A texture naming a device: one problem naming it, the model still there.
    write(&dir.join("m.mtl"), "newmtl z\nmap_Kd /dev/zero\n");
    write(
        &dir.join("t.obj"),
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl z\nf 1 2 3\ng b\nf 1 2 3\ng c\nf 1 2 3\n",
    );
    let model = load(&dir.join("t.obj"));
    assert_eq!(
        model.problems.len(),
        1,
        "one report per failing file: {:?}",
        model.problems
    );
    assert!(
        model.problems[0].to_string().contains("/dev/zero"),
        "{}",
        model.problems[0]
    );
}

#[test]
fn image_size_is_checked_from_the_header_and_big_images_are_downscaled() {
    //! A 16k PNG got the false hint "save it as PNG"; the size check ran after the decode.
    let small = png(64, 32, [10, 20, 30, 255]);
    let texture = onyx_render::texture::decode_texture_bytes(&small, Path::new("wide.png"), 16)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(texture.levels[0].dimensions(), (16, 8));
    assert_eq!(texture.original_size, (64, 32));
    assert!(texture.warning.is_some_and(|w| w.message.contains("64×32")));
    // A header claiming 100000 × 100000: refused from the header alone.
    let huge = with_png_size(&small, 100_000, 100_000);
    match onyx_render::texture::decode_texture_bytes(&huge, Path::new("huge.png"), 8192) {
        Err(error @ TextureLoadError::TooLarge { .. }) => {
            let text = error.to_string();
            assert!(
                text.contains("100000×100000") && !text.contains("save it as PNG"),
                "{text}"
            );
        }
        other => panic!("expected TooLarge, got {other:?}"),
    }
}

/// `png` with its IHDR width and height replaced (CRC recomputed).
fn with_png_size(png: &[u8], width: u32, height: u32) -> Vec<u8> {
    let mut out = png.to_vec();
    out[16..20].copy_from_slice(&width.to_be_bytes());
    out[20..24].copy_from_slice(&height.to_be_bytes());
    let crc = crc32(&out[12..29]);
    out[29..33].copy_from_slice(&crc.to_be_bytes());
    out
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}
