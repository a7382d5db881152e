//! Names a user types and the messages that answer a wrong one: the accepted name nearest to a
//! typing slip (`did you mean "restrict"?`), lists of names (`a, b or c`) and quoting.
//!
//! One home for the command line (`jobs::args`: subcommands, options, methods, arithmetic),
//! the JSON jobs (`jobs::read`: kinds and field names) and `blossom check`.

use blossom::Error;
use serde_json::{Map, Value};

/// Refuses a field of `object` (the object at `path`, `""` for the top level) that is not one
/// of `accepted`: `error: PATH.NAME: unknown field "NAME" (did you mean "..."?)`, or with the
/// accepted names listed when none is near. Fields are checked in the object's order.
pub fn expect_fields(
    object: &Map<String, Value>,
    path: &str,
    accepted: &[&str],
) -> Result<(), Error> {
    let Some(name) = object.keys().find(|k| !accepted.contains(&k.as_str())) else {
        return Ok(());
    };
    let at = if path.is_empty() {
        name.clone()
    } else {
        format!("{path}.{name}")
    };
    Err(Error::new(at, unknown_field(name, accepted)))
}

/// `unknown field "NAME" (did you mean "..."?)`, or with the accepted names listed.
pub fn unknown_field(name: &str, accepted: &[&str]) -> String {
    let hint = match did_you_mean(name, accepted) {
        near if !near.is_empty() => near,
        _ => format!(" (expected {})", listed(accepted)),
    };
    format!("unknown field {}{hint}", quoted(name))
}

/// The value named `name` among `names` (each name with its value), or the refusal `unknown
/// WHAT "NAME" (did you mean "..."?) (expected a, b or c)`.
pub fn lookup<E: Copy>(what: &str, name: &str, names: &[(&str, E)]) -> Result<E, String> {
    let list: Vec<&str> = names.iter().map(|(n, _)| *n).collect();
    let found = names.iter().find(|(n, _)| *n == name).map(|(_, e)| *e);
    found.ok_or_else(|| {
        let near = did_you_mean(name, &list);
        format!(
            "unknown {what} {}{near} (expected {})",
            quoted(name),
            listed(&list)
        )
    })
}

/// `names` as `a, b or c`.
pub fn listed(names: &[&str]) -> String {
    match names {
        [] => String::new(),
        [one] => one.to_string(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    }
}

/// `text` as a JSON string literal, for messages.
pub fn quoted(text: &str) -> String {
    serde_json::to_string(text).unwrap_or_else(|_| String::from("\"?\""))
}

/// The accepted name nearest to `word`, if it is near enough to be a typing slip: at most a
/// third of the longer word's letters inserted, deleted, replaced or swapped (the optimal
/// string alignment distance), at least one; ties go to the first name in `names`. A name
/// that starts with `word` (three letters or more) counts as near.
pub fn suggest<'a>(word: &str, names: &[&'a str]) -> Option<&'a str> {
    let word_lower = word.to_lowercase();
    let mut best: Option<(usize, &'a str)> = None;
    for &name in names {
        let distance = if word_lower.len() >= 3 && name.starts_with(&word_lower) {
            1
        } else {
            edit_distance(&word_lower, name)
        };
        let allowed = (word.chars().count().max(name.chars().count()) / 3).max(1);
        if distance <= allowed && best.is_none_or(|(d, _)| distance < d) {
            best = Some((distance, name));
        }
    }
    best.map(|(_, name)| name)
}

/// ` (did you mean "NAME"?)` after a message, or nothing.
pub fn did_you_mean(word: &str, names: &[&str]) -> String {
    suggest(word, names)
        .filter(|name| *name != word)
        .map(|name| format!(" (did you mean {}?)", quoted(name)))
        .unwrap_or_default()
}

/// The optimal string alignment distance of `a` and `b`: the fewest insertions, deletions,
/// replacements and swaps of adjacent characters that turn one into the other.
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    // rows[i][j]: the distance of a[..i] and b[..j]; three rows suffice for the swaps.
    let width = b.len() + 1;
    let mut before: Vec<usize> = vec![0; width];
    let mut previous: Vec<usize> = (0..width).collect();
    let mut current: Vec<usize> = vec![0; width];
    for i in 1..=a.len() {
        current[0] = i;
        for j in 1..=b.len() {
            let replace = previous[j - 1] + usize::from(a[i - 1] != b[j - 1]);
            let mut d = replace.min(previous[j] + 1).min(current[j - 1] + 1);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d = d.min(before[j - 2] + 1);
            }
            current[j] = d;
        }
        std::mem::swap(&mut before, &mut previous);
        std::mem::swap(&mut previous, &mut current);
    }
    previous[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edit_distance_counts_slips() {
        assert_eq!(edit_distance("", ""), 0);
        assert_eq!(edit_distance("abc", ""), 3);
        assert_eq!(edit_distance("pyramid", "pyramid"), 0);
        assert_eq!(edit_distance("pyramd", "pyramid"), 1);
        assert_eq!(edit_distance("pyarmid", "pyramid"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
    }

    #[test]
    fn expect_fields_names_the_path() {
        let object = serde_json::json!({"s": 1, "tt": 2});
        let Value::Object(object) = object else {
            unreachable!()
        };
        assert!(expect_fields(&object, "x", &["s", "tt"]).is_ok());
        let error = expect_fields(&object, "points[3]", &["s", "t"]).unwrap_err();
        assert_eq!(
            error.to_string(),
            "points[3].tt: unknown field \"tt\" (did you mean \"t\"?)"
        );
        let error = expect_fields(&object, "", &["s"]).unwrap_err();
        assert_eq!(error.to_string(), "tt: unknown field \"tt\" (expected s)");
    }

    #[test]
    fn suggestions_of_names_and_fields() {
        assert_eq!(
            did_you_mean("bezier_curve", &["curve", "bezier-curve"]),
            " (did you mean \"bezier-curve\"?)"
        );
        let fields = ["kind", "control_points", "interval"];
        assert_eq!(suggest("control_point", &fields), Some("control_points"));
        assert_eq!(suggest("intervall", &fields), Some("interval"));
        assert_eq!(suggest("Kind", &fields), Some("kind"));
        assert_eq!(suggest("comment", &fields), None);
        // The word itself is no suggestion.
        assert_eq!(did_you_mean("kind", &fields), "");
        assert_eq!(listed(&["a", "b", "c"]), "a, b or c");
        assert_eq!(listed(&["a"]), "a");
        assert_eq!(quoted("a\"b"), "\"a\\\"b\"");
    }
}
