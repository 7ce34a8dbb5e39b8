use super::*;

const V: &str = "[verdict]\nbinary32 = \"uncertain\"\ne8m15 = \"uncertain\"\nwhy = \"w\"\n";

#[test]
fn parse_errors_name_file_and_line() {
    let e = parse(
        "name = \"x\"\nfamily = \"vertex-face\"\nwhy = 3\n",
        "f.toml",
    )
    .unwrap_err();
    assert!(e.starts_with("f.toml:3:"), "{e}");
    let ok = "name = \"x\"\nfamily = \"vertex-face\"\nwhy = \"y\"\na = [[[0,0,0],[1,0,0],[0,1,0]]]\nb = [[[0,0,0],[1,0,0],[0,1,0]]]\n";
    assert!(parse(&format!("{ok}expected = [[0, 1]]\n{V}"), "f.toml")
        .unwrap_err()
        .contains("out of range"));
    assert!(
        parse(&format!("{ok}expected = [[0, 0], [0, 0]]\n{V}"), "f.toml")
            .unwrap_err()
            .contains("sorted")
    );
    assert!(parse(
        &format!("{ok}expected = []\n{V}").replace("vertex-face", "nope"),
        "f.toml"
    )
    .unwrap_err()
    .contains("unknown"));
    assert_eq!(
        parse(&format!("{ok}expected = [[0, 0]]\n{V}"), "f.toml")
            .unwrap()
            .expected,
        vec![(0, 0)]
    );
}

#[test]
fn verdict_errors_name_file_and_line() {
    assert_eq!(
        VERDICT_FORMATS.map(|f| f.to_string()),
        ["binary32", "e8m15"],
        "the files' keys"
    );
    // Two triangles of A, one of B; pair (1, 0) intersects.
    let head = "name = \"x\"\nfamily = \"vertex-face\"\nwhy = \"y\"\na = [[[0,0,0],[1,0,0],[0,1,0]], [[0,0,0],[1,0,0],[0,1,0]]]\nb = [[[0,0,0],[1,0,0],[0,1,0]]]\nexpected = [[1, 0]]\n";
    let e = parse(head, "f.toml").unwrap_err();
    assert!(e.starts_with("f.toml: no [verdict] table"), "{e}");
    let e = parse(
        &format!(
            "{head}{}",
            V.replace("e8m15 = \"uncertain\"", "e8m15 = \"maybe\"")
        ),
        "f.toml",
    )
    .unwrap_err();
    assert!(e.starts_with("f.toml:9:") && e.contains("maybe"), "{e}");
    let e = parse(
        &format!("{head}{}", V.replace("e8m15 = \"uncertain\"\n", "")),
        "f.toml",
    )
    .unwrap_err();
    assert!(e.starts_with("f.toml:7:") && e.contains("e8m15"), "{e}");
    // The default says separate, which pair (1, 0) contradicts.
    let e = parse(
        &format!(
            "{head}{}",
            V.replace("e8m15 = \"uncertain\"", "e8m15 = \"separate-or-uncertain\"")
        ),
        "f.toml",
    )
    .unwrap_err();
    assert!(
        e.starts_with(
            "f.toml:9: e8m15 verdict `separate-or-uncertain` for pair [1, 0], which intersects"
        ),
        "{e}"
    );
    let ex = |pairs: &str, b32: &str| {
        format!("{head}{V}[[verdict.exception]]\npairs = {pairs}\nbinary32 = \"{b32}\"\ne8m15 = \"uncertain\"\nwhy = \"z\"\n")
    };
    let e = parse(&ex("[[0, 1]]", "separate"), "f.toml").unwrap_err();
    assert!(
        e.starts_with("f.toml:12: exception pair [0, 1] is out of range"),
        "{e}"
    );
    let e = parse(&ex("[[0, 0]]", "intersecting"), "f.toml").unwrap_err();
    assert!(
        e.starts_with(
            "f.toml:13: binary32 verdict `intersecting` for pair [0, 0], which does not intersect"
        ),
        "{e}"
    );
    let e = parse(&ex("[[0, 0], [0, 0]]", "separate"), "f.toml").unwrap_err();
    assert!(
        e.starts_with("f.toml:12: pair [0, 0] is in two exceptions"),
        "{e}"
    );
    let e = parse(&format!("{head}{}", V.replace("\"w\"", "\" \"")), "f.toml").unwrap_err();
    assert!(
        e.starts_with("f.toml:10: the verdict's `why` must not be empty"),
        "{e}"
    );
    let c = parse(&ex("[[0, 0]]", "separate"), "f.toml").unwrap();
    assert_eq!(
        c.verdict((0, 0), Format::BINARY32),
        Some((Verdict::Separate, "z"))
    );
    assert_eq!(
        c.verdict((1, 0), Format::BINARY32),
        Some((Verdict::Uncertain, "w"))
    );
    assert_eq!(
        c.verdict((0, 0), Format::REDUCED),
        Some((Verdict::Uncertain, "z"))
    );
    assert_eq!(c.verdict((0, 0), Format::new(5, 4).unwrap()), None);
    let s = c.swapped();
    assert_eq!(
        s.verdict((0, 0), Format::BINARY32),
        Some((Verdict::Separate, "z"))
    );
    assert_eq!(
        s.verdict((0, 1), Format::BINARY32),
        Some((Verdict::Uncertain, "w"))
    );
}

#[test]
#[should_panic(expected = "not exact")]
fn generators_refuse_inexact_placements() {
    let p = Placement {
        offset: [0.0, 0.0, 1e7],
        scale: 1.0,
        turns: [0; 3],
    };
    vertex_face(&p, [0.25, 0.25], 2f64.powi(-40));
}

#[test]
fn quarter_turn_placement_is_exact() {
    let p = Placement {
        offset: [1024.0, -3.0, 0.5],
        scale: 0.25,
        turns: [1, 2, 3],
    };
    let c = vertex_face(&p, [0.25, 0.25], 0.0);
    assert_eq!(c.placed_b()[0][0], Point3::new(1024.0625, -2.9375, 0.5));
}
