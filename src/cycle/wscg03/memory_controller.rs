//! WSCG'03's Memory Controller (§4.4) clocked register by register: the ask list of the
//! Stack Engine's sequencer, the requests to memory (A's and B's triangle words first, for
//! the Triangle Unit's interrupt; then node records, a node pair per burst), the records
//! arrived, and the stream of the head ask's DOPs into the DOP Unit, a 256-bit bundle a
//! clock. Every output reads the state before the clock's edge and this clock's inputs;
//! asks, requests taken and responses are written at the edge. It is the unit the RTL is to
//! follow.

use super::dop_unit::{AlignedBundle, ClockIn, TumbledBundle};
use crate::chip::layout::Dst;
use crate::chip::rtl::{MC_ASKS, MC_RECORDS};
use std::collections::VecDeque;

/// A node word as the chip reads it from its record (the memory image's node word, decoded):
/// its distances and its fields.
#[derive(Clone, Debug, Default)]
pub struct NodeWord {
    pub dop: Vec<f64>,
    pub fields: Fields,
}

/// What the sequencer keeps of a node word: the node's id (`record << 1 | slot`), the leaf
/// bit and the two 32-bit fields: an inner node's children's ids, or a leaf's triangle and
/// its triangle's record.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Fields {
    pub id: u32,
    pub leaf: bool,
    pub f: [u32; 2],
}

/// A record: a node pair's words in slots 0 and 1 (the root alone in slot 0 of record 0).
pub type Record = [NodeWord; 2];

/// The memory the Memory Controller reads: A's and B's node records, each region's first
/// word (by [`Dst`]), k.
pub struct Images {
    pub records: [Vec<Record>; 2],
    pub bases: [u32; 4],
    pub k: usize,
}

/// What the Memory Controller is asked for, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ask {
    /// A tumbled group's DOPs into d' set `set`: the `n` nodes from id `id` (a sibling pair
    /// in slots 0 and 1 of a record, or a node alone).
    Load { set: usize, id: u32, n: usize },
    /// The aligned node `id` against d' set `set`.
    Aligned { set: usize, id: u32 },
}

impl Ask {
    /// An ask as the sequencer's push ports carry it: `(load, set, pair, id)`, zeros for
    /// none.
    pub fn ports(a: Option<Ask>) -> (bool, usize, bool, u32) {
        match a {
            Some(Ask::Load { set, id, n }) => (true, set, n == 2, id),
            Some(Ask::Aligned { set, id }) => (false, set, false, id),
            None => (false, 0, false, 0),
        }
    }
}

/// An ask and its record: `Some(address)` fetched, `None` the one streamed before it (a
/// sibling of the aligned node before); whether it was requested.
#[derive(Clone, Debug)]
struct Entry {
    ask: Ask,
    addr: Option<u32>,
    requested: bool,
}

/// One clock's inputs: `halt` (no bundle streams), an ask into the list at the edge, the
/// Triangle Unit's input stage's `need` and triangle records (`ids`), the memory's ready
/// and response (its data is the record or word of the oldest request), the DOP Unit's sets'
/// `busy` after the last edge.
#[derive(Clone, Copy, Debug, Default)]
pub struct McIn {
    pub halt: bool,
    pub push: Option<Ask>,
    pub need: [bool; 2],
    pub ids: [u16; 2],
    pub mem_ready: bool,
    pub resp: bool,
    pub busy: [bool; 2],
}

/// One clock's outputs: the request (its word address; a triangle word's?), a triangle word for the input
/// stage (B's?, its record), the head ask's bundle for the DOP Unit with an aligned node's
/// fields on its last bundle and a load's set and members' fields on its first.
#[derive(Clone, Debug, Default)]
pub struct McOut {
    pub req: Option<u32>,
    pub req_tri: bool,
    pub fill: Option<(bool, u16)>,
    pub dop_in: ClockIn,
    pub aligned: Option<Fields>,
    pub loaded: Option<(usize, Vec<Fields>)>,
}

/// WSCG'03's Memory Controller: the ask list (at most [`MC_ASKS`]), the destinations of the
/// requests outstanding, the node records arrived (`held`; with those in flight at most
/// [`MC_RECORDS`]) and the one being streamed (`cur`).
pub struct MemoryController<'a> {
    img: &'a Images,
    asks: VecDeque<Entry>,
    /// Destinations and record numbers of the requests outstanding, oldest first.
    tags: VecDeque<(Dst, u32)>,
    held: VecDeque<Record>,
    cur: Record,
    node_inflight: usize,
    /// Bundles of the head ask streamed.
    beat: usize,
    /// The last aligned record asked for (a sibling shares it).
    last_aligned: Option<u32>,
    max_outstanding: usize,
    /// The regions' first words (the host's `BASE_*` registers), by [`Dst`].
    bases: [u32; 4],
    pub node_fetches: u64,
    pub tri_fetches: u64,
    /// A's triangle words of them (A's triangle cache's misses).
    pub tri_fetches_a: u64,
}

/// Bundles of eight distances a DOP takes on the 256-bit bus.
fn beats(k: usize) -> usize {
    k.div_ceil(8)
}

fn bundle(d: &[f64], entry: usize) -> [f64; 8] {
    std::array::from_fn(|t| d.get(8 * entry + t).copied().unwrap_or(0.0))
}

impl<'a> MemoryController<'a> {
    /// On the memory `img`, its regions from the words `bases` (by [`Dst`]), with at most
    /// `max_outstanding` requests outstanding.
    pub fn new(img: &'a Images, bases: [u32; 4], max_outstanding: usize) -> Self {
        MemoryController {
            img,
            asks: VecDeque::new(),
            tags: VecDeque::new(),
            held: VecDeque::new(),
            cur: Default::default(),
            node_inflight: 0,
            beat: 0,
            last_aligned: None,
            max_outstanding,
            bases,
            node_fetches: 0,
            tri_fetches: 0,
            tri_fetches_a: 0,
        }
    }

    /// The ask list's free entries (after the last edge).
    pub fn room(&self) -> usize {
        MC_ASKS - self.asks.len()
    }

    /// Requests outstanding.
    pub fn outstanding(&self) -> usize {
        self.tags.len()
    }

    /// The destination and record of the next response (the oldest request outstanding).
    pub fn next_response(&self) -> Option<(Dst, u32)> {
        self.tags.front().copied()
    }

    /// The triangle word a response this clock (`resp`) brings: B's?, its record.
    pub fn fill(&self, resp: bool) -> Option<(bool, u16)> {
        let (d, r) = *self.tags.front().filter(|_| resp)?;
        d.is_tri().then_some((d == Dst::TriB, r as u16))
    }

    /// One clock: the outputs, then the edge.
    pub fn step(&mut self, i: &McIn) -> McOut {
        let fill = self.fill(i.resp);
        let req = self.request(i.need, i.ids);
        let mut out = (!i.halt)
            .then(|| self.stream(i.busy))
            .flatten()
            .unwrap_or_default();
        (out.req, out.fill) = (req.map(|r| r.2), fill);
        out.req_tri = req.is_some_and(|r| r.0.is_tri());
        // the edge
        if out.dop_in.t.is_some() || out.dop_in.a.is_some() {
            self.streamed();
        }
        if let Some((dst, r, _)) = req.filter(|_| i.mem_ready) {
            self.accept(dst, r);
        }
        if i.resp {
            self.respond();
        }
        if let Some(ask) = i.push {
            self.push(ask);
        }
        out
    }

    fn push(&mut self, ask: Ask) {
        assert!(self.asks.len() < MC_ASKS, "the ask list overflows");
        let addr = match ask {
            Ask::Load { id, .. } => {
                self.last_aligned = None;
                Some(self.addr(Dst::NodeB, id >> 1))
            }
            Ask::Aligned { id, .. } => {
                let r = self.addr(Dst::NodeA, id >> 1);
                let new = self.last_aligned != Some(r);
                self.last_aligned = Some(r);
                new.then_some(r)
            }
        };
        self.asks.push_back(Entry {
            ask,
            addr,
            requested: addr.is_none(),
        });
    }

    /// The word address of region `d`'s record (or triangle word) `record`.
    fn addr(&self, d: Dst, record: u32) -> u32 {
        self.bases[d as usize] + record
    }

    /// The head ask's d' set and whether its record is there to stream (`None`: no ask).
    pub fn head(&self) -> Option<(usize, bool)> {
        let e = self.asks.front()?;
        let set = match e.ask {
            Ask::Load { set, .. } | Ask::Aligned { set, .. } => set,
        };
        Some((set, self.record().is_some()))
    }

    /// The request this clock: a triangle word the input stage lacks (`need`, records
    /// `ids`; not while one of its side is outstanding, which may arrive now), else the
    /// first node record not requested, if it has room. With its destination, record
    /// number and word address: a function of the registers, `need` and `ids`.
    pub fn request(&self, need: [bool; 2], ids: [u16; 2]) -> Option<(Dst, u32, u32)> {
        if self.tags.len() >= self.max_outstanding {
            return None;
        }
        for (d, dst) in [(0, Dst::TriA), (1, Dst::TriB)] {
            if need[d] && !self.tags.iter().any(|t| t.0 == dst) {
                let id = ids[d] as u32;
                return Some((dst, id, self.addr(dst, id)));
            }
        }
        let e = self.asks.iter().find(|e| !e.requested)?;
        let (dst, id) = match e.ask {
            Ask::Load { id, .. } => (Dst::NodeB, id),
            Ask::Aligned { id, .. } => (Dst::NodeA, id),
        };
        let room = self.held.len() + self.node_inflight < MC_RECORDS;
        room.then(|| (dst, id >> 1, e.addr.unwrap()))
    }

    fn accept(&mut self, dst: Dst, record: u32) {
        self.tags.push_back((dst, record));
        if dst.is_tri() {
            self.tri_fetches += 1;
            self.tri_fetches_a += (dst == Dst::TriA) as u64;
        } else {
            self.node_inflight += 1;
            self.node_fetches += 1;
            self.asks
                .iter_mut()
                .find(|e| !e.requested)
                .unwrap()
                .requested = true;
        }
    }

    /// A response: a node record joins `held` (a triangle word went to the input stage).
    fn respond(&mut self) {
        let (dst, r) = self.tags.pop_front().expect("a response without a request");
        if !dst.is_tri() {
            let rec = &self.img.records[(dst == Dst::NodeB) as usize][r as usize];
            self.held.push_back(rec.clone());
            self.node_inflight -= 1;
        }
    }

    /// The record the head ask reads this clock: the first one held as its first bundle
    /// streams, if it fetched one; else the one it streams.
    fn record(&self) -> Option<&Record> {
        let fetched = self.asks.front()?.addr.is_some();
        match self.beat == 0 && fetched {
            true => self.held.front(),
            false => Some(&self.cur),
        }
    }

    /// This clock's bundle from the head ask, given the sets' `busy`.
    fn stream(&self, busy: [bool; 2]) -> Option<McOut> {
        let (e, rec) = (self.asks.front()?, self.record()?);
        let (k, beat) = (self.img.k, self.beat);
        let set = match e.ask {
            Ask::Load { set, .. } | Ask::Aligned { set, .. } => set,
        };
        if beat == 0 && busy[set] {
            return None;
        }
        let slot = |id: u32| &rec[id as usize & 1];
        let mut out = McOut::default();
        match e.ask {
            Ask::Load { id, n, .. } => {
                let (side, entry) = (beat / beats(k), beat % beats(k));
                out.dop_in.t = Some(TumbledBundle {
                    set,
                    side,
                    entry,
                    last: beat + 1 == n * beats(k),
                    data: bundle(&slot(id + side as u32).dop, entry),
                });
                let members = (0..n as u32).map(|m| slot(id + m).fields).collect();
                out.loaded = (beat == 0).then_some((set, members));
            }
            Ask::Aligned { id, .. } => {
                let lanes = (k - 8 * beat).min(8);
                out.dop_in.a = Some(AlignedBundle {
                    set,
                    entry: beat,
                    first: beat == 0,
                    lanes: ((1u16 << lanes) - 1) as u8,
                    e: bundle(&slot(id).dop, beat),
                });
                out.aligned = (beat + 1 == beats(k)).then_some(slot(id).fields);
            }
        }
        Some(out)
    }

    /// The edge after a bundle streamed.
    fn streamed(&mut self) {
        let e = self.asks.front().unwrap();
        if self.beat == 0 && e.addr.is_some() {
            self.cur = self.held.pop_front().unwrap();
        }
        let n = match e.ask {
            Ask::Load { n, .. } => n,
            Ask::Aligned { .. } => 1,
        };
        self.beat += 1;
        if self.beat == n * beats(self.img.k) {
            self.beat = 0;
            self.asks.pop_front();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two records of k = 8 distances: the root alone, then its children (ids 2 and 3).
    fn image() -> Images {
        let word = |id: u32, d: f64| NodeWord {
            dop: vec![d; 8],
            fields: Fields {
                id,
                leaf: id > 0,
                f: [id + 10, id + 20],
            },
        };
        let rec = |a: u32| [word(a, a as f64), word(a + 1, a as f64 + 1.0)];
        Images {
            records: [vec![rec(0), rec(2)], vec![rec(0), rec(2)]],
            bases: [100, 200, 300, 400],
            k: 8,
        }
    }

    /// Two aligned siblings share one fetch, stream from its record the clock after it
    /// arrives, with their fields on their (only) bundles; a triangle word goes first
    /// (hand-derived clock by clock).
    #[test]
    fn siblings_share_a_record_and_triangle_words_go_first() {
        let img = image();
        let mut mc = MemoryController::new(&img, img.bases, 4);
        let aligned = |id| Some(Ask::Aligned { set: 0, id });
        let ready = McIn {
            mem_ready: true,
            ..Default::default()
        };
        let o0 = mc.step(&McIn {
            push: aligned(2),
            ..ready
        });
        assert_eq!(o0.req, None);
        let o1 = mc.step(&McIn {
            push: aligned(3),
            ..ready
        });
        assert_eq!(o1.req, Some(101), "A's node region, record 1");
        let o2 = mc.step(&McIn {
            resp: true,
            ..ready
        });
        assert!((o2.req, o2.fill, o2.dop_in.a.is_some()) == (None, None, false));
        let o3 = mc.step(&McIn {
            need: [true, false],
            ids: [7, 0],
            ..ready
        });
        assert_eq!(o3.req, Some(307), "A's triangle region, record 7");
        assert_eq!(o3.dop_in.a.as_ref().map(|a| a.e[0]), Some(2.0));
        assert_eq!(o3.aligned.map(|f| f.f), Some([12, 22]));
        let o4 = mc.step(&McIn {
            resp: true,
            ..ready
        });
        assert_eq!(o4.fill, Some((false, 7)));
        assert_eq!(o4.dop_in.a.as_ref().map(|a| a.e[0]), Some(3.0));
        assert_eq!(o4.aligned.map(|f| f.id), Some(3));
        assert_eq!(
            (mc.node_fetches, mc.tri_fetches, mc.room()),
            (1, 1, MC_ASKS)
        );
    }
}
