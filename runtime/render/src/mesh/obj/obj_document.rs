//! [`ObjDocument`]: the statements of an OBJ file, read tolerantly line by line.

use std::collections::HashMap;
use std::path::Path;

use crate::asset_io::AssetWarning;
use crate::mesh::model_load_error::ModelLoadError;

/// No texture coordinate or normal at this corner.
pub(crate) const NONE: u32 = u32::MAX;

/// One corner of a face: 0-based indices into the document's lists ([`NONE`] when absent).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Corner {
    pub(crate) v: u32,
    pub(crate) vt: u32,
    pub(crate) vn: u32,
}

/// One polygon: its corners (`corners[first..first + count]`), the part it belongs to and
/// its smoothing group.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Face {
    pub(crate) first: u32,
    pub(crate) count: u32,
    pub(crate) part: u32,
    pub(crate) smoothing: u32,
}

/// The faces of one (object or group name, material) pair.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PartKey {
    pub(crate) name: String,
    /// `usemtl` name; `None` before any `usemtl` or after an empty one.
    pub(crate) material: Option<String>,
}

/// What an OBJ file holds, indices resolved and checked.
#[derive(Debug, Default)]
pub(crate) struct ObjDocument {
    pub(crate) positions: Vec<[f32; 3]>,
    pub(crate) texcoords: Vec<[f32; 2]>,
    pub(crate) normals: Vec<[f32; 3]>,
    pub(crate) corners: Vec<Corner>,
    pub(crate) faces: Vec<Face>,
    pub(crate) parts: Vec<PartKey>,
    /// `mtllib` names with the line they are on, as written (resolved by the loader).
    pub(crate) libraries: Vec<(String, usize)>,
    /// Whether any `s` statement appeared (then smoothing groups decide generated normals).
    pub(crate) has_smoothing: bool,
    pub(crate) warnings: Vec<AssetWarning>,
}

/// Counts an oddity met on many lines, to warn once with the first line and the count.
#[derive(Default)]
struct Tally {
    first: Option<usize>,
    count: usize,
}

impl Tally {
    fn add(&mut self, line: usize) {
        self.first.get_or_insert(line);
        self.count += 1;
    }
}

/// Parses OBJ text. Only a number that is not a number at all (`f 1 two 3`) is an error;
/// everything else real files contain is read or skipped with one warning per kind, naming
/// the first line: lines (`l`) and points (`p`), faces of fewer than three corners, faces
/// naming vertices that do not exist, non-finite coordinates (`nan`, `1.#IND`), statements
/// Onyx does not read (curves, `vp`), vertex colours on only some vertices.
pub(crate) fn parse_obj(text: &str, path: &Path) -> Result<ObjDocument, ModelLoadError> {
    let mut doc = ObjDocument::default();
    let mut part_ids: HashMap<PartKey, u32> = HashMap::new();
    let mut current = PartKey {
        name: String::new(),
        material: None,
    };
    let mut part: Option<u32> = None;
    let mut smoothing = 0u32;
    let (mut lines, mut points, mut short_faces, mut bad_index, mut non_finite) = (
        Tally::default(),
        Tally::default(),
        Tally::default(),
        Tally::default(),
        Tally::default(),
    );
    let mut colours = Tally::default();
    let mut unknown: Vec<(String, Tally)> = Vec::new();
    let error = |line: usize, message: String| ModelLoadError::ObjParse {
        path: path.to_owned(),
        line,
        message,
    };

    let mut logical = String::new();
    let mut physical = text.split('\n').enumerate();
    while let Some((index, raw)) = physical.next() {
        let number = index + 1;
        // A trailing backslash continues the statement on the next line.
        let mut line = raw.trim_end_matches('\r');
        if line.ends_with('\\') {
            logical.clear();
            logical.push_str(&line[..line.len() - 1]);
            for (_, more) in physical.by_ref() {
                let more = more.trim_end_matches('\r');
                match more.strip_suffix('\\') {
                    Some(rest) => logical.push_str(rest),
                    None => {
                        logical.push_str(more);
                        break;
                    }
                }
            }
            line = &logical;
        }
        let line = strip_comment(line).trim();
        let Some((keyword, rest)) = split_keyword(line) else {
            continue;
        };
        match keyword {
            "v" => {
                let mut values = [0.0f32; 7];
                let mut n = 0;
                for token in rest.split_ascii_whitespace() {
                    let value = parse_float(token).ok_or_else(|| {
                        error(number, format!("`{token}` in a vertex is not a number"))
                    })?;
                    if n < values.len() {
                        values[n] = value;
                    }
                    n += 1;
                }
                if n < 3 {
                    return Err(error(
                        number,
                        format!("a vertex needs x, y and z, this one has {n} numbers"),
                    ));
                }
                let mut p = [values[0], values[1], values[2]];
                if !p.iter().all(|c| c.is_finite()) {
                    non_finite.add(number);
                    p = p.map(|c| if c.is_finite() { c } else { 0.0 });
                }
                if n == 6 || n == 7 {
                    colours.add(number);
                }
                doc.positions.push(p);
            }
            "vt" => {
                let mut uv = [0.0f32; 2];
                for (k, token) in rest.split_ascii_whitespace().take(2).enumerate() {
                    uv[k] = parse_float(token).ok_or_else(|| {
                        error(
                            number,
                            format!("`{token}` in a texture coordinate is not a number"),
                        )
                    })?;
                }
                if !uv.iter().all(|c| c.is_finite()) {
                    non_finite.add(number);
                    uv = uv.map(|c| if c.is_finite() { c } else { 0.0 });
                }
                doc.texcoords.push(uv);
            }
            "vn" => {
                let mut n = [0.0f32; 3];
                for (k, token) in rest.split_ascii_whitespace().take(3).enumerate() {
                    n[k] = parse_float(token).ok_or_else(|| {
                        error(number, format!("`{token}` in a normal is not a number"))
                    })?;
                }
                if !n.iter().all(|c| c.is_finite()) {
                    non_finite.add(number);
                    n = [0.0; 3];
                }
                doc.normals.push(n);
            }
            "f" | "fo" => {
                let first = doc.corners.len();
                let mut ok = true;
                for token in rest.split_ascii_whitespace() {
                    match parse_corner(token, &doc) {
                        Ok(Some(corner)) => doc.corners.push(corner),
                        Ok(None) => ok = false,
                        Err(()) => {
                            return Err(error(
                                number,
                                format!(
                                    "`{token}` is not a face corner (v, v/vt, v//vn or v/vt/vn)"
                                ),
                            ))
                        }
                    }
                }
                let count = doc.corners.len() - first;
                if !ok {
                    bad_index.add(number);
                    doc.corners.truncate(first);
                    continue;
                }
                if count < 3 {
                    short_faces.add(number);
                    doc.corners.truncate(first);
                    continue;
                }
                let id = *part.get_or_insert_with(|| intern(&mut doc, &mut part_ids, &current));
                doc.faces.push(Face {
                    first: first as u32,
                    count: count as u32,
                    part: id,
                    smoothing,
                });
            }
            "l" => lines.add(number),
            "p" => points.add(number),
            "o" | "g" => {
                current.name = rest.trim().to_owned();
                part = None;
            }
            "usemtl" => {
                let name = rest.trim();
                current.material = (!name.is_empty()).then(|| name.to_owned());
                part = None;
            }
            "mtllib" => {
                if !rest.trim().is_empty() {
                    doc.libraries.push((rest.trim().to_owned(), number));
                }
            }
            "s" => {
                doc.has_smoothing = true;
                let value = rest.trim();
                smoothing = if value.eq_ignore_ascii_case("off") {
                    0
                } else {
                    value.parse().unwrap_or(0)
                };
            }
            other => match unknown.iter_mut().find(|(k, _)| k == other) {
                Some((_, tally)) => tally.add(number),
                None => {
                    let mut tally = Tally::default();
                    tally.add(number);
                    unknown.push((other.to_owned(), tally));
                }
            },
        }
    }

    // Positive indices may name vertices defined later in the file: checked at the end.
    let (np, nt, nn) = (
        doc.positions.len() as u32,
        doc.texcoords.len() as u32,
        doc.normals.len() as u32,
    );
    let corners = &doc.corners;
    let before = doc.faces.len();
    doc.faces.retain(|f| {
        corners[f.first as usize..(f.first + f.count) as usize]
            .iter()
            .all(|c| c.v < np)
    });
    let dropped = before - doc.faces.len();
    // A texture coordinate or normal that is not there is treated as absent.
    let mut dangling = 0usize;
    for c in &mut doc.corners {
        if c.vt != NONE && c.vt >= nt {
            c.vt = NONE;
            dangling += 1;
        }
        if c.vn != NONE && c.vn >= nn {
            c.vn = NONE;
            dangling += 1;
        }
    }

    let mut warn = |tally: &Tally, message: String| {
        if let Some(first) = tally.first {
            doc.warnings
                .push(AssetWarning::new(path, Some(first), message));
        }
    };
    warn(
        &lines,
        format!(
            "{} line element(s) (`l`) skipped: Onyx draws a model's faces only",
            lines.count
        ),
    );
    warn(
        &points,
        format!(
            "{} point element(s) (`p`) skipped: Onyx draws a model's faces only",
            points.count
        ),
    );
    warn(
        &short_faces,
        format!(
            "{} face(s) with fewer than three corners skipped (they have no area)",
            short_faces.count
        ),
    );
    warn(
        &bad_index,
        format!(
            "{} face(s) skipped: they name vertex 0 or a vertex before the first",
            bad_index.count
        ),
    );
    warn(
        &non_finite,
        format!(
            "{} coordinate line(s) hold NaN or infinity (`nan`, `1.#IND`); those values were set to 0",
            non_finite.count
        ),
    );
    if colours.count > 0 && colours.count < doc.positions.len() {
        warn(
            &colours,
            format!(
                "{} of {} vertices carry a colour; vertex colours are not drawn and were ignored",
                colours.count,
                doc.positions.len()
            ),
        );
    }
    for (keyword, tally) in &unknown {
        warn(
            tally,
            format!(
                "{} `{keyword}` statement(s) ignored: Onyx does not read them",
                tally.count
            ),
        );
    }
    if dropped > 0 {
        doc.warnings.push(AssetWarning::new(
            path,
            None,
            format!("{dropped} face(s) skipped: they name vertices the file does not have"),
        ));
    }
    if dangling > 0 {
        doc.warnings.push(AssetWarning::new(
            path,
            None,
            format!("{dangling} face corner(s) name texture coordinates or normals the file does not have; those were left out (normals generated)"),
        ));
    }
    Ok(doc)
}

fn intern(doc: &mut ObjDocument, ids: &mut HashMap<PartKey, u32>, key: &PartKey) -> u32 {
    if let Some(&id) = ids.get(key) {
        return id;
    }
    let id = doc.parts.len() as u32;
    doc.parts.push(key.clone());
    ids.insert(key.clone(), id);
    id
}

/// The line before its comment: a `#` at the start or after a space (MSVC numbers such as
/// `1.#IND` hold one too).
pub(crate) fn strip_comment(line: &str) -> &str {
    let bytes = line.as_bytes();
    let cut = (0..bytes.len())
        .find(|&i| bytes[i] == b'#' && (i == 0 || bytes[i - 1].is_ascii_whitespace()));
    cut.map_or(line, |i| &line[..i])
}

/// The statement keyword and the rest of the line.
fn split_keyword(line: &str) -> Option<(&str, &str)> {
    if line.is_empty() {
        return None;
    }
    Some(match line.find(|c: char| c.is_ascii_whitespace()) {
        Some(at) => (&line[..at], &line[at..]),
        None => (line, ""),
    })
}

/// A number as exporters write it: plain, `.5`, `1e-05`, `nan`, `inf`, and MSVC's `1.#IND`,
/// `-1.#INF`, `1.#QNAN`.
pub(crate) fn parse_float(token: &str) -> Option<f32> {
    if let Ok(value) = token.parse::<f32>() {
        return Some(value);
    }
    let upper = token.to_ascii_uppercase();
    if upper.contains("#INF") {
        return Some(if upper.starts_with('-') {
            f32::NEG_INFINITY
        } else {
            f32::INFINITY
        });
    }
    if upper.contains("#IND") || upper.contains("#QNAN") || upper.contains("#SNAN") {
        return Some(f32::NAN);
    }
    None
}

/// One `v/vt/vn` corner. `Ok(None)` for an index that cannot name anything (0, or negative
/// past the start); `Err` for text that is not indices at all.
fn parse_corner(token: &str, doc: &ObjDocument) -> Result<Option<Corner>, ()> {
    let mut fields = token.split('/');
    let v = fields.next().ok_or(())?;
    let vt = fields.next().unwrap_or("");
    let vn = fields.next().unwrap_or("");
    let resolve = |text: &str, count: usize| -> Result<Option<u32>, ()> {
        let index: i64 = text.parse().map_err(|_| ())?;
        Ok(match index {
            0 => None,
            i if i > 0 => u32::try_from(i - 1).ok(),
            i => u32::try_from(count as i64 + i).ok(),
        })
    };
    let Some(v) = resolve(v, doc.positions.len())? else {
        return Ok(None);
    };
    let optional = |text: &str, count| -> Result<Option<u32>, ()> {
        if text.is_empty() {
            Ok(Some(NONE))
        } else {
            resolve(text, count)
        }
    };
    let (Some(vt), Some(vn)) = (
        optional(vt, doc.texcoords.len())?,
        optional(vn, doc.normals.len())?,
    ) else {
        return Ok(None);
    };
    Ok(Some(Corner { v, vt, vn }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> ObjDocument {
        parse_obj(text, Path::new("t.obj")).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn msvc_and_c_special_numbers_are_read_and_zeroed_with_one_warning() {
        let doc = parse("v 1.#IND -1.#INF 2\nv nan 1 .5\nv 1 2 3\nf 1 2 3\n");
        assert_eq!(
            doc.positions,
            vec![[0.0, 0.0, 2.0], [0.0, 1.0, 0.5], [1.0, 2.0, 3.0]]
        );
        assert_eq!(doc.warnings.len(), 1, "{:?}", doc.warnings);
        assert_eq!(doc.warnings[0].line, Some(1));
    }

    #[test]
    fn a_word_where_an_index_belongs_is_an_error_with_its_line() {
        match parse_obj("v 0 0 0\n\nf 1 two 3\n", Path::new("t.obj")) {
            Err(ModelLoadError::ObjParse { line, .. }) => assert_eq!(line, 3),
            other => panic!("expected ObjParse, got {other:?}"),
        }
    }

    #[test]
    fn negative_indices_count_back_from_the_last_vertex() {
        let doc = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
        let c: Vec<u32> = doc.corners.iter().map(|c| c.v).collect();
        assert_eq!(c, vec![0, 1, 2]);
    }

    #[test]
    fn empty_usemtl_means_no_material() {
        let doc = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl\nf 1 2 3\n");
        assert_eq!(doc.parts[0].material, None);
    }
}
