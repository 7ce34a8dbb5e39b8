//! "The import graph of src/ has no circle and no upward arrow", and no file in src/
//! is over 1,000 lines (in rustfmt's default style) but those in [`LONG_FILES`], until they are
//! split. Checked by reading the imports out of the source text (every `crate::`, `$crate::`,
//! `super::` and `self::` path, `use` trees expanded), not by eye.

use petgraph::algo::tarjan_scc;
use petgraph::graph::DiGraph;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fs;
use std::path::{Path, PathBuf};

/// Rooms (top-level modules of src/) from the bottom up. A room may import rooms in its own
/// layer or below, never above. The crate root (lib.rs) is exempt: it declares everything.
const LAYERS: &[&[&str]] = &[
    /* 0 */ &["format", "pose", "measure", "oracle"],
    /* 1 */ &["mesh"],
    /* 2 */ &["chip"],
    /* 3 */ &["dop"],
    /* 4 */ &["golden"],
    /* 5 */ &["traversal", "fold"],
    /* 6 */ &["query", "hard_cases"],
    /* 7 */ &["cycle"],
    /* 8 */ &["rtl"],
    /* 9 */ &["harness"],
    /* 10 */ &["scene"],
    /* 11 */ &["report", "peer"],
];

/// Lines a file in src/ may have (src/bin/ included), in rustfmt's default style.
const MAX_LINES: usize = 1000;

/// The files still over [`MAX_LINES`] (paths under src/), each with the most it may have until
/// it is split by responsibility or its tests move to a sibling `tests.rs`: 1,500 lines, what
/// this guard held for every file before. A file back within MAX_LINES must leave the list.
const LONG_FILES: &[(&str, usize)] = &[];

#[test]
fn src_is_layered() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    if let Err(e) = check(&src, LAYERS, LONG_FILES) {
        panic!("\n{e}");
    }
}

type Tokens = Vec<(String, usize)>; // (token, 1-based line)

/// Blanks comments and string/char literals, keeping newlines so line numbers survive, so that
/// doc links like [`crate::rtl`] and text in strings are not read as imports.
fn strip(src: &str) -> String {
    let c: Vec<char> = src.chars().collect();
    let at = |k: usize, ch: char| c.get(k) == Some(&ch);
    let id = |k: usize| {
        c.get(k)
            .is_some_and(|ch| ch.is_alphanumeric() || *ch == '_')
    };
    let find = |from: usize, stop: &dyn Fn(usize) -> bool| {
        (from..c.len()).find(|&k| stop(k)).unwrap_or(c.len())
    };
    let (mut out, mut i) = (String::with_capacity(src.len()), 0);
    while i < c.len() {
        let hashes = (i + 1..).take_while(|&k| at(k, '#')).count();
        let end = if at(i, '/') && at(i + 1, '/') {
            find(i, &|k| c[k] == '\n')
        } else if at(i, '/') && at(i + 1, '*') {
            let (mut depth, mut k) = (0, i); // block comments nest in Rust
            loop {
                if at(k, '/') && at(k + 1, '*') {
                    (depth, k) = (depth + 1, k + 2);
                } else if at(k, '*') && at(k + 1, '/') {
                    (depth, k) = (depth - 1, k + 2);
                    if depth == 0 {
                        break k;
                    }
                } else if k >= c.len() {
                    break k;
                } else {
                    k += 1;
                }
            }
        } else if at(i, 'r')
            && at(i + 1 + hashes, '"')
            && (i == 0 || !id(i - 1) || (at(i - 1, 'b') && (i < 2 || !id(i - 2))))
        {
            // r"..", r#".."#, br#".."#: ends at a quote followed by as many hashes
            find(i + hashes + 2, &|k| {
                at(k, '"') && (1..=hashes).all(|h| at(k + h, '#'))
            }) + hashes
                + 1
        } else if at(i, '"') {
            // ends at a quote after an even number of backslashes
            find(i + 1, &|k| {
                c[k] == '"' && (i + 1..k).rev().take_while(|&j| c[j] == '\\').count() % 2 == 0
            }) + 1
        } else if at(i, '\'') && (at(i + 1, '\\') || at(i + 2, '\'')) {
            // a char literal: 'x', '"', '\n', '\'', '\u{..}'; a lifetime 'a is left alone
            find(i + if at(i + 1, '\\') { 3 } else { 2 }, &|k| c[k] == '\'') + 1
        } else {
            out.push(c[i]);
            i += 1;
            continue;
        };
        let end = end.min(c.len());
        out.extend(
            c[i..end]
                .iter()
                .map(|&ch| if ch == '\n' { '\n' } else { ' ' }),
        );
        i = end;
    }
    out
}

/// Identifiers (with `$crate`), `::`, or single other characters.
fn tokens(text: &str) -> Tokens {
    let c: Vec<char> = text.chars().collect();
    let id = |k: usize| {
        c.get(k)
            .is_some_and(|ch| ch.is_alphanumeric() || *ch == '_')
    };
    let (mut out, mut line, mut i) = (Vec::new(), 1, 0);
    while i < c.len() {
        let s = i;
        i = if id(i) || (c[i] == '$' && id(i + 1)) {
            (i + 1..=c.len()).find(|&k| !id(k)).unwrap()
        } else {
            i + if c[i] == ':' && c.get(i + 1) == Some(&':') {
                2
            } else {
                1
            }
        };
        if !c[s].is_whitespace() {
            out.push((c[s..i].iter().collect(), line));
        }
        line += (c[s] == '\n') as usize;
    }
    out
}

fn is_ident(s: &str) -> bool {
    s.starts_with(|ch: char| ch.is_alphanumeric() || ch == '_' || ch == '$')
}

/// Reads the path or `use` tree at t[i], pushing each full path (prefix + its own segments, with
/// the line of its last segment): `a::{b, c::{d, e as f}, self}` gives a::b, a::c::d, a::c::e,
/// a::self. Returns the index after it.
fn tree(
    t: &Tokens,
    mut i: usize,
    mut segs: Vec<String>,
    out: &mut Vec<(usize, Vec<String>)>,
) -> usize {
    let start = i;
    while let Some((s, line)) = t.get(i) {
        if s == "{" {
            i += 1;
            while i < t.len() && t[i].0 != "}" {
                match t[i].0.as_str() {
                    "," => i += 1,
                    "as" => i += 2,
                    _ => i = tree(t, i, segs.clone(), out).max(i + 1),
                }
            }
            return i + 1;
        }
        if s == "*" || is_ident(s) {
            segs.push(s.clone());
            i += 1;
            if s != "*" && t.get(i).is_some_and(|x| x.0 == "::") {
                i += 1;
                continue;
            }
            segs.retain(|x| x != "*"); // a glob imports from the module before it
            out.push((*line, segs));
            return i;
        }
        break; // `<` of a turbofish, or anything else, ends the path
    }
    if i > start {
        out.push((t[i - 1].1, segs));
    }
    i
}

/// Applies `crate`, `super` and `self` to `segs`, read in module `here`.
fn resolve(here: &[String], segs: &[String]) -> Vec<String> {
    let mut p = here.to_vec();
    for s in segs {
        match s.as_str() {
            "crate" | "$crate" => p.clear(),
            "super" => drop(p.pop()),
            "self" => {}
            _ => p.push(s.clone()),
        }
    }
    p
}

/// Every `crate::`/`$crate::`/`super::`/`self::` path in a file of module `here`, as
/// (line, absolute path). Inline `mod name { }` blocks are tracked, so the usual
/// `#[cfg(test)] mod tests { use super::*; }` means the file's own module, not its parent.
/// A path without such a prefix names another crate or the file's own child module, so
/// never crosses rooms and is never part of a circle (see rule 3 below).
fn refs(text: &str, here: &[String]) -> Vec<(usize, Vec<String>)> {
    let t = tokens(&strip(text));
    let (mut out, mut inline, mut depth, mut i) = (Vec::new(), Vec::<(String, usize)>::new(), 0, 0);
    while i < t.len() {
        let tok = |k: usize| t.get(k).map_or("", |x| x.0.as_str());
        match tok(i) {
            "mod" if tok(i + 2) == "{" => inline.push((tok(i + 1).to_string(), depth)),
            "{" => depth += 1,
            "}" => {
                depth = usize::saturating_sub(depth, 1);
                if inline.last().is_some_and(|m| m.1 == depth) {
                    inline.pop();
                }
            }
            _ => {}
        }
        let restriction = i >= 3 && tok(i - 1) == "in" && tok(i - 2) == "(" && tok(i - 3) == "pub";
        if ["crate", "$crate", "super", "self"].contains(&tok(i))
            && tok(i + 1) == "::"
            && !restriction
        {
            let module: Vec<String> = here
                .iter()
                .cloned()
                .chain(inline.iter().map(|m| m.0.clone()))
                .collect();
            let mut paths = Vec::new();
            i = tree(&t, i, Vec::new(), &mut paths);
            out.extend(
                paths
                    .into_iter()
                    .map(|(line, p)| (line, resolve(&module, &p))),
            );
        } else {
            i += 1;
        }
    }
    out
}

/// src/a/b.rs and src/a/b/mod.rs are module a::b; src/lib.rs is the crate root.
fn module_of(rel: &Path) -> Vec<String> {
    let mut m: Vec<String> = rel
        .with_extension("")
        .iter()
        .map(|s| s.to_string_lossy().into_owned())
        .collect();
    if m.last().is_some_and(|s| s == "mod") || m == ["lib"] {
        m.pop();
    }
    m
}

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let p = e.unwrap().path();
        if p.is_dir() {
            walk(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Checks the tree under `src` against `layers` and its files' lengths against [`MAX_LINES`]
/// and `long_files` (as [`LONG_FILES`]); Err lists every violation found.
fn check(src: &Path, layers: &[&[&str]], long_files: &[(&str, usize)]) -> Result<(), String> {
    let mut all = Vec::new();
    walk(src, &mut all);
    all.sort();
    let show = |f: &PathBuf| format!("src/{}", f.strip_prefix(src).unwrap().display());
    let text: Vec<String> = all.iter().map(|f| fs::read_to_string(f).unwrap()).collect();
    let (mut errs, mut long) = (Vec::new(), String::new());
    let lines: BTreeMap<&Path, usize> = all
        .iter()
        .zip(&text)
        .map(|(f, t)| (f.strip_prefix(src).unwrap(), t.lines().count()))
        .collect();
    let allowed: HashMap<&Path, usize> =
        long_files.iter().map(|&(f, n)| (Path::new(f), n)).collect();
    for (&f, &n) in &lines {
        let max = allowed.get(f).copied().unwrap_or(MAX_LINES);
        if n > max {
            long += &format!("\n    src/{} ({n} lines, at most {max})", f.display());
        }
    }
    for &(f, _) in long_files {
        match lines.get(Path::new(f)) {
            Some(&n) if n > MAX_LINES => {}
            Some(n) => errs.push(format!(
                "src/{f} is {n} lines, within {MAX_LINES}: delete it from LONG_FILES"
            )),
            None => errs.push(format!(
                "LONG_FILES names src/{f}, which does not exist: delete it"
            )),
        }
    }

    // The import graph: src/bin/ is a separate crate, so not part of it.
    let (files, text): (Vec<_>, Vec<_>) = all
        .into_iter()
        .zip(text)
        .filter(|(f, _)| !f.starts_with(src.join("bin")))
        .unzip();
    let mods: Vec<Vec<String>> = files
        .iter()
        .map(|f| module_of(f.strip_prefix(src).unwrap()))
        .collect();
    let index: HashMap<&[String], usize> =
        mods.iter().enumerate().map(|(k, m)| (&m[..], k)).collect();
    let mut edges: BTreeMap<(usize, usize), BTreeSet<usize>> = BTreeMap::new(); // (from, to) -> lines
    for (a, t) in text.iter().enumerate() {
        for (line, path) in refs(t, &mods[a]) {
            // The target is the longest prefix of the path that is a module file.
            match (0..=path.len()).rev().find_map(|n| index.get(&path[..n])) {
                Some(&b) if b != a => drop(edges.entry((a, b)).or_default().insert(line)),
                _ => {}
            }
        }
    }
    let list = |es: &mut dyn Iterator<Item = (&(usize, usize), &BTreeSet<usize>)>| -> String {
        es.map(|((a, b), ls)| {
            let ls: Vec<String> = ls.iter().map(|l| l.to_string()).collect();
            format!(
                "\n    {} -> {} (line{} {})",
                show(&files[*a]),
                show(&files[*b]),
                if ls.len() > 1 { "s" } else { "" },
                ls.join(", ")
            )
        })
        .collect()
    };

    // 2. No upward arrow. A room is the first segment of a module path; the root (lib.rs) has none.
    let room = |k: usize| mods[k].first().map(String::as_str);
    let layer: HashMap<&str, usize> = layers
        .iter()
        .enumerate()
        .flat_map(|(l, rs)| rs.iter().map(move |r| (*r, l)))
        .collect();
    let rooms: BTreeSet<&str> = (0..files.len()).filter_map(room).collect();
    for r in rooms.iter().filter(|r| !layer.contains_key(*r)) {
        let f = (0..files.len())
            .filter(|&k| room(k) == Some(r))
            .min_by_key(|&k| mods[k].len())
            .unwrap();
        errs.push(format!(
            "room `{r}` ({}) is not in LAYERS: add it to LAYERS",
            show(&files[f])
        ));
    }
    let cross = |&(a, b): &(usize, usize)| match (room(a), room(b)) {
        (Some(ra), Some(rb)) if ra != rb => Some((ra, rb)),
        _ => None,
    };
    let up = list(&mut edges.iter().filter(|(e, _)| {
        cross(e).is_some_and(|(ra, rb)| layer.get(rb) > layer.get(ra) && layer.contains_key(ra))
    }));
    if !up.is_empty() {
        errs.push(format!(
            "upward arrows (a room importing a room in a higher layer):{up}"
        ));
    }

    // 1. The room graph has no circle.
    let mut rg = DiGraph::<&str, ()>::new();
    let node: HashMap<&str, _> = rooms.iter().map(|r| (*r, rg.add_node(*r))).collect();
    for (ra, rb) in edges.keys().filter_map(cross).collect::<BTreeSet<_>>() {
        rg.add_edge(node[ra], node[rb], ());
    }
    for scc in tarjan_scc(&rg).into_iter().filter(|s| s.len() > 1) {
        let inside: BTreeSet<&str> = scc.iter().map(|n| rg[*n]).collect();
        let es = list(&mut edges.iter().filter(|(e, _)| {
            cross(e).is_some_and(|(ra, rb)| inside.contains(ra) && inside.contains(rb))
        }));
        errs.push(format!("circle between rooms {inside:?}:{es}"));
    }

    // 3. The file graph has no circle either. An edge from a module file to its own descendant
    // (a mod.rs declaring, re-exporting or calling into its children) is left out: the children
    // belong to it, so child -> parent -> child is not a dependency circle. Any other is.
    let down = |&(a, b): &(usize, usize)| mods[b].starts_with(&mods[a]);
    let fg = DiGraph::<(), ()>::from_edges(
        edges
            .keys()
            .filter(|e| !down(e))
            .map(|&(a, b)| (a as u32, b as u32)),
    );
    for scc in tarjan_scc(&fg).into_iter().filter(|s| s.len() > 1) {
        let inside: BTreeSet<usize> = scc.iter().map(|n| n.index()).collect();
        let es = list(
            &mut edges
                .iter()
                .filter(|(e, _)| !down(e) && inside.contains(&e.0) && inside.contains(&e.1)),
        );
        errs.push(format!("circle between files:{es}"));
    }
    // 4. No file over MAX_LINES (src/bin/ included) but those in `long_files`, within theirs.
    if !long.is_empty() {
        errs.push(format!(
            "files too long (split them by responsibility, or move their tests to a sibling tests.rs):{long}"
        ));
    }
    if errs.is_empty() {
        Ok(())
    } else {
        Err(errs.join("\n\n"))
    }
}

mod parser {
    use super::*;

    fn paths(text: &str, here: &[&str]) -> Vec<String> {
        let here: Vec<String> = here.iter().map(|s| s.to_string()).collect();
        refs(text, &here)
            .into_iter()
            .map(|(_, p)| p.join("::"))
            .collect()
    }

    #[test]
    fn use_trees_expand() {
        let got = paths(
            "use crate::a::{b, c::{d, e as f}, self};\nuse crate::g::*;",
            &["x"],
        );
        assert_eq!(got, ["a::b", "a::c::d", "a::c::e", "a", "g"]);
        assert_eq!(
            paths(
                "let p = crate::cycle::Params::<T>::RTL; $crate::rtl::m!();",
                &[]
            ),
            ["cycle::Params", "rtl::m"]
        );
        assert_eq!(
            paths(
                "pub(crate) fn f() {} pub(in crate::a) fn g() {} mod m;",
                &[]
            ),
            Vec::<String>::new()
        );
    }

    #[test]
    fn comments_and_strings_are_not_imports() {
        let text = "//! see [`crate::rtl`]\n/// [`crate::a`]\n// crate::b\n/* crate::c /* nested */ crate::d */\n\
                    let s = \"crate::e \\\" crate::f\"; let t = \"\\\\\"; let r = r#\"crate::g \" crate::h\"#; let q = '\"';\n\
                    fn f<'a>(x: &'a str) -> char { '\\n' }\nlet k = '\\''; use crate::real::Thing;";
        assert_eq!(paths(text, &[]), ["real::Thing"]);
        assert_eq!(refs(text, &[])[0].0, 7, "line numbers survive stripping");
    }

    #[test]
    fn super_and_self_resolve_from_the_file_module() {
        assert_eq!(module_of(Path::new("x/mod.rs")), ["x"]);
        assert_eq!(module_of(Path::new("x/y.rs")), ["x", "y"]);
        assert!(module_of(Path::new("lib.rs")).is_empty());
        assert_eq!(paths("use super::y; use self::z;", &["x"]), ["y", "x::z"]); // in src/x/mod.rs
        assert_eq!(
            paths("use super::z; use super::super::w;", &["x", "y"]),
            ["x::z", "w"]
        ); // in src/x/y.rs
    }

    #[test]
    fn inline_mod_tests() {
        let text = "fn f() { }\n#[cfg(test)]\nmod tests {\n use super::*;\n fn g() { { } }\n use super::super::q;\n}\nuse super::z;";
        assert_eq!(paths(text, &["x", "y"]), ["x::y", "x::q", "x::z"]);
    }

    fn tree_in(name: &str, files: &[(&str, &str)]) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("layers-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        for (p, body) in files {
            fs::create_dir_all(dir.join(p).parent().unwrap()).unwrap();
            fs::write(dir.join(p), body).unwrap();
        }
        dir
    }

    #[test]
    fn a_layered_tree_passes() {
        let src = tree_in("good", &[
            ("lib.rs", "pub mod a;\npub mod b;\n"),
            ("a/mod.rs", "//! Above us is [`crate::b`].\npub mod x;\npub use self::x::X;\npub fn helper() {}\n"),
            ("a/x.rs", "use super::helper;\npub struct X;\n#[cfg(test)]\nmod tests { use super::*; }\n"),
            ("b.rs", "use crate::a::{X, x::{self}};\nconst S: &str = \"crate::b\";\n"),
            ("bin/tool.rs", "use crate::b;\n"),
        ]);
        assert_eq!(check(&src, &[&["a"], &["b"]], &[]), Ok(()));
    }

    #[test]
    fn circles_upward_arrows_unlisted_rooms_and_long_files_fail() {
        let long = "fn f() {}\n".repeat(MAX_LINES + 1);
        let longer = "fn f() {}\n".repeat(MAX_LINES + 3);
        let src = tree_in(
            "bad",
            &[
                ("lib.rs", "pub mod a;\npub mod b;\npub mod c;\n"),
                ("a.rs", "\nuse crate::b::B;\npub struct A;\n"),
                ("b.rs", "use crate::a::A;\npub struct B;\n"),
                ("c.rs", &long),
                ("b/ok.rs", &long),
                ("b/over.rs", &longer),
            ],
        );
        let long_files = [
            ("b/ok.rs", MAX_LINES + 1),
            ("b/over.rs", MAX_LINES + 2),
            ("a.rs", 1500),
            ("gone.rs", 1500),
        ];
        let err = check(&src, &[&["a"], &["b"]], &long_files).unwrap_err();
        assert!(
            !err.contains("src/b/ok.rs"),
            "within its LONG_FILES entry:\n{err}"
        );
        for want in [
            "files too long (split them by responsibility, or move their tests to a sibling tests.rs):\n    \
             src/b/over.rs (1003 lines, at most 1002)\n    src/c.rs (1001 lines, at most 1000)",
            "src/a.rs is 3 lines, within 1000: delete it from LONG_FILES",
            "LONG_FILES names src/gone.rs, which does not exist: delete it",
            "room `c` (src/c.rs) is not in LAYERS: add it to LAYERS",
            "upward arrows",
            "src/a.rs -> src/b.rs (line 2)",
            "circle between rooms {\"a\", \"b\"}",
            "circle between files",
        ] {
            assert!(err.contains(want), "missing {want:?} in:\n{err}");
        }
    }
}
