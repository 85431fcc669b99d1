//! The dynamic section: its entries by tag, its string table, the tags that only make sense
//! together, and the order the other checks run in.

use object::elf;
use object::read::elf::Sym as _;
use object::Endianness;

use super::image::Image;
use super::relocations::{check_initializers, check_relocations};
use super::symbols::{check_versions, symbol_count};
use super::{damaged, LibraryProblem};

// Packed relative relocations; newer than the `object` release the workspace uses.
pub(super) const DT_RELRSZ: u64 = 35;

pub(super) const DT_RELR: u64 = 36;

pub(super) const DT_RELRENT: u64 = 37;

/// What the dynamic section says, by tag.
pub(super) struct Dynamic<'e> {
    entries: &'e [(u64, u64)],
}

impl Dynamic<'_> {
    pub(super) fn get(&self, tag: u32) -> Option<u64> {
        self.entries
            .iter()
            .find(|(t, _)| *t == u64::from(tag))
            .map(|(_, v)| *v)
    }
    pub(super) fn get64(&self, tag: u64) -> Option<u64> {
        self.entries
            .iter()
            .find(|(t, _)| *t == tag)
            .map(|(_, v)| *v)
    }
    pub(super) fn all(&self, tag: u32) -> impl Iterator<Item = u64> + '_ {
        self.entries
            .iter()
            .filter(move |(t, _)| *t == u64::from(tag))
            .map(|(_, v)| *v)
    }
}

/// The string table: offsets into it must name NUL-terminated strings inside it.
pub(super) struct Strings<'a>(&'a [u8]);

impl<'a> Strings<'a> {
    /// The string at `offset` (empty if outside; [`Strings::check`] refuses those).
    pub(super) fn get(&self, offset: u64) -> &'a [u8] {
        let rest = usize::try_from(offset)
            .ok()
            .and_then(|o| self.0.get(o..))
            .unwrap_or_default();
        rest.split(|b| *b == 0).next().unwrap_or_default()
    }

    pub(super) fn check(&self, offset: u64, what: &str) -> Result<(), LibraryProblem> {
        let ok = usize::try_from(offset)
            .ok()
            .and_then(|o| self.0.get(o..))
            .is_some_and(|rest| rest.contains(&0));
        if ok {
            Ok(())
        } else {
            Err(damaged(format!(
                "its {what} names a string outside the string table"
            )))
        }
    }
}

/// Tags that come in pairs (a table and its size or count): the loader reads one and trusts
/// the other is there — a lone one makes it dereference nothing or skip relocations.
const PAIRED_TAGS: [(u64, u64, &str); 10] = [
    (elf::DT_STRTAB as u64, elf::DT_STRSZ as u64, "string table"),
    (
        elf::DT_RELA as u64,
        elf::DT_RELASZ as u64,
        "relocation table",
    ),
    (
        elf::DT_RELA as u64,
        elf::DT_RELAENT as u64,
        "relocation table",
    ),
    (
        elf::DT_JMPREL as u64,
        elf::DT_PLTRELSZ as u64,
        "PLT relocation table",
    ),
    (
        elf::DT_JMPREL as u64,
        elf::DT_PLTREL as u64,
        "PLT relocation table",
    ),
    (DT_RELR, DT_RELRSZ, "packed relocations"),
    (DT_RELR, DT_RELRENT, "packed relocations"),
    (
        elf::DT_VERNEED as u64,
        elf::DT_VERNEEDNUM as u64,
        "needed-versions table",
    ),
    (
        elf::DT_VERDEF as u64,
        elf::DT_VERDEFNUM as u64,
        "defined-versions table",
    ),
    (
        elf::DT_INIT_ARRAY as u64,
        elf::DT_INIT_ARRAYSZ as u64,
        "initialiser array",
    ),
];

/// Tags that need another one: (tag, needs, what).
const NEEDED_TAGS: [(u64, u64, &str); 4] = [
    (
        elf::DT_RELACOUNT as u64,
        elf::DT_RELA as u64,
        "relative-relocation count",
    ),
    (
        elf::DT_VERNEED as u64,
        elf::DT_VERSYM as u64,
        "needed-versions table",
    ),
    (
        elf::DT_VERDEF as u64,
        elf::DT_VERSYM as u64,
        "defined-versions table",
    ),
    (
        elf::DT_FINI_ARRAYSZ as u64,
        elf::DT_FINI_ARRAY as u64,
        "finaliser array size",
    ),
];

fn check_tag_pairs(dynamic: &Dynamic<'_>) -> Result<(), LibraryProblem> {
    for (a, b, what) in PAIRED_TAGS {
        if dynamic.get64(a).is_some() != dynamic.get64(b).is_some() {
            return Err(damaged(format!(
                "its dynamic section has half of its {what}'s entries (tags {a:#x} and {b:#x})"
            )));
        }
    }
    for (tag, needs, what) in NEEDED_TAGS {
        if dynamic.get64(tag).is_some() && dynamic.get64(needs).is_none() {
            return Err(damaged(format!(
                "its dynamic section has a {what} without the table it belongs to (tag {needs:#x})"
            )));
        }
    }
    Ok(())
}

pub(super) fn check_dynamic(
    image: &Image<'_>,
    entries: &[(u64, u64)],
) -> Result<(), LibraryProblem> {
    let dynamic = Dynamic { entries };
    let endian = image.endian;
    check_tag_pairs(&dynamic)?;

    // Strings.
    let (Some(strtab), Some(strsz)) = (dynamic.get(elf::DT_STRTAB), dynamic.get(elf::DT_STRSZ))
    else {
        return Err(damaged("its dynamic section has no string table"));
    };
    let strings = Strings(image.bytes(strtab, strsz, "string table")?);
    for tag in [
        elf::DT_NEEDED,
        elf::DT_SONAME,
        elf::DT_RPATH,
        elf::DT_RUNPATH,
    ] {
        for offset in dynamic.all(tag) {
            strings.check(offset, "dynamic section")?;
        }
    }

    // Symbols: how many there are comes from the hash tables.
    let symtab = dynamic
        .get(elf::DT_SYMTAB)
        .ok_or_else(|| damaged("its dynamic section has no symbol table"))?;
    if dynamic.get(elf::DT_SYMENT).is_some_and(|n| n != 24) {
        return Err(damaged("its symbol table has the wrong entry size"));
    }
    let symbols = symbol_count(image, &dynamic)?;
    let symbol_bytes = image.bytes(symtab, symbols * 24, "symbol table")?;
    let symbol_table: &[elf::Sym64<Endianness>] =
        object::pod::slice_from_all_bytes(symbol_bytes)
            .map_err(|()| damaged("its symbol table is misaligned"))?;
    for (index, symbol) in symbol_table.iter().enumerate() {
        strings.check(u64::from(symbol.st_name(endian)), "symbol table")?;
        let defined = symbol.st_shndx(endian) != elf::SHN_UNDEF
            && symbol.st_shndx(endian) != elf::SHN_ABS
            && symbol.st_type() != elf::STT_TLS;
        if defined && !image.in_memory(symbol.st_value(endian), 0, false) {
            return Err(damaged(format!(
                "its symbol {index} points outside the library's memory"
            )));
        }
    }

    check_versions(image, &dynamic, &strings, symbols)?;
    let targets = check_relocations(image, &dynamic, symbols)?;
    check_initializers(image, &dynamic, &targets)
}
