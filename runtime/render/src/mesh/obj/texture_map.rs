//! [`TextureMap`]: an MTL `map_*` statement — the file and the options before it.

use super::obj_document::parse_float;

/// A texture an MTL material names, with the options Onyx applies.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TextureMap {
    /// The file name as written (resolved against the MTL's folder by the loader).
    pub(crate) file: String,
    /// `-s u v`: texture coordinates are multiplied by this…
    pub(crate) scale: [f32; 2],
    /// `-o u v`: …then offset by this (OBJ's convention: v up).
    pub(crate) offset: [f32; 2],
    /// `-bm`: bump multiplier (bump maps).
    pub(crate) bump_multiplier: f32,
    /// Options read but not applied (`-clamp`, `-blendu`, `-mm`, …), for one warning.
    pub(crate) ignored: Vec<String>,
}

/// Options and how many arguments each takes (`-o`, `-s`, `-t` take one to three numbers).
const OPTIONS: [(&str, usize); 12] = [
    ("-blendu", 1),
    ("-blendv", 1),
    ("-bm", 1),
    ("-boost", 1),
    ("-cc", 1),
    ("-clamp", 1),
    ("-imfchan", 1),
    ("-mm", 2),
    ("-texres", 1),
    ("-type", 1),
    ("-o", 3),
    ("-s", 3),
];

/// Parses what follows `map_Kd` (etc.): options, then the file name, which may contain
/// spaces; options may also follow the name (`bump.jpg -bm 1.5`, as some exporters write).
/// `None` when no file is named.
pub(crate) fn parse_texture_map(rest: &str) -> Option<TextureMap> {
    let tokens: Vec<&str> = rest.split_ascii_whitespace().collect();
    let mut map = TextureMap {
        file: String::new(),
        scale: [1.0, 1.0],
        offset: [0.0, 0.0],
        bump_multiplier: 1.0,
        ignored: Vec::new(),
    };
    let mut name: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < tokens.len() {
        let token = tokens[i];
        let option = token.to_ascii_lowercase();
        let arity = if option == "-t" {
            Some(3)
        } else {
            OPTIONS.iter().find(|(o, _)| *o == option).map(|(_, a)| *a)
        };
        let Some(arity) = arity else {
            name.push(token);
            i += 1;
            continue;
        };
        let numeric = matches!(
            option.as_str(),
            "-o" | "-s" | "-t" | "-mm" | "-bm" | "-boost" | "-texres"
        );
        let mut args = Vec::new();
        let mut j = i + 1;
        while j < tokens.len() && args.len() < arity {
            match (numeric, parse_float(tokens[j])) {
                (true, Some(v)) => args.push(v),
                (true, None) => break,
                (false, _) => args.push(0.0),
            }
            j += 1;
        }
        let arg = |k: usize, default: f32| args.get(k).copied().unwrap_or(default);
        match option.as_str() {
            "-s" => map.scale = [arg(0, 1.0), arg(1, 1.0)],
            "-o" => map.offset = [arg(0, 0.0), arg(1, 0.0)],
            "-bm" => map.bump_multiplier = arg(0, 1.0),
            _ => map.ignored.push(option),
        }
        i = j;
    }
    map.file = name.join(" ");
    (!map.file.is_empty()).then_some(map)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_before_and_after_the_name_are_not_part_of_it() {
        let map = parse_texture_map("-s 2 3 1 -o 0.5 0.25 0 -clamp on my wood.png")
            .unwrap_or_else(|| panic!("no map"));
        assert_eq!(map.file, "my wood.png");
        assert_eq!((map.scale, map.offset), ([2.0, 3.0], [0.5, 0.25]));
        assert_eq!(map.ignored, vec!["-clamp".to_owned()]);
        let bump = parse_texture_map("-imfchan r bumpmap2.jpg -bm 1.5").unwrap_or_else(|| panic!());
        assert_eq!(
            (bump.file.as_str(), bump.bump_multiplier),
            ("bumpmap2.jpg", 1.5)
        );
        let short = parse_texture_map("-o 0.1 diffuse.jpg").unwrap_or_else(|| panic!());
        assert_eq!(
            (short.file.as_str(), short.offset),
            ("diffuse.jpg", [0.1, 0.0])
        );
    }
}
