//! The library's loadable segments, and lookups from addresses to file bytes that stay inside
//! them: the loader reads every table where it is mapped, not where the file says it is.

use object::elf;
use std::ops::Range;

use object::read::elf::{Dyn as _, ProgramHeader as _};
use object::{Endianness, ReadRef as _};

use super::{damaged, LibraryProblem};

/// Largest thread-local block and alignment accepted (the loader allocates them per thread).
const MAX_TLS_SIZE: u64 = 256 << 20;

const MAX_ALIGN: u64 = 1 << 16;

/// Largest span of memory a library may ask to be mapped.
const MAX_IMAGE_SPAN: u64 = 1 << 40;

/// One `PT_LOAD` segment.
#[derive(Clone, Copy, Debug)]
pub(super) struct Load {
    vaddr: u64,
    memsz: u64,
    offset: u64,
    filesz: u64,
    flags: u32,
}

impl Load {
    fn memory(&self) -> Range<u64> {
        self.vaddr..self.vaddr + self.memsz
    }
}

/// The file and its segments: address → bytes lookups, all bounds-checked.
pub(super) struct Image<'a> {
    pub(super) data: &'a [u8],
    pub(super) endian: Endianness,
    pub(super) machine: u16,
    pub(super) loads: Vec<Load>,
    /// Where the program headers are in the file, and their size.
    pub(super) phoff: u64,
    pub(super) phsize: u64,
}

impl<'a> Image<'a> {
    /// The file bytes backing `size` bytes at address `addr`, all inside one segment's file
    /// part, which the loader can read.
    pub(super) fn bytes(
        &self,
        addr: u64,
        size: u64,
        what: &str,
    ) -> Result<&'a [u8], LibraryProblem> {
        let end = addr
            .checked_add(size)
            .ok_or_else(|| damaged(format!("its {what} wraps around the address space")))?;
        let load = self
            .loads
            .iter()
            .find(|l| l.vaddr <= addr && end <= l.vaddr + l.filesz)
            .ok_or_else(|| {
                damaged(format!(
                    "its {what} ({size} bytes at address {addr:#x}) is outside the file's segments"
                ))
            })?;
        if load.flags & elf::PF_R == 0 {
            return Err(damaged(format!(
                "its {what} is in a segment that cannot be read"
            )));
        }
        let offset = load.offset + (addr - load.vaddr);
        self.data
            .read_bytes_at(offset, size)
            .map_err(|()| damaged(format!("its {what} is outside the file")))
    }

    /// The file bytes from `addr` to the end of its segment's file part (for tables whose
    /// length is found by reading them).
    pub(super) fn bytes_from(&self, addr: u64, what: &str) -> Result<&'a [u8], LibraryProblem> {
        let load = self
            .loads
            .iter()
            .find(|l| l.vaddr <= addr && addr < l.vaddr + l.filesz)
            .ok_or_else(|| {
                damaged(format!(
                    "its {what} (at address {addr:#x}) is outside the file's segments"
                ))
            })?;
        self.bytes(addr, load.vaddr + load.filesz - addr, what)
    }

    /// The file offset of `size` bytes at `addr`, if one segment's file part holds them.
    pub(super) fn offset_of(&self, addr: u64, size: u64) -> Option<u64> {
        let end = addr.checked_add(size)?;
        self.loads
            .iter()
            .find(|l| l.vaddr <= addr && end <= l.vaddr + l.filesz)
            .map(|l| l.offset + (addr - l.vaddr))
    }

    /// Whether `addr` is inside the library's memory (its end included).
    pub(super) fn in_span(&self, addr: u64) -> bool {
        match (self.loads.first(), self.loads.last()) {
            (Some(first), Some(last)) => first.vaddr <= addr && addr <= last.vaddr + last.memsz,
            _ => false,
        }
    }

    /// Whether `size` bytes at `addr` are inside the library's memory, writable if `write`.
    pub(super) fn in_memory(&self, addr: u64, size: u64, write: bool) -> bool {
        let Some(end) = addr.checked_add(size) else {
            return false;
        };
        self.loads.iter().any(|l| {
            l.vaddr <= addr && end <= l.vaddr + l.memsz && (!write || l.flags & elf::PF_W != 0)
        })
    }

    pub(super) fn executable(&self, addr: u64) -> bool {
        self.loads
            .iter()
            .any(|l| l.memory().contains(&addr) && l.flags & elf::PF_X != 0)
    }
}

pub(super) fn loads(
    headers: &[elf::ProgramHeader64<Endianness>],
    endian: Endianness,
) -> Result<Vec<Load>, LibraryProblem> {
    let mut loads = Vec::new();
    for p in headers.iter().filter(|p| p.p_type(endian) == elf::PT_LOAD) {
        let load = Load {
            vaddr: p.p_vaddr(endian),
            memsz: p.p_memsz(endian),
            offset: p.p_offset(endian),
            filesz: p.p_filesz(endian),
            flags: p.p_flags(endian),
        };
        let align = p.p_align(endian);
        let n = loads.len();
        if load.filesz > load.memsz {
            return Err(damaged(format!(
                "its loadable segment {n} has more file bytes than memory"
            )));
        }
        if load.vaddr.checked_add(load.memsz).is_none() {
            return Err(damaged(format!(
                "its loadable segment {n} wraps around the address space"
            )));
        }
        if align > 1 && (!align.is_power_of_two() || load.vaddr % align != load.offset % align) {
            return Err(damaged(format!(
                "its loadable segment {n} is misaligned (alignment {align:#x})"
            )));
        }
        if let Some(last) = loads.last() {
            let last: &Load = last;
            if load.vaddr < last.vaddr + last.memsz {
                return Err(damaged(format!(
                    "its loadable segment {n} overlaps or precedes the one before it"
                )));
            }
            if load.filesz > 0 && load.offset < last.offset + last.filesz {
                return Err(damaged(format!(
                    "its loadable segment {n} maps file bytes the one before it maps too"
                )));
            }
        }
        loads.push(load);
    }
    let (Some(first), Some(last)) = (loads.first(), loads.last()) else {
        return Err(damaged("it has no loadable segment"));
    };
    if last.vaddr + last.memsz - first.vaddr > MAX_IMAGE_SPAN {
        return Err(damaged(
            "its segments span more memory than any library needs",
        ));
    }
    Ok(loads)
}

pub(super) fn check_segments(
    image: &Image<'_>,
    headers: &[elf::ProgramHeader64<Endianness>],
) -> Result<(), LibraryProblem> {
    let endian = image.endian;
    let mut dynamic = 0;
    for p in headers {
        let (vaddr, memsz, filesz) = (p.p_vaddr(endian), p.p_memsz(endian), p.p_filesz(endian));
        let kind = p.p_type(endian);
        // The loader finds these by address, tools by file offset: both must agree.
        if matches!(kind, elf::PT_DYNAMIC | elf::PT_TLS | elf::PT_PHDR) && filesz > 0 {
            let offset = image.offset_of(vaddr, filesz);
            if offset != Some(p.p_offset(endian)) {
                return Err(damaged(format!(
                    "its segment of type {kind:#x} is at an address that does not match its \
                     place in the file"
                )));
            }
        }
        match kind {
            elf::PT_DYNAMIC => {
                dynamic += 1;
                if vaddr % 8 != 0 {
                    return Err(damaged("its dynamic section is misaligned"));
                }
            }
            elf::PT_PHDR if p.p_offset(endian) != image.phoff || filesz != image.phsize => {
                return Err(damaged(
                    "its program-header segment does not match its header",
                ));
            }
            elf::PT_TLS => {
                let align = p.p_align(endian);
                if filesz > memsz
                    || memsz > MAX_TLS_SIZE
                    || align > MAX_ALIGN
                    || (align > 1 && !align.is_power_of_two())
                {
                    return Err(damaged(
                        "its thread-local segment has an impossible size or alignment",
                    ));
                }
                image.bytes(vaddr, filesz, "thread-local data")?;
            }
            elf::PT_GNU_RELRO if !image.in_memory(vaddr, memsz, false) => {
                return Err(damaged(
                    "its read-only-after-relocation segment is outside its memory",
                ));
            }
            _ => {}
        }
    }
    match dynamic {
        1 => Ok(()),
        0 => Err(damaged("it has no dynamic section")),
        _ => Err(damaged("it has more than one dynamic section")),
    }
}

/// The dynamic section's entries, up to `DT_NULL`, as (tag, value).
pub(super) fn dynamic_entries(
    image: &Image<'_>,
    headers: &[elf::ProgramHeader64<Endianness>],
) -> Result<Vec<(u64, u64)>, LibraryProblem> {
    let endian = image.endian;
    let segment = headers
        .iter()
        .find(|p| p.p_type(endian) == elf::PT_DYNAMIC)
        .ok_or_else(|| damaged("it has no dynamic section"))?;
    // The loader reads the section where it is mapped.
    let bytes = image.bytes(
        segment.p_vaddr(endian),
        segment.p_filesz(endian),
        "dynamic section",
    )?;
    let entries: &[elf::Dyn64<Endianness>] = object::pod::slice_from_bytes(
        bytes,
        bytes.len() / std::mem::size_of::<elf::Dyn64<Endianness>>(),
    )
    .map(|(entries, _)| entries)
    .map_err(|()| damaged("its dynamic section is misaligned"))?;
    let mut out = Vec::new();
    for entry in entries {
        let tag = entry.d_tag(endian);
        if tag == u64::from(elf::DT_NULL) {
            return Ok(out);
        }
        out.push((tag, entry.d_val(endian)));
    }
    Err(damaged("its dynamic section has no end marker"))
}
