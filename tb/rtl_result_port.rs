//! The result port (`rtl::ResultPort`, TRI_UNIT's read side in the chip) alone, clock by
//! clock against the rule of docs/explanation/architecture.md "Cycle semantics" (Results): TRI_UNIT's
//! head, if intersecting or uncertain, is shown to the host and leaves when the host reads
//! it; a separate pair leaves unseen; a sure hit is flagged for first-hit mode; `open`
//! counts the pairs taken whose results have not left. The cycle model has no unit of its
//! own for it (its `give` and `kept()` are in `cycle::chip`), and the chip's rust-hdl
//! queries (tb/rtl_chip.rs) show no uncertain result: breaking the port's uncertain path is
//! caught only by the exported chip's large queries under Verilator and by this test.

use collision_chip::rtl::ResultPort;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;

mod common;
use common::settle;

#[test]
fn result_port_shows_hits_and_uncertain_pairs_and_drops_separate_ones() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut uut = ResultPort::default();
    uut.clock.connect();
    uut.take.connect();
    uut.out_valid.connect();
    uut.out_hit.connect();
    uut.out_uncertain.connect();
    uut.out_tag.connect();
    uut.res_ready.connect();
    uut.connect_all();
    uut.clock.next = Clock { clk: true };
    settle(&mut uut);
    let mut open: u64 = 0;
    let (mut shown, mut dropped, mut held) = ([0usize; 2], 0, 0);
    for now in 0..5000 {
        // TRI_UNIT's head: valid only while pairs are open (hit and uncertain never both)
        let valid = open > 0 && rng.random_bool(0.6);
        let kind = rng.random_range(0..3); // 0 separate, 1 hit, 2 uncertain
        let (hit, unc) = (kind == 1, kind == 2);
        let tag: u32 = rng.random();
        let ready = rng.random_bool(0.5);
        let take = open < 511 && rng.random_bool(0.5);
        uut.take.next = take;
        uut.out_valid.next = valid;
        uut.out_hit.next = hit;
        uut.out_uncertain.next = unc;
        uut.out_tag.next = (tag as u64).into();
        uut.res_ready.next = ready;
        settle(&mut uut);
        let show = valid && (hit || unc);
        let give = valid && (ready || !(hit || unc));
        let ctx = format!("cycle {now}: valid {valid} hit {hit} uncertain {unc} ready {ready}");
        assert_eq!(uut.res_valid.val(), show, "{ctx}: res_valid");
        if show {
            assert_eq!(uut.res_tag.val().to_u64() as u32, tag, "{ctx}: res_tag");
            assert_eq!(uut.res_uncertain.val(), unc, "{ctx}: res_uncertain");
        }
        assert_eq!(
            uut.out_ready.val(),
            ready || !(hit || unc),
            "{ctx}: out_ready"
        );
        assert_eq!(uut.give.val(), give, "{ctx}: give");
        assert_eq!(uut.sure_hit.val(), valid && hit, "{ctx}: sure_hit");
        assert_eq!(uut.open.val().to_u64(), open, "{ctx}: open");
        match (show, give) {
            (true, true) => shown[unc as usize] += 1,
            (true, false) => held += 1,
            (false, true) => dropped += 1,
            _ => {}
        }
        uut.clock.next = Clock { clk: false };
        settle(&mut uut);
        uut.clock.next = Clock { clk: true };
        settle(&mut uut);
        open = open + take as u64 - give as u64;
    }
    assert!(
        shown.iter().all(|&s| s > 200) && dropped > 200 && held > 200,
        "{shown:?} {dropped} {held}"
    );
}
