//! Post-processing of rust-hdl's Verilog: one module per distinct block, not per instance.
//!
//! rust-hdl 0.46's `generate_verilog` writes one module per block *instance*, named by its
//! path (`top$lane_3$mul$s1_exp`), so a unit with 24 lanes of 7 FP units carries 168 copies
//! of the same adder or multiplier, each with its own copies of the same registers.
//! [`dedup_modules`] merges modules that are identical up to their own name and the names
//! of the modules they instantiate, bottom-up (two multipliers whose registers merged are
//! then identical too), and keeps, for each group, the module that comes first in the file
//! (rust-hdl writes them sorted by name) under its own name. Instance names are untouched,
//! so the hierarchy and the VCD scopes (`tb.<unit>.lane_3.mul.s1_exp`) are the same as
//! before; only the module *type* names in instantiations change.
//!
//! The format it relies on is rust-hdl's (module_defines.rs): a module starts with a line
//! `module NAME(ports);` at column 0 and ends with the line `endmodule // NAME`, and a
//! sub-module instance starts with a line `    KIND INSTANCE(`. Only the modules named
//! `top$...` (the blocks under the top module `top`) are merged; `top` itself, blackbox
//! or wrapper cores and any text outside modules are kept as they are.

use std::collections::{HashMap, HashSet};
use std::ops::Range;

/// One module of the input: line ranges into the input's lines.
struct Module<'a> {
    name: &'a str,
    /// The lines before the module since the previous one (rust-hdl: two blank lines).
    lead: Range<usize>,
    /// `module NAME(...);` through `endmodule // NAME`.
    body: Range<usize>,
}

/// `NAME` of a line `module NAME(...`.
fn module_header(line: &str) -> Option<&str> {
    let rest = line.strip_prefix("module ")?;
    let name = &rest[..rest.find('(')?];
    is_ident(name).then_some(name)
}

/// `(indent, KIND, INSTANCE)` of a sub-module instance line `    KIND INSTANCE(`.
fn instance(line: &str) -> Option<(&str, &str, &str)> {
    let t = line.trim_end();
    let indent = &t[..t.len() - t.trim_start().len()];
    let mut words = t.trim_start().split(' ');
    let (kind, inst) = (words.next()?, words.next()?);
    if words.next().is_some() || indent.is_empty() {
        return None;
    }
    let inst = inst.strip_suffix('(')?;
    (is_ident(kind) && is_ident(inst)).then_some((indent, kind, inst))
}

fn is_ident_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '$'
}

fn is_ident(s: &str) -> bool {
    s.chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && s.chars().all(is_ident_char)
}

/// Merges the modules of rust-hdl Verilog that are identical up to their own name and the
/// names of the modules they instantiate (see the module docs). Deterministic: the result
/// depends only on the input text. Idempotent.
///
/// Panics if a removed module's name is still referred to outside an instance line (a
/// format this function does not understand; it would otherwise emit a dangling reference).
pub fn dedup_modules(verilog: &str) -> String {
    let lines: Vec<&str> = verilog.split_inclusive('\n').collect();

    // Split into modules (each with the text before it) and a trailer.
    let mut modules: Vec<Module> = vec![];
    let (mut i, mut lead_start) = (0, 0);
    while i < lines.len() {
        if let Some(name) = module_header(lines[i]) {
            let end = format!("endmodule // {name}");
            if let Some(j) = (i + 1..lines.len()).find(|&j| lines[j].trim_end() == end) {
                modules.push(Module {
                    name,
                    lead: lead_start..i,
                    body: i..j + 1,
                });
                i = j + 1;
                lead_start = i;
                continue;
            }
        }
        i += 1;
    }
    let trailer = lead_start..lines.len();
    let index: HashMap<&str, usize> = modules
        .iter()
        .enumerate()
        .map(|(k, m)| (m.name, k))
        .collect();

    // Class of every module, children first: the key is the module's text with its own name
    // and its children's names replaced by placeholders and class numbers.
    let mut class: Vec<Option<usize>> = vec![None; modules.len()];
    let mut keys: HashMap<String, usize> = HashMap::new();
    let mut n_classes = 0;
    for root in 0..modules.len() {
        // Iterative post-order walk (a module is classed once all its children are).
        let mut stack = vec![(root, false)];
        let mut on_path: HashSet<usize> = HashSet::new();
        while let Some((m, children_done)) = stack.pop() {
            if class[m].is_some() {
                continue;
            }
            let children = || {
                lines[modules[m].body.clone()]
                    .iter()
                    .filter_map(|l| instance(l).and_then(|(_, kind, _)| index.get(kind).copied()))
            };
            if !children_done {
                assert!(
                    on_path.insert(m),
                    "dedup_modules: module {} instantiates itself",
                    modules[m].name
                );
                stack.push((m, true));
                stack.extend(
                    children()
                        .filter(|&c| class[c].is_none())
                        .map(|c| (c, false)),
                );
                continue;
            }
            on_path.remove(&m);
            if !modules[m].name.starts_with("top$") {
                class[m] = Some(n_classes);
                n_classes += 1;
                continue;
            }
            let mut key = String::new();
            for (k, l) in lines[modules[m].body.clone()].iter().enumerate() {
                if k == 0 {
                    key.push_str(&l.replacen(modules[m].name, "\0self", 1));
                } else if k == modules[m].body.len() - 1 {
                    key.push_str("\0end\n");
                } else if let Some((indent, kind, inst)) =
                    instance(l).filter(|(_, kind, _)| index.contains_key(kind))
                {
                    let c = class[index[kind]].expect("children are classed first");
                    key.push_str(&format!("{indent}\0{c} {inst}(\n"));
                } else {
                    key.push_str(l);
                }
            }
            let next = n_classes;
            let c = *keys.entry(key).or_insert(next);
            if c == next {
                n_classes += 1;
            }
            class[m] = Some(c);
        }
    }
    let class: Vec<usize> = class
        .into_iter()
        .map(|c| c.expect("every module classed"))
        .collect();

    // The first module of each class (in file order) stands for it.
    let mut canonical: Vec<Option<usize>> = vec![None; n_classes];
    for (m, &c) in class.iter().enumerate() {
        canonical[c].get_or_insert(m);
    }
    let mut out = String::with_capacity(verilog.len());
    let mut removed: HashSet<&str> = HashSet::new();
    for (m, module) in modules.iter().enumerate() {
        let lead = lines[module.lead.clone()].concat();
        if canonical[class[m]] != Some(m) {
            removed.insert(module.name);
            if !lead.trim().is_empty() {
                out.push_str(&lead);
            }
            continue;
        }
        out.push_str(&lead);
        for l in &lines[module.body.clone()] {
            match instance(l).filter(|(_, kind, _)| index.contains_key(kind)) {
                Some((indent, kind, inst)) => {
                    let name = modules[canonical[class[index[kind]]].unwrap()].name;
                    out.push_str(&format!("{indent}{name} {inst}(\n"));
                }
                None => out.push_str(l),
            }
        }
    }
    out.push_str(&lines[trailer].concat());

    if !removed.is_empty() {
        if let Some(t) = out
            .split(|c: char| !is_ident_char(c))
            .find(|t| removed.contains(t))
        {
            panic!("dedup_modules: removed module {t} is still referred to");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A register module in rust-hdl's style.
    fn dff(name: &str, width: usize) -> String {
        let w = if width == 1 {
            String::new()
        } else {
            format!("[{}:0] ", width - 1)
        };
        format!(
            "\n\nmodule {name}(d,q,clock);\n    \n    // Module arguments\n    input wire  {w}d;\n    output reg  {w}q;\n    \
             input wire  clock;\n    \n    always @(posedge clock) begin\n       q <= d;\n    end\n          \nendmodule // {name}\n"
        )
    }

    /// A module instantiating `(kind, instance)` pairs on `d,q,clock` stubs.
    fn parent(name: &str, subs: &[(&str, &str)]) -> String {
        let mut s = format!("\n\nmodule {name}(clock);\n    \n    // Module arguments\n    input wire  clock;\n    \n    // Sub module instances\n");
        for (kind, inst) in subs {
            s += &format!("    {kind} {inst}(\n        .d({inst}$d),\n        .q({inst}$q),\n        .clock(clock)\n    );\n");
        }
        s + &format!("    \nendmodule // {name}\n")
    }

    fn module_names(v: &str) -> Vec<&str> {
        v.lines().filter_map(module_header).collect()
    }

    #[test]
    fn merges_identical_leaves_and_keeps_instance_names() {
        let v = parent("top", &[("top$a", "a"), ("top$b", "b"), ("top$c", "c")])
            + &dff("top$a", 8)
            + &dff("top$b", 8)
            + &dff("top$c", 4);
        let d = dedup_modules(&v);
        assert_eq!(module_names(&d), ["top", "top$a", "top$c"]);
        assert!(
            d.contains("    top$a a(\n")
                && d.contains("    top$a b(\n")
                && d.contains("    top$c c(\n")
        );
        assert!(d.contains(".q(b$q)"), "instance wiring unchanged");
        assert!(!d.contains("top$b"));
        // What is left is rust-hdl's text, minus the removed module and its two blank lines.
        assert_eq!(
            d,
            v.replace(&dff("top$b", 8), "")
                .replace("top$b b(", "top$a b(")
        );
    }

    #[test]
    fn merges_bottom_up() {
        // Two parents whose children are distinct but identical modules merge too; a third
        // parent with a different child does not.
        let v = parent("top", &[("top$p", "p"), ("top$q", "q"), ("top$r", "r")])
            + &parent("top$p", &[("top$p$x", "x")])
            + &dff("top$p$x", 3)
            + &parent("top$q", &[("top$q$x", "x")])
            + &dff("top$q$x", 3)
            + &parent("top$r", &[("top$r$x", "x")])
            + &dff("top$r$x", 5);
        let d = dedup_modules(&v);
        assert_eq!(
            module_names(&d),
            ["top", "top$p", "top$p$x", "top$r", "top$r$x"]
        );
        assert!(d.contains("    top$p q(\n") && d.contains("    top$r r(\n"));
        assert_eq!(d.matches("    top$p$x x(\n").count(), 1);
    }

    #[test]
    fn instance_names_matter() {
        // Same child kinds, different instance names: different modules (different scopes).
        let v = parent("top", &[("top$p", "p"), ("top$q", "q")])
            + &parent("top$p", &[("top$p$x", "x")])
            + &dff("top$p$x", 3)
            + &parent("top$q", &[("top$q$y", "y")])
            + &dff("top$q$y", 3);
        let d = dedup_modules(&v);
        assert_eq!(module_names(&d), ["top", "top$p", "top$p$x", "top$q"]);
        assert!(d.contains("    top$p$x y(\n"));
    }

    #[test]
    fn top_and_foreign_modules_are_kept() {
        // `top` is never merged, modules outside `top$` (blackbox cores) are left alone, text
        // outside modules stays, and a module without its `endmodule // NAME` line is text.
        let core = "\nmodule core(a);\n  input a;\nendmodule // core\n";
        let v = parent("top", &[("top$a", "a"), ("core", "k")])
            + &dff("top$a", 8)
            + core
            + core.replace("core", "core2").as_str()
            + "// trailing text\nmodule broken(x);\n";
        let d = dedup_modules(&v);
        assert_eq!(d, v);
        let v2 = dff("top", 8) + &dff("top$a", 8);
        assert_eq!(dedup_modules(&v2), v2);
    }

    #[test]
    fn idempotent_and_deterministic() {
        let v = parent("top", &[("top$p", "p"), ("top$q", "q")])
            + &parent("top$p", &[("top$p$x", "x"), ("top$p$y", "y")])
            + &dff("top$p$x", 3)
            + &dff("top$p$y", 3)
            + &parent("top$q", &[("top$q$x", "x"), ("top$q$y", "y")])
            + &dff("top$q$x", 3)
            + &dff("top$q$y", 3);
        let d = dedup_modules(&v);
        assert_eq!(module_names(&d), ["top", "top$p", "top$p$x"]);
        assert_eq!(dedup_modules(&d), d);
        assert_eq!(dedup_modules(&v), d);
        assert_eq!(dedup_modules(""), "");
    }

    #[test]
    #[should_panic(expected = "still referred to")]
    fn refuses_dangling_references() {
        let v = parent("top", &[("top$a", "a"), ("top$b", "b")])
            + &dff("top$a", 8)
            + &dff("top$b", 8)
            + "// see top$b\n";
        dedup_modules(&v);
    }

    /// On real rust-hdl output: fewer modules, one `top`, every instance's kind defined.
    #[test]
    fn fp_add_stays_closed() {
        let v = crate::rtl::b32::verilog_fp_add(crate::format::Rounding::NearestEven);
        let d = dedup_modules(&v);
        let names = module_names(&d);
        assert!(names.len() < module_names(&v).len());
        assert_eq!(names.iter().filter(|&&n| n == "top").count(), 1);
        let defined: HashSet<&str> = names.into_iter().collect();
        let kinds: Vec<&str> = d
            .lines()
            .filter_map(instance)
            .map(|(_, kind, _)| kind)
            .collect();
        assert_eq!(
            kinds.len(),
            module_names(&v).len() - 1,
            "one instance line per original block"
        );
        assert!(kinds.iter().all(|k| defined.contains(k)));
    }
}
