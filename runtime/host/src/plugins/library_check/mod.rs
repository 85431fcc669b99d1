//! [`check_library`]: refuses a library file the system's dynamic loader would crash on,
//! before it maps it.
//!
//! The loader (glibc's `ld.so`) trusts what an ELF file says about itself: where its segments
//! are, where the dynamic section points, how many symbols there are, which version each one
//! has, where each relocation writes. A file that is cut short, or damaged in one of those
//! tables, makes it read or write wild addresses inside the host process — a segfault no
//! handler can recover from, or an assertion that ends the process with status 127. So before
//! opening a library the host reads those same tables (with the `object` crate) and checks
//! that every offset, index and address stays inside the file and the library's own memory.
//!
//! What it cannot check is the machine code: damage there shows up only when that code runs,
//! and the crash report then names the plugin and stage. Non-ELF files (macOS, Windows) are
//! left to their platform's loader.
//!
//! - `image.rs`: the segments, and address → file lookups that stay inside them.
//! - `dynamic.rs`: the dynamic section's entries, its strings, and the tags that go together.
//! - `symbols.rs`: the hash tables (how many symbols there are) and the version tables.
//! - `relocations.rs`: every relocation's type, symbol and target; the initialiser arrays.

mod dynamic;
mod image;
mod relocations;
mod symbols;

use std::path::Path;

use object::elf;
use object::read::elf::{FileHeader as _, ProgramHeader as _};
use object::Endianness;

use dynamic::check_dynamic;
use image::{check_segments, dynamic_entries, loads, Image};

pub(super) type Header = elf::FileHeader64<Endianness>;

/// Why a library file would not load safely.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LibraryProblem {
    /// The file is shorter than its own headers say (a build caught half-written).
    #[error("its headers need {needed} bytes but the file has {actual}")]
    Truncated {
        /// Bytes the headers require.
        needed: u64,
        /// Bytes in the file.
        actual: u64,
    },
    /// A header or table points outside the file or the library's memory, or makes no sense.
    #[error("{0}")]
    Damaged(String),
}

pub(super) fn damaged(what: impl Into<String>) -> LibraryProblem {
    LibraryProblem::Damaged(what.into())
}

/// The ELF machine this host runs on, if it checks that.
pub(super) const HOST_MACHINE: Option<u16> = if cfg!(target_arch = "x86_64") {
    Some(elf::EM_X86_64)
} else if cfg!(target_arch = "aarch64") {
    Some(elf::EM_AARCH64)
} else {
    None
};

/// Checks `path` (see the module docs). `Ok` for a file that is not a 64-bit ELF library: its
/// platform's loader judges it.
pub fn check_library_file(path: &Path) -> std::io::Result<Result<(), LibraryProblem>> {
    let bytes = std::fs::read(path)?;
    Ok(check_library(&bytes))
}

/// Checks a library's bytes (see the module docs).
pub fn check_library(data: &[u8]) -> Result<(), LibraryProblem> {
    if data.len() < 5 || &data[..4] != b"\x7fELF" || data[4] != elf::ELFCLASS64 {
        return Ok(()); // not a 64-bit ELF file: the platform's loader says what it is
    }
    let header = Header::parse(data).map_err(|e| damaged(format!("its ELF header: {e}")))?;
    let endian = header
        .endian()
        .map_err(|e| damaged(format!("its ELF header: {e}")))?;
    let needed = truncation_of(header, endian, data);
    if needed > data.len() as u64 {
        return Err(LibraryProblem::Truncated {
            needed,
            actual: data.len() as u64,
        });
    }
    if header.e_type(endian) != elf::ET_DYN {
        return Err(damaged(format!(
            "it is not a shared library (ELF type {})",
            header.e_type(endian)
        )));
    }
    let machine = header.e_machine(endian);
    if HOST_MACHINE.is_some_and(|host| host != machine) {
        return Err(damaged(format!(
            "it is built for another processor (ELF machine {machine}, this host is {})",
            HOST_MACHINE.unwrap_or_default()
        )));
    }
    let headers = header
        .program_headers(endian, data)
        .map_err(|e| damaged(format!("its program headers: {e}")))?;
    let image = Image {
        data,
        endian,
        machine,
        loads: loads(headers, endian)?,
        phoff: header.e_phoff(endian),
        phsize: headers.len() as u64
            * std::mem::size_of::<elf::ProgramHeader64<Endianness>>() as u64,
    };
    check_segments(&image, headers)?;
    let dynamic = dynamic_entries(&image, headers)?;
    check_dynamic(&image, &dynamic)
}

/// The size the headers require: the header tables and every segment's file part.
fn truncation_of(header: &Header, endian: Endianness, data: &[u8]) -> u64 {
    let ph_end = header
        .e_phoff(endian)
        .saturating_add(u64::from(header.e_phentsize(endian)) * u64::from(header.e_phnum(endian)));
    let sh_end = header
        .e_shoff(endian)
        .saturating_add(u64::from(header.e_shentsize(endian)) * u64::from(header.e_shnum(endian)));
    let segments = header
        .program_headers(endian, data)
        .map(|headers| {
            headers
                .iter()
                .filter(|p| p.p_type(endian) == elf::PT_LOAD)
                .map(|p| p.p_offset(endian).saturating_add(p.p_filesz(endian)))
                .max()
                .unwrap_or(0)
        })
        .unwrap_or(0);
    ph_end.max(sh_end).max(segments)
}

/// What of an ELF library the system loader reads: the bytes up to the end of the last
/// segment (or of the program headers), and the ELF header with the section-header fields
/// cleared, to write in its place. `None` when that is the whole file or it is not a 64-bit
/// ELF file whose program headers parse (then the whole file is copied).
///
/// The loader maps segments through the program headers and never reads section headers;
/// what lies after the segments (debug info, the static symbol table, the section headers) is
/// only read by tools from the file, and a hot-reload copy is deleted as soon as it is mapped.
/// Copying without it makes each swap write less (a debug plugin is mostly debug info).
pub fn loaded_part(data: &[u8]) -> Option<(usize, Vec<u8>)> {
    const HEADER_LEN: usize = std::mem::size_of::<Header>();
    if data.len() < HEADER_LEN || &data[..4] != b"\x7fELF" || data[4] != elf::ELFCLASS64 {
        return None;
    }
    let header = Header::parse(data).ok()?;
    let endian = header.endian().ok()?;
    let ph_end = header
        .e_phoff(endian)
        .checked_add(u64::from(header.e_phentsize(endian)) * u64::from(header.e_phnum(endian)))?;
    let segments_end = header
        .program_headers(endian, data)
        .ok()?
        .iter()
        .map(|p| p.p_offset(endian).checked_add(p.p_filesz(endian)))
        .try_fold(0u64, |end, e| e.map(|e| end.max(e)))?;
    let end = usize::try_from(ph_end.max(segments_end))
        .ok()?
        .max(HEADER_LEN);
    if end >= data.len() {
        return None;
    }
    let mut new_header = *header;
    new_header.e_shoff = object::U64::new(endian, 0);
    new_header.e_shnum = object::U16::new(endian, 0);
    new_header.e_shstrndx = object::U16::new(endian, 0);
    Some((end, object::pod::bytes_of(&new_header).to_vec()))
}

/// Whether `path` is an ELF file that its own headers say is complete (`false` for other
/// formats, which need another way to tell). Reads only the ELF header and the program
/// headers (a few hundred bytes), not the file.
pub fn is_complete_elf(path: &Path) -> bool {
    use std::io::Read as _;
    let Ok(file) = std::fs::File::open(path) else {
        return false;
    };
    let Ok(len) = file.metadata().map(|m| m.len()) else {
        return false;
    };
    // The ELF header, then as far as the program headers reach (they follow it in every
    // library a linker writes; a table further in is read whole).
    let mut head = Vec::with_capacity(4096);
    if file.take(4096).read_to_end(&mut head).is_err() || head.len() < 64 {
        return false;
    }
    if &head[..4] != b"\x7fELF" || head[4] != elf::ELFCLASS64 {
        return false;
    }
    let Ok(header) = Header::parse(&*head) else {
        return false;
    };
    let Ok(endian) = header.endian() else {
        return false;
    };
    let ph_end = header
        .e_phoff(endian)
        .saturating_add(u64::from(header.e_phentsize(endian)) * u64::from(header.e_phnum(endian)));
    if ph_end > head.len() as u64 {
        let Ok(all) = std::fs::read(path) else {
            return false;
        };
        return needed_size(header_of(&all), &all).is_some_and(|needed| needed <= all.len() as u64);
    }
    needed_size(Some(header), &head).is_some_and(|needed| needed <= len)
}

fn header_of(data: &[u8]) -> Option<&Header> {
    Header::parse(data).ok()
}

/// The size `header` (whose program headers lie in `data`) says its file has.
fn needed_size(header: Option<&Header>, data: &[u8]) -> Option<u64> {
    let header = header?;
    let endian = header.endian().ok()?;
    Some(truncation_of(header, endian, data))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn this_library() -> Vec<u8> {
        // The test binary is an executable, not a library; any plugin cdylib next to it would
        // do, but unit tests cannot rely on the workspace being built. A shared library every
        // Linux machine has: the C library the test links.
        let maps = std::fs::read_to_string("/proc/self/maps").unwrap_or_default();
        let libc = maps
            .lines()
            .filter_map(|l| l.split_whitespace().nth(5))
            .find(|p| p.contains("/libc.so") || p.contains("/libc-"))
            .map(std::path::PathBuf::from);
        libc.and_then(|p| std::fs::read(p).ok()).unwrap_or_default()
    }

    #[test]
    fn the_c_library_passes() {
        let libc = this_library();
        if libc.is_empty() {
            eprintln!("skipped: no libc.so mapped (not glibc on Linux)");
            return;
        }
        assert_eq!(check_library(&libc), Ok(()));
    }

    #[test]
    fn a_cut_file_is_measured() {
        let libc = this_library();
        if libc.is_empty() {
            eprintln!("skipped: no libc.so mapped (not glibc on Linux)");
            return;
        }
        let cut = &libc[..libc.len() - 1];
        match check_library(cut) {
            Err(LibraryProblem::Truncated { needed, actual }) => {
                assert_eq!((needed, actual), (libc.len() as u64, libc.len() as u64 - 1))
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(
            check_library(b"plain text"),
            Ok(()),
            "not ELF: the loader judges"
        );
    }

    #[test]
    fn the_loaded_part_keeps_every_segment_and_drops_the_section_headers() {
        let libc = this_library();
        if libc.is_empty() {
            eprintln!("skipped: no libc.so mapped (not glibc on Linux)");
            return;
        }
        let Some((end, header)) = loaded_part(&libc) else {
            // A libc with nothing after its segments: nothing to drop.
            return;
        };
        assert!(end < libc.len());
        let mut copy = header.clone();
        copy.extend_from_slice(&libc[header.len()..end]);
        let parsed = Header::parse(&*copy).expect("still an ELF header");
        let endian = parsed.endian().unwrap();
        assert_eq!((parsed.e_shoff(endian), parsed.e_shnum(endian)), (0, 0));
        let original = Header::parse(&*libc).unwrap();
        let before = original.program_headers(endian, &*libc).unwrap();
        let after = parsed.program_headers(endian, &*copy).unwrap();
        assert_eq!(before.len(), after.len());
        for (b, a) in before.iter().zip(after) {
            // Past the ELF header (the first segment holds it, patched), byte for byte.
            let start = (b.p_offset(endian) as usize).max(header.len());
            let end = ((b.p_offset(endian) + b.p_filesz(endian)) as usize).max(start);
            assert_eq!(b.p_type(endian), a.p_type(endian));
            assert!(
                libc[start..end] == copy[start..end],
                "a segment's bytes changed"
            );
        }
        // And the loader's own check passes on what is written.
        assert_eq!(check_library(&copy), Ok(()));
        assert_eq!(
            loaded_part(b"not an ELF file at all, but long enough for a header....."),
            None
        );
    }

    #[test]
    fn completeness_is_read_from_the_headers_alone() {
        let libc = this_library();
        if libc.is_empty() {
            eprintln!("skipped: no libc.so mapped (not glibc on Linux)");
            return;
        }
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("libc-copy.so");
        std::fs::write(&path, &libc).unwrap();
        assert!(is_complete_elf(&path));
        // Cut anywhere after the headers: the headers still say how long it must be.
        for cut in [libc.len() / 3, libc.len() - 1] {
            std::fs::write(&path, &libc[..cut]).unwrap();
            assert!(!is_complete_elf(&path), "cut at {cut}");
        }
        std::fs::write(&path, &libc[..10]).unwrap();
        assert!(!is_complete_elf(&path), "a cut ELF header");
        std::fs::write(
            &path,
            b"plain text, long enough to hold an ELF header but not one",
        )
        .unwrap();
        assert!(!is_complete_elf(&path), "not ELF");
        assert!(!is_complete_elf(&dir.path().join("missing.so")));
    }
}
