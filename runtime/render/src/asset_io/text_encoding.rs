//! [`TextEncoding`] and [`decode_text`]: text asset files (OBJ, MTL, glTF JSON) as exporters
//! wrote them — UTF-8 with or without a byte-order mark, UTF-16 with one, or a legacy 8-bit
//! code page (decoded as Latin-1, which maps every byte to a character, so nothing is lost).

/// How a text file was encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextEncoding {
    /// UTF-8 without a byte-order mark (or plain ASCII).
    Utf8,
    /// UTF-8 with a byte-order mark (stripped).
    Utf8Bom,
    /// UTF-16, little-endian, from its byte-order mark.
    Utf16Le,
    /// UTF-16, big-endian, from its byte-order mark.
    Utf16Be,
    /// Not valid UTF-8: decoded byte by byte as Latin-1 (ISO 8859-1).
    Latin1,
}

impl TextEncoding {
    /// Whether a loader should say how it read the file: every encoding but UTF-8 was a
    /// guess or a conversion.
    #[must_use]
    pub fn is_unusual(self) -> bool {
        matches!(
            self,
            TextEncoding::Utf16Le | TextEncoding::Utf16Be | TextEncoding::Latin1
        )
    }

    /// The encoding's name, for messages.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            TextEncoding::Utf8 => "UTF-8",
            TextEncoding::Utf8Bom => "UTF-8 with a byte-order mark",
            TextEncoding::Utf16Le => "UTF-16 (little-endian)",
            TextEncoding::Utf16Be => "UTF-16 (big-endian)",
            TextEncoding::Latin1 => "Latin-1",
        }
    }
}

/// Decodes a text file's bytes: a UTF-8 byte-order mark is stripped, a UTF-16 one selects
/// UTF-16 (unpaired surrogates become U+FFFD), other bytes are UTF-8 when they are valid
/// UTF-8 and Latin-1 otherwise. Never fails: every byte sequence is some text.
#[must_use]
pub fn decode_text(bytes: &[u8]) -> (String, TextEncoding) {
    if let Some(rest) = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]) {
        return (latin1_unless_utf8(rest).0, TextEncoding::Utf8Bom);
    }
    if let Some(rest) = bytes.strip_prefix(&[0xFF, 0xFE]) {
        return (utf16(rest, u16::from_le_bytes), TextEncoding::Utf16Le);
    }
    if let Some(rest) = bytes.strip_prefix(&[0xFE, 0xFF]) {
        return (utf16(rest, u16::from_be_bytes), TextEncoding::Utf16Be);
    }
    latin1_unless_utf8(bytes)
}

fn latin1_unless_utf8(bytes: &[u8]) -> (String, TextEncoding) {
    match std::str::from_utf8(bytes) {
        Ok(text) => (text.to_owned(), TextEncoding::Utf8),
        Err(_) => (
            bytes.iter().map(|&b| char::from(b)).collect(),
            TextEncoding::Latin1,
        ),
    }
}

fn utf16(bytes: &[u8], unit: fn([u8; 2]) -> u16) -> String {
    let units = bytes.chunks_exact(2).map(|pair| unit([pair[0], pair[1]]));
    char::decode_utf16(units)
        .map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_encoding_decodes_to_the_same_text() {
        let text = "v 1 2 3 # Modèle\n";
        let utf8 = text.as_bytes().to_vec();
        let bom = [&[0xEF, 0xBB, 0xBF][..], text.as_bytes()].concat();
        let latin1: Vec<u8> = text.chars().map(|c| c as u8).collect();
        let le: Vec<u8> = [0xFF, 0xFE]
            .into_iter()
            .chain(text.encode_utf16().flat_map(u16::to_le_bytes))
            .collect();
        let be: Vec<u8> = [0xFE, 0xFF]
            .into_iter()
            .chain(text.encode_utf16().flat_map(u16::to_be_bytes))
            .collect();
        for (bytes, encoding) in [
            (utf8, TextEncoding::Utf8),
            (bom, TextEncoding::Utf8Bom),
            (latin1, TextEncoding::Latin1),
            (le, TextEncoding::Utf16Le),
            (be, TextEncoding::Utf16Be),
        ] {
            assert_eq!(decode_text(&bytes), (text.to_owned(), encoding));
        }
    }
}
