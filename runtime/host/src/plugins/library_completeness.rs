//! [`check_complete`]: refuses a library file that is cut short, before the loader maps it.
//!
//! A build can be caught half-written, and the dynamic loader maps segments that extend past
//! the end of a truncated file; touching them later kills the process with SIGBUS. On ELF
//! platforms the headers say how long the file must be, so a short file is refused up front.

use std::io::Read;
use std::path::Path;

/// The size the file's headers require, when it is larger than the file (`Some((needed,
/// actual))`); `None` when the file is complete or not an ELF file (the loader judges those).
pub fn truncation(path: &Path) -> std::io::Result<Option<(u64, u64)>> {
    let mut file = std::fs::File::open(path)?;
    let len = file.metadata()?.len();
    let mut header = [0u8; 64];
    if file.read(&mut header)? < 64 || &header[..4] != b"\x7fELF" || header[4] != 2 {
        return Ok(None); // not a 64-bit ELF file
    }
    let little = header[5] == 1;
    let u16_at = |b: &[u8], o: usize| {
        let v = [b[o], b[o + 1]];
        u64::from(if little {
            u16::from_le_bytes(v)
        } else {
            u16::from_be_bytes(v)
        })
    };
    let u64_at = |b: &[u8], o: usize| {
        let mut v = [0u8; 8];
        v.copy_from_slice(&b[o..o + 8]);
        if little {
            u64::from_le_bytes(v)
        } else {
            u64::from_be_bytes(v)
        }
    };
    let (phoff, phentsize, phnum) = (
        u64_at(&header, 0x20),
        u16_at(&header, 0x36),
        u16_at(&header, 0x38),
    );
    let (shoff, shentsize, shnum) = (
        u64_at(&header, 0x28),
        u16_at(&header, 0x3A),
        u16_at(&header, 0x3C),
    );
    let mut needed = shoff.saturating_add(shentsize.saturating_mul(shnum));
    needed = needed.max(phoff.saturating_add(phentsize.saturating_mul(phnum)));
    // Every loadable segment must be in the file.
    let bytes = std::fs::read(path)?;
    for i in 0..phnum {
        let at = phoff.saturating_add(i.saturating_mul(phentsize)) as usize;
        if at.saturating_add(56) > bytes.len() {
            break;
        }
        let p_type = u16_at(&bytes, at) | (u16_at(&bytes, at + 2) << 16);
        const PT_LOAD: u64 = 1;
        if p_type == PT_LOAD {
            let (offset, filesz) = (u64_at(&bytes, at + 8), u64_at(&bytes, at + 32));
            needed = needed.max(offset.saturating_add(filesz));
        }
    }
    Ok((needed > len).then_some((needed, len)))
}

/// Whether `path` is an ELF file that its own headers say is complete (`false` for other
/// formats, which need another way to tell).
pub fn is_complete_elf(path: &Path) -> bool {
    let mut magic = [0u8; 4];
    let is_elf = std::fs::File::open(path)
        .and_then(|mut f| f.read_exact(&mut magic))
        .is_ok()
        && &magic == b"\x7fELF";
    is_elf && matches!(truncation(path), Ok(None))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_complete_library_passes_and_a_cut_one_is_measured() {
        let exe = std::env::current_exe().unwrap();
        assert_eq!(
            truncation(&exe).unwrap(),
            None,
            "this test binary is complete"
        );
        let dir = tempfile::tempdir().unwrap();
        let cut = dir.path().join("cut");
        let bytes = std::fs::read(&exe).unwrap();
        std::fs::write(&cut, &bytes[..bytes.len() - 1]).unwrap();
        let (needed, actual) = truncation(&cut).unwrap().expect("one byte short is caught");
        assert_eq!(
            (needed, actual),
            (bytes.len() as u64, bytes.len() as u64 - 1)
        );
        std::fs::write(&cut, b"plain text").unwrap();
        assert_eq!(
            truncation(&cut).unwrap(),
            None,
            "non-ELF files are left to the loader"
        );
    }
}
