//! The chip's memory port in RTL (`rtl::e8m15::MemoryPort`, rtl/memory_port.rs) against the
//! cycle model's unit `cycle::memory_port::MemPort` (the requests outstanding: which destination
//! may ask, which request a response answers) and the cycle chip's node-word lists
//! (`cycle::chip`: `to_ask`, the words arrived), clock by clock on random traffic: every
//! request (valid, address, destination), every response's destination and triangle id,
//! the FIFOs' empty flags and the DOP unit's words of the current pair.
//!
//! The port runs alone here: D_CNTR's pops and issues, the leaf register's triangle needs
//! and the memory are the testbench's, drawn at random within what the chip guarantees
//! (at most `PAIR_BUF` pairs popped and not issued, an issue only when its words are
//! there, a start only with nothing outstanding). The rest of the chip is checked with it
//! in tb/rtl_chip.rs.

use collision_chip::chip::layout::Dst;
use collision_chip::chip::rtl::PAIR_BUF;
use collision_chip::cycle::memory_port::MemPort;
use collision_chip::rtl::e8m15::{MemoryPort, CHIP_WORD_BITS};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use std::collections::VecDeque;

mod common;
use common::settle;

type Word = Bits<CHIP_WORD_BITS>;

/// The memory's word at `addr`: the address in bits 0..24 and, inverted, in 150..174 (both
/// inside a node word, so that a wrong slice or a wrong word shows).
fn word(addr: u32) -> Word {
    let mut w = Word::default();
    for i in 0..24 {
        w = w
            .replace_bit(i, (addr >> i) & 1 == 1)
            .replace_bit(150 + i, (addr >> i) & 1 == 0);
    }
    w
}

/// The address a node word of the port shows (0 for the register's reset value).
fn addr_of<const B: usize>(w: Bits<B>) -> Option<u32> {
    let a = w.get_bits::<24>(0).to_u64() as u32;
    let b = w.get_bits::<24>(150).to_u64() as u32;
    if a == 0 && b == 0 {
        return None;
    }
    assert_eq!(
        a ^ b,
        0xff_ffff,
        "a node word that is no memory word: {a:#x} {b:#x}"
    );
    Some(a)
}

/// A pair popped and not yet issued: which of its node words come from memory.
#[derive(Clone, Copy, Debug)]
struct Ahead {
    fetch: [bool; 2],
}

/// The reference: `MemPort` for the requests outstanding, the lists of `cycle::chip`.
struct Model {
    port: MemPort,
    base: [u32; 4],
    pf_on: bool,
    to_ask: VecDeque<(Dst, u32, u64)>,
    words: [VecDeque<u32>; 2],
    last: [Option<u32>; 2],
    ahead: VecDeque<Ahead>,
    seq: u64,
    seq_head: u64,
    /// The memory: accepted addresses, each with the first cycle it may be answered in.
    mem: VecDeque<(u32, u64)>,
}

#[derive(Default, Debug)]
struct Coverage {
    accepts: [usize; 4],
    responses: usize,
    issues: usize,
    at_max: usize,
    tri_blocked: usize,
    clears: usize,
}

fn run(seed: u64, cycles: u64, cov: &mut Coverage) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let port_out: u32 = rng.random_range(0..16);
    let max = port_out + 1;
    let mut m = Model {
        port: MemPort::new(max),
        base: [0; 4].map(|_| rng.random_range(0..1 << 24)),
        pf_on: rng.random_bool(0.5),
        to_ask: VecDeque::new(),
        words: [VecDeque::new(), VecDeque::new()],
        last: [None; 2],
        ahead: VecDeque::new(),
        seq: 0,
        seq_head: 0,
        mem: VecDeque::new(),
    };
    let mut uut = MemoryPort::new();
    uut.clock.connect();
    uut.clear.connect();
    uut.go.connect();
    uut.pf_on.connect();
    uut.port_out.connect();
    uut.base_na.connect();
    uut.base_nb.connect();
    uut.base_ta.connect();
    uut.base_tb.connect();
    uut.pop.connect();
    uut.pop_entry.connect();
    uut.pop_fetch.connect();
    uut.issue.connect();
    uut.cur_fa.connect();
    uut.cur_fb.connect();
    // the `words` layout (slot_bits, cur_sa, cur_sb 0; the `records` layout: tb/rtl_chip.rs)
    uut.slot_bits.connect();
    uut.cur_sa.connect();
    uut.cur_sb.connect();
    uut.need_ta.connect();
    uut.need_tb.connect();
    uut.leaf_tag.connect();
    uut.mem_req_ready.connect();
    uut.mem_resp_valid.connect();
    uut.mem_resp_data.connect();
    uut.connect_all();
    uut.clock.next = Clock { clk: true };
    settle(&mut uut); // the clock's first rise, before any input
    uut.port_out.next = (port_out as u64).into();
    uut.pf_on.next = m.pf_on;
    uut.base_na.next = (m.base[0] as u64).into();
    uut.base_nb.next = (m.base[1] as u64).into();
    uut.base_ta.next = (m.base[2] as u64).into();
    uut.base_tb.next = (m.base[3] as u64).into();
    // a few ids, so that words repeat
    let id = |rng: &mut ChaCha8Rng| rng.random_range(0..40u32);
    for now in 0..cycles {
        let ctx = format!("seed {seed}, cycle {now} (max {max}, prefetch {})", m.pf_on);
        // ---- this cycle's inputs
        let clear = now == 0 || (m.port.is_empty() && rng.random_bool(0.01));
        let go = rng.random_bool(0.9);
        let (need_ta, need_tb) = (rng.random_bool(0.15), rng.random_bool(0.15));
        let leaf = (id(&mut rng), id(&mut rng));
        let n = rng.random_range(1..=2usize);
        let pop = !clear && rng.random_bool(0.4) && m.ahead.len() + n <= PAIR_BUF;
        let ids = [0; 4].map(|_| id(&mut rng));
        let fetch = [0, 1, 2, 3].map(|k| k < 2 * n && rng.random_bool(0.6));
        let cur = m.ahead.front().copied();
        let (fa, fb) = cur.map_or((false, false), |c| (c.fetch[0], c.fetch[1]));
        let issue = !clear
            && cur.is_some()
            && (!fa || !m.words[0].is_empty())
            && (!fb || !m.words[1].is_empty())
            && rng.random_bool(0.5);
        let ready = rng.random_bool(0.7);
        let resp = m.mem.front().is_some_and(|&(_, t)| t <= now) && rng.random_bool(0.8);
        let mut entry: u128 = ids[0] as u128
            | (ids[1] as u128) << 16
            | (ids[2] as u128) << 33
            | (ids[3] as u128) << 49;
        if n == 2 {
            entry |= 1 << 66;
        }
        uut.clear.next = clear;
        uut.go.next = go;
        uut.need_ta.next = need_ta;
        uut.need_tb.next = need_tb;
        uut.leaf_tag.next = (leaf.0 as u64 | (leaf.1 as u64) << 16).into();
        uut.pop.next = pop;
        uut.pop_entry.next = entry.to_bits();
        uut.pop_fetch.next = ((0..4).map(|k| (fetch[k] as u64) << k).sum::<u64>()).into();
        uut.issue.next = issue;
        uut.cur_fa.next = fa;
        uut.cur_fb.next = fb;
        uut.mem_req_ready.next = ready;
        uut.mem_resp_valid.next = resp;
        uut.mem_resp_data.next = if resp {
            word(m.mem[0].0)
        } else {
            Word::default()
        };
        settle(&mut uut);
        // ---- the model's cycle: MemPort decides who may ask
        let node = m
            .to_ask
            .front()
            .filter(|f| go && (m.pf_on || f.2 % 32 == m.seq_head % 32));
        let req = if need_ta && m.port.free(Dst::TriA) {
            Some((Dst::TriA, leaf.0))
        } else if need_tb && m.port.free(Dst::TriB) {
            Some((Dst::TriB, leaf.1))
        } else {
            node.filter(|f| m.port.free(f.0)).map(|f| (f.0, f.1))
        };
        if m.port.len() == max as usize {
            cov.at_max += 1;
        }
        if (need_ta && !m.port.free(Dst::TriA) && m.port.len() < max as usize)
            || (need_tb && !m.port.free(Dst::TriB) && m.port.len() < max as usize)
        {
            cov.tri_blocked += 1;
        }
        let addr = |(d, id): (Dst, u32)| (m.base[d as usize] + id) & 0xff_ffff;
        assert_eq!(
            uut.mem_req_valid.val(),
            req.is_some(),
            "{ctx}: mem_req_valid, model {req:?}"
        );
        if let Some(r) = req {
            assert_eq!(uut.req_dst.val().to_u64(), r.0 as u64, "{ctx}: req_dst");
            assert_eq!(
                uut.mem_req_addr.val().to_u64() as u32,
                addr(r),
                "{ctx}: mem_req_addr of {r:?}"
            );
        }
        assert_eq!(uut.accept.val(), req.is_some() && ready, "{ctx}: accept");
        assert_eq!(
            uut.outstanding.val(),
            !m.port.is_empty(),
            "{ctx}: outstanding"
        );
        assert_eq!(uut.resp.val(), resp, "{ctx}: resp");
        let answered = if resp { m.port.respond() } else { None };
        if let Some((d, id)) = answered {
            assert_eq!(uut.resp_dst.val().to_u64(), d as u64, "{ctx}: resp_dst");
            match d {
                Dst::TriA => assert_eq!(uut.ta_req.val().to_u64() as u32, id, "{ctx}: ta_req"),
                Dst::TriB => assert_eq!(uut.tb_req.val().to_u64() as u32, id, "{ctx}: tb_req"),
                _ => {}
            }
        }
        assert_eq!(uut.wa_empty.val(), m.words[0].is_empty(), "{ctx}: wa_empty");
        assert_eq!(uut.wb_empty.val(), m.words[1].is_empty(), "{ctx}: wb_empty");
        for (k, (f, got)) in [(fa, uut.na_in.val()), (fb, uut.nb_in.val())]
            .into_iter()
            .enumerate()
        {
            if f && m.words[k].is_empty() {
                continue; // the pair waits for its word: na_in / nb_in unused
            }
            let want = if f {
                m.words[k].front().copied()
            } else {
                m.last[k]
            };
            assert_eq!(
                addr_of(got),
                want,
                "{ctx}: the DOP unit's word {k} (fetched: {f})"
            );
        }
        // ---- the rising edge
        uut.clock.next = Clock { clk: false };
        settle(&mut uut);
        uut.clock.next = Clock { clk: true };
        settle(&mut uut);
        if let Some((d, id)) = answered {
            let (a, _) = m.mem.pop_front().unwrap();
            assert_eq!(
                a,
                addr((d, id)),
                "{ctx}: the memory answers the oldest request"
            );
            cov.responses += 1;
            if !d.is_tri() {
                m.words[d as usize].push_back(a);
            }
        }
        if let Some(r) = req.filter(|_| ready) {
            m.port.accept(r.0, r.1);
            m.mem.push_back((addr(r), now + 1 + rng.random_range(0..4)));
            cov.accepts[r.0 as usize] += 1;
            if !r.0.is_tri() {
                m.to_ask.pop_front();
            }
        }
        if issue {
            cov.issues += 1;
            m.seq_head += 1;
            m.ahead.pop_front();
            for k in 0..2 {
                if [fa, fb][k] {
                    m.last[k] = m.words[k].pop_front();
                }
            }
        }
        if pop {
            for p in 0..n {
                for (k, d) in [Dst::NodeA, Dst::NodeB].into_iter().enumerate() {
                    if fetch[2 * p + k] {
                        m.to_ask.push_back((d, ids[2 * p + k], m.seq));
                    }
                }
                m.ahead.push_back(Ahead {
                    fetch: [fetch[2 * p], fetch[2 * p + 1]],
                });
                m.seq += 1;
            }
        }
        if clear {
            cov.clears += 1;
            m.to_ask.clear();
            m.words.iter_mut().for_each(VecDeque::clear);
            m.ahead.clear();
            m.seq = 0;
            m.seq_head = 0;
        }
    }
}

#[test]
fn memory_port_matches_the_cycle_models_port_clock_by_clock() {
    let mut cov = Coverage::default();
    for seed in 0..24 {
        run(seed, 1500, &mut cov);
    }
    eprintln!("{cov:?}");
    // the runs reached what the port does: every destination, full and blocked requests,
    // responses, issues and starts
    assert!(cov.accepts.iter().all(|&a| a > 200), "{cov:?}");
    assert!(
        cov.responses > 1000
            && cov.issues > 1000
            && cov.at_max > 500
            && cov.tri_blocked > 100
            && cov.clears > 10,
        "{cov:?}"
    );
}
