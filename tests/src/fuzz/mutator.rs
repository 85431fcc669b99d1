//! [`mutate`]: a deterministic mutation of a file's bytes.

/// Values that break parsers more often than random ones do.
const INTERESTING_NUMBERS: [&str; 16] = [
    "0",
    "-0",
    "1",
    "-1",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "1e309",
    "-1e309",
    "1e-45",
    "4294967295",
    "4294967296",
    "18446744073709551616",
    "-2147483649",
    "0.0000000000000000000001",
];
const INTERESTING_WORDS: [u64; 10] = [
    0,
    1,
    0x7f,
    0x80,
    0xff,
    0x7fff,
    0xffff,
    0x7fff_ffff,
    0xffff_ffff,
    u64::MAX,
];

/// A mutation of `input`, the same for the same `seed` and `case`: one to eight edits, some
/// byte-level (flips, random or boundary values, cuts, copies, insertions, truncation) and,
/// for `text` formats, some token-level (a number replaced by an extreme one, a line dropped,
/// doubled or moved, a stray quote or bracket).
pub fn mutate(input: &[u8], seed: u64, case: u64, text: bool) -> Vec<u8> {
    let mut rng = fastrand::Rng::with_seed(seed ^ case.wrapping_mul(0x9E37_79B9_7F4A_7C15));
    let mut bytes = input.to_vec();
    let edits = rng.usize(1..=8);
    for _ in 0..edits {
        if bytes.is_empty() {
            bytes.push(rng.u8(..));
            continue;
        }
        let kinds = if text { 12 } else { 8 };
        match rng.usize(..kinds) {
            0 => {
                let at = rng.usize(..bytes.len());
                bytes[at] ^= 1 << rng.u32(..8);
            }
            1 => {
                let at = rng.usize(..bytes.len());
                bytes[at] = rng.u8(..);
            }
            2 => {
                let word = INTERESTING_WORDS[rng.usize(..INTERESTING_WORDS.len())];
                let width = [1usize, 2, 4, 8][rng.usize(..4)];
                let at = rng.usize(..bytes.len());
                let le = word.to_le_bytes();
                for (i, b) in le.iter().take(width).enumerate() {
                    if let Some(slot) = bytes.get_mut(at + i) {
                        *slot = *b;
                    }
                }
            }
            3 => {
                let (at, len) = span(&mut rng, bytes.len());
                bytes.drain(at..at + len);
            }
            4 => {
                let (at, len) = span(&mut rng, bytes.len());
                let copy = bytes[at..at + len].to_vec();
                let to = rng.usize(..=bytes.len());
                bytes.splice(to..to, copy);
            }
            5 => {
                let to = rng.usize(..=bytes.len());
                let n = rng.usize(1..=16);
                let noise: Vec<u8> = (0..n).map(|_| rng.u8(..)).collect();
                bytes.splice(to..to, noise);
            }
            6 => {
                let keep = rng.usize(..bytes.len());
                bytes.truncate(keep);
            }
            7 => {
                // Swap two spans' first bytes: reorders fields of binary headers.
                let a = rng.usize(..bytes.len());
                let b = rng.usize(..bytes.len());
                bytes.swap(a, b);
            }
            8 => replace_number(&mut rng, &mut bytes),
            9 => line_edit(&mut rng, &mut bytes),
            10 => {
                let stray = [
                    b'"', b'(', b')', b'[', b']', b'{', b'}', b',', b':', 0, 0xff, b'\\',
                ];
                let to = rng.usize(..=bytes.len());
                bytes.insert(to, stray[rng.usize(..stray.len())]);
            }
            _ => replace_number(&mut rng, &mut bytes),
        }
    }
    bytes
}

/// A random span inside `len` bytes: (start, length ≥ 1), at most 1/8 of the file or 4 KiB.
fn span(rng: &mut fastrand::Rng, len: usize) -> (usize, usize) {
    let max = (len / 8).clamp(1, 4096);
    let n = rng.usize(1..=max).min(len);
    let at = rng.usize(..=len - n);
    (at, n)
}

/// Replaces one number in the text (a run of digits, `.`, `-`, `e`) with an interesting one.
fn replace_number(rng: &mut fastrand::Rng, bytes: &mut Vec<u8>) {
    let starts: Vec<usize> = (0..bytes.len())
        .filter(|&i| bytes[i].is_ascii_digit() && (i == 0 || !bytes[i - 1].is_ascii_digit()))
        .collect();
    if starts.is_empty() {
        return;
    }
    let at = starts[rng.usize(..starts.len())];
    let end = (at..bytes.len())
        .find(|&i| !matches!(bytes[i], b'0'..=b'9' | b'.' | b'e' | b'E' | b'-' | b'+'))
        .unwrap_or(bytes.len());
    let number = INTERESTING_NUMBERS[rng.usize(..INTERESTING_NUMBERS.len())];
    bytes.splice(at..end, number.bytes());
}

/// Drops, doubles or moves one line.
fn line_edit(rng: &mut fastrand::Rng, bytes: &mut Vec<u8>) {
    let mut lines: Vec<Vec<u8>> = bytes.split(|b| *b == b'\n').map(<[u8]>::to_vec).collect();
    if lines.is_empty() {
        return;
    }
    let i = rng.usize(..lines.len());
    match rng.usize(..3) {
        0 => {
            lines.remove(i);
        }
        1 => {
            let line = lines[i].clone();
            lines.insert(i, line);
        }
        _ => {
            let line = lines.remove(i);
            let to = rng.usize(..=lines.len());
            lines.insert(to, line);
        }
    }
    *bytes = lines.join(&b'\n');
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_case_gives_the_same_bytes_and_cases_differ() {
        let input = b"entities: [(id: 1, transform: (translation: (1.0, 2.0, 3.0)))]".repeat(8);
        let a = mutate(&input, 7, 42, true);
        assert_eq!(a, mutate(&input, 7, 42, true));
        let distinct: std::collections::HashSet<Vec<u8>> =
            (0..50).map(|case| mutate(&input, 7, case, true)).collect();
        assert!(distinct.len() > 45, "{}", distinct.len());
        assert!(distinct.iter().all(|m| m != &input) || distinct.len() > 45);
    }

    #[test]
    fn empty_and_tiny_inputs_are_fine() {
        for case in 0..200 {
            let _ = mutate(b"", 1, case, false);
            let _ = mutate(b"x", 1, case, true);
        }
    }
}
