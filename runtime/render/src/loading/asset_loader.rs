//! [`AssetLoader`]: model files and images read and decoded on worker threads, so the frame
//! that asks for them never waits; the frame takes back what is done and uploads it.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use super::loaded::Loaded;
use crate::mesh::{is_gltf, GltfFiles, ImportSettings, ModelSource, SubAsset};
use crate::model_material::ImageSource;
use crate::texture::decode_texture;

/// Most worker threads a loader starts (each may hold a large image while decoding it).
const MAX_WORKERS: usize = 4;

type Job<K> = Box<dyn FnOnce() -> Loaded<K> + Send>;

/// Loads on worker threads (started on the first request, up to [`MAX_WORKERS`], fewer on a
/// machine with fewer cores). Requests are served in order; [`AssetLoader::poll`] hands back
/// each finished one once, under the key it was asked for. The glTF files the loads of
/// `file.glb#mesh/N` name are read once for all the requests made before the first of them
/// finishes ([`GltfFiles`]). Dropping the loader lets the workers finish their current job
/// and end; nothing waits for them.
pub struct AssetLoader<K> {
    max_texture_side: u32,
    jobs: Option<Sender<Job<K>>>,
    done_tx: Sender<Loaded<K>>,
    done: Receiver<Loaded<K>>,
    workers: Vec<JoinHandle<()>>,
    pending: usize,
    files: GltfFiles,
}

impl<K> std::fmt::Debug for AssetLoader<K> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AssetLoader")
            .field("workers", &self.workers.len())
            .field("pending", &self.pending)
            .finish_non_exhaustive()
    }
}

impl<K: Clone + Send + 'static> AssetLoader<K> {
    /// A loader decoding images at most `max_texture_side` pixels a side (the GPU's limit:
    /// [`crate::Renderer::max_texture_side`]); no thread runs until the first request.
    #[must_use]
    pub fn new(max_texture_side: u32) -> Self {
        let (done_tx, done) = channel();
        Self {
            max_texture_side,
            jobs: None,
            done_tx,
            done,
            workers: Vec::new(),
            pending: 0,
            files: GltfFiles::default(),
        }
    }

    /// Asks for the model file at `path` (OBJ, glTF, `file.glb#mesh/N`) read with
    /// `settings`, its images decoded and its tangents generated.
    pub fn request_model(&mut self, key: K, path: &Path, settings: ImportSettings) {
        let (file, _) = SubAsset::split(path);
        let lease = is_gltf(&file).then(|| self.files.lease(&file));
        let max_side = self.max_texture_side;
        let path = path.to_owned();
        self.submit(key.clone(), path.clone(), move || {
            let result = ModelSource::load_leased(&path, &settings, max_side, lease.as_ref()).map(
                |mut source| {
                    source.generate_tangents();
                    source
                },
            );
            drop(lease);
            Loaded::Model { key, path, result }
        });
    }

    /// Asks for the image file at `path` decoded with its mip chain, as data (`linear`) or
    /// sRGB colour.
    pub fn request_texture(&mut self, key: K, path: &Path, linear: bool) {
        let max_side = self.max_texture_side;
        let path = path.to_owned();
        self.submit(key.clone(), path.clone(), move || {
            let result = decode_texture(&ImageSource::File(path.clone()), max_side);
            Loaded::Texture {
                key,
                path,
                linear,
                result,
            }
        });
    }

    /// Requests not handed back yet.
    #[must_use]
    pub fn pending(&self) -> usize {
        self.pending
    }

    /// The next finished load, if one is done (never waits).
    pub fn poll(&mut self) -> Option<Loaded<K>> {
        let loaded = self.done.try_recv().ok()?;
        self.pending -= 1;
        Some(loaded)
    }

    /// The next finished load, waiting until `deadline` for one; `None` when nothing is
    /// pending or the deadline passed.
    pub fn wait_until(&mut self, deadline: Instant) -> Option<Loaded<K>> {
        if self.pending == 0 {
            return None;
        }
        let left = deadline.saturating_duration_since(Instant::now());
        match self.done.recv_timeout(left.max(Duration::from_millis(1))) {
            Ok(loaded) => {
                self.pending -= 1;
                Some(loaded)
            }
            Err(RecvTimeoutError::Timeout | RecvTimeoutError::Disconnected) => None,
        }
    }

    /// Runs `work` on a worker; a panic inside becomes [`Loaded::Panicked`].
    fn submit(&mut self, key: K, path: PathBuf, work: impl FnOnce() -> Loaded<K> + Send + 'static) {
        let job: Job<K> = Box::new(move || {
            catch_unwind(AssertUnwindSafe(work)).unwrap_or_else(|payload| {
                let message = payload
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                    .unwrap_or_else(|| "no message".to_owned());
                Loaded::Panicked { key, path, message }
            })
        });
        self.pending += 1;
        let job = match &self.jobs {
            None => job,
            Some(jobs) => match jobs.send(job) {
                Ok(()) => return,
                Err(returned) => returned.0,
            },
        };
        // First request (or every worker gone): start the workers, then hand the job over.
        let (jobs, queue) = channel::<Job<K>>();
        let queue = Arc::new(Mutex::new(queue));
        let count = std::thread::available_parallelism()
            .map_or(2, std::num::NonZero::get)
            .clamp(1, MAX_WORKERS);
        self.workers.clear();
        for i in 0..count {
            let queue = queue.clone();
            let done = self.done_tx.clone();
            let spawned = std::thread::Builder::new()
                .name(format!("onyx-loader-{i}"))
                .spawn(move || loop {
                    let next = queue.lock().unwrap_or_else(PoisonError::into_inner).recv();
                    let Ok(job) = next else { return };
                    if done.send(job()).is_err() {
                        return;
                    }
                });
            match spawned {
                Ok(handle) => self.workers.push(handle),
                Err(error) => tracing::warn!(%error, "could not start an asset loader thread"),
            }
        }
        if self.workers.is_empty() {
            // No thread at all: load here rather than never.
            let loaded = job();
            let _ = self.done_tx.send(loaded);
            return;
        }
        let _ = jobs.send(job);
        self.jobs = Some(jobs);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loads_come_back_once_each_under_their_keys_failures_included() {
        let dir = std::env::temp_dir().join(format!("onyx-loader-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
        let png = dir.join("red.png");
        image::RgbaImage::from_pixel(8, 4, image::Rgba([255, 0, 0, 255]))
            .save(&png)
            .unwrap_or_else(|e| panic!("{e}"));
        let obj = dir.join("tri.obj");
        std::fs::write(&obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
            .unwrap_or_else(|e| panic!("{e}"));
        let mut loader = AssetLoader::new(4);
        loader.request_texture(1, &png, false);
        loader.request_texture(2, &dir.join("missing.png"), true);
        loader.request_model(3, &obj, ImportSettings::default());
        assert_eq!(loader.pending(), 3);
        let deadline = Instant::now() + Duration::from_secs(30);
        let mut done = Vec::new();
        while let Some(loaded) = loader.wait_until(deadline) {
            done.push(loaded);
        }
        assert_eq!(loader.pending(), 0, "every load came back");
        done.sort_by_key(|l| *l.key());
        match &done[..] {
            [Loaded::Texture {
                result: Ok(red),
                linear: false,
                ..
            }, Loaded::Texture {
                result: Err(_),
                linear: true,
                ..
            }, Loaded::Model {
                result: Ok(model), ..
            }] => {
                // Decoded at most 4 pixels a side, with its mips below.
                assert_eq!(red.levels[0].dimensions(), (4, 2));
                assert_eq!(red.original_size, (8, 4));
                assert_eq!(model.triangle_count(), 1);
            }
            other => panic!("{other:?}"),
        }
        assert!(loader.poll().is_none());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
