//! Serde's and the YAML library's messages in the words of a case file.
//!
//! The derived deserialisers of src/case/schema.rs report what they expected by Rust type
//! (`expected struct Units`, `data did not match any variant of untagged enum BoundarySpec`,
//! `integer … as u128`): names the reader of a case file cannot act on. [`plain_message`]
//! rewrites each into what the key takes; cases/README.md lists every key and its values.

/// What each untagged enum of the schema takes, in YAML, by its Rust name.
const UNTAGGED: &[(&str, &str)] = &[
    (
        "BoundarySpec",
        "expected `fixed`, `free` or one mapping {displacement: [u_x, u_y]}, {traction: [t_x, t_y]} \
         or {pressure: p}",
    ),
    ("Penalty", "expected `auto` or a positive number"),
    ("CoreSpec", "expected `rigid` or {material: NAME}"),
];

/// Serde's message in the words of a case file: Rust's type names become what a value must
/// be ("expected f64" → "expected a number", "expected struct Units" → "expected a mapping"),
/// the YAML library's name for an enum becomes what to write, and a whole number beyond 64
/// bits is named as such with what to write instead.
pub fn plain_message(message: &str) -> String {
    if let Some(number) = wide_integer(message) {
        return format!(
            "the whole number `{number}` does not fit in 64 bits: write it with an exponent \
             (e.g. 1.5e20) if a number this large is meant"
        );
    }
    let mut out = message.to_string();
    if let Some(at) = out.find("data did not match any variant of untagged enum ") {
        let name = &out[at + "data did not match any variant of untagged enum ".len()..];
        let name: String = name.chars().take_while(|c| c.is_alphanumeric()).collect();
        let plain = UNTAGGED.iter().find(|(rust, _)| *rust == name).map_or(
            "expected one of the forms this key takes (cases/README.md)",
            |(_, plain)| plain,
        );
        out = format!("{}{plain}", &out[..at]);
    }
    for (rust, plain) in [
        ("expected f64", "expected a number"),
        ("expected f32", "expected a number"),
        ("expected usize", "expected a whole number (0, 1, 2, …)"),
        ("expected u64", "expected a whole number (0, 1, 2, …)"),
        ("expected u32", "expected a whole number (0, 1, 2, …)"),
        ("expected u16", "expected a whole number (0, 1, 2, …)"),
        ("expected u8", "expected a whole number (0, 1, 2, …)"),
        ("expected i64", "expected a whole number"),
        ("expected i32", "expected a whole number"),
        ("expected a boolean", "expected true or false"),
        (
            "expected a Value::Tagged enum",
            "expected one of the names this key takes (cases/README.md); leave the key out for its default",
        ),
        (
            "expected variant identifier",
            "expected one of the names this key takes (cases/README.md)",
        ),
        ("unknown variant `", "unknown name `"),
        ("expected a map", "expected a mapping (key: value)"),
        ("expected a sequence", "expected a list"),
        ("invalid type: unit value", "got null"),
        ("invalid type: floating point `", "got the number `"),
        ("invalid type: integer `", "got the number `"),
        ("invalid type: sequence", "got a list"),
        ("invalid type: map", "got a mapping"),
        ("invalid type: string ", "got the text "),
        ("invalid type: boolean ", "got "),
        ("invalid type: ", "got "),
        ("invalid value: integer `", "got the number `"),
        ("invalid value: floating point `", "got the number `"),
        ("invalid value: ", "got "),
    ] {
        out = out.replace(rust, plain);
    }
    // After the plain replacements, whose "expected a map" would match in "a mapping".
    out = replace_named(
        &out,
        "expected internally tagged enum ",
        "expected a mapping with a `model` key (cases/README.md lists the models)",
    );
    out = replace_named(
        &out,
        "expected struct ",
        "expected a mapping of keys (key: value; cases/README.md lists them)",
    );
    short_numbers(&out)
}

/// `… expected struct Units` → `… expected <plain>`: the type's name (one word) goes too.
fn replace_named(message: &str, rust: &str, plain: &str) -> String {
    let mut out = String::new();
    let mut rest = message;
    while let Some(at) = rest.find(rust) {
        out.push_str(&rest[..at]);
        out.push_str(plain);
        let after = &rest[at + rust.len()..];
        let name_len = after
            .find(|c: char| !c.is_alphanumeric() && c != '_')
            .unwrap_or(after.len());
        rest = &after[name_len..];
    }
    out.push_str(rest);
    out
}

/// The number of the YAML library's "invalid type: integer `N` as u128" (or i128): a whole
/// number that a 64-bit integer cannot hold.
fn wide_integer(message: &str) -> Option<&str> {
    let start = message.find("integer `")? + "integer `".len();
    let len = message[start..].find('`')?;
    let after = &message[start + len + 1..];
    (after.starts_with(" as u128") || after.starts_with(" as i128")).then(|| &message[start..start + len])
}

/// Serde prints a float in full (1e300 as 301 digits): a back-quoted number longer than 20
/// characters is shown in exponent form.
fn short_numbers(message: &str) -> String {
    let parts: Vec<&str> = message.split('`').collect();
    let mut out = String::new();
    for (i, part) in parts.iter().enumerate() {
        if i > 0 {
            out.push('`');
        }
        // Odd parts lie between back quotes.
        match part.parse::<f64>() {
            Ok(v) if i % 2 == 1 && part.len() > 20 && v.is_finite() => out.push_str(&format!("{v:e}")),
            _ => out.push_str(part),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::plain_message;

    #[test]
    fn rust_names_become_what_to_write() {
        assert_eq!(
            plain_message("got string \"abc\", expected struct Units"),
            "got string \"abc\", expected a mapping of keys (key: value; cases/README.md lists them)"
        );
        assert!(plain_message("data did not match any variant of untagged enum BoundarySpec").contains("`fixed`"));
        assert!(
            plain_message("invalid type: integer `18446744073709551616` as u128, expected any YAML value")
                .starts_with("the whole number `18446744073709551616` does not fit in 64 bits")
        );
        assert_eq!(
            plain_message("invalid type: floating point `100000000000000000000000`, x"),
            "got the number `1e23`, x"
        );
    }
}
