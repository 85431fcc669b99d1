//! Models the project makes itself and commits: the files under `assets/` are exactly what
//! their generator writes (so nobody edits one by hand and loses the way back, and nothing
//! fetched from elsewhere hides among them). `ONYX_UPDATE_GOLDEN=1` rewrites them.

use std::path::Path;

use onyx_tests::vase;

#[test]
fn the_committed_vase_is_what_its_generator_makes() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/models/vase");
    if std::env::var_os("ONYX_UPDATE_GOLDEN").is_some() {
        vase::write(&dir).expect("write the vase");
        eprintln!("updated {}", dir.display());
        return;
    }
    let read = |name: &str| {
        std::fs::read_to_string(dir.join(name)).unwrap_or_else(|e| {
            panic!(
                "{}: {e} (ONYX_UPDATE_GOLDEN=1 makes it)",
                dir.join(name).display()
            )
        })
    };
    assert!(
        read(vase::OBJ) == vase::obj(),
        "{} differs from tests/src/vase.rs",
        vase::OBJ
    );
    assert!(
        read(vase::MTL) == vase::mtl(),
        "{} differs from tests/src/vase.rs",
        vase::MTL
    );
    // Pixels, not PNG bytes: another encoder version may compress the same image differently.
    let texture = onyx_render::image::open(dir.join(vase::TEXTURE))
        .expect("the vase texture decodes")
        .to_rgba8();
    assert!(
        texture == vase::texture(),
        "{} differs from tests/src/vase.rs",
        vase::TEXTURE
    );
}
