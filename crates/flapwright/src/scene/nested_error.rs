//! Error messages that carry a key path out of a nested deserialisation (the mechanism
//! kinds' own `Deserialize`), so that the parser can name the key that failed; a
//! leaf module, so that the kinds can raise them without importing the parser.

use serde_path_to_error::Path as KeyPath;

/// Marks an error raised inside a nested deserialisation (see [`nested_error`]): the text
/// between the first two markers is the inner key path.
pub(super) const NESTED_MARK: char = '\u{1}';

/// Starts the text of an error after which the rest of its table is moot (see
/// [`deciding_error_at`]).
pub(super) const DECIDES_MARK: char = '\u{2}';

/// An error message naming the key `key` that decides what the rest of its table means (a
/// mechanism's `kind`): once it is wrong, the table's other keys are not reported, since
/// they would be judged against a table the user did not mean (a misspelt kind would
/// otherwise be followed by every missing key of the stand-in kind).
pub fn deciding_error_at(key: &str, message: &str) -> String {
    nested_error_at(key, &format!("{DECIDES_MARK}{message}"))
}

/// An error message that carries the key path of a nested deserialisation, so that a
/// custom `Deserialize` (the mechanism kinds) does not hide which key failed.
pub fn nested_error(inner_path: &KeyPath, message: &str) -> String {
    // A nested error of a nested deserialisation is already marked: join the paths.
    let (deeper, message) = split_nested(message);
    let mut path = inner_path.to_string();
    if let Some(deeper) = deeper {
        if path == "." || path.is_empty() {
            path = deeper;
        } else if deeper.starts_with('[') {
            path.push_str(&deeper);
        } else {
            path = format!("{path}.{deeper}");
        }
    }
    format!("{NESTED_MARK}{path}{NESTED_MARK}{message}")
}

/// An error message naming the key `key` of the table being deserialised.
pub fn nested_error_at(key: &str, message: &str) -> String {
    format!("{NESTED_MARK}{key}{NESTED_MARK}{message}")
}

/// Splits a message made by [`nested_error`] into its inner path and text.
pub(super) fn split_nested(message: &str) -> (Option<String>, &str) {
    if let Some(rest) = message.strip_prefix(NESTED_MARK) {
        if let Some((path, text)) = rest.split_once(NESTED_MARK) {
            return (Some(path.to_string()), text);
        }
    }
    (None, message)
}
