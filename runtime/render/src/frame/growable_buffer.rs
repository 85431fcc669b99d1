//! [`GrowableBuffer`]: a GPU buffer reused every frame, grown geometrically when too small.

/// Smallest allocation, bytes.
const MIN_CAPACITY: u64 = 4096;

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

    /// Writes `bytes` at offset 0, growing the buffer first if needed; `true` when it grew (a
    /// new buffer: bind groups naming it must be rebuilt).
    pub(crate) fn write(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        bytes: &[u8],
    ) -> bool {
        let mut grew = false;
        let needed = bytes.len() as u64;
        if needed > self.capacity {
            self.capacity = needed.next_power_of_two().max(MIN_CAPACITY);
            tracing::debug!(
                label = self.label,
                bytes = self.capacity,
                "growing GPU buffer"
            );
            self.buffer = create(device, self.capacity, self.usage, self.label);
            grew = true;
        }
        if !bytes.is_empty() {
            queue.write_buffer(&self.buffer, 0, bytes);
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
