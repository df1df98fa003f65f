//! The known names nearest a mistyped one, so that a refusal says what was probably meant
//! instead of listing every name.

/// Most names offered.
const MOST: usize = 3;

/// Up to three of `known` nearest `given` by edit distance (optimal string alignment,
/// `strsim`), each within a third of the longer name's length (at least 2 edits), the
/// nearest first.
pub fn nearest_names<'a>(given: &str, known: impl IntoIterator<Item = &'a str>) -> Vec<&'a str> {
    let mut scored: Vec<(usize, &str)> = known
        .into_iter()
        .map(|name| (strsim::osa_distance(given, name), name))
        .filter(|&(distance, name)| distance <= (given.len().max(name.len()) / 3).max(2))
        .collect();
    scored.sort();
    scored.dedup();
    scored
        .into_iter()
        .take(MOST)
        .map(|(_, name)| name)
        .collect()
}

/// [`nearest_names`] as a clause of a message: "; did you mean `a` or `b`?", or nothing
/// where no name is near.
pub fn did_you_mean<'a>(given: &str, known: impl IntoIterator<Item = &'a str>) -> String {
    let near = nearest_names(given, known);
    if near.is_empty() {
        return String::new();
    }
    let quoted: Vec<String> = near.iter().map(|n| format!("`{n}`")).collect();
    format!("; did you mean {}?", quoted.join(" or "))
}

#[cfg(test)]
mod tests {
    use super::{did_you_mean, nearest_names};

    #[test]
    fn a_typo_finds_its_name_and_nonsense_finds_none() {
        let known = ["backlash_mm", "brake_drag_nm", "teeth", "module_m"];
        assert_eq!(nearest_names("backlsh_mm", known), ["backlash_mm"]);
        assert_eq!(nearest_names("teth", known), ["teeth"]);
        assert!(nearest_names("zzzzzzzzzz", known).is_empty());
        assert_eq!(did_you_mean("modul_m", known), "; did you mean `module_m`?");
        assert_eq!(did_you_mean("qqq", known), "");
    }
}
