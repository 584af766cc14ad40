// The library's functions as `nm -n --defined-only` lists them. Shared with tests/speed.rs
// (include!), which checks the recorded order against them.

/// The function symbols of the library's code (.text) in `nm -n --defined-only`'s output, by
/// address (_init and _fini have sections of their own).
pub fn text_symbols(nm: &str) -> Vec<String> {
    nm.lines()
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            let (_, kind, name) = (w.next()?, w.next()?, w.next()?);
            (matches!(kind, "t" | "T" | "W" | "w") && !matches!(name, "_init" | "_fini"))
                .then(|| name.to_string())
        })
        .collect()
}
