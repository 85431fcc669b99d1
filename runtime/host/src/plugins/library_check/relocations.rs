//! Relocations — what the loader writes into the library, and where — and the initialiser
//! arrays it calls through once they are written.

use std::collections::HashMap;

use object::elf;
use object::read::elf::Rela as _;
use object::Endianness;

use super::dynamic::{Dynamic, DT_RELR, DT_RELRENT, DT_RELRSZ};
use super::image::Image;
use super::{damaged, LibraryProblem};

/// The relocation types the host's loader handles in a shared library, by machine.
fn known_relocation(machine: u16, kind: u32) -> bool {
    match machine {
        elf::EM_X86_64 => matches!(
            kind,
            elf::R_X86_64_NONE
                | elf::R_X86_64_64
                | elf::R_X86_64_PC32
                | elf::R_X86_64_COPY
                | elf::R_X86_64_GLOB_DAT
                | elf::R_X86_64_JUMP_SLOT
                | elf::R_X86_64_RELATIVE
                | elf::R_X86_64_DTPMOD64
                | elf::R_X86_64_DTPOFF64
                | elf::R_X86_64_TPOFF64
                | elf::R_X86_64_TLSDESC
                | elf::R_X86_64_IRELATIVE
        ),
        elf::EM_AARCH64 => matches!(
            kind,
            elf::R_AARCH64_NONE
                | elf::R_AARCH64_ABS64
                | elf::R_AARCH64_COPY
                | elf::R_AARCH64_GLOB_DAT
                | elf::R_AARCH64_JUMP_SLOT
                | elf::R_AARCH64_RELATIVE
                | elf::R_AARCH64_TLS_DTPMOD
                | elf::R_AARCH64_TLS_DTPREL
                | elf::R_AARCH64_TLS_TPREL
                | elf::R_AARCH64_TLSDESC
                | elf::R_AARCH64_IRELATIVE
        ),
        _ => true,
    }
}

/// Relocations that fill global-offset-table slots, which are always 8-byte aligned.
fn got_entry(machine: u16, kind: u32) -> bool {
    match machine {
        elf::EM_X86_64 => matches!(
            kind,
            elf::R_X86_64_GLOB_DAT
                | elf::R_X86_64_JUMP_SLOT
                | elf::R_X86_64_DTPMOD64
                | elf::R_X86_64_TPOFF64
        ),
        elf::EM_AARCH64 => matches!(
            kind,
            elf::R_AARCH64_GLOB_DAT | elf::R_AARCH64_JUMP_SLOT | elf::R_AARCH64_TLS_DTPMOD
        ),
        _ => false,
    }
}

fn relative_relocation(machine: u16) -> Option<u32> {
    match machine {
        elf::EM_X86_64 => Some(elf::R_X86_64_RELATIVE),
        elf::EM_AARCH64 => Some(elf::R_AARCH64_RELATIVE),
        _ => None,
    }
}

/// Where relocations write, and for relative ones the address they write (`None` for those
/// that write a symbol's address, known only when it is bound).
pub(super) type Targets = HashMap<u64, Option<u64>>;

/// Checks every relocation: a known type, a symbol that exists, a target inside the library's
/// writable memory that no other relocation also writes, aligned where the slot is a pointer
/// the loader fills, PLT slots inside the PLT's table. Returns the targets.
pub(super) fn check_relocations(
    image: &Image<'_>,
    dynamic: &Dynamic<'_>,
    symbols: u64,
) -> Result<Targets, LibraryProblem> {
    let endian = image.endian;
    if dynamic.get(elf::DT_REL).is_some() && relative_relocation(image.machine).is_some() {
        return Err(damaged(
            "it has REL relocations, which this processor's libraries never use",
        ));
    }
    if dynamic.get(elf::DT_RELAENT).is_some_and(|n| n != 24) {
        return Err(damaged("its relocation table has the wrong entry size"));
    }
    if dynamic
        .get(elf::DT_PLTREL)
        .is_some_and(|kind| kind != u64::from(elf::DT_RELA))
    {
        return Err(damaged("its PLT relocations are of the wrong kind"));
    }
    let mut targets = Targets::new();
    let mut add = |target: u64, value: Option<u64>, what: &str| {
        if targets.insert(target, value).is_some() {
            return Err(damaged(format!(
                "its {what} write address {target:#x} twice"
            )));
        }
        Ok(())
    };
    let tables = [
        (elf::DT_RELA, elf::DT_RELASZ, "relocation table"),
        (elf::DT_JMPREL, elf::DT_PLTRELSZ, "PLT relocation table"),
    ];
    for (index, (at, size, what)) in tables.into_iter().enumerate() {
        let (Some(addr), Some(size)) = (dynamic.get(at), dynamic.get(size)) else {
            continue; // pairs were checked: neither is there
        };
        if size % 24 != 0 {
            return Err(damaged(format!(
                "its {what} is not a whole number of entries"
            )));
        }
        let bytes = image.bytes(addr, size, what)?;
        let relocations: &[elf::Rela64<Endianness>] = object::pod::slice_from_all_bytes(bytes)
            .map_err(|()| damaged(format!("its {what} is misaligned")))?;
        // The loader assumes the first RELACOUNT relocations are relative ones.
        let relative_count = if index == 0 {
            dynamic.get(elf::DT_RELACOUNT).unwrap_or(0)
        } else {
            0
        };
        if relative_count > relocations.len() as u64 {
            return Err(damaged(format!(
                "its {what} counts more relative relocations than it has"
            )));
        }
        // PLT slots follow the three entries the loader keeps at the PLT's table.
        let plt_slots = dynamic.get(elf::DT_PLTGOT).map(|got| {
            let first = got.saturating_add(24);
            first..first.saturating_add(relocations.len() as u64 * 8)
        });
        let relative = relative_relocation(image.machine);
        for (n, relocation) in relocations.iter().enumerate() {
            let kind = relocation.r_type(endian, false);
            if !known_relocation(image.machine, kind) {
                return Err(damaged(format!(
                    "its {what} entry {n} has an unknown type ({kind})"
                )));
            }
            if kind == 0 {
                continue;
            }
            if (n as u64) < relative_count && Some(kind) != relative {
                return Err(damaged(format!(
                    "its {what} entry {n} is counted as relative but is not"
                )));
            }
            if u64::from(relocation.r_sym(endian, false)) >= symbols.max(1) {
                return Err(damaged(format!(
                    "its {what} entry {n} names a symbol that does not exist"
                )));
            }
            let target = relocation.r_offset(endian);
            if !image.in_memory(target, 8, true) {
                return Err(damaged(format!(
                    "its {what} entry {n} writes outside the library's writable memory"
                )));
            }
            if (got_entry(image.machine, kind) || Some(kind) == relative) && target % 8 != 0 {
                return Err(damaged(format!(
                    "its {what} entry {n} writes a pointer at a misaligned address"
                )));
            }
            let jump_slot = matches!(
                (image.machine, kind),
                (elf::EM_X86_64, elf::R_X86_64_JUMP_SLOT)
                    | (elf::EM_AARCH64, elf::R_AARCH64_JUMP_SLOT)
            );
            if jump_slot
                && index == 1
                && plt_slots
                    .as_ref()
                    .is_some_and(|slots| !slots.contains(&target))
            {
                return Err(damaged(format!(
                    "its {what} entry {n} writes outside the PLT's table"
                )));
            }
            let value = (Some(kind) == relative).then(|| relocation.r_addend(endian) as u64);
            if value.is_some_and(|address| !image.in_span(address)) {
                return Err(damaged(format!(
                    "its {what} entry {n} makes a pointer outside the library"
                )));
            }
            add(target, value, what)?;
        }
    }
    if let (Some(addr), Some(size)) = (dynamic.get64(DT_RELR), dynamic.get64(DT_RELRSZ)) {
        if dynamic.get64(DT_RELRENT).is_some_and(|n| n != 8) || size % 8 != 0 {
            return Err(damaged("its packed relocations have the wrong entry size"));
        }
        let bytes = image.bytes(addr, size, "packed relocations")?;
        let mut next = 0u64;
        let mut relocate = |target: u64| -> Result<(), LibraryProblem> {
            if !target.is_multiple_of(8) || !image.in_memory(target, 8, true) {
                return Err(damaged(
                    "its packed relocations write outside the library's writable memory",
                ));
            }
            // A packed relocation adds the base to the word already there.
            let word = image.bytes(target, 8, "packed relocation target").ok();
            let value = word.map(|w| read_u64(w, endian));
            add(target, value, "packed relocations")
        };
        for word in bytes.chunks_exact(8) {
            let value = read_u64(word, endian);
            if value & 1 == 0 {
                relocate(value)?;
                next = value.saturating_add(8);
            } else {
                // A bitmap of the next 63 words.
                let bits = value >> 1;
                for bit in 0..63 {
                    if bits & (1 << bit) != 0 {
                        relocate(next.saturating_add(bit * 8))?;
                    }
                }
                next = next.saturating_add(63 * 8);
            }
        }
    }
    Ok(targets)
}

fn read_u64(bytes: &[u8], endian: Endianness) -> u64 {
    let mut value = [0u8; 8];
    value.copy_from_slice(&bytes[..8]);
    match endian {
        Endianness::Little => u64::from_le_bytes(value),
        Endianness::Big => u64::from_be_bytes(value),
    }
}

/// Checks the initialiser and finaliser functions and arrays the loader calls: each entry,
/// once relocated, must be an address in the library's code.
pub(super) fn check_initializers(
    image: &Image<'_>,
    dynamic: &Dynamic<'_>,
    targets: &Targets,
) -> Result<(), LibraryProblem> {
    for (tag, what) in [(elf::DT_INIT, "initialiser"), (elf::DT_FINI, "finaliser")] {
        if let Some(addr) = dynamic.get(tag) {
            if !image.executable(addr) {
                return Err(damaged(format!("its {what} is not in its code")));
            }
        }
    }
    for (at, size, what) in [
        (
            elf::DT_INIT_ARRAY,
            elf::DT_INIT_ARRAYSZ,
            "initialiser array",
        ),
        (elf::DT_FINI_ARRAY, elf::DT_FINI_ARRAYSZ, "finaliser array"),
        (
            elf::DT_PREINIT_ARRAY,
            elf::DT_PREINIT_ARRAYSZ,
            "pre-initialiser array",
        ),
    ] {
        let Some(addr) = dynamic.get(at) else {
            continue;
        };
        let size = dynamic.get(size).unwrap_or(0);
        if !size.is_multiple_of(8) || size > 1 << 20 || !image.in_memory(addr, size, false) {
            return Err(damaged(format!("its {what} is outside its memory")));
        }
        for slot in (0..size / 8).map(|i| addr + i * 8) {
            match targets.get(&slot) {
                Some(Some(function)) if image.executable(*function) => {}
                Some(None) => {} // a symbol's address, bound at load time
                _ => {
                    return Err(damaged(format!(
                        "its {what} entry at {slot:#x} is not a function in its code"
                    )))
                }
            }
        }
    }
    Ok(())
}
