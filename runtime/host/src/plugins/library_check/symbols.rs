//! The symbol hash tables (the only place that says how many dynamic symbols there are) and
//! the version tables the loader indexes with each symbol's version.

use std::collections::HashSet;

use object::elf;
use object::{Endianness, ReadRef as _, U32};

use super::dynamic::{Dynamic, Strings};
use super::image::Image;
use super::{damaged, LibraryProblem};

/// The number of dynamic symbols, from the GNU hash table (or the SysV one), after checking
/// that every bucket and chain the loader follows stays inside it.
pub(super) fn symbol_count(
    image: &Image<'_>,
    dynamic: &Dynamic<'_>,
) -> Result<u64, LibraryProblem> {
    let endian = image.endian;
    if let Some(addr) = dynamic.get(elf::DT_GNU_HASH) {
        let data = image.bytes_from(addr, "GNU hash table")?;
        let header: &elf::GnuHashHeader<Endianness> = data
            .read_at(0)
            .map_err(|()| damaged("its GNU hash table is cut short"))?;
        let buckets = u64::from(header.bucket_count.get(endian));
        let base = u64::from(header.symbol_base.get(endian));
        let bloom = u64::from(header.bloom_count.get(endian));
        if buckets == 0 || !bloom.is_power_of_two() || header.bloom_shift.get(endian) >= 64 {
            return Err(damaged("its GNU hash table has an impossible header"));
        }
        let buckets_at = 16 + bloom * 8;
        let bucket_values: &[U32<Endianness>] = data
            .read_slice_at(buckets_at, buckets as usize)
            .map_err(|()| damaged("its GNU hash table's buckets are outside the file"))?;
        let chains_at = buckets_at + buckets * 4;
        let chains: &[U32<Endianness>] = data
            .read_slice_at(
                chains_at,
                ((data.len() as u64 - chains_at.min(data.len() as u64)) / 4) as usize,
            )
            .map_err(|()| damaged("its GNU hash table's chains are outside the file"))?;
        let mut count = base;
        for bucket in bucket_values {
            let start = u64::from(bucket.get(endian));
            if start == 0 {
                continue;
            }
            if start < base {
                return Err(damaged(
                    "its GNU hash table has a bucket before its first symbol",
                ));
            }
            // Follow the chain to its end marker.
            let mut index = start;
            loop {
                let value = chains
                    .get((index - base) as usize)
                    .ok_or_else(|| damaged("its GNU hash table has a chain with no end"))?;
                index += 1;
                if value.get(endian) & 1 != 0 {
                    break;
                }
            }
            count = count.max(index);
        }
        return Ok(count);
    }
    if let Some(addr) = dynamic.get(elf::DT_HASH) {
        let data = image.bytes_from(addr, "hash table")?;
        let header: &elf::HashHeader<Endianness> = data
            .read_at(0)
            .map_err(|()| damaged("its hash table is cut short"))?;
        let buckets = header.bucket_count.get(endian) as usize;
        let chains = header.chain_count.get(endian);
        let values: &[U32<Endianness>] = data
            .read_slice_at(8, buckets + chains as usize)
            .map_err(|()| damaged("its hash table is outside the file"))?;
        if buckets == 0 || values.iter().any(|v| v.get(endian) >= chains.max(1)) {
            return Err(damaged("its hash table points past its symbols"));
        }
        return Ok(u64::from(chains));
    }
    Err(damaged("its dynamic section has no symbol hash table"))
}

/// Checks the version tables: the needed and defined versions, and the version of every
/// symbol (the loader indexes an array with it).
pub(super) fn check_versions(
    image: &Image<'_>,
    dynamic: &Dynamic<'_>,
    strings: &Strings<'_>,
    symbols: u64,
) -> Result<(), LibraryProblem> {
    let endian = image.endian;
    let mut indexes: HashSet<u16> = [0, 1].into_iter().collect();
    let needed: HashSet<&[u8]> = dynamic
        .all(elf::DT_NEEDED)
        .map(|offset| strings.get(offset))
        .collect();
    if let Some(addr) = dynamic.get(elf::DT_VERNEED) {
        let count = dynamic.get(elf::DT_VERNEEDNUM).unwrap_or(0);
        let data = image.bytes_from(addr, "needed-versions table")?;
        let mut at = 0u64;
        for n in 0..count {
            let need: &elf::Verneed<Endianness> = data
                .read_at(at)
                .map_err(|()| damaged("its needed-versions table is outside the file"))?;
            if need.vn_version.get(endian) != elf::VER_NEED_CURRENT {
                return Err(damaged("its needed-versions table has an unknown revision"));
            }
            let file = u64::from(need.vn_file.get(endian));
            strings.check(file, "needed-versions table")?;
            if !needed.contains(&strings.get(file)) {
                return Err(damaged(
                    "its needed-versions table names a library it does not depend on",
                ));
            }
            let mut aux_at = at + u64::from(need.vn_aux.get(endian));
            let auxes = need.vn_cnt.get(endian);
            for a in 0..auxes {
                let aux: &elf::Vernaux<Endianness> = data
                    .read_at(aux_at)
                    .map_err(|()| damaged("its needed-versions table is outside the file"))?;
                strings.check(u64::from(aux.vna_name.get(endian)), "needed-versions table")?;
                indexes.insert(aux.vna_other.get(endian) & elf::VERSYM_VERSION);
                // The loader follows the links, not the count: they must agree.
                let next = u64::from(aux.vna_next.get(endian));
                if (next == 0) != (a + 1 == auxes) {
                    return Err(damaged(
                        "its needed-versions table does not have the entries its count says",
                    ));
                }
                aux_at += next;
            }
            let next = u64::from(need.vn_next.get(endian));
            if (next == 0) != (n + 1 == count) {
                return Err(damaged(
                    "its needed-versions table does not have the entries its count says",
                ));
            }
            at += next;
        }
    }
    if let Some(addr) = dynamic.get(elf::DT_VERDEF) {
        let count = dynamic.get(elf::DT_VERDEFNUM).unwrap_or(0);
        let data = image.bytes_from(addr, "defined-versions table")?;
        let mut at = 0u64;
        for n in 0..count {
            let def: &elf::Verdef<Endianness> = data
                .read_at(at)
                .map_err(|()| damaged("its defined-versions table is outside the file"))?;
            if def.vd_version.get(endian) != elf::VER_DEF_CURRENT {
                return Err(damaged(
                    "its defined-versions table has an unknown revision",
                ));
            }
            indexes.insert(def.vd_ndx.get(endian) & elf::VERSYM_VERSION);
            let mut aux_at = at + u64::from(def.vd_aux.get(endian));
            let auxes = def.vd_cnt.get(endian);
            for a in 0..auxes {
                let aux: &elf::Verdaux<Endianness> = data
                    .read_at(aux_at)
                    .map_err(|()| damaged("its defined-versions table is outside the file"))?;
                strings.check(
                    u64::from(aux.vda_name.get(endian)),
                    "defined-versions table",
                )?;
                let next = u64::from(aux.vda_next.get(endian));
                if (next == 0) != (a + 1 == auxes) {
                    return Err(damaged(
                        "its defined-versions table does not have the entries its count says",
                    ));
                }
                aux_at += next;
            }
            let next = u64::from(def.vd_next.get(endian));
            if (next == 0) != (n + 1 == count) {
                return Err(damaged(
                    "its defined-versions table does not have the entries its count says",
                ));
            }
            at += next;
        }
    }
    if let Some(addr) = dynamic.get(elf::DT_VERSYM) {
        let bytes = image.bytes(addr, symbols * 2, "symbol-versions table")?;
        for (index, pair) in bytes.chunks_exact(2).enumerate() {
            let raw = match endian {
                Endianness::Little => u16::from_le_bytes([pair[0], pair[1]]),
                Endianness::Big => u16::from_be_bytes([pair[0], pair[1]]),
            };
            if !indexes.contains(&(raw & elf::VERSYM_VERSION)) {
                return Err(damaged(format!(
                    "its symbol {index} has a version the library does not list"
                )));
            }
        }
    }
    Ok(())
}
