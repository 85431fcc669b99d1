//! Every Khronos glTF sample in `../shared/fixtures/gltf/` opened directly as a scene with
//! `onyx run --headless --scene FILE --screenshot S`: no crash, an image, each unsupported
//! feature named once. Skips, saying so, when the samples are absent.

use std::path::{Path, PathBuf};
use std::process::Command;

use onyx_tests::{gltf_samples, onyx_binary, target_dir};

/// One file per sample: its binary variant, else its glTF one, else any; plus loose files.
fn one_file_per_sample(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let Ok(entries) = std::fs::read_dir(dir) else {
        return files;
    };
    let mut entries: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
    entries.sort();
    for entry in entries {
        if onyx_render::mesh::is_gltf(&entry) {
            files.push(entry);
            continue;
        }
        let name = entry.file_name().map(|n| n.to_string_lossy().into_owned());
        let Some(name) = name else { continue };
        let found = ["glTF-Binary", "glTF", "glTF-Embedded"]
            .iter()
            .flat_map(|variant| {
                ["glb", "gltf"].map(|ext| entry.join(variant).join(format!("{name}.{ext}")))
            })
            .find(|p| p.is_file());
        files.extend(found);
    }
    files
}

#[test]
fn every_sample_opens_as_a_scene_and_screenshots_without_a_crash() {
    let Some(dir) = gltf_samples() else { return };
    let files = one_file_per_sample(&dir);
    assert!(files.len() >= 28, "found only {} samples", files.len());
    let out_dir = tempfile::tempdir().unwrap();
    for file in &files {
        let png = out_dir.path().join("shot.png");
        let _ = std::fs::remove_file(&png);
        let out = Command::new(onyx_binary())
            .args(["run", "--headless", "--frames", "3", "--size", "96x72"])
            .arg("--scene")
            .arg(file)
            .arg("--screenshot")
            .arg(&png)
            .env("ONYX_PLUGIN_PATH", target_dir())
            .env("RUST_LOG", "warn")
            .env("NO_COLOR", "1")
            .output()
            .expect("onyx runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            out.status.success(),
            "{}: exit {:?}\n{stderr}",
            file.display(),
            out.status
        );
        let image = onyx_render::image::open(&png)
            .unwrap_or_else(|e| panic!("{}: no screenshot ({e})\n{stderr}", file.display()))
            .to_rgba8();
        assert_eq!(image.dimensions(), (96, 72), "{}", file.display());
        // Each warning once: no line of the log repeats (timestamps stripped).
        let mut warnings: Vec<&str> = stderr
            .lines()
            .filter(|l| l.contains("WARN"))
            .map(|l| l.split_once("WARN").map_or(l, |(_, rest)| rest))
            .collect();
        let count = warnings.len();
        warnings.sort_unstable();
        warnings.dedup();
        assert_eq!(
            warnings.len(),
            count,
            "{}: a warning repeats:\n{stderr}",
            file.display()
        );
    }
}

#[test]
fn a_box_opened_as_a_scene_is_framed_by_the_default_camera() {
    let Some(dir) = gltf_samples() else { return };
    let out_dir = tempfile::tempdir().unwrap();
    let png = out_dir.path().join("box.png");
    let out = Command::new(onyx_binary())
        .args([
            "run",
            "--headless",
            "--frames",
            "2",
            "--size",
            "64x64",
            "--scene",
        ])
        .arg(dir.join("Box/glTF-Binary/Box.glb"))
        .arg("--screenshot")
        .arg(&png)
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env("RUST_LOG", "warn")
        .output()
        .expect("onyx runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let image = onyx_render::image::open(&png).unwrap().to_rgba8();
    // The box fills the middle of the frame and leaves the corners to the background.
    let centre = image.get_pixel(32, 32).0;
    let corner = image.get_pixel(1, 1).0;
    let differs = centre.iter().zip(corner).any(|(a, b)| a.abs_diff(b) > 24);
    assert!(
        differs,
        "centre {centre:?} looks like the corner {corner:?}: the box is not in view"
    );
}
