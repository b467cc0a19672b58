//! A mechanism file is data: free text from it (the description, a driver's expression) that
//! reaches the generated module's header cannot end the comment and add code. Each hostile text
//! must give a module with exactly the items of the plain file (parsed by syn, compared by
//! their tokens outside the doc comments).

use symbody_codegen::generate;

fn four_bar() -> String {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    std::fs::read_to_string(root.join("mechanisms/four_bar.toml")).unwrap()
}

/// The module's items without their doc comments (those hold the file's text by design) and
/// with the file text's hash (`Origin::Compiled { hash }`, different for any other text by
/// design) replaced by a placeholder.
fn items(code: &str) -> Vec<String> {
    let file: syn::File = syn::parse_file(code).unwrap_or_else(|e| panic!("{e}\n{code}"));
    file.items
        .iter()
        .map(|item| {
            let text = quote::quote!(#item).to_string();
            // `#[doc = "..."]` attributes carry text from the file; compare the code only.
            let code = text
                .split("# [doc =")
                .map(|part| part.split_once("\"]").map_or(part, |(_, rest)| rest))
                .collect::<String>();
            match code.split_once("hash : ") {
                Some((head, tail)) => {
                    let rest = tail.split_once("u64").map_or(tail, |(_, r)| r);
                    format!("{head}hash : HASH{rest}")
                }
                None => code,
            }
        })
        .collect()
}

const HOSTILE: [&str; 8] = [
    "ok\nfn injected() { std::process::exit(3) }\n//",
    "ok\r\nfn injected() {}\r\n",
    "ok\u{2028}fn injected() {}\u{2029}",
    "ok\u{85}fn injected() {}",
    "ok */ fn injected() {} /*",
    "quote \" and backslash \\ and tab \t and bell \u{7}",
    "ok\n#![allow(unused)] pub fn injected() {}",
    "ok\n}\nfn injected() {\n",
];

#[test]
fn hostile_descriptions_add_no_code() {
    let plain = generate("mechanisms/four_bar.toml", &four_bar()).unwrap();
    let reference = items(&plain.code);
    for text in HOSTILE {
        let escaped = toml_basic_string(text);
        let file = four_bar().replacen(
            "description = ",
            &format!("description = {escaped}\nold_description = "),
            1,
        );
        let file = file.replacen("old_description = ", "# ", 1);
        let g =
            generate("mechanisms/four_bar.toml", &file).unwrap_or_else(|e| panic!("{text:?}: {e}"));
        // The text is still shown (escaped), but only inside comments.
        for line in g.code.lines().filter(|l| l.contains("injected")) {
            assert!(line.starts_with("//!"), "{text:?} reached the code: {line}");
        }
        assert_eq!(items(&g.code), reference, "{text:?}");
    }
}

#[test]
fn a_driver_expression_with_a_comment_adds_no_code() {
    // Parses as an expression (the block comment is skipped), but its text is in the header.
    let value = "initial + 2.0 * pi * t /*\nfn evil() { std::process::exit(4) }\n*/";
    let file = four_bar().replacen(
        "value = \"initial + 2.0 * pi * t\"",
        &format!("value = {}", toml_basic_string(value)),
        1,
    );
    assert_ne!(file, four_bar(), "the driver line was found");
    let g = generate("mechanisms/four_bar.toml", &file).unwrap_or_else(|e| panic!("{e}"));
    for line in g.code.lines().filter(|l| l.contains("evil")) {
        assert!(
            line.starts_with("//!"),
            "the expression reached the code: {line}"
        );
    }
    let plain = generate("mechanisms/four_bar.toml", &four_bar()).unwrap();
    assert_eq!(items(&g.code), items(&plain.code));
}

/// `s` as a TOML basic string.
fn toml_basic_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
