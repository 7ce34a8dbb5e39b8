use super::*;

/// Words are laid out as `crate::golden::memory` says: a node's leaf bit, distances and fields,
/// a triangle's 24 values and two flags, most significant hex digit first.
#[test]
fn memory_words_and_writes() {
    let q = queries()
        .into_iter()
        .find(|q| q.name == "sphere_fifo_all")
        .unwrap();
    let p = q.prepare().unwrap();
    let a = &p.chip.a;
    assert_eq!(
        p.image.memory.len(),
        2 * a.tree.len() + 2 * a.tri_count(),
        "A and B are the same sphere"
    );
    let f = ChipKind::K6E8m15.config().format.dop;
    let w = &p.image.memory[0];
    let field = |w: &Word, at: usize, bits: usize| {
        (0..bits).fold(0u64, |v, k| {
            v | (w[(at + k) / 64] >> ((at + k) % 64) & 1) << k
        })
    };
    // hand-derived widths: 24-bit words, 1 + 6 * 24 + 64 node bits, 23 * 24 + 2 triangle bits
    const W: usize = 24;
    const NODE_BITS: usize = 209;
    const MEM_BITS: usize = 554;
    assert_eq!(W, f.width() as usize);
    // (the RTL's word widths are checked against the layout at compile time, rtl/mod.rs)
    assert_eq!(ChipKind::K6E8m15.word_bits(), MEM_BITS);
    // the papers' chip: 1 + 24 * 32 + 64 node bits, wider than its 23 * 32 + 2 triangle bits
    // a record: two node words padded to 256 bytes (it also reads the `records` layout)
    assert_eq!(ChipKind::K24B32.word_bits(), 2048);
    // e8m15 nodes, binary32 triangles: 1 + 24 * 24 + 64 = 641 node bits, 23 * 32 + 2 = 738;
    // it reads records too: two node words padded to 256 bytes
    assert_eq!(ChipKind::K24E8m15B32.word_bits(), 2048);
    assert_eq!(
        crate::chip::layout::Layout::new(&ChipKind::K24E8m15B32.config()).node_bits,
        641
    );
    assert!(p.image.memory[..a.tree.len()]
        .iter()
        .all(|w| field(w, NODE_BITS, 64) == 0
            && field(w, NODE_BITS + 64, MEM_BITS - NODE_BITS - 64) == 0));
    assert_eq!(field(w, 0, 1), 0, "the root is inner");
    assert_eq!(field(w, 1 + 2 * W, W), f.to_bits(a.tree.dop(0)[2]));
    let Node::Inner([c0, c1]) = a.tree.node(0) else {
        panic!()
    };
    assert_eq!(
        (field(w, 145, 32), field(w, 177, 32)),
        (c0 as u64, c1 as u64)
    );
    let t = &p.image.memory[a.tree.len() + 3];
    let l = LeafIn::of(f, &a.tri(3));
    assert_eq!(field(t, 4 * W, W), l.v[1][1]);
    assert_eq!(field(t, 9 * W + 5 * W, W), l.m[5]);
    assert_eq!(field(t, 22 * W, W), l.alpha_f);
    assert_eq!(
        field(t, 23 * W, 2),
        l.v_exact as u64 | (l.degenerate as u64) << 1
    );
    let hex = p.image.memory_hex();
    let line = hex.lines().nth(a.tree.len() + 3).unwrap();
    assert_eq!(line.len(), 139);
    assert_eq!(
        u64::from_str_radix(&line[line.len() - 6..], 16).unwrap(),
        l.v[0][0]
    );
    assert!(p.image.writes.contains(&(reg::MODE, 0)));
    assert!(p.image.writes_hex().lines().all(|l| l.len() == 11));
}

#[test]
fn too_large_a_tree_is_an_error() {
    let big = crate::mesh::builtin("sphere:40000")
        .unwrap()
        .triangles_f64();
    let chip = crate::query::Chip::new(&big, &big[..1], ChipKind::K6E8m15.config()).unwrap();
    let setup = chip.setup(&crate::pose::Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
    let e = QueryImage::new(
        ChipKind::K6E8m15,
        &chip.a,
        &chip.b,
        &setup,
        Order::Lifo,
        Mode::All,
        &Params::RTL,
        &chip.cfg,
    )
    .unwrap_err();
    assert!(e.contains("16 bits"), "{e}");
}

/// Records of stored DOP precision as the host writes them (binary32, k = 24, 4-bit codes,
/// two levels a record: 6 node words of 1 + 24 * 4 + 64 = 161 bits, then 24 distances of 32
/// bits and 24 exponents of 9 bits, 1,950 bits in a 2,048-bit word), read back bit by bit and
/// decoded plane by plane with `dop::stored::decode`: every node's distances are the golden
/// tree's, its fields its children's ids (or its triangle and record).
#[test]
fn coded_records_decode_to_the_golden_distances() {
    use crate::chip::layout::{exp_range, slot_bits};
    use crate::dop::stored::decode;
    let mut cfg = ChipKind::K24B32.config();
    cfg.layout = MemLayout::Records;
    cfg.dop_bits = DopBits::Bits(4);
    let l = Layout::new(&cfg);
    assert_eq!((l.node_bits, l.levels, l.shared_bits), (161, 2, 24 * 41));
    let field = |w: &Word, at: usize, bits: usize| {
        (0..bits).fold(0u64, |v, k| {
            v | (w[(at + k) / 64] >> ((at + k) % 64) & 1) << k
        })
    };
    let (f, rnd, lo) = (
        Format::BINARY32,
        cfg.dop_rounding.op(),
        exp_range(Format::BINARY32, 4).0,
    );
    let tris = crate::mesh::builtin("torus:300").unwrap().triangles_f64();
    let obj = ObjectImage::build(tris, &cfg);
    let [nodes, _] = object_words(ChipKind::K24B32, &cfg, &obj);
    for n in 0..obj.tree.len() as u32 {
        let w = &nodes[obj.record(n) as usize];
        let at = 161 * (obj.ids[n as usize] & ((1 << slot_bits(2)) - 1)) as usize;
        let golden = obj.tree.dop(n);
        for i in 0..24 {
            let q = field(w, at + 1 + 4 * i, 4) as u32;
            let r = f.from_bits(field(w, 6 * 161 + 32 * i, 32));
            let e = lo + field(w, 6 * 161 + 24 * 32 + 9 * i, 9) as i32;
            assert_eq!(
                f.to_bits(decode(f, rnd, r, q, e)),
                f.to_bits(golden[i]),
                "node {n}, plane {i}"
            );
        }
        let (leaf, f0) = (field(w, at, 1) == 1, field(w, at + 97, 32) as u32);
        match obj.tree.node(n) {
            Node::Inner([c0, _]) => assert!(!leaf && f0 == obj.ids[c0 as usize], "node {n}"),
            Node::Leaf(t) => assert!(leaf && f0 == t, "node {n}"),
        }
    }
}
