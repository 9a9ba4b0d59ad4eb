//! The scene's JSON Schema and the template `flapwright init` writes.
//!
//! The schema is derived from the scene types by `schemars` (their doc comments become
//! the keys' descriptions, `deny_unknown_fields` becomes `additionalProperties: false`),
//! so it cannot drift from what the parser accepts; `docs/scene.schema.json` is a copy a
//! test keeps equal to it. It checks the file's shape (keys, types, which kind takes which
//! keys); the ranges and the rules between keys stay with [`super::Scene::from_toml`],
//! whose messages name the line.

use super::Scene;
use crate::kinds::MechanismScene;

/// The `$id` of the schema: the name a TOML language server shows, and how `flapwright
/// init` recognises a schema file it wrote.
pub const SCHEMA_ID: &str = "https://flapwright.invalid/scene.schema.json";

/// The file name `flapwright init` writes the schema under, beside the scene (the
/// template's first line, `#:schema ./scene.schema.json`, names it).
pub const SCHEMA_FILE_NAME: &str = "scene.schema.json";

/// The scene template (`data/templates/scene.toml`): a small swept wing, one flap, two
/// dropped-hinge stations, settings with gap and overlap targets, a flight load case.
const TEMPLATE: &str = include_str!("../../../../data/templates/scene.toml");

/// The scene's JSON Schema (draft 2020-12), pretty-printed with a trailing newline.
pub fn scene_schema() -> String {
    let mut schema = schemars::generate::SchemaSettings::draft2020_12()
        .for_deserialize()
        .into_generator()
        .into_root_schema_for::<Scene>();
    schema.insert("$id".into(), SCHEMA_ID.into());
    schema.insert("title".into(), "Flapwright scene".into());
    let mut schema = schema.to_value();
    without_null(&mut schema);
    let mut text = serde_json::to_string_pretty(&schema).unwrap_or_default();
    text.push('\n');
    text
}

/// The kinds the template may be written with: those synthesised from the flap settings,
/// whose only needed key is the flap's mass share.
pub fn template_kinds() -> &'static [&'static str] {
    MechanismScene::SYNTHESISED_KINDS
}

/// The template with every station's mechanism of `kind`; None for a kind
/// [`template_kinds`] does not hold.
pub fn template(kind: &str) -> Option<String> {
    if !template_kinds().contains(&kind) {
        return None;
    }
    // The template's only `kind = ` lines are its stations' mechanisms.
    let lines: Vec<String> = TEMPLATE
        .lines()
        .map(|line| match line.starts_with("kind = ") {
            true => format!("kind = \"{kind}\""),
            false => line.to_string(),
        })
        .collect();
    Some(lines.join("\n") + "\n")
}

/// Removes `null` from the schema: TOML has no null, so an optional key is one that may be
/// left out, and `anyOf: [T, null]` (which makes a validator report a misspelt key inside
/// an optional table as the whole table matching neither) becomes T.
fn without_null(value: &mut serde_json::Value) {
    use serde_json::Value;
    match value {
        Value::Object(object) => {
            if let Some(Value::Array(types)) = object.get_mut("type") {
                types.retain(|t| t != "null");
                if types.len() == 1 {
                    let only = types.remove(0);
                    object.insert("type".into(), only);
                }
            }
            if object.get("default").is_some_and(Value::is_null) {
                object.remove("default");
            }
            let is_null = |v: &Value| v.get("type").is_some_and(|t| t == "null");
            let nullable = match object.get("anyOf") {
                Some(Value::Array(options)) if options.len() == 2 && options.iter().any(is_null) => {
                    options.iter().find(|o| !is_null(o)).cloned()
                }
                _ => None,
            };
            if let Some(Value::Object(inner)) = nullable {
                object.remove("anyOf");
                for (key, v) in inner {
                    object.entry(key).or_insert(v);
                }
            }
            object.values_mut().for_each(without_null);
        }
        Value::Array(items) => items.iter_mut().for_each(without_null),
        _ => {}
    }
}
