//! [`GrowableBuffer`]: a GPU buffer reused every frame, grown geometrically when too small,
//! and [`Upload`]: how a frame's data reaches it.

/// Smallest allocation, bytes.
const MIN_CAPACITY: u64 = 4096;
/// Alignment of a staging allocation (copies between buffers need multiples of 4).
const COPY_ALIGNMENT: wgpu::BufferSize =
    wgpu::BufferSize::new(wgpu::COPY_BUFFER_ALIGNMENT).unwrap();

/// Where a frame's uploads go: copies recorded into the frame's encoder from a staging belt
/// whose mapped buffers are reused frame after frame. (`Queue::write_buffer` makes a fresh
/// staging buffer per call: for the 8 MB of 100,000 objects that cost page faults and an
/// unmap every frame, more than the culling itself.)
pub(crate) struct Upload<'a> {
    pub(crate) device: &'a wgpu::Device,
    pub(crate) belt: &'a mut wgpu::util::StagingBelt,
    pub(crate) encoder: &'a mut wgpu::CommandEncoder,
}

/// A GPU buffer that is rewritten each frame and only reallocated (to the next power of two)
/// when the data outgrows it.
#[derive(Debug)]
pub(crate) struct GrowableBuffer {
    buffer: wgpu::Buffer,
    capacity: u64,
    usage: wgpu::BufferUsages,
    label: &'static str,
}

impl GrowableBuffer {
    pub(crate) fn new(
        device: &wgpu::Device,
        usage: wgpu::BufferUsages,
        label: &'static str,
    ) -> Self {
        let usage = usage | wgpu::BufferUsages::COPY_DST;
        Self {
            buffer: create(device, MIN_CAPACITY, usage, label),
            capacity: MIN_CAPACITY,
            usage,
            label,
        }
    }

    /// Writes `bytes` (a multiple of 4 long) at offset 0 through `upload`, growing the buffer
    /// first if needed; `true` when it grew (a new buffer: bind groups naming it must be
    /// rebuilt).
    pub(crate) fn write(&mut self, upload: &mut Upload<'_>, bytes: &[u8]) -> bool {
        let mut grew = false;
        let needed = bytes.len() as u64;
        if needed > self.capacity {
            self.capacity = needed.next_power_of_two().max(MIN_CAPACITY);
            tracing::debug!(
                label = self.label,
                bytes = self.capacity,
                "growing GPU buffer"
            );
            self.buffer = create(upload.device, self.capacity, self.usage, self.label);
            grew = true;
        }
        if let Some(size) = wgpu::BufferSize::new(needed) {
            let staging = upload.belt.allocate(size, COPY_ALIGNMENT);
            // Not mappable only when the device is lost: the frame is lost with it.
            match staging.get_mapped_range_mut() {
                Ok(mut view) => {
                    view.copy_from_slice(bytes);
                    drop(view);
                    upload.encoder.copy_buffer_to_buffer(
                        staging.buffer(),
                        staging.offset(),
                        &self.buffer,
                        0,
                        needed,
                    );
                }
                Err(error) => tracing::debug!(label = self.label, %error, "upload skipped"),
            }
        }
        grew
    }

    pub(crate) fn buffer(&self) -> &wgpu::Buffer {
        &self.buffer
    }
}

fn create(
    device: &wgpu::Device,
    size: u64,
    usage: wgpu::BufferUsages,
    label: &str,
) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        usage,
        mapped_at_creation: false,
    })
}
